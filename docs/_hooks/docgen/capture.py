"""Markdown for the "Captures and CLI" page: units from `veronte4x.units`, and what the
command line writes, from running it."""

from __future__ import annotations

import contextlib
import io

from veronte4x.cli import main
from veronte4x.units import UNIT_NAMES, UNITS


def units_table() -> str:
    """Every field with a unit: message, field, unit symbol and its name."""
    rows = [
        f"| `{message}` | `{field}` | {symbol} | {UNIT_NAMES[symbol]} |"
        for message, fields in UNITS.items()
        for field, symbol in fields.items()
    ]
    return "\n".join(["| message | field | unit | |", "|---|---|---|---|", *rows])


def decode_example() -> str:
    """The first lines `veronte4x decode` writes for the example capture, in each format."""
    blocks = []
    for options in ([], ["--time", "relative"], ["--output", "jsonl"]):
        lines = _decode(["examples/capture.log", *options]).splitlines()[4:8]
        command = " ".join(["veronte4x decode examples/capture.log", *options])
        blocks.append(f"`{command}`:\n\n```text\n" + "\n".join(lines) + "\n```\n")
    return "\n".join(blocks)


def _decode(arguments: list[str]) -> str:
    """Standard output of ``veronte4x decode`` with these arguments, run in this process."""
    out = io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(io.StringIO()):
        main(["decode", *arguments])
    return out.getvalue()
