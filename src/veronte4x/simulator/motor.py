"""A deterministic first-order model of a motor, its supply and its temperatures.

Not from Vertiq's DroneCAN support document, which only names the telemetry fields (sections 1.2
and 1.3): the model
is the simulator's own, made to give plausible, smoothly varying telemetry. Every constant
is a field of `MotorModel`; the docs page "Simulated ESC" tabulates them. Each quantity
follows a first-order lag ``x += (target - x) * (1 - exp(-dt / tau))``, the exact solution
for a constant target, so any step length is stable and no randomness is involved.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from veronte4x.dronecan.vertiq import ZeroBehavior


@dataclass(frozen=True, slots=True)
class MotorModel:
    """The constants of the motor model (all SI, temperatures in kelvin).

    Attributes:
        max_rpm: Speed at full throttle (RawCommand 8191), rpm.
        drive_time_constant: Lag of the speed behind the commanded speed while driven, s.
        coast_time_constant: Lag of the speed towards 0 while coasting, s.
        brake_time_constant: Lag of the speed towards 0 while braking, s.
        brake_stop_rpm: Below this speed a braking motor counts as stopped and coasts, rpm.
        supply_voltage: Open-circuit supply voltage (a full 6S battery), V.
        source_resistance: Supply resistance: the voltage sags by this times the current, ohm.
        idle_current: Current of the running controller at zero speed, A.
        max_current: Load current at full speed, added to the idle current, A; the load
            current grows with the cube of the speed (propeller power).
        ambient_temperature: Temperature of the surroundings and of a cold module, K.
        coil_heating: Steady coil temperature rise per ampere squared (copper losses), K/A².
        coil_time_constant: Thermal lag of the coils, s.
        mcu_self_heating: Steady MCU temperature rise of the running electronics, K.
        mcu_heating: Steady MCU temperature rise per ampere, K/A.
        mcu_time_constant: Thermal lag of the microcontroller, s.
        mcu_overheat_temperature: MCU temperature at and above which device.Temperature sets
            its OVERHEATING flag, K.
    """

    max_rpm: float = 10000.0
    drive_time_constant: float = 0.25
    coast_time_constant: float = 3.0
    brake_time_constant: float = 0.1
    brake_stop_rpm: float = 1.0
    supply_voltage: float = 25.2
    source_resistance: float = 0.05
    idle_current: float = 0.3
    max_current: float = 30.0
    ambient_temperature: float = 298.15
    coil_heating: float = 0.08
    coil_time_constant: float = 60.0
    mcu_self_heating: float = 5.0
    mcu_heating: float = 2.0
    mcu_time_constant: float = 30.0
    mcu_overheat_temperature: float = 353.15


DEFAULT_MODEL = MotorModel()
"""The constants the simulator uses unless given others."""

MODEL_CONSTANT_UNITS: dict[str, str] = {
    "max_rpm": "rpm",
    "drive_time_constant": "s",
    "coast_time_constant": "s",
    "brake_time_constant": "s",
    "brake_stop_rpm": "rpm",
    "supply_voltage": "V",
    "source_resistance": "Ω",
    "idle_current": "A",
    "max_current": "A",
    "ambient_temperature": "K",
    "coil_heating": "K/A²",
    "coil_time_constant": "s",
    "mcu_self_heating": "K",
    "mcu_heating": "K/A",
    "mcu_time_constant": "s",
    "mcu_overheat_temperature": "K",
}
"""Unit of each `MotorModel` field, for the docs table."""


@dataclass(frozen=True, slots=True)
class MotorState:
    """The physical state of the motor at one instant.

    Attributes:
        throttle: Commanded throttle fraction in [-1, 1] (RawCommand / 8191 or 8192).
        driven: Whether the controller drives the motor (False while coasting).
        braking: Whether the motor is braking after a zero setpoint (`ZeroBehavior.BRAKE`).
        rpm: Speed, negative in reverse.
        current: Supply current, A.
        voltage: Supply voltage at the module, V.
        coil_temperature: Motor coil temperature, K.
        mcu_temperature: Microcontroller temperature, K.
    """

    throttle: float
    driven: bool
    braking: bool
    rpm: float
    current: float
    voltage: float
    coil_temperature: float
    mcu_temperature: float

    @property
    def power_rating_pct(self) -> int:
        """PWM duty cycle in percent, 0..100 (Vertiq's DroneCAN support, 1.2): |throttle| while
        driven."""
        return round(abs(self.throttle) * 100) if self.driven else 0


def at_rest(model: MotorModel = DEFAULT_MODEL) -> MotorState:
    """A cold, stopped, undriven motor."""
    return MotorState(
        throttle=0.0,
        driven=False,
        braking=False,
        rpm=0.0,
        current=0.0,
        voltage=model.supply_voltage,
        coil_temperature=model.ambient_temperature,
        mcu_temperature=model.ambient_temperature,
    )


def command(state: MotorState, throttle: float, zero_behavior: ZeroBehavior) -> MotorState:
    """Apply a new throttle setpoint (Vertiq's DroneCAN support, 1.4 and 3.4).

    A non-zero setpoint drives the motor. A zero one coasts (`ZeroBehavior.COAST`), brakes
    until stopped and then coasts (`ZeroBehavior.BRAKE`) or keeps driving at 0 %
    (`ZeroBehavior.NORMAL_CONTROLLER`).
    """
    if throttle != 0.0:
        return replace(state, throttle=throttle, driven=True, braking=False)
    if zero_behavior is ZeroBehavior.NORMAL_CONTROLLER:
        return replace(state, throttle=0.0, driven=True, braking=False)
    braking = zero_behavior is ZeroBehavior.BRAKE and state.rpm != 0.0
    return replace(state, throttle=0.0, driven=False, braking=braking)


def release(state: MotorState) -> MotorState:
    """Stop driving: the controller lets go (restart, bootloader, firmware update)."""
    return replace(state, throttle=0.0, driven=False, braking=False)


def _lag(value: float, target: float, dt: float, time_constant: float) -> float:
    return value + (target - value) * -math.expm1(-dt / time_constant)


def advance(state: MotorState, dt: float, model: MotorModel = DEFAULT_MODEL) -> MotorState:
    """The state ``dt`` seconds later under the same command (``dt <= 0`` changes nothing).

    Speed lags towards its target; current and voltage follow the new speed at once; the
    temperatures lag towards the steady values of that new current. Speed settles within
    a second while temperatures take minutes, so long steps stay close to many short ones.
    """
    if dt <= 0:
        return state
    if state.driven:
        rpm = _lag(state.rpm, state.throttle * model.max_rpm, dt, model.drive_time_constant)
    elif state.braking:
        rpm = _lag(state.rpm, 0.0, dt, model.brake_time_constant)
    else:
        rpm = _lag(state.rpm, 0.0, dt, model.coast_time_constant)
    braking = state.braking and abs(rpm) >= model.brake_stop_rpm
    if state.braking and not braking:
        rpm = 0.0
    if state.driven:
        current = model.idle_current + model.max_current * abs(rpm / model.max_rpm) ** 3
    else:
        current = 0.0
    electronics = model.mcu_self_heating if state.driven else 0.0
    coil_target = model.ambient_temperature + model.coil_heating * current**2
    mcu_target = model.ambient_temperature + electronics + model.mcu_heating * current
    return MotorState(
        throttle=state.throttle,
        driven=state.driven,
        braking=braking,
        rpm=rpm,
        current=current,
        voltage=model.supply_voltage - model.source_resistance * current,
        coil_temperature=_lag(state.coil_temperature, coil_target, dt, model.coil_time_constant),
        mcu_temperature=_lag(state.mcu_temperature, mcu_target, dt, model.mcu_time_constant),
    )
