"""Markdown tables for the "Simulated ESC" docs page, from the simulator's own definitions.

Each function returns Markdown for a ``<!-- generate: docgen.simulator:name -->``
line (see ``docs/_hooks/generate.py``).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import fields

from veronte4x.simulator.motor import DEFAULT_MODEL, MODEL_CONSTANT_UNITS, MotorModel
from veronte4x.simulator.parameters import PARAMETERS


def _table(header: tuple[str, ...], rows: Sequence[tuple[object, ...]]) -> str:
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(str(cell) for cell in row) + " |" for row in rows]
    return "\n".join(lines) + "\n"


def _attribute_docs() -> dict[str, str]:
    """Each `MotorModel` field's description, from the class docstring's Attributes."""
    docs: dict[str, str] = {}
    name = ""
    section = (MotorModel.__doc__ or "").split("Attributes:", 1)[1]
    for line in section.splitlines():
        text = line.strip()
        head, sep, rest = text.partition(": ")
        if sep and head in MODEL_CONSTANT_UNITS:
            name = head
            docs[name] = rest
        elif text and name:
            docs[name] += " " + text
    return docs


def model_constants_table() -> str:
    """The motor model's constants: name, default value, unit, meaning."""
    docs = _attribute_docs()
    rows = [
        (f"`{f.name}`", getattr(DEFAULT_MODEL, f.name), MODEL_CONSTANT_UNITS[f.name], docs[f.name])
        for f in fields(MotorModel)
    ]
    return _table(("constant", "default", "unit", "meaning"), rows)


def parameters_table() -> str:
    """The simulated parameters in discovery order: index, name, range, when a set applies."""
    rows = [
        (i, f"`{r.parameter.value}`", r.minimum, r.maximum, r.takes_effect)
        for i, r in enumerate(PARAMETERS)
    ]
    return _table(("index", "name", "min", "max", "a new value takes effect"), rows)
