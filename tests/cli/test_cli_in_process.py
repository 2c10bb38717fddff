"""What the command line does that only a subprocess or a terminal test saw before, called
in-process: the monitor's filter of its rich table, and replay's warning without
``--config``."""

from __future__ import annotations

from pathlib import Path

import pytest
from rich.console import Console

from veronte4x import capture
from veronte4x.capture.monitor import MonitorState
from veronte4x.cli import main
from veronte4x.cli.monitor import _table
from veronte4x.cli.replay import NO_CONFIG

CAPTURE = Path(__file__).resolve().parents[2] / "examples" / "capture.log"


def _shown(text_filter: str) -> tuple[list[tuple[str, str]], list[tuple[str, str]]]:
    """The (sender, type) of each row the rich table shows with ``text_filter``, and of
    every row."""
    state = MonitorState()
    for record in capture.read(CAPTURE):
        state.add(record)
    rows = state.rows()
    console = Console(width=400, record=True, color_system=None)
    console.print(_table(("arbiter", "summary", rows, False), text_filter))
    cells = [[c.strip() for c in line.split("│")] for line in console.export_text().splitlines()]
    shown = [(c[0], c[1]) for c in cells if len(c) > 2 and c[0]]
    return shown, [(r.sender, r.kind) for r in rows]


def test_the_monitor_filter_keeps_the_rows_whose_sender_or_type_holds_it() -> None:
    shown, every = _shown("")
    assert shown == every and len(every) > 3
    senders = sorted({sender for sender, _ in every})
    wanted = senders[0]
    shown, _ = _shown(wanted.upper())  # case does not matter
    assert shown == [(s, k) for s, k in every if wanted.lower() in s.lower() + k.lower()]
    assert 0 < len(shown) < len(every)
    shown, _ = _shown("no row has this")
    assert shown == []


def test_replay_without_config_warns_once(capsys: pytest.CaptureFixture[str]) -> None:
    main(["replay", str(CAPTURE)])
    assert capsys.readouterr().err.splitlines().count(NO_CONFIG) == 1


def test_replay_with_config_does_not_warn(capsys: pytest.CaptureFixture[str]) -> None:
    config = CAPTURE.parent / "arbiter.toml"
    main(["replay", str(CAPTURE), "--config", str(config)])
    assert NO_CONFIG not in capsys.readouterr().err
