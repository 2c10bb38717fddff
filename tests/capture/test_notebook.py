"""The notebook API: records, stats, DataFrame columns and values, the plot."""

from pathlib import Path

import matplotlib
import pytest

from veronte4x import capture, codec
from veronte4x.capture.plot import arbitration_timeline

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
