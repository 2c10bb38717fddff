"""`make check` runs every step, whichever failed before it, and its last line names the
steps that failed (issue 39, item 1: it stopped at the first red step, so the strict docs
build never ran). The Makefile's own ``check`` recipe runs over stand-in steps: a file
given in ``MAKEFILES`` (which every make of the recipe reads) defines them, and ``VENV``
points at a directory whose install stamp is already there."""

from __future__ import annotations

import os
import shutil
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent

STEPS = """
red:
\t@echo ran red; false
green:
\t@echo ran green
blue:
\t@echo ran blue
"""


@pytest.mark.skipif(shutil.which("make") is None, reason="no make")
@pytest.mark.parametrize(
    ("steps", "ran", "last", "code"),
    [
        ("red green blue", ["ran red", "ran green", "ran blue"], "make check: failed: red", 2),
        ("green red blue red", ["ran green", "ran red", "ran blue", "ran red"],
         "make check: failed: red red", 2),
        ("green blue", ["ran green", "ran blue"], "make check: green blue passed", 0),
    ],
)  # fmt: skip
def test_every_step_runs_and_the_last_line_names_the_failed(
    steps: str, ran: list[str], last: str, code: int, tmp_path: Path
) -> None:
    venv = tmp_path / "venv"
    (venv / "bin").mkdir(parents=True)
    (venv / "bin" / "python").touch()
    (venv / ".installed-dev").touch()  # newer than pyproject.toml: nothing to install
    extra = tmp_path / "steps.mk"
    extra.write_text(STEPS)
    result = subprocess.run(
        ["make", "--no-print-directory", "check", f"VENV={venv}", f"CHECK_STEPS={steps}"],
        cwd=ROOT,
        env={**os.environ, "MAKEFILES": str(extra)},
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )
    lines = result.stdout.splitlines()
    assert [line for line in lines if line.startswith("ran ")] == ran
    assert lines[-1] == last
    assert result.returncode == code, result.stderr
