"""The commit of a capture's tables into a dataset, under kills and file system errors at
each of its stages: ``veronte4x convert`` run as a subprocess whose commit hook kills the
process (SIGKILL) or raises ``ENOSPC`` when it passes stage N; the dataset read back with
DuckDB, Polars and pyarrow."""

from __future__ import annotations

import shutil
import signal
import subprocess
import sys
from pathlib import Path

import duckdb
import polars as pl
import pyarrow.dataset as ds
import pyarrow.parquet as pq
import pytest

from tests.capture.test_dataset import FLIGHT
from veronte4x import capture

TABLES = {kind: len(table) for kind, table in capture.read_tables(FLIGHT).items()}
STAGES = ["written", "journal", *(f"renamed {kind}" for kind in TABLES), "committed"]
"""The stages a commit of the example flight passes, in order."""

HOOKED = """
import errno, os, signal, sys
from veronte4x.capture.columnar import dataset
from veronte4x.cli import main

stop, action = int(sys.argv[1]), sys.argv[2]
passed = []

def reached(stage):
    passed.append(stage)
    if len(passed) == stop:
        if action == "kill":
            os.kill(os.getpid(), signal.SIGKILL)
        raise OSError(errno.ENOSPC, "No space left on device")

dataset._reached = reached
sys.exit(main(sys.argv[3:]))
"""


def convert(*args: str, stop: int = 0, action: str = "") -> subprocess.CompletedProcess[str]:
    """``veronte4x convert ARGS``, its commit stopped at stage ``stop`` (1 is the first)."""
    command = ["-m", "veronte4x"] if not stop else ["-c", HOOKED, str(stop), action]
    return subprocess.run(
        [sys.executable, *command, "convert", *args],
        capture_output=True,
        text=True,
        check=False,
        timeout=180,
    )


def visible(out: Path, source: Path) -> dict[str, int]:
    """Rows of one capture that DuckDB reads, per table (tables with none left out)."""
    rows = {}
    for folder in sorted(out.glob("message=*")):
        if not list(folder.glob("*.parquet")):
            continue
        (count,) = duckdb.execute(
            "SELECT count(*) FROM read_parquet(?) WHERE source = ?",
            [f"{folder}/*.parquet", str(source)],
        ).fetchone() or (0,)
        if count:
            rows[folder.name.removeprefix("message=")] = count
    return rows


def leftovers(out: Path) -> list[Path]:
    """Files of the dataset that are not in place: temporary files and journals."""
    return [p for p in out.rglob("*") if p.is_file() and p.name.startswith(".")]


@pytest.fixture
def flights(tmp_path: Path) -> tuple[Path, Path, Path]:
    """Two captures (the example flight under two names) and a dataset holding one."""
    flight, other, out = tmp_path / "flight.log", tmp_path / "other.log", tmp_path / "data"
    shutil.copy(FLIGHT, flight)
    shutil.copy(FLIGHT, other)
    assert convert(str(other), "--to", "parquet", str(out)).returncode == 0
    return flight, other, out


def test_the_example_flight_has_several_tables() -> None:
    assert len(TABLES) >= 5  # else the kills below prove little


@pytest.mark.parametrize("stop", range(1, len(STAGES) + 1), ids=STAGES)
def test_a_kill_at_any_stage_leaves_none_or_all_once_the_next_run_is_done(
    flights: tuple[Path, Path, Path], stop: int
) -> None:
    flight, other, out = flights
    killed = convert(str(flight), "--to", "parquet", str(out), stop=stop, action="kill")
    assert killed.returncode == -signal.SIGKILL
    assert visible(out, other) == TABLES
    seen = visible(out, flight)
    if STAGES[stop - 1] == "written":
        assert seen == {}  # nothing renamed yet
    elif STAGES[stop - 1] == "committed":
        assert seen == TABLES
    else:  # during the renames: each table whole or absent until the next run
        assert all(seen[kind] == TABLES[kind] for kind in seen)
    # The next conversion into the directory, of another capture, finishes the commit.
    assert convert(str(other), "--to", "parquet", str(out)).returncode == 0
    assert visible(out, flight) == ({} if STAGES[stop - 1] == "written" else TABLES)
    assert visible(out, other) == TABLES
    assert leftovers(out) == []
    assert convert(str(flight), "--to", "parquet", str(out)).returncode == 0
    assert visible(out, flight) == TABLES
    assert leftovers(out) == []


@pytest.mark.parametrize("stop", range(1, len(STAGES) + 1), ids=STAGES)
def test_a_file_system_error_at_any_stage_is_one_line_and_leaves_no_temporary_file(
    flights: tuple[Path, Path, Path], stop: int
) -> None:
    flight, other, out = flights
    failed = convert(str(flight), "--to", "parquet", str(out), stop=stop, action="error")
    assert failed.returncode == 2
    (line,) = failed.stderr.splitlines()
    assert "No space left on device" in line
    assert "Traceback" not in failed.stderr
    assert leftovers(out) == []
    # Before the journal nothing is put in place; from it on, everything is.
    assert visible(out, flight) == ({} if STAGES[stop - 1] == "written" else TABLES)
    assert visible(out, other) == TABLES


def test_readers_skip_the_temporary_and_journal_names(tmp_path: Path) -> None:
    """What the layout counts on: the names a run writes before its commit is done are
    taken by none of the documented readers, with the docs' own paths and options."""
    out = tmp_path / "data"
    capture.to_parquet(FLIGHT, out, progress=False)
    folder = out / "message=Status"
    (real,) = folder.glob("*.parquet")
    rows = pq.read_metadata(real).num_rows
    temporary = folder / f".{real.name}.4242-0a1b2c3d.tmp"
    shutil.copy(real, temporary)
    (out / f".commit-{real.name}.4242-0a1b2c3d.json").write_text("{}")
    assert ds.dataset(folder, format="parquet").count_rows() == rows
    assert (
        ds.dataset(out, format="parquet", partitioning="hive")
        .to_table(filter=ds.field("message") == "Status", columns=["can_id"])
        .num_rows
        == rows
    )
    glob = f"{folder}/*.parquet"
    assert duckdb.execute(f"SELECT count(*) FROM read_parquet('{glob}')").fetchone() == (rows,)
    assert duckdb.execute(
        f"SELECT count(*) FROM read_parquet('{out}/*/*.parquet', hive_partitioning = true, "
        "union_by_name = true) WHERE message = 'Status'"
    ).fetchone() == (rows,)
    scanned = pl.scan_parquet(glob, hive_partitioning=False)
    assert scanned.select(pl.len()).collect().item() == rows


@pytest.mark.parametrize("prefix", [".", "_"])
def test_which_names_each_reader_skips(tmp_path: Path, prefix: str) -> None:
    """Each reader's rule for a ``.parquet`` file whose name starts with ``.`` or ``_``:
    pyarrow datasets skip it; the ``*.parquet`` globs of DuckDB and Polars take it. So a
    file in the dataset never starts so, and temporary files end in ``.tmp``, not
    ``.parquet``: a leading ``.`` alone would not hide them from DuckDB and Polars."""
    capture.to_parquet(FLIGHT, tmp_path, progress=False)
    folder = tmp_path / "message=Status"
    (real,) = folder.glob("*.parquet")
    rows = pq.read_metadata(real).num_rows
    shutil.copy(real, folder / f"{prefix}copy.parquet")
    assert ds.dataset(folder, format="parquet").count_rows() == rows
    glob = f"{folder}/*.parquet"
    assert duckdb.execute(f"SELECT count(*) FROM read_parquet('{glob}')").fetchone() == (2 * rows,)
    assert pl.scan_parquet(glob).select(pl.len()).collect().item() == 2 * rows


def test_a_real_file_system_error_while_writing_is_one_line(
    flights: tuple[Path, Path, Path],
) -> None:
    """No hook: a table's directory that cannot be made (a file stands in its place)."""
    flight, _, out = flights
    shutil.rmtree(out / "message=Status")
    (out / "message=Status").write_bytes(b"not a directory")
    failed = convert(str(flight), "--to", "parquet", str(out))
    assert failed.returncode == 2
    (line,) = failed.stderr.splitlines()
    assert "message=Status" in line
    assert "Traceback" not in failed.stderr
    assert leftovers(out) == []
    assert visible(out, flight) == {}
