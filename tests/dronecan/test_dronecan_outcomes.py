"""What happened to a frame, as a value: `Reassembler.push` against `feed` and the records.

`push` returns the transfer a frame completes, the `Problems` it caused, or None. On long
fault streams (with junk frames, bytes-like data of every kind and a small session table
mixed in) its values must be exactly what the reassembler counts and records, and its
transfers exactly those of `feed` on a twin reassembler.
"""

from __future__ import annotations

import random
from typing import Any

import fault_streams
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from veronte4x import dronecan
from veronte4x.dronecan import Problem, ProblemReport, Problems, Transfer

OK, OPERATIONAL = dronecan.Health.OK, dronecan.Mode.OPERATIONAL
NODE_STATUS = dronecan.NodeStatus(1, OK, OPERATIONAL, 0, 0)


def _frames(message: Any, source: int = 5, tid: int = 0, **kw: Any) -> list[tuple[int, bytes]]:
    return [
        (f.can_id, f.data)
        for f in dronecan.encode(message, source_node_id=source, transfer_id=tid, **kw)
    ]


def _junk(rng: random.Random) -> tuple[int, Any]:
    """A frame no sender makes: anonymous, unknown type, no tail, too long, 0 node ids."""
    kind = rng.randrange(6)
    if kind == 0:
        return rng.randrange(1 << 24) << 8, rng.randbytes(rng.randrange(1, 9))  # anonymous
    if kind == 1:
        return 0x3FF0 << 8 | rng.randrange(1, 128), rng.randbytes(rng.randrange(1, 9))
    if kind == 2:
        return rng.randrange(1 << 29), b""
    if kind == 3:
        return rng.randrange(1 << 29), rng.randbytes(9)
    if kind == 4:
        return rng.randrange(1 << 30, 1 << 31), rng.randbytes(rng.randrange(1, 9))
    return 0x80 | rng.randrange(1 << 29) & ~0x7F7F, rng.randbytes(rng.randrange(1, 9))


def _bytes_like(rng: random.Random, data: bytes) -> Any:
    return rng.choice([data, data, data, bytearray(data), memoryview(data)])


def _expected_feed(outcome: Transfer | Problems | None) -> Transfer | None:
    return outcome.transfer if isinstance(outcome, Problems) else outcome


@settings(max_examples=60)
@given(
    seed=st.integers(0, 2**32),
    rate=st.sampled_from([0.0, 0.05, 0.2, 0.5]),
    sessions=st.integers(1, 6),
    limit=st.sampled_from([1, 2, 3, 1024]),
    junk=st.sampled_from([0.0, 0.1]),
)
def test_push_returns_what_is_counted_and_recorded(
    seed: int, rate: float, sessions: int, limit: int, junk: float
) -> None:
    """Per frame: the reports push returns are the ones `problems` got, in order; a
    transfer comes only with the reports before it; feed gives the same transfers and
    leaves the same counts and records; expire_reports returns the last ones."""
    wire = fault_streams.stream(seed, 120, rate, sessions)[1]
    rng = random.Random(seed)
    pushed = dronecan.Reassembler(max_sessions=limit, max_reports=100_000)
    fed = dronecan.Reassembler(max_sessions=limit, max_reports=100_000)
    frames = [(f.can_id, f.data) for f in wire]
    for position in range(len(frames)):
        if rng.random() < junk:
            frames.insert(position, _junk(rng))
    now = 0.0
    for can_id, raw in frames:
        now += rng.choice([0.001] * 20 + [0.0, 2.5])
        data = _bytes_like(rng, raw)
        before = pushed.reported
        outcome = pushed.push(can_id, data, now)
        recorded = list(pushed.problems)[before:]
        if isinstance(outcome, Problems):
            assert 1 <= len(outcome.reports) <= 2
            assert list(outcome.reports) == recorded
            assert all(isinstance(r, ProblemReport) for r in outcome.reports)
        else:
            assert recorded == []
            assert outcome is None or isinstance(outcome, Transfer)
        assert fed.feed(can_id, data, now) == _expected_feed(outcome)
    assert pushed.counts == fed.counts
    assert list(pushed.problems) == list(fed.problems)
    assert pushed.transfers == fed.transfers
    before = pushed.reported
    reports = pushed.expire_reports(now + 10.0)
    assert reports == list(pushed.problems)[before:]
    assert all(r.problem is Problem.TIMEOUT for r in reports)
    assert fed.expire(now + 10.0) >= len(reports)
    assert pushed.counts == fed.counts
    assert pushed.session_count == fed.session_count == 0


def test_a_clean_transfer_is_the_transfer_itself() -> None:
    r = dronecan.Reassembler()
    ((can_id, data),) = _frames(NODE_STATUS)
    transfer = r.push(can_id, data, 1.0)
    assert type(transfer) is Transfer
    assert transfer.message == NODE_STATUS
    first = _frames(dronecan.EscStatus(3, 24.5, 12.25, 310.0, 4321, 55, 2))[0]
    assert r.push(*first, 1.0) is None  # taken, nothing to tell
    assert r.reported == 0


def test_one_problem() -> None:
    r = dronecan.Reassembler(strict=True)
    ((can_id, data),) = _frames(NODE_STATUS)
    r.push(can_id, data, 1.0)
    outcome = r.push(can_id, data, 1.001)
    assert outcome == Problems(
        (ProblemReport(Problem.DUPLICATE_FRAME, can_id, data, 1.001, "frame again"),), None
    )
    assert r.feed(can_id, b"", 1.002) is None
    assert r.problems[-1].problem is Problem.MALFORMED_FRAME


def test_an_interrupted_transfer_then_the_single_frame_that_interrupted_it() -> None:
    """A multi-frame RawCommand cut short by a single-frame one of the same session."""
    r = dronecan.Reassembler()
    first = _frames(dronecan.RawCommand(tuple(range(8))), tid=3)[0]
    ((can_id, single),) = _frames(dronecan.RawCommand((7,)), tid=4)
    assert r.push(*first, 1.0) is None
    outcome = r.push(can_id, single, 1.001)
    assert isinstance(outcome, Problems)
    (report,) = outcome.reports
    assert report == ProblemReport(Problem.INTERRUPTED, can_id, single, 1.001, "transfer id 3")
    assert outcome.transfer is not None
    assert outcome.transfer.message == dronecan.RawCommand((7,))
    assert outcome.transfer.transfer_id == 4


def test_a_transfer_lost_to_make_room_then_the_frame_that_made_it() -> None:
    """With room for one session, a new session's frame evicts a transfer in progress."""
    r = dronecan.Reassembler(max_sessions=1)
    first = _frames(dronecan.RawCommand(tuple(range(8))), source=5)[0]
    ((can_id, data),) = _frames(NODE_STATUS, source=6)
    r.push(*first, 1.0)
    outcome = r.push(can_id, data, 1.5)
    assert isinstance(outcome, Problems)
    assert [(p.problem, p.can_id) for p in outcome.reports] == [
        (Problem.EVICTED, first[0] & 0xFFFFFF)
    ]
    assert outcome.transfer is not None
    assert outcome.transfer.message == NODE_STATUS
    assert r.feed(*first, 1.6) is None  # and again through the full update
    assert r.problems[-1].problem is Problem.EVICTED


def test_two_reports_from_one_frame() -> None:
    """A first frame with its toggle set, after the transfer in progress timed out."""
    r = dronecan.Reassembler()
    can_id, data = _frames(dronecan.RawCommand(tuple(range(8))), tid=3)[0]
    r.push(can_id, data, 1.0)
    toggled = data[:-1] + bytes([0x80 | 0x20 | 9])
    outcome = r.push(can_id, toggled, 4.0)
    assert isinstance(outcome, Problems)
    assert [p.problem for p in outcome.reports] == [Problem.TIMEOUT, Problem.TOGGLE_ERROR]
    assert outcome.transfer is None
    assert list(r.problems) == list(outcome.reports)


def test_expire_reports() -> None:
    r = dronecan.Reassembler()
    for source in (5, 6):
        r.push(*_frames(dronecan.RawCommand(tuple(range(8))), source=source)[0], 1.0)
    r.push(*_frames(NODE_STATUS, source=7)[0], 1.0)
    reports = r.expire_reports(5.0)
    assert [(p.problem, p.can_id & 0x7F, p.timestamp) for p in reports] == [
        (Problem.TIMEOUT, 5, 5.0),
        (Problem.TIMEOUT, 6, 5.0),
    ]
    assert r.session_count == 0
    assert r.expire_reports(9.0) == []


@pytest.mark.parametrize("method", ["push", "feed"])
def test_arguments_of_the_wrong_type_name_the_method(method: str) -> None:
    call = getattr(dronecan.Reassembler(), method)
    with pytest.raises(TypeError, match=rf"^Reassembler\.{method}\(\): data must be bytes-like"):
        call(0x155, "c0", 0.0)
    with pytest.raises(TypeError, match=rf"^Reassembler\.{method}\(\): can_id must be an int"):
        call(1.5, b"\xc0", 0.0)
    with pytest.raises(TypeError, match=r"^Reassembler\.expire_reports\(\): timestamp"):
        dronecan.Reassembler().expire_reports("1")  # type: ignore[arg-type]
