"""The live monitor's view on a screen narrower than its table: a row stays one line."""

from __future__ import annotations

import io

from rich.console import Console

from tests.capture.test_monitor_rates import node_status, ready
from veronte4x.capture.monitor import MonitorState
from veronte4x.cli import monitor


def test_on_a_narrow_screen_each_row_is_one_line() -> None:
    """A mutation survivor: the columns allowed to wrap, so a row took two lines and the
    rows that fit the screen were miscounted."""
    state = MonitorState()
    for tick in range(3):
        state.add(node_status(10.0 + tick, 20))
        state.add(ready(10.0 + tick))
    snapshot = (state.arbiter.describe(), "6 records", state.rows(now=None), state.rates)
    screen = Console(width=44, height=20, record=True, file=io.StringIO(), color_system=None)
    screen.print(monitor._table(snapshot, "", screen=screen))
    lines = screen.export_text().splitlines()
    assert lines[:2] == ["arbiter: no Status yet", "6 records"]
    assert len(lines) == 6  # the two lines above, the table's head and rule, two rows
    assert lines[4].startswith("AP2 ") and lines[5].startswith("node")
