"""``veronte4x monitor`` readable in the terminal everyone has, 80x24 (issue 39, item 6), in
tmux as a person sees it: the narrow layout's rule (cli/monitor.py's docstring) — the
arbiter's line wrapped between its parts, narrow columns, each row's fields whole on the
line under it, the keys on the summary line; the same layout in the last table."""

from __future__ import annotations

import itertools
import re
from pathlib import Path

from tests.tmux_support import keys, needs_tmux, terminal, wait_for

CAPTURE = Path(__file__).resolve().parents[2] / "examples" / "capture.log"

pytestmark = needs_tmux


ROW = re.compile(r"(\S+ )+ *\S+ +[0-9A-F]{3} +\d+ +[\d.]+ +\d+")
"""A row's line in the narrow layout: sender, type, id, count, rate/s, err."""


def _rows(screen: str) -> list[tuple[str, str]]:
    """(row line, fields line) pairs of the narrow table on a screen (a row without fields
    has an empty line under it)."""
    lines = screen.splitlines()
    return [
        (line, below)
        for line, below in itertools.pairwise(lines)
        if ROW.fullmatch(line) and (below.startswith("  ") or not below)
    ]


def test_the_monitor_at_80x24() -> None:
    # 0.5 s of capture at a tenth of its pace: 5 s on screen, then the last table.
    with terminal("monitor", str(CAPTURE), "--speed", "0.1", width=80, height=24) as tmux:
        live = wait_for(tmux, lambda s: "scores AP1" in s and "  ready=True" in s)
        keys(tmux, "q")
        last = wait_for(tmux, lambda s: "exit=0" in s)
    lines = live.splitlines()
    # 80 characters: the arbiter's state and flags, then its scores on a line of their own.
    assert (
        lines[0]
        == "arbiter: selected AP2, arbitration on; alive AP1 AP2 AP3 -; ready AP1 AP2 AP3 -"
    )
    assert lines[1].startswith("scores AP1 ")
    summary = next(line for line in lines if " records, " in line)
    assert summary.endswith("p pause · f filter · c clear · q quit · ↑↓ scroll")
    heads = next(line for line in lines if line.startswith("sender "))
    assert heads.split() == ["sender", "type", "id", "count", "rate/s", "err"]
    rows = _rows(live)
    assert rows and len(live.splitlines()) <= 24
    assert len(rows) == (len(lines) - lines.index(heads) - 2) // 2  # two lines a row
    fields = dict((head.split()[0] + " " + head.split()[1], below.strip()) for head, below in rows)
    assert fields["AP1 Ready"] == "ready=True"
    # The last table, printed at the pane's width: the narrow layout, every row (its end
    # on screen: the pane scrolls).
    tail = [(head.split()[:3], below) for head, below in _rows(last)]
    assert (["AP3", "Ready", "00A"], "  ready=True") in tail
