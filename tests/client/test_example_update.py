"""examples/esc_update.py updates a simulated ESC and exits 0, with an exact output."""

from __future__ import annotations

import runpy
from pathlib import Path

import pytest

from ..simulator.support import StepClock

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "esc_update.py"

EXPECTED = """\
nodes: [21]
  waiting: 0 of 3000 bytes
  reading: 1024 of 3000 bytes
  reading: 2048 of 3000 bytes
  restarting: 3000 of 3000 bytes
  done: 3000 of 3000 bytes
image CRC before: 0x0000000000000000, after: 0x4b98d46f9508cd65
the image's CRC-64-WE: 0x4b98d46f9508cd65
"""


def test_example_output_with_a_stepping_clock(capsys: pytest.CaptureFixture[str]) -> None:
    module = runpy.run_path(str(EXAMPLE))
    assert module["main"](clock=StepClock(0.001), channel="test-esc-update") == 0
    assert capsys.readouterr().out == EXPECTED
