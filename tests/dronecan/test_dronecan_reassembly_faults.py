"""The reassembler on long streams with frame faults, judged against what was sent.

Each stream carries 4,000 transfers of four sessions with 5 % or 20 % of the frames
damaged (`fault_streams`). Every intact transfer must be delivered, save those no receiver
can tell from a replay (see `fault_streams.check`), and nothing may be delivered that was
not sent, save a damaged single frame (no CRC protects it).
"""

from __future__ import annotations

import pytest
from fault_streams import check, stream

from veronte4x import dronecan
from veronte4x.dronecan import Problem

OK, OPERATIONAL = dronecan.Health.OK, dronecan.Mode.OPERATIONAL


@pytest.mark.parametrize("rate", [0.05, 0.2])
@pytest.mark.parametrize("seed", range(10))
def test_no_intact_transfer_is_lost_that_could_be_recovered(seed: int, rate: float) -> None:
    sent, wire, times = stream(seed, 4000, rate)
    r = dronecan.Reassembler(strict=True)
    results = [r.feed(f.can_id, f.data, t) for f, t in zip(wire, times, strict=True)]
    verdict = check(sent, wire, times, results)
    assert verdict.lost == []
    assert verdict.corrupted > 0  # the stream does damage single frames


def _frames(message: object, tid: int) -> list[tuple[int, bytes]]:
    frames = dronecan.encode(message, source_node_id=5, transfer_id=tid)
    return [(f.can_id, f.data) for f in frames]


def _with_tid(frame: tuple[int, bytes], tid: int) -> tuple[int, bytes]:
    can_id, data = frame
    return can_id, data[:-1] + bytes([data[-1] & 0xE0 | tid])


ESC = dronecan.EscStatus(1, 12.5, -3.0, 300.0, 7, 50, 2)  # three frames, same session key
ONE_FRAME = dronecan.RawCommand((1, 2))  # RawCommand: one frame, or more with more entries
SEVERAL = dronecan.RawCommand(tuple(range(-8, 8)))


def test_a_multi_frame_transfer_after_a_single_frame_with_its_transfer_id_is_delivered() -> None:
    """Transfer 6 (one frame) arrives with a tail bit flipped to say 7; the real transfer 7
    (several frames, each naming 7, with a CRC) is taken, not refused as a replay."""
    r = dronecan.Reassembler(strict=True)
    (damaged,) = _frames(ONE_FRAME, 6)
    assert r.feed(*_with_tid(damaged, 7), 0.0) is not None  # a single frame: no CRC to tell
    frames = _frames(SEVERAL, 7)
    assert len(frames) > 1 and frames[0][0] == damaged[0]
    results = [r.feed(can_id, data, 0.001 * n) for n, (can_id, data) in enumerate(frames, 1)]
    assert results[:-1] == [None] * (len(frames) - 1)
    transfer = results[-1]
    assert transfer is not None and transfer.message == SEVERAL and transfer.transfer_id == 7
    assert r.counts[Problem.UNEXPECTED_TRANSFER_ID] == 0
    assert sum(r.counts[p] for p in dronecan.TRANSFER_PROBLEMS) == 0


def test_such_a_transfer_that_fails_its_crc_is_counted_once_and_not_delivered() -> None:
    r = dronecan.Reassembler(strict=True)
    (single,) = _frames(ONE_FRAME, 7)
    assert r.feed(*single, 0.0) is not None
    frames = _frames(SEVERAL, 7)
    can_id, data = frames[-1]
    frames[-1] = (can_id, bytes([data[0] ^ 1]) + data[1:])
    assert [r.feed(c, d, 0.01) for c, d in frames] == [None] * len(frames)
    assert r.counts[Problem.CRC_MISMATCH] == 1
    assert sum(r.counts[p] for p in dronecan.TRANSFER_PROBLEMS) == 1


def test_a_multi_frame_transfer_again_after_a_multi_frame_one_is_still_a_replay() -> None:
    """Only a single frame delivered last can be the damaged one; two multi-frame transfers
    with one transfer id within the timeout are a replay, whatever their content."""
    r = dronecan.Reassembler(strict=True)
    first = _frames(SEVERAL, 7)
    assert [r.feed(c, d, 0.0) for c, d in first][-1] is not None
    other = _frames(dronecan.RawCommand(tuple(range(16))), 7)
    assert [r.feed(c, d, 0.1) for c, d in other] == [None] * len(other)
    assert r.counts[Problem.UNEXPECTED_TRANSFER_ID] == 1


def test_a_single_frame_after_a_single_frame_with_its_transfer_id_is_refused() -> None:
    """The case no receiver can recover: which of the two frames is the damaged one?"""
    r = dronecan.Reassembler(strict=True)
    (damaged,) = _frames(dronecan.NodeStatus(1, OK, OPERATIONAL, 0, 0), 6)
    can_id, data = _with_tid(damaged, 7)
    assert r.feed(can_id, data, 0.0) is not None
    ((_, real),) = _frames(dronecan.NodeStatus(2, OK, OPERATIONAL, 0, 0), 7)
    assert r.feed(can_id, real, 0.001) is None
    assert r.counts[Problem.UNEXPECTED_TRANSFER_ID] == 1
