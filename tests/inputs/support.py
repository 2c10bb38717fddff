"""What the bad-input tests share: the CLI run as a subprocess, and captures to damage."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def run(*args: str, stdin: bytes | None = None) -> subprocess.CompletedProcess[str]:
    """The command line in a subprocess, as a person runs it."""
    result = subprocess.run(
        [sys.executable, "-m", "veronte4x", *args],
        input=stdin,
        capture_output=True,
        check=False,
    )
    return subprocess.CompletedProcess(
        result.args,
        result.returncode,
        result.stdout.decode("utf-8", "replace"),
        result.stderr.decode("utf-8", "replace"),
    )


def candump(count: int, start: float = 1_763_737_000.0, step: float = 0.01) -> str:
    """``count`` Ready frames of AP2 as candump text, ``step`` seconds apart."""
    return "".join(f"({start + i * step:.6f}) can0 009#00FF01\n" for i in range(count))
