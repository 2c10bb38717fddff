"""The reassembler under faults: drops, duplicates, reordering, interleaving, corruption,
transfer-id wrap-around, timeouts and bounded memory."""

from __future__ import annotations

import contextlib
from typing import Any

from hypothesis import given, settings
from hypothesis import strategies as st

from veronte4x import dronecan
from veronte4x.dronecan import Problem

TRANSFER_PROBLEMS = {
    Problem.MISSED_START,
    Problem.TOGGLE_ERROR,
    Problem.CRC_MISMATCH,
    Problem.TIMEOUT,
    Problem.INTERRUPTED,
    Problem.PAYLOAD_TOO_LONG,
    Problem.BAD_PAYLOAD,
    Problem.EVICTED,
}
OK = dronecan.Health.OK
OPERATIONAL = dronecan.Mode.OPERATIONAL


def _broken(r: dronecan.Reassembler) -> int:
    return sum(r.counts[p] for p in TRANSFER_PROBLEMS)


def _frames(message: Any, source: int, tid: int, **kwargs: Any) -> list[tuple[int, bytes]]:
    return [
        (f.can_id, f.data)
        for f in dronecan.encode(message, source_node_id=source, transfer_id=tid, **kwargs)
    ]


_MESSAGES = st.one_of(
    st.builds(
        lambda u, v: dronecan.NodeStatus(u, OK, OPERATIONAL, 0, v),
        st.integers(0, 2**32 - 1),
        st.integers(0, 65535),
    ),
    st.builds(
        lambda e, r, i: dronecan.EscStatus(e, 12.5, -3.0, 300.0, r, 50, i),
        st.integers(0, 2**32 - 1),
        st.integers(-(2**17), 2**17 - 1),
        st.integers(0, 31),
    ),
    st.lists(st.integers(-8192, 8191), max_size=20).map(lambda c: dronecan.RawCommand(tuple(c))),
)

# A session: (source node, list of messages of one type family); transfer ids run on.
_SESSION = st.tuples(st.integers(1, 127), st.integers(0, 31), st.lists(_MESSAGES, max_size=40))


def _stream(
    sessions: list[tuple[int, int, list[Any]]], faults: list[int], order: list[int]
) -> tuple[list[tuple[int, bytes]], list[Any], int]:
    """Frames of all sessions interleaved, with faults; the expected transfers and breaks.

    Fault codes per transfer: 0 none, 1 drop one frame, 2 duplicate every frame, 3 swap two
    adjacent frames.
    """
    per_session: list[list[tuple[int, bytes]]] = []
    expected: list[Any] = []
    broken = 0
    fault_index = 0
    for s, (source, first_tid, messages) in enumerate(sessions):
        frames: list[tuple[int, bytes]] = []
        for n, message in enumerate(messages):
            # One session per (source, type): give each type its own source offset.
            node = (
                source
                + 40
                * [dronecan.NodeStatus, dronecan.EscStatus, dronecan.RawCommand].index(
                    type(message)
                )
            ) % 127 + 1
            transfer = _frames(message, node, (first_tid + n) % 32)
            fault = faults[fault_index % len(faults)] if faults else 0
            fault_index += 1
            if fault == 1 and len(transfer) > 1:
                del transfer[(s + n) % len(transfer)]
                broken += 1
            elif fault == 1:
                transfer = []
            elif fault == 2:
                transfer = [f for f in transfer for _ in (0, 1)]
                expected.append((node, message))
            elif fault == 3 and len(transfer) > 1:
                i = (s + n) % (len(transfer) - 1)
                transfer[i], transfer[i + 1] = transfer[i + 1], transfer[i]
                broken += 1
            else:
                expected.append((node, message))
            frames += transfer
        per_session.append(frames)
    # Interleave the sessions, each in its own order, as chosen by ``order``.
    stream: list[tuple[int, bytes]] = []
    cursors = [0] * len(per_session)
    choice = 0
    while any(c < len(f) for c, f in zip(cursors, per_session, strict=True)):
        live = [i for i, f in enumerate(per_session) if cursors[i] < len(f)]
        pick = live[order[choice % len(order)] % len(live)] if order else live[0]
        choice += 1
        stream.append(per_session[pick][cursors[pick]])
        cursors[pick] += 1
    return stream, expected, broken


def _sorted(items: list[Any]) -> list[Any]:
    return sorted(items, key=repr)


@settings(max_examples=150)
@given(
    sessions=st.lists(_SESSION, min_size=1, max_size=4, unique_by=lambda s: s[0]),
    faults=st.lists(st.sampled_from([0, 0, 0, 1, 2, 3]), max_size=20),
    order=st.lists(st.integers(0, 100), max_size=50),
)
def test_every_good_transfer_comes_out_and_every_broken_one_counts_once(
    sessions: list[tuple[int, int, list[Any]]], faults: list[int], order: list[int]
) -> None:
    stream, expected, broken = _stream(sessions, faults, order)
    r = dronecan.Reassembler(strict=True)
    out = []
    for i, (can_id, data) in enumerate(stream):
        t = r.feed(can_id, data, timestamp=i * 0.001)
        if t is not None:
            out.append((t.source_node_id, t.message))
    r.expire(len(stream) * 0.001 + 10.0)
    assert _sorted(out) == _sorted(expected)
    assert _broken(r) == broken
    assert r.transfers == len(expected)


def test_interleaved_nodes_and_types_in_order() -> None:
    r = dronecan.Reassembler()
    a = _frames(dronecan.EscStatus(1, 1.0, 2.0, 3.0, 4, 5, 6), 10, 0)
    b = _frames(dronecan.RawCommand(tuple(range(10))), 10, 0)
    c = _frames(dronecan.EscStatus(7, 1.0, 2.0, 3.0, 4, 5, 6), 11, 0)
    b = b[:1] + b  # a duplicated first frame is ignored
    stream = [frames[i] for i in range(4) for frames in (a, b, c) if i < len(frames)]
    out = [r.feed(can_id, data, timestamp=0.0) for can_id, data in stream]
    messages = [t.message for t in out if t is not None]
    assert messages == [
        dronecan.EscStatus(1, 1.0, 2.0, 3.0, 4, 5, 6),
        dronecan.EscStatus(7, 1.0, 2.0, 3.0, 4, 5, 6),
        dronecan.RawCommand(tuple(range(10))),
    ]
    assert r.counts[Problem.DUPLICATE_FRAME] == 1
    r.counts[Problem.DUPLICATE_FRAME] = 0
    assert sum(r.counts.values()) == 0


def test_crc_corruption_is_counted_once() -> None:
    r = dronecan.Reassembler()
    frames = _frames(dronecan.EscStatus(1, 1.0, 2.0, 3.0, 4, 5, 6), 10, 3)
    bad = bytearray(frames[1][1])
    bad[0] ^= 0x01
    frames[1] = (frames[1][0], bytes(bad))
    assert [r.feed(c, d, timestamp=0.0) for c, d in frames] == [None, None, None]
    assert r.counts[Problem.CRC_MISMATCH] == 1
    assert _broken(r) == 1
    assert r.problems[-1].problem is Problem.CRC_MISMATCH
    # The next transfer is fine.
    good = _frames(dronecan.EscStatus(2, 1.0, 2.0, 3.0, 4, 5, 6), 10, 4)
    assert [r.feed(c, d, timestamp=0.1) for c, d in good][-1] is not None


def test_flipped_toggle_is_counted_once() -> None:
    r = dronecan.Reassembler(strict=True)
    frames = _frames(dronecan.RawCommand(tuple(range(20))), 10, 3)
    flipped = frames[2][1][:-1] + bytes((frames[2][1][-1] ^ 0x20,))
    frames[2] = (frames[2][0], flipped)
    assert all(r.feed(c, d, timestamp=0.0) is None for c, d in frames)
    assert r.counts[Problem.TOGGLE_ERROR] == 1
    assert _broken(r) == 1


def test_transfer_id_wraps_past_31() -> None:
    r = dronecan.Reassembler()
    delivered = 0
    for n in range(100):
        for c, d in _frames(dronecan.NodeStatus(n, OK, OPERATIONAL, 0, 0), 5, n % 32):
            t = r.feed(c, d, timestamp=n * 0.5)
            if t is not None:
                assert t.message.uptime_sec == n
                assert t.transfer_id == n % 32
                delivered += 1
        for c, d in _frames(dronecan.EscStatus(n, 1.0, 2.0, 3.0, 4, 5, 6), 5, n % 32):
            if r.feed(c, d, timestamp=n * 0.5) is not None:
                delivered += 1
    assert delivered == 200
    assert sum(r.counts.values()) == 0


def test_duplicate_single_frame_is_ignored_then_accepted_after_the_timeout() -> None:
    r = dronecan.Reassembler(strict=True)
    ((c, d),) = _frames(dronecan.NodeStatus(1, OK, OPERATIONAL, 0, 0), 5, 7)
    assert r.feed(c, d, timestamp=0.0) is not None
    assert r.feed(c, d, timestamp=1.0) is None
    assert r.counts[Problem.DUPLICATE_FRAME] == 1
    # Spec 4.1: past the transfer-ID timeout (2 s) a start frame restarts the session.
    assert r.feed(c, d, timestamp=2.5) is not None


def test_incomplete_transfer_times_out() -> None:
    r = dronecan.Reassembler(strict=True)
    frames = _frames(dronecan.EscStatus(1, 1.0, 2.0, 3.0, 4, 5, 6), 10, 0)
    assert r.feed(*frames[0], timestamp=0.0) is None
    assert r.feed(*frames[1], timestamp=2.1) is None  # too late: the transfer timed out
    assert r.feed(*frames[2], timestamp=2.2) is None  # the rest of it is dropped silently
    assert r.counts[Problem.TIMEOUT] == 1
    assert _broken(r) == 1
    again = _frames(dronecan.EscStatus(1, 1.0, 2.0, 3.0, 4, 5, 6), 10, 0)
    assert r.feed(*again[0], timestamp=3.0) is None
    assert r.feed(*again[1], timestamp=3.0) is None
    assert r.feed(*again[2], timestamp=3.0) is not None


def test_expire_counts_transfers_whose_end_never_came() -> None:
    r = dronecan.Reassembler()
    frames = _frames(dronecan.RawCommand(tuple(range(20))), 10, 0)
    for c, d in frames[:-1]:
        r.feed(c, d, timestamp=0.0)
    assert r.expire(1.0) == 0
    assert r.expire(2.5) == 1
    assert r.counts[Problem.TIMEOUT] == 1
    assert r.session_count == 0


def test_payload_too_long_and_bad_payload() -> None:
    r = dronecan.Reassembler()
    # A 3-frame NodeStatus is too long for its 7-byte type: the payload does not decode.
    frames = dronecan.encode(
        dronecan.GetSetRequest(name=b"x" * 20),
        source_node_id=1,
        destination_node_id=2,
        transfer_id=0,
    )
    status_id = dronecan.message_can_id(0, 341, 1)
    for f in frames:
        r.feed(status_id, f.data, timestamp=0.0)
    assert r.counts[Problem.PAYLOAD_TOO_LONG] + r.counts[Problem.BAD_PAYLOAD] == 1
    r2 = dronecan.Reassembler()
    r2.feed(status_id, b"\x00\x00\xc0", timestamp=0.0)  # 2 bytes for a 7-byte type
    assert r2.counts[Problem.BAD_PAYLOAD] == 1
    assert "NodeStatus" in r2.problems[0].detail
    request_id = dronecan.service_can_id(0, 1, True, source_node_id=5, destination_node_id=6)
    assert r2.feed(request_id, b"\xc0", timestamp=0.0) is not None  # empty GetNodeInfo request
    assert r2.feed(request_id, b"\x01\xc1", timestamp=0.1) is None  # one byte too many
    assert r2.counts[Problem.BAD_PAYLOAD] == 2


def test_unknown_types_and_malformed_frames_are_counted() -> None:
    """19000: no type of the default set (the shipped vendor roots take 20000 and on)."""
    r = dronecan.Reassembler()
    assert r.feed(dronecan.message_can_id(0, 19000, 1), b"\xc0", timestamp=0.0) is None
    assert r.feed(dronecan.anonymous_can_id(0, 2, 5), b"\x01\xc0", timestamp=0.0) is None
    assert r.feed(dronecan.message_can_id(0, 341, 1), b"", timestamp=0.0) is None
    assert r.feed(1 << 29, b"\xc0", timestamp=0.0) is None
    assert r.feed(dronecan.message_can_id(0, 341, 1), bytes(9), timestamp=0.0) is None
    assert r.counts[Problem.UNKNOWN_TYPE] == 2
    assert r.counts[Problem.MALFORMED_FRAME] == 3


def test_memory_stays_bounded() -> None:
    r = dronecan.Reassembler(max_sessions=16, max_reports=8)
    for node in range(1, 128):
        for type_id, frame in ((1034, 0), (1030, 1)):
            first = _frames(
                dronecan.EscStatus(1, 1.0, 2.0, 3.0, 4, 5, 6)
                if type_id == 1034
                else dronecan.RawCommand(tuple(range(20))),
                node,
                0,
            )[frame * 0]
            r.feed(*first, timestamp=0.0)  # start frames only: every session stays open
        assert r.session_count <= 16
    assert len(r.problems) <= 8
    assert r.counts[Problem.EVICTED] == 2 * 127 - 16


@settings(max_examples=300)
@given(
    st.lists(
        st.tuples(
            st.one_of(st.integers(-(2**31), 2**31), st.integers(0, 2**29 - 1)),
            st.binary(max_size=10),
            st.floats(-1e3, 1e3),
        ),
        max_size=30,
    )
)
def test_arbitrary_frames_never_raise(frames: list[tuple[int, bytes, float]]) -> None:
    r = dronecan.Reassembler()
    for can_id, data, timestamp in frames:
        r.feed(can_id, data, timestamp)
        with contextlib.suppress(dronecan.DecodeError):
            dronecan.decode_frames([(can_id, data)])
    assert r.session_count <= r.max_sessions


def test_a_lost_transfer_0_is_not_taken_for_a_delivered_transfer_31() -> None:
    """A lost transfer is marked apart from every transfer id (0..31): transfer 31 right
    after a lost transfer 0 is new, not a repeat of what was delivered last."""
    r = dronecan.Reassembler(strict=True)
    status = dronecan.EscStatus(1, 1.0, 2.0, 3.0, 4, 5, 6)
    delivered = [r.feed(c, d, timestamp=0.0) for c, d in _frames(status, 10, 30)]
    assert delivered[-1] is not None and delivered[-1].transfer_id == 30
    lost = _frames(status, 10, 0)
    del lost[1]  # transfer 0 loses its middle frame
    assert [r.feed(c, d, timestamp=0.1) for c, d in lost] == [None, None]
    assert _broken(r) == 1
    last = [r.feed(c, d, timestamp=0.2) for c, d in _frames(status, 10, 31)][-1]
    assert last is not None and last.transfer_id == 31 and last.message == status
