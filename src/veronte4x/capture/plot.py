"""Plot arbitration over time from decoded records (needs the ``plot`` extra, matplotlib).

Top: each autopilot's score from the arbiter's Score frames. Bottom: the selected autopilot
from its Status frames, with every autopilot's dead periods (alive flag clear while
arbitrating) and the arbiter's maintenance periods shaded.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import TYPE_CHECKING

from veronte4x.capture.busmap import AUTOPILOT_NAMES
from veronte4x.capture.records import Record
from veronte4x.codec import Score, Status

if TYPE_CHECKING:
    from matplotlib.figure import Figure

Span = tuple[float, float]


def arbitration_timeline(records: Iterable[Record]) -> Figure:
    """Draw scores, the selected autopilot, dead and maintenance periods; return the figure."""
    from matplotlib.figure import Figure

    scores: dict[int, tuple[list[float], list[float]]] = {}
    selected: tuple[list[float], list[int]] = ([], [])
    dead: dict[int, list[Span]] = {i: [] for i in range(4)}
    maintenance: list[Span] = []
    dead_since: dict[int, float] = {}
    maintenance_since: float | None = None
    last = 0.0
    for record in records:
        message, stamp = record.message, record.timestamp
        if stamp is None or record.error is not None:
            continue
        last = stamp
        if isinstance(message, Score):
            times, values = scores.setdefault(message.autopilot, ([], []))
            times.append(stamp)
            values.append(message.score)
        elif isinstance(message, Status):
            selected[0].append(stamp)
            selected[1].append(message.selected)
            for ap, alive in enumerate(message.alive):
                if message.arbitrating and not alive:
                    dead_since.setdefault(ap, stamp)
                elif ap in dead_since:
                    dead[ap].append((dead_since.pop(ap), stamp))
            if message.normal_mode is False and maintenance_since is None:
                maintenance_since = stamp
            elif message.normal_mode is not False and maintenance_since is not None:
                maintenance.append((maintenance_since, stamp))
                maintenance_since = None
    for ap, since in dead_since.items():
        dead[ap].append((since, last))
    if maintenance_since is not None:
        maintenance.append((maintenance_since, last))

    figure = Figure(figsize=(10, 6))
    top, bottom = figure.subplots(2, 1, sharex=True)
    for ap, (times, values) in sorted(scores.items()):
        top.plot(times, values, label=AUTOPILOT_NAMES[ap])
    top.set_ylabel("score (lower is better)")
    if scores:
        top.legend(loc="upper right")
    bottom.step(selected[0], selected[1], where="post", color="black", label="selected")
    for ap, spans in dead.items():
        for start, end in spans:
            bottom.axvspan(start, end, ymin=ap / 4, ymax=(ap + 1) / 4, color="red", alpha=0.3)
    for start, end in maintenance:
        for axes in (top, bottom):
            axes.axvspan(start, end, color="orange", alpha=0.2)
    bottom.set_ylim(-0.5, 3.5)
    bottom.set_yticks(range(4), AUTOPILOT_NAMES)
    bottom.set_ylabel("selected (red: dead)")
    bottom.set_xlabel("time (s)")
    figure.suptitle("Veronte 4x arbitration")
    return figure
