"""``plot``: nothing to plot is said (no blank image), time reads as time, legends sit outside
the data."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from tests.inputs.support import EXAMPLES, candump, run
from veronte4x import capture

pytest.importorskip("matplotlib")

CAPTURE = EXAMPLES / "capture.log"


def test_an_empty_capture_has_nothing_to_plot(tmp_path: Path) -> None:
    path, image = tmp_path / "quiet.log", tmp_path / "plot.png"
    path.write_text("")
    for kind in ("arbitration", "esc"):
        result = run("plot", str(path), "--kind", kind, "--output", str(image))
        assert result.returncode == 2
        assert result.stderr == f"veronte4x: nothing to plot: {path} holds no CAN frame\n"
        assert not image.exists()


def test_a_capture_without_what_a_kind_draws(tmp_path: Path) -> None:
    path, image = tmp_path / "ready.log", tmp_path / "plot.png"
    path.write_text(candump(10))
    result = run("plot", str(path), "--output", str(image))
    assert result.returncode == 2
    assert result.stderr == (
        f"veronte4x: nothing to plot: {path} has no Score or Status frame of the arbiter; try "
        "--kind esc, or another --only-channel\n"
    )
    result = run("plot", str(CAPTURE), "--kind", "esc", "--output", str(image))
    assert result.returncode == 2
    assert result.stderr == (
        f"veronte4x: nothing to plot: {CAPTURE} has no ESC status or temperature of a DroneCAN "
        "node; try --kind arbitration, or another --only-channel\n"
    )
    assert not image.exists()


def test_time_is_seconds_from_the_start_and_legends_are_outside(tmp_path: Path) -> None:
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    from veronte4x.capture.plot import arbitration_timeline

    figure: Any = arbitration_timeline(capture.read(CAPTURE))
    canvas: Any = FigureCanvasAgg(figure)
    canvas.draw()
    top, bottom = figure.axes
    assert bottom.get_xlabel() == "time (s) from 2025-11-21 15:00:00.000 UTC"
    assert top.xaxis.get_offset_text().get_text() == ""  # no +1.763737e9
    assert min(line.get_xdata()[0] for line in top.get_lines()) == pytest.approx(0.26)
    legend = top.get_legend().get_window_extent()
    assert legend.x0 >= top.get_window_extent().x1  # right of the data, covering none
    result = run("plot", str(CAPTURE), "--output", str(tmp_path / "plot.png"))
    assert (result.returncode, result.stderr) == (0, f"veronte4x: wrote {tmp_path / 'plot.png'}\n")
    assert (tmp_path / "plot.png").read_bytes().startswith(b"\x89PNG")


def test_a_capture_clock_is_drawn_as_captured() -> None:
    from veronte4x.capture.plot import time_axis

    assert time_axis(12.5) == (0.0, "time (s, capture clock)")
    assert time_axis(1_763_737_200.25) == (
        1_763_737_200.25,
        "time (s) from 2025-11-21 15:00:00.250 UTC",
    )
