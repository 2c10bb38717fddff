"""The notebook API: records, stats, DataFrame columns and values, the plot."""

import math
from pathlib import Path

import matplotlib
import pytest

from veronte4x import capture, codec
from veronte4x.capture.busmap import Role
from veronte4x.capture.plot import arbitration_timeline, timeline
from veronte4x.capture.records import Record

matplotlib.use("Agg")
EXAMPLE = str(Path(__file__).resolve().parents[2] / "examples" / "capture.log")


def test_read_and_stats() -> None:
    records = list(capture.read(EXAMPLE))
    assert len(records) == 39
    counts = capture.stats(records)
    assert counts.by_type["Score"] == 3
    assert counts.errors == {"unknown command": 1}
    assert counts.by_sender["AP2"] == 9


def test_fields_flatten_tuples() -> None:
    status = codec.Status(1, True, (True, False, True, False), (False,) * 4)
    fields = capture.fields(status)
    assert fields["alive_0"] is True
    assert fields["alive_1"] is False
    assert fields["selected"] == 1
    assert fields["cbit_ok"] is None
    assert capture.fields(codec.PwmSet(4, (1, 2, 3, 4)))["values_3"] == 4


def test_dataframe() -> None:
    pytest.importorskip("pandas")
    frame = capture.to_dataframe(capture.read(EXAMPLE))
    assert len(frame) == 39
    assert list(frame.columns[:8]) == [
        "timestamp", "channel", "can_id", "sender", "message", "error", "detail", "data"
    ]  # fmt: skip
    scores = frame[frame.message == "Score"]
    assert list(scores.autopilot) == [0, 1, 2]
    assert list(scores.score.round(3)) == [0.058, 0.026, 0.054]
    assert frame.loc[frame.error.notna(), "data"].tolist() == ["0401"]


def test_plot_draws_scores_and_selection() -> None:
    figure = arbitration_timeline(capture.read(EXAMPLE))
    top, bottom = figure.axes
    assert [line.get_label() for line in top.get_lines()] == ["AP1", "AP2", "AP3"]
    assert list(bottom.get_lines()[0].get_ydata()) == [1, 1]


def _status(stamp: float, alive: tuple[bool, bool, bool, bool], selected: int) -> Record:
    status = codec.Status(
        selected=selected, arbitrating=True, alive=alive, ready=alive, **STATUS_FLAGS
    )
    return Record(stamp, "can0", 255, Role.ARBITER, None, None, status, None, "", b"")


def _score(stamp: float, ap: int, score: float) -> Record:
    message = codec.Score(autopilot=ap, score=score)
    return Record(stamp, "can0", 255, Role.ARBITER, None, None, message, None, "", b"")


STATUS_FLAGS = {name: True for name in (
    "cbit_ok", "pbit_ok", "pdi_ok", "memory_ok", "can_a_ok", "can_b_ok", "cio_low_ok",
    "cio_high_ok", "power_ok", "bus_a_voltage_ok", "bus_b_voltage_ok", "arbiter_voltage_ok",
    "ap1_voltage_ok", "ap2_voltage_ok", "ap3_voltage_ok", "normal_mode",
)}  # fmt: skip


def test_absent_is_absent_and_a_dead_score_line_ends_at_death() -> None:
    """The external autopilot never appears: no dead shading. AP2 dies at 2.0: its score
    line ends there, though the arbiter goes on reporting its last score."""
    up, ap2_dead = (True, True, True, False), (True, False, True, False)
    records = [
        _status(0.0, up, 1), _score(0.5, 1, 0.2), _score(0.5, 0, 0.3),
        _status(1.0, up, 1), _score(1.5, 1, 0.25),
        _status(2.0, ap2_dead, 0), _score(2.5, 1, 0.25), _score(2.5, 0, 0.35),
        _status(3.0, ap2_dead, 0), _score(3.5, 1, 0.25),
    ]  # fmt: skip
    data = timeline(records)
    assert data.dead == {1: [(2.0, 3.5)]}
    times, values = data.scores[1]
    assert times == [0.5, 1.5, 2.0, 2.0]
    assert values[:3] == [0.2, 0.25, 0.25] and math.isnan(values[3])
    assert data.scores[0] == ([0.5, 2.5], [0.3, 0.35])
    figure = arbitration_timeline(records)
    top, bottom = figure.axes
    assert len(bottom.patches) == 1  # AP2's dead span only, nothing for the external one
    assert list(top.get_lines()[1].get_xdata()) == [0.5, 1.5, 2.0, 2.0]
