"""Plot arbitration over time from decoded records (needs the ``plot`` extra, matplotlib).

Top: each autopilot's score from the arbiter's Score frames; a line ends where its autopilot
dies and starts again if it comes back. Bottom: the selected autopilot from the arbiter's
Status frames, with dead periods (alive flag clear while arbitrating) shaded for each
autopilot that has appeared (alive in a Status, or sending) and the arbiter's maintenance
periods. An autopilot absent from the capture (an external one that is not fitted) is
neither drawn nor shaded.

Time runs along the x axis in seconds from the capture's first timestamp, the axis label
giving that start as a UTC clock time (for a capture clock below 1e8 s, one that starts near
0, the times are drawn as captured). Legends sit outside the data, right of the panels.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from veronte4x.capture.busmap import AUTOPILOT_NAMES, Role
from veronte4x.capture.records import Record
from veronte4x.codec import Score, Status
from veronte4x.extras import require
from veronte4x.times import EPOCH_THRESHOLD, format_time

if TYPE_CHECKING:
    from matplotlib.figure import Figure

Span = tuple[float, float]
_MARKED = 100


@dataclass
class Timeline:
    """What the arbitration plot draws, gathered from the records.

    Attributes:
        scores: Per autopilot, the times and scores of its line; a NaN score breaks the
            line (the autopilot died there).
        selected: Times and selected autopilot of each Status frame.
        dead: Per autopilot that appeared, its dead periods.
        maintenance: The arbiter's maintenance periods.
        start: The capture's first timestamp of a decoded record.
    """

    scores: dict[int, tuple[list[float], list[float]]] = field(default_factory=dict)
    selected: tuple[list[float], list[int]] = field(default_factory=lambda: ([], []))
    dead: dict[int, list[Span]] = field(default_factory=dict)
    maintenance: list[Span] = field(default_factory=list)
    start: float | None = None

    @property
    def empty(self) -> bool:
        """Nothing to draw: no Score or Status frame of the arbiter."""
        return not self.scores and not self.selected[0]


def timeline(records: Iterable[Record]) -> Timeline:
    """Gather scores, selection, dead and maintenance periods from records, in time order."""
    out = Timeline()
    seen: set[int] = set()
    dead_since: dict[int, float] = {}
    maintenance_since: float | None = None
    last = 0.0
    for record in records:
        message, stamp = record.message, record.timestamp
        if stamp is None or message is None:
            continue
        last = stamp
        if out.start is None:
            out.start = stamp
        if record.role is Role.AUTOPILOT and record.autopilot is not None:
            seen.add(record.autopilot)
        if isinstance(message, Score):
            times, values = out.scores.setdefault(message.autopilot, ([], []))
            if message.autopilot not in dead_since:
                times.append(stamp)
                values.append(message.score)
        elif isinstance(message, Status):
            out.selected[0].append(stamp)
            out.selected[1].append(message.selected)
            for ap, alive in enumerate(message.alive):
                if alive:
                    seen.add(ap)
                if message.arbitrating and not alive and ap in seen:
                    if ap not in dead_since:
                        dead_since[ap] = stamp
                        _end_line(out.scores.get(ap), stamp)
                elif ap in dead_since:
                    out.dead.setdefault(ap, []).append((dead_since.pop(ap), stamp))
            if message.normal_mode is False and maintenance_since is None:
                maintenance_since = stamp
            elif message.normal_mode is not False and maintenance_since is not None:
                out.maintenance.append((maintenance_since, stamp))
                maintenance_since = None
    for ap, since in dead_since.items():
        out.dead.setdefault(ap, []).append((since, last))
    if maintenance_since is not None:
        out.maintenance.append((maintenance_since, last))
    return out


def _end_line(line: tuple[list[float], list[float]] | None, stamp: float) -> None:
    """End a score line at a death: its last score up to that time, then a break."""
    if line is None or not line[0]:
        return
    times, values = line
    times += [stamp, stamp]
    values += [values[-1], math.nan]


def arbitration_timeline(records: Iterable[Record]) -> Figure:
    """Draw scores, the selected autopilot, dead and maintenance periods; return the figure.

    Raises:
        MissingExtraError: matplotlib (the ``plot`` extra) is not installed.
    """
    return draw_timeline(timeline(records))


def draw_timeline(data: Timeline) -> Figure:
    """Draw a `Timeline` gathered by `timeline`; return the figure.

    Raises:
        MissingExtraError: matplotlib (the ``plot`` extra) is not installed.
    """
    figure_module = require("matplotlib.figure", "plot", "plotting")
    figure: Figure = figure_module.Figure(figsize=(10, 6), layout="constrained")
    top, bottom = figure.subplots(2, 1, sharex=True)
    origin, label = time_axis(data.start)
    for ap, (times, values) in sorted(data.scores.items()):
        style = ".-" if len(times) <= _MARKED else "-"  # a few scores: each one seen
        top.plot([t - origin for t in times], values, style, label=AUTOPILOT_NAMES[ap])
    top.set_ylabel("score (lower is better)")
    if data.scores:
        legend_outside(top)
    bottom.step(
        [t - origin for t in data.selected[0]],
        data.selected[1],
        where="post",
        color="black",
        label="selected",
    )
    for ap, spans in sorted(data.dead.items()):
        for start, end in spans:
            bottom.axvspan(
                start - origin, end - origin, ymin=ap / 4, ymax=(ap + 1) / 4, color="red", alpha=0.3
            )
    for start, end in data.maintenance:
        for axes in (top, bottom):
            axes.axvspan(start - origin, end - origin, color="orange", alpha=0.2)
    bottom.set_ylim(-0.5, 3.5)
    bottom.set_yticks(range(4), AUTOPILOT_NAMES)
    bottom.set_ylabel("selected (red: dead)")
    bottom.set_xlabel(label)
    figure.suptitle("Veronte 4x arbitration")
    return figure


def time_axis(start: float | None) -> tuple[float, str]:
    """The time subtracted from every timestamp drawn, and the x axis label that says it:
    seconds from the first timestamp for Unix time, the capture's own clock otherwise."""
    if start is None or start < EPOCH_THRESHOLD:
        return 0.0, "time (s, capture clock)"
    clock = format_time(start).replace("T", " ")[:-4]  # to the millisecond
    return start, f"time (s) from {clock} UTC"


def legend_outside(axes: Any, **options: Any) -> None:
    """A legend right of the axes, where it covers no data."""
    axes.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0, **options)
