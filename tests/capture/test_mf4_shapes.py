"""MF4 bus logs in shapes the other MF4 tests leave out, read in chunks: CAN FD frames of
more than eight bytes, a group without a bus channel (a logger of one bus), and chunks that
hold no record; the same frames as python-can's reader, the same tables as the per-frame
path.

Branches of `veronte4x.capture.columnar.mf4` no input reaches:

- ``mf4.py:100`` on its ``failed = False`` side (the ``else`` of ``_read``'s ``try``): the
  loop inside leaves only by ``return``, which skips the ``else``, or by an error, which
  sets ``failed``.
- ``mf4.py:251`` to 252 (a batch of python-can's frames after asammdf failed here):
  python-can's reader opens the file with asammdf too, reading every group whole on
  opening (its bus-logging pass), so a file or a chunk asammdf cannot read here makes
  python-can's reader fail before its first frame (a `SourceError`, as in
  ``test_a_damaged_data_block_is_the_per_frame_paths_error``) or give none past the
  frames the chunks read.
"""

from __future__ import annotations

import datetime
import heapq
from collections.abc import Iterator
from pathlib import Path
from typing import Literal

import pytest
from hypothesis import given
from hypothesis import strategies as st

from tests.capture.columnar_support import assert_same_tables
from veronte4x import capture
from veronte4x.capture.frames import Frame
from veronte4x.errors import SourceError

np = pytest.importorskip("numpy")
can = pytest.importorskip("can")
pytest.importorskip("asammdf")

from asammdf import MDF, Signal  # noqa: E402
from asammdf.blocks.source_utils import Source  # noqa: E402
from can.io.mf4 import STD_DTYPE  # noqa: E402

from veronte4x.capture.columnar import mf4  # noqa: E402
from veronte4x.capture.columnar.batches import read_batches  # noqa: E402
from veronte4x.capture.columnar.frames import FrameColumns, concat, from_frames  # noqa: E402
from veronte4x.capture.readers.pythoncan import read_with_python_can  # noqa: E402

NAMES = ("order", "timestamp", "can_id", "extended", "remote", "fd", "error", "length")


def _same_frames(got: FrameColumns, expected: FrameColumns) -> None:
    """The same columns, and the same frames (data of any length) taken out of them."""
    for name in NAMES:
        assert getattr(got, name).tolist() == getattr(expected, name).tolist(), name
    short = expected.length <= 8  # longer data: in long_data (data holds what it likes)
    assert got.data[short].tolist() == expected.data[short].tolist()
    assert got.long_data == expected.long_data
    rows = np.arange(len(expected.can_id))
    assert got.frames_of(rows) == expected.frames_of(rows)


def _fd_log(path: Path) -> Path:
    """Classic and CAN FD frames (up to 64 bytes), on two channels, through python-can's
    MF4 writer."""
    with can.Logger(str(path)) as logger:
        for i in range(60):
            size = (0, 3, 8, 12, 20, 48, 64)[i % 7]
            logger(
                can.Message(
                    timestamp=1_763_737_000 + i * 0.002,
                    arbitration_id=0x1000 + i if i % 2 else i,
                    is_extended_id=bool(i % 2),
                    is_fd=size > 8 or i % 5 == 0,
                    bitrate_switch=i % 3 == 0,
                    data=bytes((i * 7 + k) & 0xFF for k in range(size)),
                    channel=i % 2,
                )
            )
    return path


@pytest.mark.parametrize("size", [1, 5, 7, 1000])
def test_can_fd_frames_longer_than_eight_bytes(tmp_path: Path, size: int) -> None:
    path = _fd_log(tmp_path / "fd.mf4")
    expected = from_frames(list(enumerate(read_with_python_can(path), 1)))
    assert {len(d) for d in expected.long_data.values()} == {12, 20, 48, 64}
    got = concat([batch.frames for batch in read_batches(path, batch_frames=size)])
    _same_frames(got, expected)
    assert got.frames_of(np.arange(len(got.can_id)))[4].data == bytes(
        (4 * 7 + k) & 0xFF for k in range(20)
    )
    assert_same_tables(capture.read_tables(path), capture.tables_from_records(capture.read(path)))


def _one_bus(path: Path, count: int, compression: Literal[0, 1] = 0) -> Path:
    """A CAN_DataFrame group without a BusChannel channel (asammdf's writer, as loggers of
    one bus write it), in data blocks of 16 records (deflated ones with ``compression``)."""
    fields = [f for f in STD_DTYPE.descr if f[0] != "CAN_DataFrame.BusChannel"]
    dtype = np.dtype(fields)
    records = np.zeros(count, dtype=dtype)
    for row in range(count):
        data = bytes((row + k) & 0xFF for k in range(row % 9))
        records[row]["CAN_DataFrame.ID"] = 0x100 + row
        records[row]["CAN_DataFrame.DLC"] = len(data)
        records[row]["CAN_DataFrame.DataLength"] = len(data)
        records[row]["CAN_DataFrame.DataBytes"][: len(data)] = list(data)
    mdf = MDF(version="4.10")
    mdf.configure(write_fragment_size=16 * (dtype.itemsize + 8))
    mdf.header.start_time = datetime.datetime(2025, 11, 21, 12, 0, tzinfo=datetime.timezone.utc)
    mdf.append(
        Signal(
            name="CAN_DataFrame",
            samples=records,
            timestamps=np.arange(count, dtype="<f8") * 0.01,
            source=Source("CAN", "CAN", "", Source.SOURCE_BUS, Source.BUS_TYPE_CAN),
        )
    )
    mdf.save(path, overwrite=True, compression=compression)
    mdf.close()
    return path


@pytest.mark.parametrize("records", [1, 16, 17, 1000])
def test_a_group_without_a_bus_channel_has_frames_without_a_channel(
    tmp_path: Path, records: int
) -> None:
    path = _one_bus(tmp_path / "one_bus.mf4", 50)
    expected = from_frames(list(enumerate(read_with_python_can(path), 1)))
    assert expected.channels == [""] and len(expected.can_id) == 50
    batches = list(read_batches(path, batch_bytes=records * (STD_DTYPE.itemsize + 7)))
    got = concat([batch.frames for batch in batches])
    _same_frames(got, expected)
    assert got.can_id.tolist() == [0x100 + row for row in range(50)]
    expected_tables = capture.tables_from_records(capture.read(path))
    assert_same_tables(capture.read_tables(path), expected_tables)


_STAMPS = st.lists(st.integers(0, 6).map(float), max_size=12)


@given(st.lists(_STAMPS, min_size=1, max_size=3), st.integers(1, 5), st.data())
def test_chunks_without_records_merge_as_heapq_merges_them(
    groups: list[list[float]], size: int, data: st.DataObject
) -> None:
    """A group's chunks may hold no record (a reader's chunk past the records it has):
    the merge goes on to the next chunk, in ``heapq.merge``'s order still."""
    frames = [
        [Frame(stamp, "g", group * 100 + row, b"") for row, stamp in enumerate(stamps)]
        for group, stamps in enumerate(groups)
    ]
    expected = [f.can_id for f in heapq.merge(*frames, key=lambda f: f.timestamp or 0.0)]
    empties = [
        data.draw(st.lists(st.booleans(), min_size=len(g) // size + 2, max_size=len(g) // size + 2))
        for g in frames
    ]

    def chunks(group: list[Frame], empty: list[bool]) -> Iterator[FrameColumns]:
        for index, start in enumerate(range(0, len(group) + 1, size)):
            if empty[index]:
                yield from_frames([])
            part = group[start : start + size]
            if part:
                yield from_frames(list(enumerate(part)))

    merged = mf4.merge([chunks(g, e) for g, e in zip(frames, empties, strict=True)])
    got = [int(i) for part in merged for i in part.can_id]
    assert got == expected


def test_a_damaged_data_block_is_the_per_frame_paths_error(tmp_path: Path) -> None:
    """A deflated data block in the middle of the file overwritten: the chunks before it
    read, the one holding it fails, and python-can's reader, taking over from there,
    refuses the file as the per-frame path does (reading all of it on opening)."""
    path = _one_bus(tmp_path / "damaged.mf4", 400, compression=1)
    data = bytearray(path.read_bytes())
    blocks = [at for at in range(len(data)) if data[at : at + 4] == b"##DZ"]
    assert len(blocks) == 25  # 16 records a block
    middle = blocks[12]
    data[middle + 60 : middle + 90] = bytes(b ^ 0x55 for b in data[middle + 60 : middle + 90])
    path.write_bytes(bytes(data))
    with pytest.raises(SourceError) as per_frame:
        list(capture.read(path))
    assert str(per_frame.value).startswith(f"{path}: not a readable MF4 file (")
    batches = read_batches(path, batch_frames=16)
    first = next(batches).frames.can_id.tolist()  # the rows no later chunk precedes
    assert first == [0x100 + row for row in range(len(first))] and 0 < len(first) <= 16
    with pytest.raises(SourceError) as columnar:
        list(batches)
    assert str(columnar.value) == str(per_frame.value)
    with pytest.raises(SourceError) as tables:
        capture.read_tables(path)
    assert str(tables.value) == str(per_frame.value)
