"""MF4 bus logs written by asammdf in the layouts loggers use (uncompressed, deflated (DZ)
and transposed-deflated data blocks; one CAN_DataFrame group for every bus, or one group a
bus), read in chunks whose boundaries fall inside data blocks: the same frames as
python-can's reader, and the same tables as the per-frame path."""

from __future__ import annotations

import datetime
import runpy
from pathlib import Path
from typing import Any, Literal

import pytest

from tests.capture.columnar_support import assert_same_tables
from veronte4x import capture

np = pytest.importorskip("numpy")
can = pytest.importorskip("can")
pytest.importorskip("asammdf")

from asammdf import MDF, Signal  # noqa: E402
from asammdf.blocks.source_utils import Source  # noqa: E402
from can.io.mf4 import STD_DTYPE  # noqa: E402

from veronte4x.capture.columnar import batches as batching  # noqa: E402
from veronte4x.capture.columnar.batches import read_batches  # noqa: E402
from veronte4x.capture.columnar.frames import concat, from_frames  # noqa: E402
from veronte4x.capture.readers.pythoncan import read_with_python_can  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
RECORD = STD_DTYPE.itemsize + 8
"""Bytes of one record: the frame structure and its float64 time."""


@pytest.fixture(scope="module")
def flight(tmp_path_factory: pytest.TempPathFactory) -> list[Any]:
    """Three seconds of the example flight (Veronte and DroneCAN), as python-can messages."""
    path = tmp_path_factory.mktemp("flight") / "flight.log"
    runpy.run_path(str(ROOT / "examples" / "make_capture.py"))["generate"](0.05, 1.0, 4).write(path)
    return list(can.CanutilsLogReader(str(path)))


def _write(path: Path, messages: list[Any], buses: int, compression: Literal[0, 1, 2]) -> Path:
    """``messages`` as asammdf writes them: ``buses`` CAN_DataFrame groups (frame i on bus
    i % buses, numbered from 1), in data blocks of about 40 records."""
    mdf = MDF(version="4.10")
    mdf.configure(write_fragment_size=40 * RECORD)
    start = messages[0].timestamp
    mdf.header.start_time = datetime.datetime.fromtimestamp(start, datetime.timezone.utc)
    for bus in range(buses):
        mine = messages[bus::buses]
        records = np.zeros(len(mine), dtype=STD_DTYPE)
        for row, message in enumerate(mine):
            records[row]["CAN_DataFrame.BusChannel"] = bus + 1
            records[row]["CAN_DataFrame.ID"] = message.arbitration_id | (
                message.is_extended_id << 31
            )
            records[row]["CAN_DataFrame.IDE"] = message.is_extended_id
            records[row]["CAN_DataFrame.DLC"] = len(message.data)
            records[row]["CAN_DataFrame.DataLength"] = len(message.data)
            records[row]["CAN_DataFrame.DataBytes"][: len(message.data)] = list(message.data)
        # equal times across the groups: the merge's ties, broken by group order
        stamps = np.array([round(m.timestamp - start, 3) for m in mine], dtype="<f8")
        name = f"CAN{bus + 1}"
        mdf.append(
            Signal(
                name="CAN_DataFrame",
                samples=records,
                timestamps=stamps,
                source=Source(name, name, "", Source.SOURCE_BUS, Source.BUS_TYPE_CAN),
            )
        )
    mdf.save(path, overwrite=True, compression=compression)
    mdf.close()
    return path


@pytest.mark.parametrize("compression", [0, 1, 2], ids=["plain", "deflate", "transposed"])
@pytest.mark.parametrize("buses", [1, 2])
def test_chunks_inside_blocks_are_python_cans_frames(
    flight: list[Any], tmp_path: Path, buses: int, compression: Literal[0, 1, 2]
) -> None:
    path = _write(tmp_path / "bus.mf4", flight, buses, compression)
    expected = from_frames(list(enumerate(read_with_python_can(path), 1)))
    assert len(expected) == len(flight)
    assert set(expected.channels) == {str(bus + 1) for bus in range(buses)}
    run = max(np.unique(expected.timestamp, return_counts=True)[1])
    names = ("order", "timestamp", "can_id", "extended", "remote", "error", "length", "data")
    for records in (1, 7, 40, 41, 97, 10_000):
        parts = list(read_batches(path, batch_bytes=records * RECORD))
        if records < 40:  # at most a chunk of each group, and the frames at its last time
            assert max(len(part.frames) for part in parts) <= buses * (records + run)
        got = concat([part.frames for part in parts])
        for name in names:
            assert getattr(got, name).tolist() == getattr(expected, name).tolist(), name
        assert _channels(got) == _channels(expected)


def _channels(frames: Any) -> list[str]:
    return [frames.channels[code] for code in frames.channel.tolist()]


@pytest.mark.parametrize("compression", [0, 2], ids=["plain", "transposed"])
def test_read_tables_in_small_batches_equals_the_per_frame_path(
    flight: list[Any], tmp_path: Path, monkeypatch: pytest.MonkeyPatch, compression: Literal[0, 2]
) -> None:
    path = _write(tmp_path / "bus.mf4", flight, 2, compression)
    expected = capture.tables_from_records(capture.read(path))
    monkeypatch.setattr(batching, "BATCH_BYTES", 33 * RECORD)
    assert_same_tables(capture.read_tables(path), expected)


@pytest.mark.parametrize("flags", [1, 4, 16])
def test_an_unfinalised_file_reads_as_the_per_frame_path_quietly(
    flight: list[Any], tmp_path: Path, capfd: pytest.CaptureFixture[str], flags: int
) -> None:
    """A file whose identification block says it is unfinalised (ASAM MDF 4.1,
    ``id_unfin_flags``, a 16-bit field at byte 60), which asammdf finalises in a copy."""
    path = _write(tmp_path / "bus.mf4", flight, 2, 0)
    data = bytearray(path.read_bytes())
    data[60:62] = flags.to_bytes(2, "little")
    path.write_bytes(bytes(data))
    expected = capture.tables_from_records(capture.read(path))
    capfd.readouterr()
    assert_same_tables(capture.read_tables(path), expected)
    assert capfd.readouterr() == ("", "")
