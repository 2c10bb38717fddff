"""Markdown for the "Captures and CLI" page, from `veronte4x.units`."""

from __future__ import annotations

from veronte4x.units import UNIT_NAMES, UNITS


def units_table() -> str:
    """Every field with a unit: message, field, unit symbol and its name."""
    rows = [
        f"| `{message}` | `{field}` | {symbol} | {UNIT_NAMES[symbol]} |"
        for message, fields in UNITS.items()
        for field, symbol in fields.items()
    ]
    return "\n".join(["| message | field | unit | |", "|---|---|---|---|", *rows])
