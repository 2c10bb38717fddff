"""MF4 read in chunks: the batches, at any size, are python-can's frames in python-can's
order, and the groups merge as ``heapq.merge`` merges them, timestamps out of order included."""

from __future__ import annotations

import heapq
from collections.abc import Iterator
from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

from tests.capture.columnar_support import assert_same_tables
from veronte4x import capture
from veronte4x.capture.frames import Frame

np = pytest.importorskip("numpy")
can = pytest.importorskip("can")
pytest.importorskip("asammdf")

from veronte4x.capture.columnar import mf4  # noqa: E402
from veronte4x.capture.columnar.batches import read_batches  # noqa: E402
from veronte4x.capture.columnar.frames import FrameColumns, concat, from_frames  # noqa: E402
from veronte4x.capture.readers.pythoncan import read_with_python_can  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]


def _write(path: Path, count: int) -> Path:
    """Data, error and remote frames (three groups) on two channels, some at one time."""
    with can.Logger(str(path)) as logger:
        for i in range(count):
            kind = i % 11
            logger(
                can.Message(
                    timestamp=1_763_737_000 + (i // 3) * 0.001,  # runs of equal times
                    arbitration_id=(0x1000 + i * 7) & 0x1FFFFFFF if kind % 2 else i & 0x7FF,
                    is_extended_id=bool(kind % 2),
                    data=bytes((i + k) & 0xFF for k in range(i % 9)),
                    is_error_frame=kind == 5,
                    is_remote_frame=kind == 8,
                    channel=i % 2,
                )
            )
    return path


def _fields(frames: object) -> list[list[object]]:
    columns = vars(frames)
    names = ("order", "timestamp", "can_id", "extended", "remote", "error", "length", "data")
    got = [columns[name].tolist() for name in names]
    got.append([frames.channels[c] for c in columns["channel"].tolist()])  # type: ignore[attr-defined]
    return got


@pytest.fixture(scope="module")
def mixed(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return _write(tmp_path_factory.mktemp("mf4") / "mixed.mf4", 400)


@pytest.mark.parametrize("size", [1, 2, 3, 7, 64, 399, 400, 10_000])
def test_batches_of_any_size_are_python_cans_frames(mixed: Path, size: int) -> None:
    expected = from_frames(list(enumerate(read_with_python_can(mixed), 1)))
    assert expected.error.any() and expected.remote.any()
    batches = [b.frames for b in read_batches(mixed, batch_frames=size)]
    assert _fields(concat(batches)) == _fields(expected)
    if size < 100:
        assert max(len(b) for b in batches) <= 3 * size * 2  # bounded by the chunks


def test_read_tables_equals_the_per_frame_path(mixed: Path, tmp_path: Path) -> None:
    flight = tmp_path / "flight.mf4"
    with can.Logger(str(flight)) as logger:
        for message in can.CanutilsLogReader(str(ROOT / "examples" / "capture.log")):
            logger.on_message_received(message)
    for path in (mixed, flight):
        expected = capture.tables_from_records(capture.read(path))
        assert_same_tables(capture.read_tables(path), expected)


_STAMPS = st.lists(st.integers(0, 6).map(float), max_size=12)


@given(st.lists(_STAMPS, min_size=1, max_size=3), st.integers(1, 5))
def test_groups_merge_as_heapq_merges_them(groups: list[list[float]], size: int) -> None:
    """Timestamps out of order within a group (python-can's writer never makes them, other
    loggers may) still come out in ``heapq.merge``'s order, at any chunk size."""
    frames = [
        [Frame(stamp, "g", group * 100 + row, b"") for row, stamp in enumerate(stamps)]
        for group, stamps in enumerate(groups)
    ]
    expected = [f.can_id for f in heapq.merge(*frames, key=lambda f: f.timestamp or 0.0)]

    def chunks(group: list[Frame]) -> Iterator[FrameColumns]:
        for start in range(0, len(group), size):
            yield from_frames(list(enumerate(group[start : start + size])))

    got = [int(i) for part in mf4.merge([chunks(g) for g in frames]) for i in part.can_id]
    assert got == expected
