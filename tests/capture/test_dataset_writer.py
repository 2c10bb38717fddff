"""A dataset's writer in this process: row groups and buffered bytes at their bounds, the
commit on a system without renameat2's flags and under runs that keep replacing the
capture, what it refuses; every dataset read back with DuckDB and pyarrow.

Branches of `veronte4x.capture.columnar.dataset` no test reaches:

- ``dataset.py:356`` (``_flush`` of a table with nothing buffered): every caller names a
  table with rows buffered (``write`` the one it just buffered or the one holding the most
  bytes, ``commit`` those in ``_buffers``), and the buffers are dropped together.
- ``dataset.py:450-454`` (``_discard`` when closing a writer fails): only a disk that fills
  (or fails) while a run is aborted makes ``ParquetWriter.close`` raise; and a writer given
  a path, as every one here is, always has a file handle (``dataset.py:452``, its None side).
"""

from __future__ import annotations

import ctypes
import errno
import os
import shutil
from pathlib import Path
from typing import Any

import duckdb
import pyarrow.parquet as pq
import pytest

from tests.capture.columnar_support import assert_same_tables
from tests.capture.test_dataset import FLIGHT, read_back
from veronte4x import capture
from veronte4x.capture import datasets
from veronte4x.capture.columnar import dataset
from veronte4x.capture.datasets import capture_directory, dataset_files
from veronte4x.errors import SourceError

EXPECTED = capture.read_tables(FLIGHT)


def _duckdb_rows(out: Path) -> dict[str, int]:
    """Rows per table as DuckDB reads the docs' glob, with a connection of its own."""
    counts = {}
    with duckdb.connect() as connection:
        for kind in capture.dataset_tables(out):
            (count,) = connection.execute(
                "SELECT count(*) FROM read_parquet(?, hive_partitioning = true)",
                [f"{out}/capture=*/{kind}.parquet"],
            ).fetchone() or (0,)
            counts[kind] = count
    return counts


def _leftovers(out: Path) -> list[str]:
    return [p.name for p in out.iterdir() if not p.name.startswith(datasets.CAPTURE)]


def test_tables_past_a_row_group_are_written_in_row_groups(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Rows gathered past ``ROW_GROUP`` are written as one row group, the next ones into
    the same file: read back, the rows of ``read_tables`` in their order."""
    monkeypatch.setattr(dataset, "ROW_GROUP", 4)
    out = tmp_path / "data"
    summary = dataset.convert_file(FLIGHT, out, batch_bytes=200)
    assert summary.records == {kind: len(table) for kind, table in EXPECTED.items()}
    assert_same_tables(read_back(out), EXPECTED)
    assert _duckdb_rows(out) == summary.records
    for kind, rows in summary.records.items():
        [path] = dataset_files(out, kind)
        groups = [g.num_rows for g in _row_groups(path)]
        assert sum(groups) == rows
        assert all(size >= 4 for size in groups[:-1]), (kind, groups)  # the last: the rest
        if rows > 8:
            assert len(groups) > 1, kind


def _row_groups(path: str) -> list[Any]:
    metadata = pq.ParquetFile(path).metadata
    return [metadata.row_group(i) for i in range(metadata.num_row_groups)]


def test_tables_past_the_buffered_bytes_are_written_largest_first(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Past ``BUFFERED`` bytes held back over all tables, the table holding the most is
    written: every batch then, and the dataset is the same."""
    monkeypatch.setattr(dataset, "BUFFERED", 0)
    out = tmp_path / "data"
    summary = dataset.convert_file(FLIGHT, out, batch_bytes=200)
    assert_same_tables(read_back(out), EXPECTED)
    assert _duckdb_rows(out) == summary.records
    groups = {kind: len(_row_groups(dataset_files(out, kind)[0])) for kind in summary.records}
    assert max(groups.values()) > 1, groups  # far fewer rows than ROW_GROUP, yet written


def _unsupported(code: int) -> Any:
    """renameat2 of a file system without its flags: fails with ``code``, renames nothing."""

    def call(*_: object) -> int:
        ctypes.set_errno(code)
        return -1

    return call


@pytest.mark.parametrize("code", [errno.EINVAL, errno.ENOSYS, errno.EOPNOTSUPP])
def test_without_renameat2_flags_a_capture_is_put_in_place_and_replaced(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, code: int
) -> None:
    """A file system whose renameat2 refuses its flags (EINVAL, ENOSYS, EOPNOTSUPP) takes
    the portable rename: a first run puts the capture in place, a second replaces it."""
    monkeypatch.setattr(dataset, "_renameat2_call", _unsupported(code))
    out = tmp_path / "data"
    head = tmp_path / "flight.log"
    head.write_text("".join(FLIGHT.read_text().splitlines(keepends=True)[:12]))
    first = capture.to_parquet(head, out, progress=False)
    assert _duckdb_rows(out) == first.records
    shutil.copy(FLIGHT, head)
    second = capture.to_parquet(head, out, progress=False)
    assert second.records != first.records
    assert_same_tables(read_back(out), EXPECTED)
    assert _duckdb_rows(out) == second.records
    assert [p.name for p in out.iterdir()] == [capture_directory(str(head))]


def test_runs_that_keep_replacing_the_capture_end_in_one_error(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Without an exchanging rename a run moves the capture's directory aside, then puts
    its own in place; when another run's directory is there again every time, it gives up
    after ``TRIES`` with EBUSY, leaving the other run's tables and nothing of its own."""
    monkeypatch.setattr(dataset, "_renameat2_call", None)
    out = tmp_path / "data"
    capture.to_parquet(FLIGHT, out, progress=False)
    final = out / capture_directory(str(FLIGHT))
    theirs = tmp_path / "theirs"
    shutil.copytree(final, theirs)
    asides = []

    def another_run_puts_its_own(stage: str) -> None:
        if stage == "aside":
            asides.append(stage)
            shutil.copytree(theirs, final)

    monkeypatch.setattr(dataset, "_reached", another_run_puts_its_own)
    with pytest.raises(OSError, match="other conversions of this capture keep replacing it") as e:
        capture.to_parquet(FLIGHT, out, progress=False)
    assert e.value.errno == errno.EBUSY
    assert str(e.value) == (
        f"[Errno {errno.EBUSY}] other conversions of this capture keep replacing it; convert "
        f"it again when they end: '{final}'"
    )
    assert len(asides) == dataset.TRIES
    assert _leftovers(out) == []
    assert_same_tables(read_back(out), EXPECTED)


def test_a_file_where_the_capture_goes_is_an_error_without_renameat2(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The portable rename cannot put a directory over a file: the error names it, the
    file stays, and the run leaves nothing."""
    monkeypatch.setattr(dataset, "_renameat2_call", None)
    out = tmp_path / "data"
    out.mkdir()
    final = out / capture_directory(str(FLIGHT))
    final.write_bytes(b"not a capture")
    with pytest.raises(NotADirectoryError) as raised:
        capture.to_parquet(FLIGHT, out, progress=False)
    assert (raised.value.errno, raised.value.filename2) == (errno.ENOTDIR, str(final))
    assert final.read_bytes() == b"not a capture"
    assert _leftovers(out) == []


def test_standard_input_is_refused_by_convert_file(tmp_path: Path) -> None:
    with pytest.raises(SourceError) as refused:
        dataset.convert_file("-", tmp_path / "data")
    assert str(refused.value) == "a dataset is written from files: give a capture file, not -"
    assert not (tmp_path / "data").exists()


def test_a_dataset_of_the_older_layout_is_refused_before_any_file_is_read(
    tmp_path: Path,
) -> None:
    out = tmp_path / "data"
    (out / "message=Status").mkdir(parents=True)
    with pytest.raises(FileExistsError) as refused:
        capture.to_parquet(FLIGHT, out, progress=False)
    assert (refused.value.errno, refused.value.filename) == (errno.EEXIST, str(out))
    assert refused.value.strerror == (
        "holds a dataset of the older layout (message=TABLE directories); convert into a new "
        "directory, or convert its captures again there"
    )
    assert [p.name for p in out.iterdir()] == ["message=Status"]


def test_a_table_no_capture_has_is_an_error_listing_those_there_are(tmp_path: Path) -> None:
    out = tmp_path / "data"
    with pytest.raises(FileNotFoundError) as empty:
        capture.open_dataset(tmp_path, "Status")
    assert empty.value.strerror == "no capture has a table Status (the tables: none)"
    capture.to_parquet(FLIGHT, out, progress=False)
    with pytest.raises(FileNotFoundError) as missing:
        capture.open_dataset(out, "NoSuchTable")
    assert (missing.value.errno, missing.value.filename) == (errno.ENOENT, str(out))
    tables = ", ".join(sorted(EXPECTED))
    assert missing.value.strerror == f"no capture has a table NoSuchTable (the tables: {tables})"


def test_a_capture_with_a_long_name_is_converted(tmp_path: Path) -> None:
    """A base name of 240 characters (file systems take 255): the directory's name keeps
    200 of them (the run's hidden directory, longer by its suffix, failed with ENAMETOOLONG
    before)."""
    path = tmp_path / ("f" * 236 + ".log")
    shutil.copy(FLIGHT, path)
    out = tmp_path / "data"
    summary = capture.to_parquet(path, out, progress=False)
    [directory] = out.iterdir()
    assert directory.name == capture_directory(str(path))
    assert directory.name.startswith(datasets.CAPTURE + "f" * 200 + "-")
    assert len(directory.name) == len(datasets.CAPTURE) + 200 + 13
    assert_same_tables(read_back(out), EXPECTED)
    assert _duckdb_rows(out) == summary.records
    assert len(os.fsencode(directory.name)) <= 255
