"""Markdown for the docs, generated from the model's own definitions.

Each function is named in a ``<!-- generate: docgen.arbiter:function -->`` marker of
a docs page; the docs hook puts its result there.
"""

from __future__ import annotations

import dataclasses
import enum
from collections.abc import Collection

from veronte4x import codec
from veronte4x.arbiter.config import ArbiterConfig, VariableConfig, autopilot_name
from veronte4x.arbiter.machine import AUTOPILOT_TRANSITIONS, TRANSITIONS
from veronte4x.arbiter.replay import replay
from veronte4x.arbiter.scores import compute_scores, explain_scores

#: The seed's arbitration example (seed 003, "Arbitration Example"): roll and pitch
#: relative with weight 1, GNSS 1 accuracy absolute with weight 0.01.
SEED_EXAMPLE_NAMES = ("Roll", "Pitch", "GNSS 1 Accuracy")
SEED_EXAMPLE_VARIABLES = (
    VariableConfig(weight=1.0, absolute=False),
    VariableConfig(weight=1.0, absolute=False),
    VariableConfig(weight=0.01, absolute=True),
)
SEED_EXAMPLE_VALUES = {0: [0.12, 0.30, 1.7], 1: [0.10, 0.28, 1.9], 2: [0.07, 0.27, 1.5]}
#: The totals the seed's table prints.
SEED_EXAMPLE_TOTALS = {0: 0.058, 1: 0.026, 2: 0.054}


def _diagram(
    transitions: Collection[tuple[tuple[enum.Enum, enum.Enum], enum.Enum]], first: str
) -> str:
    states: dict[str, str] = {}
    for (source, _), target in transitions:
        states.setdefault(source.name, str(source.value))
        states.setdefault(target.name, str(target.value))
    lines = ["```mermaid", "stateDiagram-v2"]
    lines += [f'    state "{label}" as {name}' for name, label in states.items()]
    lines.append(f"    [*] --> {first}")
    lines += [
        f"    {source.name} --> {target.name}: {event.value}"
        for (source, event), target in transitions
    ]
    lines.append("```")
    return "\n".join(lines)


def state_diagram() -> str:
    """The arbiter's phases, drawn from `veronte4x.arbiter.machine.TRANSITIONS`."""
    return _diagram(TRANSITIONS.items(), "IDLE")


def autopilot_diagram() -> str:
    """One autopilot's phases, drawn from `AUTOPILOT_TRANSITIONS`."""
    return _diagram(AUTOPILOT_TRANSITIONS.items(), "WAITING")


def seed_example() -> str:
    """The seed's example worked through by `explain_scores`, in the seed table's layout."""
    rows = explain_scores(SEED_EXAMPLE_VALUES, SEED_EXAMPLE_VARIABLES)
    totals = compute_scores(SEED_EXAMPLE_VALUES, SEED_EXAMPLE_VARIABLES)
    lines = [
        "| Autopilot | Var. | Variable | Type | Value | Mean | Deviation | Weight "
        "| Contribution | Total score | Manual's total |",
        "|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for row in rows:
        variable = SEED_EXAMPLE_VARIABLES[row.number]
        first = row.number == 0
        mean = "" if row.mean is None else f"{row.mean:.4f}"
        deviation = "" if row.mean is None else f"{row.error:.4f}"
        lines.append(
            f"| {autopilot_name(row.autopilot) if first else ''} | {row.number + 1} "
            f"| {SEED_EXAMPLE_NAMES[row.number]} "
            f"| {'Absolute' if variable.absolute else 'Relative'} | {row.value:g} | {mean} "
            f"| {deviation} | {variable.weight:g} | {row.contribution:.4f} "
            f"| {f'**{totals[row.autopilot]:.4f}**' if first else ''} "
            f"| {SEED_EXAMPLE_TOTALS[row.autopilot] if first else ''} |"
        )
    return "\n".join(lines)


def config_defaults() -> str:
    """`ArbiterConfig`'s fields and their defaults."""
    lines = ["| Field | Default |", "|---|---|"]
    for item in dataclasses.fields(ArbiterConfig):
        default = item.default
        shown = default.name if isinstance(default, enum.Enum) else repr(default)
        lines.append(f"| `{item.name}` | `{shown}` |")
    return "\n".join(lines)


def _example_status(selected: int, alive: tuple[bool, bool, bool, bool]) -> bytes:
    everything_ok = dict.fromkeys(
        (item.name for item in dataclasses.fields(codec.Status)[4:]), True
    )
    ready = (True, True, True, False)
    return codec.encode(codec.Status(selected, True, alive, ready, **everything_ok))


def example_capture() -> list[tuple[float, int, bytes]]:
    """A made-up capture for the replay how-to: the seed example's three autopilots send
    every 0.05 s; AP2 falls silent from 1.55 s; the recorded arbiter reports the switch
    one Status late (at 2.0 s instead of 1.75 s)."""
    frames: list[tuple[float, int, bytes]] = []
    before = _example_status(1, (True, True, True, False))
    after = _example_status(2, (True, False, True, False))
    ready = codec.encode(codec.Ready(True))
    for tick in range(61):
        time = round(tick * 0.05, 9)
        for autopilot, can_id in enumerate((8, 9, 10)):
            if autopilot == 1 and time >= 1.55:
                continue
            frames.append((time, can_id, ready))
            for number, value in enumerate(SEED_EXAMPLE_VALUES[autopilot]):
                message = codec.ArbitrationVariable(number, value)
                frames.append((time, can_id, codec.encode(message)))
        if tick % 5 == 0:
            frames.append((time, 255, before if time < 2.0 else after))
    return frames


def replay_example() -> str:
    """The timeline `replay` gives for `example_capture`, as a text block."""
    config = ArbiterConfig(variables=SEED_EXAMPLE_VARIABLES)
    result = replay(example_capture(), config)
    return f"```text\n{result.timeline()}\n```"
