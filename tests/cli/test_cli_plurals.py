"""The command line's summaries say "1 record", not "1 records", in a subprocess."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

ONE_FRAME = "(0.0) can0 009#00FF01\n"


def run(*args: str) -> subprocess.CompletedProcess[bytes]:
    return subprocess.run(
        [sys.executable, "-m", "veronte4x", *args], capture_output=True, check=False
    )


def test_decode_of_one_frame(tmp_path: Path) -> None:
    capture = tmp_path / "one.log"
    capture.write_text(ONE_FRAME)
    result = run("decode", str(capture))
    assert result.returncode == 0
    assert result.stderr == b"veronte4x: 1 record, 0 undecoded, 0 bad (skip)\n"


def test_convert_of_one_frame(tmp_path: Path) -> None:
    pytest.importorskip("pyarrow.parquet")
    capture = tmp_path / "one.log"
    capture.write_text(ONE_FRAME)
    result = run("convert", str(capture), "--to", "parquet", str(tmp_path / "out"))
    assert result.returncode == 0
    line = result.stderr.decode()
    assert line.startswith("veronte4x: 1 file, 1 frame, 1 record (Ready 1), 0 errors, ")


def test_convert_to_csv_of_one_row(tmp_path: Path) -> None:
    pytest.importorskip("pyarrow")
    capture = tmp_path / "one.log"
    capture.write_text(ONE_FRAME)
    out = tmp_path / "one.csv"
    result = run("convert", str(capture), "--to", "csv", str(out), "--on", "Ready")
    assert result.returncode == 0
    assert result.stderr.decode().startswith("veronte4x: 1 row, ")
