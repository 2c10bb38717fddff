"""One driver for files and streams: a capture gives the same tables read from its path
and piped in on standard input, in batches of any size, and those of the per-frame decoder;
generated captures with faults (bad lines, CRC errors, lost and doubled frames, interleaved
sessions), cut into batches anywhere."""

from __future__ import annotations

import os
import tempfile
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import veronte4x.dronecan
from tests.capture.columnar_support import (
    BUS_MAPS,
    assert_same_tables,
    captures,
    many_sessions,
    read_piped,
    write,
)
from veronte4x import capture
from veronte4x.capture import BusMap
from veronte4x.capture.columnar import batches, dronecan

pytest.importorskip("pyarrow")


@contextmanager
def batch_bytes(size: int) -> Iterator[None]:
    """`read_tables` reading batches of about ``size`` bytes (cut at line breaks)."""
    before = batches.BATCH_BYTES
    batches.BATCH_BYTES = size
    try:
        yield
    finally:
        batches.BATCH_BYTES = before


@st.composite
def sessions_between(draw: st.DrawFn, bus_map: BusMap) -> list[str]:
    """Generated lines with a run of interleaved sessions (faults included) put in among
    them, its timestamps after theirs."""
    lines = draw(captures(bus_map))
    count = draw(st.integers(0, 40))
    if not count:
        return lines
    run = many_sessions(
        count,
        concurrent=draw(st.booleans()),
        faults=draw(st.sampled_from([0.0, 0.1, 0.3])),
        seed=draw(st.integers(0, 1_000)),
    )
    at = draw(st.integers(0, len(lines)))
    return lines[:at] + run + lines[at:]


@settings(max_examples=40, suppress_health_check=[HealthCheck.too_slow])
@given(st.data(), BUS_MAPS, st.sampled_from([None, "can0"]), st.integers(1, 3_000))
def test_a_capture_from_its_path_and_piped_in_gives_the_same_tables(
    data: st.DataObject, bus_map: BusMap, channel: str | None, size: int
) -> None:
    lines = data.draw(sessions_between(bus_map))
    with tempfile.TemporaryDirectory() as folder:
        path = write(Path(folder) / "capture.log", lines)
        expected = capture.tables_from_records(capture.read(path, bus_map, channel), bus_map)
        with batch_bytes(size):
            from_path = capture.read_tables(path, bus_map, channel)
            piped = read_piped(path, bus_map, channel)
    assert_same_tables(from_path, expected)
    assert_same_tables(piped, expected)


@pytest.mark.parametrize("size", [700, 20_000, 1 << 22])
def test_a_crowded_channel_piped_in_is_decoded_again_from_what_was_kept(
    size: int, tmp_path: Path
) -> None:
    """A transfer left open before more sessions than the table holds: the channel is
    decoded again frame by frame, from the batches kept (standard input is read once)."""
    request = veronte4x.dronecan.GetSetRequest(index=1, name=b"a long parameter name")
    made = veronte4x.dronecan.encode(
        request, source_node_id=126, transfer_id=3, destination_node_id=127
    )
    cut = f"(1699999999.000000) can0 {made[0].can_id:08X}#{made[0].data.hex()}"
    others = many_sessions(dronecan.MAX_SESSIONS + 3, concurrent=False, transfers=1)
    path = write(tmp_path / "crowded.log", [cut, *others])
    expected = capture.tables_from_records(capture.read(path))
    with batch_bytes(size):
        assert_same_tables(read_piped(path), expected)
        assert_same_tables(capture.read_tables(path), expected)


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="named pipes")
def test_a_crowded_channel_from_a_named_pipe_is_decoded_again_from_what_was_kept(
    tmp_path: Path,
) -> None:
    """A pipe given by its path (``<(zcat f.log.gz)``) is read once too: the pass that
    takes the crowded channel frame by frame reads the kept batches, not the empty pipe."""
    request = veronte4x.dronecan.GetSetRequest(index=1, name=b"a long parameter name")
    made = veronte4x.dronecan.encode(
        request, source_node_id=126, transfer_id=3, destination_node_id=127
    )
    cut = f"(1699999999.000000) can0 {made[0].can_id:08X}#{made[0].data.hex()}"
    path = write(
        tmp_path / "crowded.log",
        [cut, *many_sessions(dronecan.MAX_SESSIONS + 3, concurrent=False, transfers=1)],
    )
    expected = capture.tables_from_records(capture.read(path))
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    writer = threading.Thread(target=fifo.write_bytes, args=(path.read_bytes(),))
    writer.start()
    try:
        with batch_bytes(20_000):
            got = capture.read_tables(fifo)
    finally:
        writer.join()
    assert_same_tables(got, expected)
