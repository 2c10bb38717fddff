"""Plot the telemetry of Vertiq ESCs from decoded records (the ``plot`` extra, matplotlib).

One line per node in each panel: speed and supply current from ``uavcan.equipment.esc.Status``,
supply voltage, and the temperatures: the coils' from esc.Status and the microcontroller's
from ``uavcan.equipment.device.Temperature`` (Vertiq "Standard DroneCAN Support", sections
1.2 and 1.3). The time axis and legends are drawn as on the arbitration plot
(`veronte4x.capture.plot.time_axis`).
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from veronte4x.capture.records import Record
from veronte4x.dronecan.messages import EscStatus, Temperature
from veronte4x.extras import require

if TYPE_CHECKING:
    from matplotlib.figure import Figure


@dataclass
class _Series:
    times: list[float] = field(default_factory=list)
    rpm: list[int] = field(default_factory=list)
    current: list[float] = field(default_factory=list)
    voltage: list[float] = field(default_factory=list)
    coil: list[float] = field(default_factory=list)
    mcu_times: list[float] = field(default_factory=list)
    mcu: list[float] = field(default_factory=list)


def esc_series(records: Iterable[Record]) -> dict[int, _Series]:
    """The telemetry of each node id, in time order of the records."""
    nodes: dict[int, _Series] = {}
    for record in records:
        message, stamp = record.message, record.timestamp
        if stamp is None or record.error is not None or record.node_id is None:
            continue
        if isinstance(message, EscStatus):
            s = nodes.setdefault(record.node_id, _Series())
            s.times.append(stamp)
            s.rpm.append(message.rpm)
            s.current.append(message.current)
            s.voltage.append(message.voltage)
            s.coil.append(message.temperature)
        elif isinstance(message, Temperature):
            s = nodes.setdefault(record.node_id, _Series())
            s.mcu_times.append(stamp)
            s.mcu.append(message.temperature)
    return nodes


def esc_telemetry(records: Iterable[Record]) -> Figure:
    """Draw speed, current, voltage and temperatures of every ESC; return the figure.

    Raises:
        MissingExtraError: matplotlib (the ``plot`` extra) is not installed.
    """
    return draw_esc_telemetry(esc_series(records))


def draw_esc_telemetry(nodes: dict[int, _Series]) -> Figure:
    """Draw the series `esc_series` gathers; return the figure.

    Raises:
        MissingExtraError: matplotlib (the ``plot`` extra) is not installed.
    """
    figure_module = require("matplotlib.figure", "plot", "plotting")

    from veronte4x.capture.plot import legend_outside, time_axis

    figure: Figure = figure_module.Figure(figsize=(10, 8), layout="constrained")
    speed, current, voltage, heat = figure.subplots(4, 1, sharex=True)
    starts = [t[0] for s in nodes.values() for t in (s.times, s.mcu_times) if t]
    origin, label = time_axis(min(starts, default=None))
    for node, s in sorted(nodes.items()):
        name = f"node {node}"
        times = [t - origin for t in s.times]
        speed.plot(times, s.rpm, label=name)
        current.plot(times, s.current, label=name)
        voltage.plot(times, s.voltage, label=name)
        line = heat.plot(times, s.coil, label=f"{name} coils")[0]
        mcu_times = [t - origin for t in s.mcu_times]
        heat.plot(mcu_times, s.mcu, linestyle="--", color=line.get_color(), label=f"{name} MCU")
    speed.set_ylabel("speed (rpm)")
    current.set_ylabel("current (A)")
    voltage.set_ylabel("voltage (V)")
    heat.set_ylabel("temperature (K)")
    heat.set_xlabel(label)
    if nodes:
        legend_outside(speed)
        legend_outside(heat, fontsize="small")
    figure.suptitle("ESC telemetry" if nodes else "ESC telemetry: none in this capture")
    return figure
