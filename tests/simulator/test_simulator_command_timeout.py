"""The simulated ESC's command timeout: a setpoint not renewed falls to zero (issue 20, 5)."""

from __future__ import annotations

import pytest

from veronte4x.dronecan import vertiq
from veronte4x.dronecan.vertiq import ZeroBehavior
from veronte4x.errors import EncodeError
from veronte4x.simulator import SimulatedEsc
from veronte4x.simulator.esc import COMMAND_TIMEOUT

from .support import ESC, feed


def test_a_setpoint_not_renewed_falls_to_zero_after_the_timeout() -> None:
    esc = SimulatedEsc(ESC)
    assert COMMAND_TIMEOUT == 0.2
    feed(esc, vertiq.raw_command([0.5]), 0.0)
    esc.poll(0.19)
    assert esc.state.throttle == vertiq.raw_to_throttle(4096) and esc.motor.driven
    esc.poll(0.21)  # the last command is 0.21 s old: the ESC took a zero setpoint at 0.2 s
    assert esc.state.throttle == 0.0 and not esc.motor.driven
    rpm = esc.state.rpm
    esc.poll(6.5)  # the case: 6.5 s after the ground tool was killed
    assert 0 < esc.state.rpm < rpm / 5  # coasting down (zero_behavior COAST), not driven


def test_commands_in_time_keep_the_motor_driven() -> None:
    esc = SimulatedEsc(ESC)
    for step in range(100):  # 50 Hz for 2 s, as `esc spin` sends
        feed(esc, vertiq.raw_command([0.5]), step * 0.02)
        esc.poll(step * 0.02 + 0.01)
    assert esc.state.throttle == vertiq.raw_to_throttle(4096) and esc.motor.driven


def test_the_timeout_takes_the_zero_behavior() -> None:
    esc = SimulatedEsc(ESC, zero_behavior=ZeroBehavior.NORMAL_CONTROLLER, command_timeout=0.5)
    feed(esc, vertiq.raw_command([1.0]), 0.0)
    esc.poll(0.4)
    assert esc.state.throttle == 1.0
    esc.poll(0.6)
    assert esc.state.throttle == 0.0 and esc.motor.driven  # held at zero speed, driven


def test_the_timeout_applies_at_its_time_even_when_polled_late() -> None:
    late, early = SimulatedEsc(ESC), SimulatedEsc(ESC)
    for esc in (late, early):
        feed(esc, vertiq.raw_command([0.8]), 0.0)
    early.poll(0.2)
    early.poll(3.0)
    late.poll(3.0)
    assert late.state.rpm == pytest.approx(early.state.rpm)


def test_none_never_times_out_and_bad_values_are_refused() -> None:
    esc = SimulatedEsc(ESC, command_timeout=None)
    feed(esc, vertiq.raw_command([0.5]), 0.0)
    esc.poll(60.0)
    assert esc.state.throttle == vertiq.raw_to_throttle(4096)
    for bad in (0, -1.0, float("nan"), float("inf"), True, "0.2"):
        with pytest.raises(EncodeError, match="command_timeout"):
            SimulatedEsc(ESC, command_timeout=bad)  # type: ignore[arg-type]
