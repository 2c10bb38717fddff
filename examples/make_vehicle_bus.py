"""Write the candump log of an ArduPilot-style DroneCAN vehicle bus.

Usage: python examples/make_vehicle_bus.py [OUTPUT] [--seconds 30]

What is on the bus, each type at its usual rate, encoded by `veronte4x.dronecan.encode`:
- An autopilot (node 10) commanding 8 ESCs (esc.RawCommand at 400 Hz) and two servos
  (actuator.ArrayCommand at 100 Hz); its safety.ArmingStatus and indication.LightsCommand
  at 10 Hz.
- Eight ESCs (nodes 60-67): esc.Status at 50 Hz each; their loads differ a little, and
  one (node 65) warms up through the flight.
- Two servos (nodes 80, 81): actuator.Status at 20 Hz.
- A GNSS receiver (node 70): gnss.Fix2 at 10 Hz, gnss.Auxiliary at 5 Hz, a
  debug.LogMessage a second.
- A compass (71): ahrs.MagneticFieldStrength2 at 25 Hz; a barometer (72):
  air_data.StaticPressure and StaticTemperature at 10 Hz; an airspeed sensor (73):
  air_data.RawAirData at 20 Hz; a battery monitor (74): power.BatteryInfo at 5 Hz.
- The NodeStatus of every node, once a second.

Every frame is stamped when it ends on a 1 Mbit/s bus that carries one frame at a time,
the lowest CAN ID first (`veronte4x.capture.bus_time`), so bus load and rates are those a
real bus would show.

The vehicle flies a 60-second cycle (disarmed, spool-up, hover, climb, cruise, descent):
the commands, ESC speeds and currents, battery voltage and height follow it, so the values
are worth plotting. The same arguments give the same file. `benchmarks/bench_columnar.py`
times ``read_tables`` on this bus; ``examples/vehicle_bus.ipynb`` decodes it.
"""

from __future__ import annotations

import argparse
import math
from collections.abc import Callable
from itertools import pairwise
from pathlib import Path
from typing import Any

from veronte4x import dronecan
from veronte4x.capture.bus_time import PendingFrame, transmit
from veronte4x.dronecan.definitions import DATA_TYPES
from veronte4x.dronecan.schema import Array, Struct, Union

START = 1_700_000_000.0  # capture clock at t = 0 (2023-11-14 22:13:20 UTC)
AUTOPILOT, ESCS, SERVOS = 10, range(60, 68), (80, 81)
GPS, COMPASS, BARO, AIRSPEED, BATTERY = 70, 71, 72, 73, 74
NODES = (AUTOPILOT, *ESCS, *SERVOS, GPS, COMPASS, BARO, AIRSPEED, BATTERY)
BITRATE = 1_000_000  # bit/s

Fields = Callable[[float], dict[str, Any]]
"""The fields of a transfer sent at ``t`` seconds (the defaults of the rest are zero)."""

_PROFILE = ((0, 0.0), (2, 0.0), (5, 0.55), (20, 0.55), (28, 0.75), (45, 0.6), (55, 0.35))
"""(s into the 60-second cycle, collective throttle 0..1); 0 again at 60 s."""


def throttle(t: float) -> float:
    """The collective throttle at ``t`` seconds: the profile, linearly interpolated, with
    the small corrections of gusts."""
    cycle = t % 60.0
    points = (*_PROFILE, (60.0, 0.0))
    for (t0, v0), (t1, v1) in pairwise(points):
        if t0 <= cycle < t1:
            level = v0 + (v1 - v0) * (cycle - t0) / (t1 - t0)
            return level * (1.0 + 0.03 * math.sin(1.7 * t))  # gusts
    return 0.0


def esc_throttle(t: float, index: int) -> float:
    """One ESC's share: the collective plus the attitude controller's small corrections."""
    return max(0.0, throttle(t) * (1.0 + 0.04 * (index - 3.5) / 3.5 * math.sin(0.9 * t + index)))


def esc_temperature(t: float, index: int) -> float:
    """An ESC's temperature, K: warmer under load; ESC 5 (node 65), poorly cooled, warms up
    by 1 K every 10 s to 40 K above the others."""
    warming = min(40.0, 0.1 * t) if index == 5 else 0.0
    return 300.0 + 25.0 * esc_throttle(t, index) + warming


def battery_current(t: float) -> float:
    """The battery current, A: 0.4 A of avionics plus the eight motors."""
    return 0.4 + sum(30.0 * esc_throttle(t, i) ** 2 for i in range(len(ESCS)))


def battery_voltage(t: float) -> float:
    """A 6S battery: 25.2 V full, sagging under load, draining slowly."""
    return 25.2 - 0.012 * battery_current(t) - 0.004 * t


def height(t: float) -> float:
    """Height above the take-off point, m (climbing from 5 s, down again by 60 s)."""
    t %= 60.0
    if t < 5:
        return 0.0
    if t < 45:
        return min(40.0, 0.6 * (t - 5) + 0.8 * max(0.0, t - 20))
    return max(0.0, 40.0 * (60.0 - t) / 15.0)


def _traffic() -> list[tuple[float, int, str, Fields]]:
    """(period s, node, type, fields at t) of every stream of the bus."""
    cov = [0.01 * i for i in range(9)]
    traffic: list[tuple[float, int, str, Fields]] = [
        (
            1 / 400,
            AUTOPILOT,
            "uavcan.equipment.esc.RawCommand",
            lambda t: {"cmd": [round(8191 * esc_throttle(t, i)) for i in range(len(ESCS))]},
        ),
        (
            1 / 100,
            AUTOPILOT,
            "uavcan.equipment.actuator.ArrayCommand",
            lambda t: {
                "commands": [
                    {"actuator_id": i, "command_type": 0, "command_value": (t % 2) - 1}
                    for i in range(len(SERVOS))
                ]
            },
        ),
        (
            1 / 10,
            AUTOPILOT,
            "uavcan.equipment.safety.ArmingStatus",
            lambda t: {"status": 255 if t % 60 >= 1 else 0},
        ),
        (
            1 / 10,
            AUTOPILOT,
            "uavcan.equipment.indication.LightsCommand",
            lambda t: {
                "commands": [
                    {"light_id": i, "color": {"red": int(t) % 32, "green": 0, "blue": 31}}
                    for i in range(2)
                ]
            },
        ),
        (
            1 / 10,
            GPS,
            "uavcan.equipment.gnss.Fix2",
            lambda t: {
                "timestamp": {"usec": round(t * 1e6)},
                "gnss_time_standard": 2,
                "longitude_deg_1e8": -12_245_000_000 + round(t * 1000),
                "latitude_deg_1e8": 4_750_000_000,
                "height_ellipsoid_mm": round(120_000 + 1000 * height(t)),
                "height_msl_mm": round(75_000 + 1000 * height(t)),
                "ned_velocity": [1.0, 0.5, -0.1],
                "sats_used": 14,
                "status": 3,
                "covariance": [0.5, 0.5, 1.0, 0.1, 0.1, 0.2],
                "pdop": 1.2,
            },
        ),
        (
            1 / 5,
            GPS,
            "uavcan.equipment.gnss.Auxiliary",
            lambda t: {"hdop": 0.8, "vdop": 1.1, "sats_visible": 20, "sats_used": 14},
        ),
        (
            1 / 25,
            COMPASS,
            "uavcan.equipment.ahrs.MagneticFieldStrength2",
            lambda t: {"sensor_id": 0, "magnetic_field_ga": [0.2, -0.1, 0.45]},
        ),
        (
            1 / 10,
            BARO,
            "uavcan.equipment.air_data.StaticPressure",
            lambda t: {
                "static_pressure": 101_325.0 - 12.0 * height(t),
                "static_pressure_variance": 2.0,
            },
        ),
        (
            1 / 10,
            BARO,
            "uavcan.equipment.air_data.StaticTemperature",
            lambda t: {"static_temperature": 288.0, "static_temperature_variance": 0.5},
        ),
        (
            1 / 20,
            AIRSPEED,
            "uavcan.equipment.air_data.RawAirData",
            lambda t: {
                "differential_pressure": 150.0 * throttle(t),
                "static_air_temperature": 290.0,
                "covariance": cov[:2],
            },
        ),
        (
            1 / 5,
            BATTERY,
            "uavcan.equipment.power.BatteryInfo",
            lambda t: {
                "voltage": battery_voltage(t),
                "current": battery_current(t),
                "remaining_capacity_wh": 222.0 - 0.01 * t,
                "full_charge_capacity_wh": 222.0,
                "state_of_charge_pct": 100 - int(t / 60),
                "battery_id": 0,
                "model_instance_id": 7,
                "model_name": b"Tattu 6S 10000mAh",
            },
        ),
        (
            1.0,
            GPS,
            "uavcan.protocol.debug.LogMessage",
            lambda t: {"level": {"value": 1}, "source": b"GPS", "text": b"fix 3D, 14 sats"},
        ),
    ]
    for index, node in enumerate(ESCS):
        traffic.append(
            (
                1 / 50,
                node,
                "uavcan.equipment.esc.Status",
                lambda t, i=index: {
                    "error_count": 0,
                    "voltage": battery_voltage(t) - 0.1,
                    "current": 30.0 * esc_throttle(t, i) ** 2,
                    "temperature": esc_temperature(t, i),
                    "rpm": round(9000 * esc_throttle(t, i)),
                    "power_rating_pct": round(100 * esc_throttle(t, i)),
                    "esc_index": i,
                },
            )
        )
    for index, node in enumerate(SERVOS):
        traffic.append(
            (
                1 / 20,
                node,
                "uavcan.equipment.actuator.Status",
                lambda t, i=index: {
                    "actuator_id": i,
                    "position": (t % 2) - 1,
                    "power_rating_pct": 5,
                },
            )
        )
    for node in NODES:
        traffic.append((1.0, node, "uavcan.protocol.NodeStatus", lambda t: {"uptime_sec": int(t)}))
    return traffic


def _plain_defaults(t: Any) -> Any:
    """Plain data of a DSDL type with every number 0 and every dynamic array empty."""
    if isinstance(t, Struct):
        return {f.name: _plain_defaults(f.type) for f in t.fields if f.name}
    if isinstance(t, Union):
        return {t.members[0].name: _plain_defaults(t.members[0].type)}
    if isinstance(t, Array):
        return [] if t.dynamic else [_plain_defaults(t.item)] * t.max_size
    return False if t.kind == "bool" else 0


def _message(data_type: Any, fields: dict[str, Any]) -> Any:
    data = _plain_defaults(data_type.schema)
    data.update(fields)
    return dronecan.from_builtin(data_type.schema.cls, data)


_BY_NAME = {t.full_name: t for t in DATA_TYPES if t.kind is dronecan.TransferKind.MESSAGE}


def frames_per_second() -> float:
    """How many frames a second the bus carries."""
    total = 0.0
    for period, node, name, fields in _traffic():
        message = _message(_BY_NAME[name], fields(0.0))
        total += len(dronecan.encode(message, source_node_id=node, transfer_id=0)) / period
    return total


def bus_lines(seconds: float) -> list[str]:
    """candump ``-L`` lines of the bus's first ``seconds``, in time order.

    Each transfer is ready at its stream's time (streams a little out of phase); its frames
    then go onto a 1 Mbit/s bus as a real one carries them (`veronte4x.capture.bus_time`:
    one frame at a time, the lowest CAN ID first), stamped when they end."""
    frames: list[PendingFrame] = []
    texts: list[str] = []
    for stream, (period, node, name, fields) in enumerate(_traffic()):
        data_type = _BY_NAME[name]
        phase = stream * 1e-4
        for k in range(int(seconds / period)):
            t = k * period
            made = dronecan.encode(
                _message(data_type, fields(t)), source_node_id=node, transfer_id=k % 32
            )
            for f in made:
                frames.append(PendingFrame(phase + t, f.can_id, True, len(f.data), node))
                texts.append(f"{f.can_id:08X}#{f.data.hex().upper()}")
    order = sorted(range(len(frames)), key=lambda i: frames[i].ready)  # as nodes queue them
    frames, texts = [frames[i] for i in order], [texts[i] for i in order]
    ends = transmit(frames, BITRATE)
    return [
        f"({START + ends[i]:.6f}) can0 {texts[i]}"
        for i in sorted(range(len(ends)), key=ends.__getitem__)
    ]


def vehicle_lines(frames: int) -> list[str]:
    """The first ``frames`` lines of the bus (as long a bus as that takes)."""
    return bus_lines(frames / frames_per_second() + 1.0)[:frames]


def write(path: str | Path, seconds: float = 30.0) -> int:
    """Write the bus's first ``seconds`` to ``path`` as a candump log; return the frames."""
    lines = bus_lines(seconds)
    Path(path).write_text("".join(line + "\n" for line in lines))
    return len(lines)


def main() -> None:
    """Parse the arguments, write the file."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("output", nargs="?", default=str(Path(__file__).with_name("vehicle.log")))
    parser.add_argument("--seconds", type=float, default=30.0, help="length of the capture")
    args = parser.parse_args()
    if not Path(args.output).resolve().parent.is_dir():  # before the work, not after it
        parser.error(f"{Path(args.output).parent}: no such directory for the output")
    frames = write(args.output, args.seconds)
    print(f"wrote {frames:,} frames ({args.seconds:g} s) to {args.output}")


if __name__ == "__main__":
    main()
