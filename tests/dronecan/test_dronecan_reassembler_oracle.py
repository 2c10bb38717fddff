"""The strict reassembler (``strict=True``) against an oracle that knows which transfers
arrived intact.

The strict rule: every transfer whose frames all arrive, once, in order and uncorrupted,
with no other frame of its session in between and within the transfer-ID timeout, is
delivered, unless it repeats the transfer id delivered last in its session within the
timeout.
Streams interleave messages and service transfers of many sessions, with drops,
duplicates, swaps and bit flips per frame, and gaps in time that time sessions out.

The default acceptance is libcanard's, which can splice a repeated start frame's transfer
onto the continuation of an earlier one with the same transfer ID (its toggle check drops
the second start frame); it is checked against libcanard's own output in
test_dronecan_libcanard_acceptance.py, not against this rule.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from hypothesis import given
from hypothesis import strategies as st
from tests.soak import differential

from veronte4x import dronecan
from veronte4x.dronecan import Problem, TransferKind

OK = dronecan.Health.OK
OPERATIONAL = dronecan.Mode.OPERATIONAL
TIMEOUT = dronecan.TRANSFER_ID_TIMEOUT

# (message, is a service request): single frames, 3 frames, 1..4 frames, generic codecs.
_PAYLOADS = st.one_of(
    st.builds(
        lambda u, v: (dronecan.NodeStatus(u, OK, OPERATIONAL, 0, v), False),
        st.integers(0, 3),
        st.integers(0, 3),
    ),
    st.builds(
        lambda e, i: (dronecan.EscStatus(e, 12.5, -3.0, 300.0, 7, 50, i), False),
        st.integers(0, 3),
        st.integers(0, 2),
    ),
    st.lists(st.integers(-2, 2), max_size=16).map(lambda c: (dronecan.RawCommand(tuple(c)), False)),
    st.just((dronecan.GetNodeInfoRequest(), True)),
    st.binary(max_size=20).map(lambda n: (dronecan.GetSetRequest(name=n), True)),
)


@dataclass
class Sent:
    """One transfer put on the bus."""

    key: int  # the session: CAN ID without priority
    tid: int
    message: Any
    source: int
    destination: int | None
    frames: list[tuple[int, bytes]]


@dataclass
class OnWire:
    """One frame of the stream, with where it came from."""

    can_id: int
    data: bytes
    transfer: int  # index into the sent transfers
    index: int  # frame index within its transfer
    damaged: bool  # bits flipped


# Per frame: 0 as is, 1 dropped, 2 sent twice, 3 swapped with the next, 4 a bit flipped.
_FAULT = st.sampled_from([0] * 12 + [1, 2, 3, 4])


def _same_kind(request: bool) -> Callable[[tuple[Any, bool]], bool]:
    """A filter for payloads of the same kind (message or request) as ``request``."""
    return lambda payload: payload[1] == request


@st.composite
def _scenario(draw: st.DrawFn) -> tuple[list[Sent], list[OnWire], list[float]]:
    sessions = draw(
        st.lists(
            st.tuples(st.integers(1, 6), st.integers(1, 6), st.integers(0, 31), _PAYLOADS),
            min_size=1,
            max_size=5,
        )
    )
    sent: list[Sent] = []
    per_session: list[list[OnWire]] = []
    for source, destination, first_tid, (first, request) in sessions:
        count = draw(st.integers(1, 40))
        stream: list[OnWire] = []
        for n in range(count):
            message = first if n == 0 else draw(_PAYLOADS.filter(_same_kind(request)))[0]
            tid = (first_tid + n) % 32
            dest = destination if request else None
            frames = [
                (f.can_id, f.data)
                for f in dronecan.encode(
                    message, source_node_id=source, transfer_id=tid, destination_node_id=dest
                )
            ]
            number = len(sent)
            sent.append(Sent(frames[0][0] & 0xFFFFFF, tid, message, source, dest, frames))
            wire = [OnWire(c, d, number, i, False) for i, (c, d) in enumerate(frames)]
            out: list[OnWire] = []
            i = 0
            while i < len(wire):
                fault = draw(_FAULT)
                frame = wire[i]
                if fault == 1:
                    pass
                elif fault == 2:
                    out += [frame, frame]
                elif fault == 3 and i + 1 < len(wire):
                    out += [wire[i + 1], frame]
                    i += 1
                elif fault == 4:
                    bit = draw(st.integers(0, 8 * len(frame.data) - 1))
                    flipped = bytearray(frame.data)
                    flipped[bit // 8] ^= 1 << (bit % 8)
                    out.append(OnWire(frame.can_id, bytes(flipped), number, i, True))
                else:
                    out.append(frame)
                i += 1
            stream += out
        per_session.append(stream)
    # Interleave the sessions; each keeps its own order.
    merged: list[OnWire] = []
    cursors = [0] * len(per_session)
    while True:
        live = [s for s, frames in enumerate(per_session) if cursors[s] < len(frames)]
        if not live:
            break
        pick = live[draw(st.integers(0, len(live) - 1))] if len(live) > 1 else live[0]
        merged.append(per_session[pick][cursors[pick]])
        cursors[pick] += 1
    # Time: mostly 1 ms steps, now and then a gap past the transfer-ID timeout.
    steps = draw(
        st.lists(
            st.sampled_from([0.001] * 30 + [0.0, 0.7, 2.5]),
            min_size=len(merged),
            max_size=len(merged),
        )
    )
    times, now = [], 0.0
    for step in steps:
        now += step
        times.append(now)
    return sent, merged, times


def _intact(sent: list[Sent], wire: list[OnWire], times: list[float]) -> dict[int, int]:
    """Transfers that arrived intact: transfer index to the stream index of its last frame."""
    positions: dict[int, list[int]] = {}
    for position, frame in enumerate(wire):
        positions.setdefault(frame.transfer, []).append(position)
    intact = {}
    for number, transfer in enumerate(sent):
        where = positions.get(number, [])
        frames = [wire[p] for p in where]
        if (
            [f.index for f in frames] != list(range(len(transfer.frames)))
            or any(f.damaged for f in frames)
            or times[where[-1]] - times[where[0]] > TIMEOUT
        ):
            continue
        # No other frame of the same session (by its CAN ID as received) in between.
        between = wire[where[0] : where[-1] + 1]
        if any(f.can_id & 0xFFFFFF == transfer.key and f.transfer != number for f in between):
            continue
        intact[number] = where[-1]
    return intact


@differential(300)
@given(scenario=_scenario())
def test_every_intact_transfer_is_delivered(
    scenario: tuple[list[Sent], list[OnWire], list[float]],
) -> None:
    sent, wire, times = scenario
    r = dronecan.Reassembler(strict=True)
    results = [r.feed(f.can_id, f.data, t) for f, t in zip(wire, times, strict=True)]
    intact = _intact(sent, wire, times)
    first: dict[int, int] = {}
    for position, frame in enumerate(wire):
        first.setdefault(frame.transfer, position)
    for number, last in intact.items():
        transfer = sent[number]
        start = first[number]
        got = results[last]
        if got is None:
            # Allowed only for a repeat of the transfer id delivered last in its session,
            # within the timeout.
            previous = [
                t
                for t, f in zip(results[:start], wire[:start], strict=True)
                if t is not None and f.can_id & 0xFFFFFF == transfer.key
            ]
            assert previous, f"transfer {number} (tid {transfer.tid}) lost"
            assert previous[-1].transfer_id == transfer.tid, f"transfer {number} lost"
            assert times[start] - previous[-1].timestamp <= TIMEOUT, f"transfer {number} lost"
            assert r.counts[Problem.UNEXPECTED_TRANSFER_ID] + r.counts[Problem.DUPLICATE_FRAME]
            continue
        assert got.message == transfer.message
        assert got.transfer_id == transfer.tid
        assert got.source_node_id == transfer.source
        assert got.destination_node_id == transfer.destination
        assert got.timestamp == times[start]
        assert got.kind is (
            TransferKind.MESSAGE if transfer.destination is None else TransferKind.REQUEST
        )
    assert r.transfers == sum(t is not None for t in results)
    assert r.session_count <= r.max_sessions


@differential(200)
@given(scenario=_scenario(), limit=st.integers(1, 4))
def test_a_small_session_table_stays_bounded(
    scenario: tuple[list[Sent], list[OnWire], list[float]], limit: int
) -> None:
    """With room for few sessions the table never grows past it; expire empties it."""
    _, wire, times = scenario
    r = dronecan.Reassembler(max_sessions=limit)
    for f, t in zip(wire, times, strict=True):
        r.feed(f.can_id, f.data, t)
        assert r.session_count <= limit
    r.expire(times[-1] + 10.0 if times else 10.0)
    assert r.session_count == 0


def test_a_stray_end_frame_does_not_hide_the_next_transfer() -> None:
    """The minimal case: tid 5 delivered, a lone end frame with tid 6, then an intact tid 6."""
    r = dronecan.Reassembler(strict=True)
    ((can_id, five),) = [
        (f.can_id, f.data)
        for f in dronecan.encode(
            dronecan.NodeStatus(1, OK, OPERATIONAL, 0, 0), source_node_id=5, transfer_id=5
        )
    ]
    assert r.feed(can_id, five, 0.0) is not None
    assert r.feed(can_id, bytes(7) + b"\x46", 0.1) is None
    assert r.counts[Problem.MISSED_START] == 1
    ((_, six),) = [
        (f.can_id, f.data)
        for f in dronecan.encode(
            dronecan.NodeStatus(2, OK, OPERATIONAL, 0, 0), source_node_id=5, transfer_id=6
        )
    ]
    transfer = r.feed(can_id, six, 0.2)
    assert transfer is not None
    assert transfer.message.uptime_sec == 2
    assert transfer.transfer_id == 6
    assert r.counts[Problem.UNEXPECTED_TRANSFER_ID] == 0
