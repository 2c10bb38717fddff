"""examples/esc_demo.py runs against the simulated ESC on the virtual bus and exits 0."""

from __future__ import annotations

import runpy
from pathlib import Path

import pytest

from .support import StepClock

DEMO = Path(__file__).resolve().parents[2] / "examples" / "esc_demo.py"

EXPECTED = """\
node 20: iq_motion.esc, mode OPERATIONAL
telemetry heard in the first 0.5 s: EscStatus x11, Temperature x11
parameter uavcan_node_id = 20 (1..127)
parameter bit_rate = 500000 (10000..1000000)
parameter esc_index = 0 (0..19)
parameter zero_behavior = 0 (0..2)
parameter telem_frequency = 20 (0..1000)
set esc_index by name -> 2
RawCommand 60 % at index 2: rpm 119 -> 5983, esc_index 2
reboot into bootloader: ok=True
frames from node 20 in the next 1.2 s: 0
"""


def test_demo_output_with_a_stepping_clock(capsys: pytest.CaptureFixture[str]) -> None:
    # Every clock reading moves 5 ms on: the run is the same each time, whatever the machine.
    module = runpy.run_path(str(DEMO))
    assert module["main"](clock=StepClock(0.005), channel="test-esc-demo") == 0
    assert capsys.readouterr().out == EXPECTED
