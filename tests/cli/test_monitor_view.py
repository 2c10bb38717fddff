"""The live monitor's view: a row stays one line on a narrow screen; numbers are
right-aligned, names left-aligned."""

from __future__ import annotations

import io

from rich.console import Console

from tests.capture.test_monitor_rates import node_status, ready
from veronte4x.capture.monitor import MonitorState
from veronte4x.cli import monitor


def test_on_a_narrow_screen_each_row_is_two_lines() -> None:
    """A mutation survivor: the columns allowed to wrap, so a row took more lines and the
    rows that fit the screen were miscounted. Narrow (under 100 columns), a row is its
    columns' line and its fields' line; the rows that fit are counted by two lines."""
    state = MonitorState()
    for tick in range(3):
        state.add(node_status(10.0 + tick, 20))
        state.add(ready(10.0 + tick))
    snapshot = (state.arbiter.describe(), "6 records", state.rows(now=None), state.rates)
    screen = Console(width=44, height=20, record=True, file=io.StringIO(), color_system=None)
    screen.print(monitor._table(snapshot, "", screen=screen))
    lines = screen.export_text().splitlines()
    assert lines[:2] == ["arbiter: no Status yet", "6 records"]
    assert len(lines) == 7  # the two lines above, the table's head, two rows of two lines
    assert lines[3].startswith("AP2 ") and lines[5].startswith("node")
    assert lines[4] == "  ready=True" and lines[6].startswith("  uptime_sec=12 s, health=OK")
    short = Console(width=44, height=6, record=True, file=io.StringIO(), color_system=None)
    short.print(monitor._table(snapshot, "", screen=short))
    assert short.export_text().splitlines()[3:] == [
        lines[3],
        lines[4],
        "+1 more rows (↓); f to filter",
    ]


def test_numbers_are_right_aligned_and_names_left_aligned() -> None:
    """A mutation survivor: the count column's alignment dropped (numbers left-aligned)."""
    state = MonitorState()
    for tick in range(12):
        state.add(ready(10.0 + tick))
        if tick < 3:
            state.add(node_status(10.0 + tick, 20))
    snapshot = (state.arbiter.describe(), "15 records", state.rows(now=None), state.rates)
    screen = Console(width=120, height=20, record=True, file=io.StringIO(), color_system=None)
    screen.print(monitor._table(snapshot, "", screen=screen))
    head, *rows = [line for line in screen.export_text().splitlines() if "│" in line or "┃" in line]
    names = [cell.strip() for cell in head.split("┃")]
    assert names[:6] == ["sender", "type", "id", "count", "rate/s", "errors"]
    for line in rows:
        cells = line.split("│")
        for name, cell in zip(names, cells, strict=False):
            text = cell.strip(" ")
            if name in ("sender", "type"):
                assert cell.startswith(text) or cell.startswith(f" {text}"), (name, line)
            elif name in ("id", "count", "rate/s", "errors"):
                assert cell.endswith(text) or cell.endswith(f"{text} "), (name, line)
    counts = [line.split("│")[3] for line in rows]
    assert [c.strip() for c in counts] == ["12", "3"]
    assert len({len(c.rstrip()) for c in counts}) == 1  # the digits end in one column
