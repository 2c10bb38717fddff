"""``veronte4x convert`` end to end, in a subprocess: the dataset, the summary line, the
exit codes of ``decode``."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from tests.capture.columnar_support import assert_same_tables
from tests.capture.test_dataset import FLIGHT, read_back
from veronte4x import capture
from veronte4x.words import counted


def convert(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "veronte4x", "convert", *args],
        capture_output=True,
        text=True,
        check=False,
    )


def test_convert_writes_the_dataset_and_one_summary_line(tmp_path: Path) -> None:
    out = tmp_path / "data"
    result = convert(str(FLIGHT), "--to", "parquet", str(out))
    assert result.returncode == 0
    assert result.stdout == ""
    (line,) = result.stderr.splitlines()  # no progress bar: standard error is not a terminal
    expected = capture.read_tables(FLIGHT)
    rows = sum(len(t) for kind, t in expected.items() if kind != "errors")
    assert line.startswith(f"veronte4x: 1 file, 39 frames, {rows} records (")
    assert f", {counted(len(expected['errors']), 'error')}, " in line
    assert line.endswith(f" s, dataset in {out}")
    assert_same_tables(read_back(out), expected)


def test_convert_keeps_one_channel(tmp_path: Path) -> None:
    result = convert(str(FLIGHT), "--to", "parquet", str(tmp_path), "--only-channel", "can1")
    assert result.returncode == 0
    assert_same_tables(read_back(tmp_path), capture.read_tables(FLIGHT, channel="can1"))


def test_usage_errors_exit_2_with_one_line(tmp_path: Path) -> None:
    result = convert(str(FLIGHT), "--to", "xlsx", str(tmp_path))
    assert (result.returncode, result.stderr) == (
        2,
        "veronte4x: cannot convert to 'xlsx': the formats are parquet, csv, pydronecan\n",
    )
    missing = tmp_path / "missing.log"
    result = convert(str(FLIGHT), str(missing), "--to", "parquet", str(tmp_path / "out"))
    assert (result.returncode, result.stderr) == (
        2,
        f"veronte4x: {missing}: No such file or directory\n",
    )
    assert not (tmp_path / "out").exists()
    result = convert("-", "--to", "parquet", str(tmp_path / "out"))
    assert result.returncode == 2
    assert result.stderr == (
        "veronte4x: a dataset is written from files: give a capture file, not -\n"
    )
    result = convert(str(FLIGHT), "--to", "parquet")
    assert result.returncode == 2
    assert "--to: expected 2 arguments" in result.stderr
