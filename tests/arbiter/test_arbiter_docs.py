"""The docs generators draw from the model's own tables and functions."""

from __future__ import annotations

from docgen import arbiter as docs

from veronte4x.arbiter import AUTOPILOT_TRANSITIONS, TRANSITIONS


def test_state_diagram_has_every_transition() -> None:
    text = docs.state_diagram()
    assert text.startswith("```mermaid\nstateDiagram-v2\n") and text.endswith("\n```")
    assert "    [*] --> IDLE" in text
    for (source, event), target in TRANSITIONS.items():
        assert f"    {source.name} --> {target.name}: {event.value}" in text
    assert text.count("-->") == len(TRANSITIONS) + 1


def test_autopilot_diagram_has_every_transition() -> None:
    text = docs.autopilot_diagram()
    for (source, event), target in AUTOPILOT_TRANSITIONS.items():
        assert f"    {source.name} --> {target.name}: {event.value}" in text
    assert not any(source.name == "DEAD" for source, _ in AUTOPILOT_TRANSITIONS)


def test_seed_example_table() -> None:
    lines = docs.seed_example().splitlines()
    assert len(lines) == 2 + 9
    assert lines[2] == (
        "| AP1 | 1 | Roll | Relative | 0.12 | 0.0967 | 0.0233 | 1 | 0.0233 | **0.0570** | 0.058 |"
    )
    assert lines[5].startswith("| AP2 |") and "**0.0257** | 0.026 |" in lines[5]
    assert lines[10] == "|  | 3 | GNSS 1 Accuracy | Absolute | 1.5 |  |  | 0.01 | 0.0150 |  |  |"


def test_config_defaults_and_replay_example() -> None:
    table = docs.config_defaults()
    assert "| `autopilot_ids` | `(8, 9, 10, 11)` |" in table
    assert "| `method` | `ALWAYS_BEST` |" in table
    example = docs.replay_example()
    assert "AP2 -> AP3: AP2 is dead: AP3 (best score 0.015)" in example
    assert "DISAGREES   selected: recorded AP2, model AP3 (1.750-1.750 s, 1 frame(s))" in example
