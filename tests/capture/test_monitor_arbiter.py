"""The monitor's arbiter line (selection, arbitration, mode, alive and ready flags, scores)
and a capture without timestamps (candump's human view without ``-t``): no rate, no span,
no timing, errors counted on the row of their CAN ID."""

from __future__ import annotations

import dataclasses
from pathlib import Path

from veronte4x import capture, codec
from veronte4x.capture.busmap import Role
from veronte4x.capture.monitor import ArbiterView, MonitorState, render_text
from veronte4x.capture.records import Record

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "capture.log"
FLAGS = {f.name: True for f in dataclasses.fields(codec.Status) if f.name.endswith("_ok")}
"""Every check of a Status passed."""


def _arbiter(stamp: float, message: codec.Status | codec.Score) -> Record:
    return Record(stamp, "can0", 0xFF, Role.ARBITER, None, None, message, None, "", b"")


def _status(normal_mode: bool | None, arbitrating: bool = True) -> codec.Status:
    alive = (True, False, True, True)
    ready = (False, False, True, True)
    return codec.Status(2, arbitrating, alive, ready, **FLAGS, normal_mode=normal_mode)


def test_the_arbiter_line_of_the_example_capture() -> None:
    state = MonitorState()
    for record in capture.read(EXAMPLE):
        state.add(record)
    assert render_text(state).splitlines()[:2] == [
        "arbiter: selected AP2, arbitration on; alive AP1 AP2 AP3 -; ready AP1 AP2 AP3 -; "
        "scores AP1 0.058 AP2 0.026 AP3 0.054",  # a CEX-form Status: no mode bit
        "39 records, 1 bad, 0.501 s",
    ]


def test_the_mode_and_arbitration_off_are_said() -> None:
    state = MonitorState()
    state.add(_arbiter(1.0, _status(normal_mode=True)))
    assert state.arbiter.describe() == (
        "arbiter: selected AP3, arbitration on, normal mode; alive AP1 - AP3 external; "
        "ready - - AP3 external"
    )
    state.add(_arbiter(1.5, codec.Score(autopilot=3, score=0.25)))
    state.add(_arbiter(1.6, codec.Score(autopilot=0, score=0.0625)))
    state.add(_arbiter(2.0, _status(normal_mode=False, arbitrating=False)))
    assert state.arbiter.describe() == (
        "arbiter: selected AP3, arbitration OFF, MAINTENANCE mode; alive AP1 - AP3 external; "
        "ready - - AP3 external; scores AP1 0.0625 external 0.25"
    )


def test_scores_before_any_status() -> None:
    assert ArbiterView(None, ()).describe() == "arbiter: no Status yet"
    state = MonitorState()
    state.add(_arbiter(0.0, codec.Score(autopilot=1, score=0.5)))
    assert state.arbiter.describe() == "arbiter: no Status yet; scores AP2 0.5"


def test_a_capture_without_timestamps(tmp_path: Path) -> None:
    """Candump's human view without ``-t`` has no time: counts and errors are shown, no
    rate, span or timing is made up."""
    path = tmp_path / "untimed.log"
    path.write_text(
        "  can0  009   [3]  00 FF 01\n"
        "  can0  009   [3]  00 FF 00\n"
        "  can0  009   [1]  04\n"  # a bad frame on AP2's ID: counted on its Ready row
        "  can0  00A   [2]  04 01\n"  # AP3 has sent nothing good: a row of its error
    )
    state = MonitorState(rates=True)
    for record in capture.read(path):
        state.add(record)
    assert (state.first_timestamp, state.last_timestamp) == (None, None)
    assert [(r.sender, r.kind, r.count, r.errors, r.rate, r.last_seen) for r in state.rows()] == [
        ("AP2", "Ready", 2, 1, 0.0, None),
        ("AP3", "error: unknown command", 0, 1, 0.0, None),
    ]
    assert render_text(state).splitlines() == [
        "arbiter: no Status yet",
        "4 records, 2 bad",
        "sender  type                          id    count   rate/s  period  jitter  gap  state"
        "  errors  fields",
        "AP2     Ready                        009        2      0.0       -       -    -"
        "              1  ready=False",
        "AP3     error: unknown command       00A        0      0.0       -       -    -"
        "              1",
    ]


def test_the_filter_keeps_rows_whose_sender_or_type_holds_it_in_any_case() -> None:
    state = MonitorState()
    for record in capture.read(EXAMPLE):
        state.add(record)
    assert [(r.sender, r.kind) for r in state.rows("ap2")] == [
        ("AP2", "ArbitrationVariable"),
        ("AP2", "PwmSet"),
        ("AP2", "Ready"),
    ]
    assert [(r.sender, r.kind) for r in state.rows("READY")] == [
        ("AP1", "Ready"),
        ("AP2", "Ready"),
        ("AP3", "Ready"),
    ]
    assert state.rows("no such row") == []
    lines = render_text(state, "status").splitlines()
    assert [line.split()[:2] for line in lines[3:]] == [["arbiter", "Status"]]
