"""The commit of a capture's directory into a dataset, under kills and file system errors
at each of its stages, and under readers reading while conversions commit:
``veronte4x convert`` run as a subprocess whose commit hook kills the process (SIGKILL) or
raises ``ENOSPC`` when it passes stage N, on Linux's exchanging rename and on the portable
fallback; the dataset read back with DuckDB and pyarrow, as the docs read it."""

from __future__ import annotations

import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import warnings
from pathlib import Path

import dask.dataframe as dd
import duckdb
import pandas as pd
import polars as pl
import pyarrow.dataset as ds
import pyarrow.parquet as pq
import pytest

from tests.capture.test_dataset import FLIGHT
from veronte4x import capture
from veronte4x.capture.columnar import dataset
from veronte4x.capture.datasets import capture_directory

LINES = FLIGHT.read_text().splitlines(keepends=True)
TABLES = {kind: len(table) for kind, table in capture.read_tables(FLIGHT).items()}
"""Rows per table of the example flight: what a conversion of it puts in place."""


def _head_tables() -> dict[str, int]:
    with tempfile.TemporaryDirectory() as folder:
        head = Path(folder) / "head.log"
        head.write_text("".join(LINES[:12]))
        return {kind: len(table) for kind, table in capture.read_tables(head).items()}


OLD = _head_tables()
"""Rows per table of the flight's first lines: what an earlier conversion put in place."""

HOOKED = """
import errno, os, signal, sys
from veronte4x.capture.columnar import dataset
from veronte4x.cli import main

stop, action, rename = int(sys.argv[1]), sys.argv[2], sys.argv[3]
passed = []

def reached(stage):
    passed.append(stage)
    if len(passed) == stop:
        if action == "kill":
            os.kill(os.getpid(), signal.SIGKILL)
        raise OSError(errno.ENOSPC, "No space left on device")

dataset._reached = reached
if rename == "fallback":
    dataset._renameat2_call = None
sys.exit(main(sys.argv[4:]))
"""
RENAMES = ["exchange", "fallback"]
"""Linux's renameat2 (one step), and what other systems get (move aside, then in)."""


def stages(rename: str, replace: bool) -> list[str]:
    """The stages a commit passes, in order."""
    aside = ["aside"] if rename == "fallback" and replace else []
    return ["written", *aside, "published", "committed"]


CASES = [
    (rename, replace, stage)
    for rename in RENAMES
    for replace in (False, True)
    for stage in stages(rename, replace)
]
IDS = [f"{r}-{'replace' if p else 'new'}-{s}" for r, p, s in CASES]


def convert(
    *args: str, stop: int = 0, action: str = "", rename: str = "exchange"
) -> subprocess.CompletedProcess[str]:
    """``veronte4x convert ARGS``, its commit stopped at stage ``stop`` (1 is the first)."""
    hooked = stop or rename != "exchange"
    command = ["-c", HOOKED, str(stop), action, rename] if hooked else ["-m", "veronte4x"]
    return subprocess.run(
        [sys.executable, *command, "convert", *args],
        capture_output=True,
        text=True,
        check=False,
        timeout=600,
    )


def visible(out: Path, source: Path) -> dict[str, int]:
    """Rows of one capture per table (tables with none left out), as DuckDB reads them
    with the docs' glob, and as pyarrow reads them with `capture.open_dataset`: both the
    same."""
    duck = {}
    for kind in sorted({*TABLES, *OLD}):
        try:
            (count,) = duckdb.connect().execute(
                "SELECT count(*) FROM read_parquet(?, hive_partitioning = true) WHERE source = ?",
                [f"{out}/capture=*/{kind}.parquet", str(source)],
            ).fetchone() or (0,)
        except duckdb.IOException:  # no file matches the glob
            count = 0
        if count:
            duck[kind] = count
    arrow = {}
    for kind in capture.dataset_tables(out):
        count = capture.open_dataset(out, kind).count_rows(filter=ds.field("source") == str(source))
        if count:
            arrow[kind] = count
    assert duck == arrow
    return duck


def leftovers(out: Path) -> list[Path]:
    """What is in the dataset and not a capture's published directory or its files."""
    return [p for p in out.rglob("*") if p.name.startswith((".", "_"))]


@pytest.fixture(scope="module")
def datasets(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, Path, Path, Path]:
    """Made once a module (each test copies what it starts from): two captures (the example
    flight under two names, never written after), a dataset holding ``other``, and one
    holding ``other`` and the flight's first lines under the flight's name (the version a
    run replaces), each made by ``veronte4x convert`` as the tests' own runs are."""
    base = tmp_path_factory.mktemp("commit")
    flight, other, new, replace = (
        base / "flight.log", base / "other.log", base / "new", base / "replace"
    )  # fmt: skip
    shutil.copy(FLIGHT, other)
    assert convert(str(other), "--to", "parquet", str(new)).returncode == 0
    shutil.copytree(new, replace)
    flight.write_text("".join(LINES[:12]))
    assert convert(str(flight), "--to", "parquet", str(replace)).returncode == 0
    shutil.copy(FLIGHT, flight)
    return flight, other, new, replace


def _start(
    datasets: tuple[Path, Path, Path, Path], tmp_path: Path, replace: bool = False
) -> tuple[Path, Path, Path]:
    """The flight, the other capture and this test's own copy of a dataset holding the
    other capture, and the flight's earlier version when ``replace``."""
    flight, other, new, earlier = datasets
    out = tmp_path / "data"
    shutil.copytree(earlier if replace else new, out)
    return flight, other, out


def test_the_versions_differ_in_tables_and_rows() -> None:
    """Else the kills below prove little."""
    assert len(TABLES) >= 5
    assert set(OLD) < set(TABLES)
    assert {kind: TABLES[kind] for kind in OLD} != OLD


@pytest.mark.parametrize(("rename", "replace", "stage"), CASES, ids=IDS)
def test_a_kill_at_any_stage_leaves_readers_all_or_none(
    datasets: tuple[Path, Path, Path, Path], tmp_path: Path, rename: str, replace: bool, stage: str
) -> None:
    flight, other, out = _start(datasets, tmp_path, replace)
    if replace:
        assert visible(out, flight) == OLD
    before = OLD if replace else {}
    stop = stages(rename, replace).index(stage) + 1
    killed = convert(
        str(flight), "--to", "parquet", str(out), stop=stop, action="kill", rename=rename
    )
    assert killed.returncode == -signal.SIGKILL
    # Before any repair: the old version, none (moved aside), or the new one, never a mix.
    now = {"written": before, "aside": {}}.get(stage, TABLES)
    assert visible(out, flight) == now
    assert visible(out, other) == TABLES
    # The next conversion into the directory, of another capture, puts back what the
    # killed run moved aside and removes its hidden directory.
    assert convert(str(other), "--to", "parquet", str(out), rename=rename).returncode == 0
    assert visible(out, flight) == (before if stage in ("written", "aside") else TABLES)
    assert visible(out, other) == TABLES
    assert leftovers(out) == []
    assert convert(str(flight), "--to", "parquet", str(out), rename=rename).returncode == 0
    assert visible(out, flight) == TABLES
    assert leftovers(out) == []


@pytest.mark.parametrize(("rename", "replace", "stage"), CASES, ids=IDS)
def test_a_file_system_error_at_any_stage_is_one_line_and_leaves_no_temporary_file(
    datasets: tuple[Path, Path, Path, Path], tmp_path: Path, rename: str, replace: bool, stage: str
) -> None:
    flight, other, out = _start(datasets, tmp_path, replace)
    stop = stages(rename, replace).index(stage) + 1
    failed = convert(
        str(flight), "--to", "parquet", str(out), stop=stop, action="error", rename=rename
    )
    assert failed.returncode == 2
    (line,) = failed.stderr.splitlines()
    assert line.startswith("veronte4x: ")
    assert "No space left on device" in line
    assert "Traceback" not in failed.stderr
    assert leftovers(out) == []
    # Before it is in place the capture is left as it was; from then on, it is the new one.
    before = OLD if replace else {}
    assert visible(out, flight) == (before if stage in ("written", "aside") else TABLES)
    assert visible(out, other) == TABLES


def test_readers_skip_a_run_in_progress(tmp_path: Path) -> None:
    """What the layout counts on: the hidden directory of a run, whole files in it, is
    taken by none of the documented readers, with the docs' own paths and options (and
    neither by a bare ``*`` in place of ``capture=*``, nor by pyarrow's discovery)."""
    out = tmp_path / "data"
    capture.to_parquet(FLIGHT, out, progress=False)
    (published,) = out.iterdir()
    running = out / f".{capture_directory('other.log')}.{dataset.HOST}-{os.getpid()}-0a1b2c3d"
    shutil.copytree(published, running / "new")
    rows = TABLES["Status"]
    for glob in ("capture=*/Status.parquet", "*/Status.parquet"):
        pattern = f"{out}/{glob}"
        query = f"SELECT count(*) FROM read_parquet('{pattern}', hive_partitioning = true)"
        assert duckdb.connect().execute(query).fetchone() == (rows,)
        scan = pl.scan_parquet(pattern, hive_partitioning=True)
        assert scan.select(pl.len()).collect().item() == rows
        with warnings.catch_warnings():  # dask's own use of pandas, deprecated in pandas 3.1
            warnings.simplefilter("ignore")
            assert len(dd.read_parquet(pattern).compute(scheduler="sync")) == rows
    assert capture.open_dataset(out, "Status").count_rows() == rows
    files = capture.dataset_files(out, "Status")
    assert pq.read_table(files).num_rows == rows
    assert len(pd.read_parquet(files)) == rows
    assert ds.dataset(out, format="parquet").files == sorted(map(str, published.iterdir()))


@pytest.mark.parametrize("prefix", [".", "_"])
def test_which_names_each_reader_skips(tmp_path: Path, prefix: str) -> None:
    """Each reader's rule for a ``.parquet`` file whose name starts with ``.`` or ``_``:
    pyarrow's discovery skips it; the ``*.parquet`` globs of DuckDB and Polars take it. So
    no name in the dataset starts so (a table named so is written ``table-_Name.parquet``)."""
    capture.to_parquet(FLIGHT, tmp_path, progress=False)
    (folder,) = tmp_path.iterdir()
    real = folder / "Status.parquet"
    rows = pq.read_metadata(real).num_rows
    shutil.copy(real, folder / f"{prefix}Status.parquet")
    total = sum(TABLES.values())
    assert sum(pq.read_metadata(f).num_rows for f in ds.dataset(folder).files) == total
    glob = f"{folder}/*Status.parquet"
    assert duckdb.connect().execute(f"SELECT count(*) FROM read_parquet('{glob}')").fetchone() == (
        2 * rows,
    )
    assert pl.scan_parquet(glob).select(pl.len()).collect().item() == 2 * rows


def test_a_real_file_system_error_is_one_line(
    datasets: tuple[Path, Path, Path, Path], tmp_path: Path
) -> None:
    """No hook: the dataset's directory is a file."""
    flight, _, out = _start(datasets, tmp_path)
    shutil.rmtree(out)
    out.write_bytes(b"not a directory")
    failed = convert(str(flight), "--to", "parquet", str(out))
    assert (failed.returncode, failed.stderr) == (2, f"veronte4x: {out}: File exists\n")
    assert out.read_bytes() == b"not a directory"


def test_a_dataset_of_the_older_layout_is_refused(tmp_path: Path) -> None:
    """Two layouts in one directory: readers of either would see part of the dataset."""
    out = tmp_path / "data"
    (out / "message=Status").mkdir(parents=True)
    failed = convert(str(FLIGHT), "--to", "parquet", str(out))
    assert failed.returncode == 2
    assert failed.stderr == (
        f"veronte4x: {out}: holds a dataset of the older layout (message=TABLE directories); "
        "convert into a new directory, or convert its captures again there\n"
    )
    assert [p.name for p in out.iterdir()] == ["message=Status"]


@pytest.mark.parametrize("rename", RENAMES)
def test_two_commands_on_one_capture_at_once_both_succeed(tmp_path: Path, rename: str) -> None:
    out = tmp_path / "data"
    hooked = ["-c", HOOKED, "0", "", rename] if rename != "exchange" else ["-m", "veronte4x"]
    command = [sys.executable, *hooked, "convert", str(FLIGHT), "--to", "parquet", str(out)]
    runs = [subprocess.Popen(command, stderr=subprocess.PIPE, text=True) for _ in range(3)]
    errors = [run.communicate(timeout=600)[1] for run in runs]
    assert [run.returncode for run in runs] == [0, 0, 0], errors
    assert all(e.startswith("veronte4x: 1 file, 39 frames") for e in errors)
    assert visible(out, FLIGHT) == TABLES
    assert leftovers(out) == []


def _snapshot_duckdb(out: Path) -> dict[str, dict[str, int]]:
    """Rows per table of each capture, from one DuckDB listing of every table's files."""
    found: dict[str, dict[str, int]] = {}
    try:
        listed = (
            duckdb.connect()
            .execute(
                "SELECT file_name, num_rows FROM parquet_file_metadata(?)",
                [f"{out}/capture=*/*.parquet"],
            )
            .fetchall()
        )
    except duckdb.IOException:  # nothing published yet
        return found
    for name, rows in listed:
        path = Path(name)
        found.setdefault(path.parent.name, {})[path.stem] = rows
    return found


def _snapshot_arrow(out: Path) -> dict[str, dict[str, int]]:
    """The same from one listing by pyarrow's dataset discovery."""
    found: dict[str, dict[str, int]] = {}
    if not out.exists():
        return found
    for name in ds.dataset(out, format="parquet").files:
        path = Path(name)
        found.setdefault(path.parent.name, {})[path.stem] = pq.read_metadata(name).num_rows
    return found


def test_readers_in_a_loop_see_whole_captures_while_conversions_commit(tmp_path: Path) -> None:
    """Four captures converted anew and four replaced (their first lines converted before),
    by two commands at once, while this test reads the dataset in a loop, with DuckDB and
    pyarrow, each read listing every table's files at once. A new capture is seen with all
    its tables and rows or not at all. A replaced one is seen with the tables of one
    version, each whole; a read that lists the files of a capture and opens them after it
    was replaced may take some tables from the new version (the documented limit: a path
    is looked up again when the file is opened)."""
    out = tmp_path / "data"
    replaced = [tmp_path / f"flight{n}.log" for n in range(4)]
    for name in replaced:
        name.write_text("".join(LINES[:12]))
    assert convert(*map(str, replaced), "--to", "parquet", str(out)).returncode == 0
    for name in replaced:
        shutil.copy(FLIGHT, name)
    new = [tmp_path / f"new{n}.log" for n in range(4)]
    for name in new:
        shutil.copy(FLIGHT, name)
    command = [sys.executable, "-m", "veronte4x", "convert", *map(str, [*replaced, *new])]
    runs = [subprocess.Popen([*command, "--to", "parquet", str(out)]) for _ in range(2)]
    fresh = {capture_directory(str(p)) for p in new}
    reads = 0
    while any(run.poll() is None for run in runs) or reads < 20:
        for snapshot in (_snapshot_duckdb(out), _snapshot_arrow(out)):
            for directory, tables in snapshot.items():
                if directory in fresh:
                    assert tables == TABLES, directory
                else:
                    assert set(tables) in (set(OLD), set(TABLES)), directory
                    assert all(rows in (OLD.get(k), TABLES[k]) for k, rows in tables.items())
        reads += 1
        time.sleep(0)
    assert [run.wait() for run in runs] == [0, 0]
    final = _snapshot_duckdb(out)
    assert sorted(final) == sorted(capture_directory(str(p)) for p in [*replaced, *new])
    assert all(tables == TABLES for tables in final.values())
    assert leftovers(out) == []
