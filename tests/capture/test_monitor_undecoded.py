"""The monitor over a shared bus: frames outside the bus map (another 11-bit CAN ID, a
DroneCAN data type with no codec) get a row each, by what they are, with their bytes as
``decode`` shows them; the decoded rows are unchanged. It raised ``TypeError`` on the first
one (``veronte4x monitor`` of any bus carrying foreign traffic ended in a traceback)."""

from __future__ import annotations

from pathlib import Path

from veronte4x import capture
from veronte4x.capture.monitor import MonitorState, render_text

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "capture.log"
FOREIGN = (
    "(1763737200.100000) can0 123#0102\n"
    "(1763737200.200000) can0 123#0304\n"
    "(1763737200.300000) can0 104E2815#01C0\n"  # data type 20008 (none shipped), node 21
)


def test_foreign_frames_get_a_row_each(tmp_path: Path) -> None:
    mixed = tmp_path / "mixed.log"
    mixed.write_text(EXAMPLE.read_text(encoding="utf-8") + FOREIGN, encoding="utf-8")
    state, alone = MonitorState(), MonitorState()
    for record in capture.read(mixed):
        state.add(record)
    for record in capture.read(EXAMPLE):
        alone.add(record)
    rows = state.rows()
    foreign = [(r.sender, r.kind, r.can_id, r.count, r.errors, r.fields) for r in rows[-2:]]
    assert foreign == [
        ("node 21", "DroneCAN data type 20008", 0x104E2815, 1, 0, "[01 c0]"),
        ("unknown", "11-bit CAN ID 0x123", 0x123, 2, 0, "[03 04]"),
    ]
    assert [(r.sender, r.kind, r.count, r.fields) for r in rows[:-2]] == [
        (r.sender, r.kind, r.count, r.fields) for r in alone.rows()
    ]
    assert state.summary() == "42 records, 1 bad, 0.501 s"
    lines = render_text(state, "unknown").splitlines()
    assert lines[2:] == [
        "sender   type                       id    count   rate/s  errors  fields",
        "unknown  11-bit CAN ID 0x123       123        2     10.0       0  [03 04]",
    ]
