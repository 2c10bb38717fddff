"""One capture, one directory: every spelling of a capture's path (relative, ``./``,
absolute, a symbolic link) converts into one directory of the dataset, its rows counted
once; converting it again under another spelling replaces that directory."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest

from veronte4x import capture
from veronte4x.capture.datasets import capture_directory

FLIGHT = Path(__file__).parents[2] / "examples" / "capture.log"


def convert(cwd: Path, *files: str) -> subprocess.CompletedProcess[str]:
    """``veronte4x convert FILES --to parquet data`` in ``cwd``."""
    command = [sys.executable, "-m", "veronte4x", "convert", *files, "--to", "parquet", "data"]
    return subprocess.run(command, cwd=cwd, capture_output=True, text=True, check=False)


def duckdb_rows(out: Path, table: str) -> list[tuple[Any, ...]]:
    """Rows per capture directory of one table over every capture, read with DuckDB."""
    duckdb = pytest.importorskip("duckdb")
    query = (
        f"SELECT capture, count(*) FROM read_parquet('{out}/capture=*/{table}.parquet', "
        "hive_partitioning = true) GROUP BY capture ORDER BY capture"
    )
    rows: list[tuple[Any, ...]] = duckdb.connect().sql(query).fetchall()
    return rows


def test_three_spellings_and_a_link_are_one_capture(tmp_path: Path) -> None:
    (tmp_path / "flight.log").write_bytes(FLIGHT.read_bytes())
    os.symlink("flight.log", tmp_path / "latest.log")
    spellings = ["flight.log", "./flight.log", str(tmp_path / "flight.log"), "latest.log"]
    result = convert(tmp_path, *spellings)
    assert (result.returncode, result.stderr.count("\n")) == (0, 1), result.stderr
    expected = capture.read_tables(FLIGHT)
    frames = sum(1 for line in FLIGHT.read_text().splitlines() if line.strip())
    assert result.stderr.startswith(f"veronte4x: 1 file, {frames} frames, ")
    out = tmp_path / "data"
    name = capture_directory(str(tmp_path / "flight.log"))
    assert [p.name for p in out.iterdir()] == [name]
    for table in ("Status", "Score"):
        assert duckdb_rows(out, table) == [(name.removeprefix("capture="), len(expected[table]))]


def test_converting_again_by_another_spelling_replaces_the_capture(tmp_path: Path) -> None:
    (tmp_path / "flight.log").write_bytes(FLIGHT.read_bytes())
    os.symlink(tmp_path / "flight.log", tmp_path / "latest.log")
    for spelling in ("flight.log", "./flight.log", str(tmp_path / "flight.log"), "latest.log"):
        result = convert(tmp_path, spelling)
        assert result.returncode == 0, result.stderr
    out = tmp_path / "data"
    assert len(list(out.iterdir())) == 1
    (row,) = duckdb_rows(out, "Status")
    assert row[1] == len(capture.read_tables(FLIGHT)["Status"])


def test_a_directory_name_comes_from_the_resolved_path(tmp_path: Path) -> None:
    (tmp_path / "sub").mkdir()
    target = tmp_path / "sub" / "flight.log"
    target.write_bytes(b"")
    os.symlink(target, tmp_path / "link.log")
    names = {
        capture_directory(str(target)),
        capture_directory(str(tmp_path / "sub" / ".." / "sub" / "flight.log")),
        capture_directory(str(tmp_path / "link.log")),
    }
    (name,) = names
    assert name.startswith("capture=flight.log-")
    assert capture_directory(str(tmp_path / "sub" / "other.log")) != name
