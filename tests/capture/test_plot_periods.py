"""The arbitration plot's periods: an autopilot that dies and comes back, the arbiter's
maintenance periods (closed, and open at the end of the capture), and a capture of Status
frames without any Score."""

from __future__ import annotations

import dataclasses
import math
from typing import Any

import pytest

from veronte4x import codec
from veronte4x.capture.busmap import Role
from veronte4x.capture.plot import draw_timeline, timeline
from veronte4x.capture.records import Record

pytest.importorskip("matplotlib")

FLAGS = {f.name: True for f in dataclasses.fields(codec.Status) if f.name.endswith("_ok")}
"""Every check of a Status passed."""
Alive = tuple[bool, bool, bool, bool]
UP: Alive = (True, True, True, False)
AP1_DEAD: Alive = (False, True, True, False)


def _status(stamp: float, alive: Alive, selected: int, normal: bool | None) -> Record:
    status = codec.Status(selected, True, alive, alive, **FLAGS, normal_mode=normal)
    return Record(stamp, "can0", 0xFF, Role.ARBITER, None, None, status, None, "", b"")


def _score(stamp: float, ap: int, score: float) -> Record:
    message = codec.Score(autopilot=ap, score=score)
    return Record(stamp, "can0", 0xFF, Role.ARBITER, None, None, message, None, "", b"")


def test_an_autopilot_that_comes_back_has_one_dead_period_and_its_line_again() -> None:
    records = [
        _status(10.0, UP, 0, True), _score(10.5, 0, 0.1),
        _status(11.0, AP1_DEAD, 1, True), _score(11.5, 0, 0.1),  # dead: not drawn
        _status(12.0, AP1_DEAD, 1, True),
        _status(13.0, UP, 1, True), _score(13.5, 0, 0.2),  # back at 13.0
    ]  # fmt: skip
    data = timeline(records)
    assert data.dead == {0: [(11.0, 13.0)]}
    times, values = data.scores[0]
    assert times == [10.5, 11.0, 11.0, 13.5]
    assert values[:2] == [0.1, 0.1] and math.isnan(values[2]) and values[3] == 0.2
    assert data.maintenance == []
    assert data.selected == ([10.0, 11.0, 12.0, 13.0], [0, 1, 1, 1])


def test_maintenance_periods_closed_and_open_at_the_end() -> None:
    """A CEX-form Status (no mode bit) ends a maintenance period as a normal one does; one
    still open at the capture's end lasts to its last record."""
    records = [
        _status(1.0, UP, 0, True),
        _status(2.0, UP, 0, False), _status(3.0, UP, 0, False),
        _status(4.0, UP, 0, None),
        _status(5.0, UP, 0, False), _score(6.5, 1, 0.3),
    ]  # fmt: skip
    data = timeline(records)
    assert data.maintenance == [(2.0, 4.0), (5.0, 6.5)]
    assert data.dead == {}


def test_status_frames_without_scores_draw_selection_and_maintenance() -> None:
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    records = [
        _status(1.0, UP, 0, True),
        _status(2.0, UP, 2, False),
        _status(3.0, UP, 2, True),
    ]
    data = timeline(records)
    assert (data.scores, data.empty) == ({}, False)
    figure: Any = draw_timeline(data)
    canvas: Any = FigureCanvasAgg(figure)
    canvas.draw()
    top, bottom = figure.axes
    assert top.get_legend() is None and top.get_lines() == []  # no score: no legend
    assert bottom.get_lines()[0].get_ydata().tolist() == [0, 2, 2]
    for axes in (top, bottom):
        [span] = axes.patches  # the maintenance period, on both panels
        assert span.get_facecolor()[:3] == pytest.approx((1.0, 0.647, 0.0), abs=1e-3)
        assert (span.get_x(), span.get_x() + span.get_width()) == (2.0, 3.0)
    assert bottom.get_xlabel() == "time (s, capture clock)"
