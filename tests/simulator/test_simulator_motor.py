"""The motor model: lags, current, voltage sag, temperatures and the overheating flag."""

from __future__ import annotations

import math
from dataclasses import fields

from veronte4x import dronecan
from veronte4x.dronecan import vertiq
from veronte4x.dronecan.vertiq import ZeroBehavior
from veronte4x.simulator import DEFAULT_MODEL, MotorModel, SimulatedEsc
from veronte4x.simulator.motor import MODEL_CONSTANT_UNITS, advance, at_rest, command, release

from .support import ESC, decode, f16, feed

M = DEFAULT_MODEL


def test_every_constant_has_a_unit() -> None:
    assert list(MODEL_CONSTANT_UNITS) == [f.name for f in fields(MotorModel)]


def test_rest_state_and_idle_telemetry_values() -> None:
    esc = SimulatedEsc(ESC, 4)
    _, status, temperature = (t.message for t in decode(esc.poll(0.0)))
    assert status == dronecan.EscStatus(0, f16(25.2), 0.0, f16(298.15), 0, 0, 4)
    assert (status.voltage, status.temperature) == (25.203125, 298.25)
    assert temperature == dronecan.Temperature(4, 298.25, 0)


def test_speed_follows_throttle_with_a_first_order_lag() -> None:
    state = command(at_rest(), 0.5, ZeroBehavior.COAST)
    one = advance(state, M.drive_time_constant)
    assert one.rpm == 5000.0 * -math.expm1(-1.0)
    assert one.power_rating_pct == 50
    assert one.current == M.idle_current + M.max_current * (one.rpm / M.max_rpm) ** 3
    assert one.voltage == M.supply_voltage - M.source_resistance * one.current
    two = advance(one, M.drive_time_constant)
    assert math.isclose(two.rpm, 5000.0 * -math.expm1(-2.0), rel_tol=1e-12)
    assert advance(two, 0.0) is two
    assert advance(two, -1.0) is two


def test_zero_behaviors() -> None:
    spinning = advance(command(at_rest(), 1.0, ZeroBehavior.COAST), 5.0)
    assert round(spinning.rpm) == 10000
    coast = advance(command(spinning, 0.0, ZeroBehavior.COAST), 1.0)
    assert math.isclose(coast.rpm, spinning.rpm * math.exp(-1.0 / M.coast_time_constant))
    assert (coast.current, coast.power_rating_pct, coast.voltage) == (0.0, 0, M.supply_voltage)
    braking = command(spinning, 0.0, ZeroBehavior.BRAKE)
    assert braking.braking and not braking.driven
    brake = advance(braking, 0.5)
    assert math.isclose(brake.rpm, spinning.rpm * math.exp(-0.5 / M.brake_time_constant))
    stopped = advance(brake, 1.0)
    assert (stopped.rpm, stopped.braking) == (0.0, False)
    normal = advance(command(spinning, 0.0, ZeroBehavior.NORMAL_CONTROLLER), 10.0)
    assert normal.driven and abs(normal.rpm) < 1e-9
    assert normal.current == M.idle_current
    assert not release(normal).driven


def test_reverse_throttle_gives_negative_rpm() -> None:
    esc = SimulatedEsc(ESC, command_timeout=None)
    feed(esc, vertiq.raw_command([-0.25]), 0.0)
    esc.poll(0.0)
    status = decode(esc.poll(2.0))[1].message
    assert status.rpm == round(-0.25 * 10000 * -math.expm1(-2.0 / M.drive_time_constant))
    assert status.power_rating_pct == 25


def test_temperatures_rise_then_fall_and_flag_overheating() -> None:
    esc = SimulatedEsc(ESC, telem_frequency=1, command_timeout=None)
    feed(esc, vertiq.raw_command([1.0]), 0.0)
    flags = []
    for second in range(0, 121):
        for transfer in decode(esc.poll(float(second))):
            if isinstance(transfer.message, dronecan.Temperature):
                flags.append(transfer.message.error_flags)
    hot = esc.state
    assert hot.overheating and flags[-1] == dronecan.TemperatureErrorFlag.OVERHEATING
    assert flags[0] == 0
    first = flags.index(1)
    assert 30 < first < 80 and set(flags[first:]) == {1}
    steady_coil = M.ambient_temperature + M.coil_heating * hot.current**2
    assert hot.coil_temperature < steady_coil
    assert hot.mcu_temperature < M.ambient_temperature + M.mcu_self_heating + M.mcu_heating * (
        hot.current
    )
    feed(esc, vertiq.raw_command([0.0]), 120.0)
    esc.poll(300.0)
    cool = esc.state
    assert not cool.overheating
    assert M.ambient_temperature < cool.mcu_temperature < hot.mcu_temperature
    assert M.ambient_temperature < cool.coil_temperature < hot.coil_temperature


def test_custom_model_constants() -> None:
    model = MotorModel(max_rpm=2000.0, supply_voltage=12.0)
    esc = SimulatedEsc(ESC, model=model, command_timeout=None)
    feed(esc, vertiq.raw_command([1.0]), 0.0)
    esc.poll(100.0)
    assert round(esc.state.rpm) == 2000
    assert esc.state.voltage == 12.0 - model.source_resistance * esc.state.current


def test_docs_tables_describe_every_constant_and_parameter() -> None:
    from docgen import simulator as docs

    constants = docs.model_constants_table().splitlines()
    assert len(constants) == 2 + len(fields(MotorModel))
    assert (
        constants[2]
        == "| `max_rpm` | 10000.0 | rpm | Speed at full throttle (RawCommand 8191), rpm. |"
    )
    assert docs.parameters_table().splitlines()[2:] == [
        "| 0 | `uavcan_node_id` | 1 | 127 | after a restart (Vertiq document, 3.1) |",
        "| 1 | `bit_rate` | 10000 | 1000000 | at once, stored only: the simulator has no wire |",
        "| 2 | `esc_index` | 0 | 19 | at once: the next RawCommand |",
        "| 3 | `zero_behavior` | 0 | 2 | at once: the next zero setpoint |",
        "| 4 | `telem_frequency` | 0 | 1000 | at once: the schedule restarts |",
    ]
