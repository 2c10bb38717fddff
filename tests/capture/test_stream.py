"""The batched decoder against `read_tables` of the whole capture: the same rows, whatever
the cuts between batches."""

from __future__ import annotations

import tempfile
from pathlib import Path

import pyarrow as pa
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.capture.columnar_support import (
    BUS_MAPS,
    VENDOR_BUS_MAPS,
    assert_same_tables,
    captures,
    many_sessions,
    write,
)
from veronte4x import capture, dronecan
from veronte4x.capture import BusMap
from veronte4x.capture.columnar import dronecan as dronecan_columns
from veronte4x.capture.columnar import stream
from veronte4x.capture.columnar.frames import FrameColumns
from veronte4x.capture.columnar.sources import read_frames


def batched(
    frames: FrameColumns,
    sizes: list[int],
    bus_map: BusMap | None = None,
    channel: str | None = None,
) -> dict[str, pa.Table]:
    """The tables of a capture decoded in batches of ``sizes`` frames, joined."""
    per_frame: list[str] = []
    while True:
        decoder = stream.StreamDecoder(bus_map, channel, per_frame)
        parts: dict[str, list[pa.Table]] = {}
        try:
            for batch in stream.split(frames, sizes):
                for kind, table in decoder.feed(batch).items():
                    parts.setdefault(kind, []).append(table)
            decoder.finish()
        except stream.TooManySessions as signal:
            per_frame.append(signal.channel)
            continue
        return {k: pa.concat_tables(t).unify_dictionaries() for k, t in parts.items()}


@settings(max_examples=60, suppress_health_check=[HealthCheck.too_slow])
@given(st.data(), BUS_MAPS | VENDOR_BUS_MAPS, st.sampled_from([None, "can0"]))
def test_generated_captures_in_random_batches(
    data: st.DataObject, bus_map: BusMap, channel: str | None
) -> None:
    lines = data.draw(captures(bus_map))
    sizes = data.draw(st.lists(st.integers(0, 12), max_size=30))
    with tempfile.TemporaryDirectory() as folder:
        path = write(Path(folder) / "capture.log", lines)
        expected = capture.read_tables(path, bus_map, channel)
        got = batched(read_frames(path), sizes, bus_map, channel)
    assert_same_tables(got, expected)


def _transfer_lines(stamp: float, message: object, node: int, tid: int) -> list[str]:
    frames = dronecan.encode(message, source_node_id=node, transfer_id=tid)
    return [f"({stamp:.6f}) can0 {f.can_id:08X}#{f.data.hex().upper()}" for f in frames]


def _interleaved_flight() -> list[str]:
    """Multi-frame transfers of two nodes interleaved with Veronte frames and single-frame
    transfers, with a transfer-id repeat, a gap past the timeout and a lost frame."""
    lines = []
    stamp = 100.0
    for step in range(6):
        stamp += 0.01 if step != 3 else 2.5
        raw = dronecan.RawCommand(cmd=tuple(range(step, step + 12)))
        a = _transfer_lines(stamp, raw, 20, step % 32)
        b = _transfer_lines(stamp + 0.001, raw, 21, (step * 3) % 32)
        if step == 4:
            del a[1]  # a lost frame: that session leaves the column path
        for x, y in zip(a, b, strict=False):
            lines += [x, f"({stamp:.6f}) can0 001#0102", y]
        status = dronecan.NodeStatus(
            uptime_sec=step, health=dronecan.Health.OK, mode=0, sub_mode=0,
            vendor_specific_status_code=0,
        )  # fmt: skip
        lines += _transfer_lines(stamp, status, 22, 0 if step < 2 else step)
    return lines


def test_every_cut_in_multi_frame_transfers() -> None:
    with tempfile.TemporaryDirectory() as folder:
        path = write(Path(folder) / "flight.log", _interleaved_flight())
        expected = capture.read_tables(path)
        frames = read_frames(path)
    assert len(frames) > 40
    for cut in range(len(frames) + 1):
        assert_same_tables(batched(frames, [cut]), expected)
    for size in (1, 2, 3, 5, 7):
        assert_same_tables(batched(frames, [size] * len(frames)), expected)


def test_many_sessions_one_after_another_stay_column_wise() -> None:
    """1,270 sessions, never two open at once: no start over (issue 19, no cliff)."""
    lines = many_sessions(1_270, concurrent=False, transfers=2)
    with tempfile.TemporaryDirectory() as folder:
        path = write(Path(folder) / "busy.log", lines)
        expected = capture.tables_from_records(capture.read(path))
        frames = read_frames(path)
    decoder = stream.StreamDecoder()
    for batch in stream.split(frames, [500] * 10):
        decoder.feed(batch)
    decoder.finish()
    assert not decoder.decoder.reassemblers  # nothing went frame by frame
    assert_same_tables(batched(frames, [500] * 10), expected)


@pytest.mark.parametrize(
    ("count", "concurrent", "faults"),
    [(1_100, True, 0.0), (1_500, True, 0.05), (1_500, False, 0.05), (3_000, False, 0.02)],
)
def test_many_sessions_in_batches_agree(count: int, concurrent: bool, faults: float) -> None:
    lines = many_sessions(count, concurrent, faults, seed=count)
    with tempfile.TemporaryDirectory() as folder:
        path = write(Path(folder) / "busy.log", lines)
        expected = capture.tables_from_records(capture.read(path))
        frames = read_frames(path)
    assert_same_tables(batched(frames, [700] * 20), expected)


def test_a_session_left_open_before_a_thousand_others_starts_over() -> None:
    request = dronecan.GetSetRequest(index=1, name=b"a long parameter name")
    made = dronecan.encode(request, source_node_id=126, transfer_id=3, destination_node_id=127)
    cut = f"(1699999999.000000) can0 {made[0].can_id:08X}#{made[0].data.hex()}"
    lines = [cut, *many_sessions(dronecan_columns.MAX_SESSIONS + 3, False, transfers=1)]
    with tempfile.TemporaryDirectory() as folder:
        path = write(Path(folder) / "busy.log", lines)
        expected = capture.tables_from_records(capture.read(path))
        frames = read_frames(path)
    decoder = stream.StreamDecoder()
    with pytest.raises(stream.TooManySessions):
        for batch in stream.split(frames, [400] * 10):
            decoder.feed(batch)
        decoder.finish()
    assert_same_tables(batched(frames, [400] * 10), expected)


def _returning_sessions(count: int, transfers: int, seed: int) -> list[str]:
    """candump lines of ``count`` sessions that fall silent and come back at random, with
    faults: frames dropped or doubled, toggle bits flipped, transfer ids repeated (within
    the timeout and after it), and gaps past the transfer-ID timeout."""
    import random

    chooser = random.Random(seed)
    messages = [
        dronecan.NodeStatus(
            uptime_sec=5, health=dronecan.Health.OK, mode=0, sub_mode=0,
            vendor_specific_status_code=0,
        ),
        dronecan.RawCommand(cmd=tuple(range(12))),  # two frames
        dronecan.GetSetRequest(index=3, name=b"a parameter"),  # three frames
    ]  # fmt: skip
    sessions = chooser.sample(
        [(kind, node, target) for kind in range(3) for node in range(1, 128)
         for target in ((None,) if kind < 2 else range(1, 40))],
        count,
    )  # fmt: skip
    tids = [chooser.randrange(32) for _ in sessions]
    lines = []
    stamp = 1_700_000_000.0
    for _ in range(transfers):
        session = chooser.randrange(count)
        kind, node, target = sessions[session]
        fault = chooser.randrange(12)
        if fault == 0:
            stamp += 2.5  # past the transfer-ID timeout
        if fault != 1:  # 1: the transfer id of the session's last transfer, again
            tids[session] = (tids[session] + 1) % 32
        made = dronecan.encode(
            messages[kind],
            source_node_id=node,
            transfer_id=tids[session],
            destination_node_id=target,
        )
        frames = [(f.can_id, bytearray(f.data)) for f in made]
        at = chooser.randrange(len(frames))
        if fault == 2:
            del frames[at]
        elif fault == 3:
            frames.insert(at, frames[at])
        elif fault == 4:
            frames[at][1][-1] ^= 0x20  # the toggle bit
        for can_id, data in frames:
            stamp += chooser.choice((1e-4, 1e-3, 0.3))
            lines.append(f"({stamp:.6f}) can0 {can_id:08X}#{bytes(data).hex().upper()}")
    return lines


@pytest.mark.parametrize(
    ("count", "transfers", "sizes"),
    [(40, 600, [1, 3]), (400, 2_000, [5, 16]), (1_500, 4_000, [13, 64])],
)
def test_sessions_that_fall_silent_and_return_in_small_batches(
    count: int, transfers: int, sizes: list[int]
) -> None:
    """Small batches cut inside transfers and between repeats of sessions silent for many
    batches (their context kept aside), faults included: the rows of `capture.read`."""
    lines = _returning_sessions(count, transfers, seed=count)
    with tempfile.TemporaryDirectory() as folder:
        path = write(Path(folder) / "returning.log", lines)
        expected = capture.tables_from_records(capture.read(path))
        frames = read_frames(path)
    for size in sizes:
        assert_same_tables(batched(frames, [size] * len(frames)), expected)
