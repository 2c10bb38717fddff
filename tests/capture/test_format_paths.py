"""`format_message`'s short ways for int, bool and float fields, and its units looked up
once per class, give the text of the one general way (kept here as it was): every message
of the demo vehicle bus (DroneCAN types with nested structures, arrays, enums and
units), the demo flight and the test captures."""

from __future__ import annotations

import runpy
from pathlib import Path
from typing import Any

import pytest

from veronte4x import capture
from veronte4x.capture.flat import field_names, is_message
from veronte4x.capture.readable import format_message
from veronte4x.units import unit
from veronte4x.values import shown, text_fields

ROOT = Path(__file__).resolve().parents[2]


def general(message: Any, top: str = "", prefix: str = "") -> str:
    """`format_message` as one general path: every value through ``shown``."""
    top = top or type(message).__name__
    owner = type(message)
    parts = []
    for attr in field_names(owner):
        value = getattr(message, attr)
        if is_message(value):
            text = general(value, top, f"{prefix}{attr}.")
        elif type(value) is tuple:
            items = (
                general(item, top, f"{prefix}{attr}.")
                if is_message(item)
                else scalar(owner, attr, item)
                for item in value
            )
            text = "(" + ", ".join(items) + ")"
        else:
            text = scalar(owner, attr, value)
            symbol = unit(top, prefix + attr)
            if symbol is not None:
                text = f"{text} {symbol}"
        parts.append(f"{attr}={text}")
    return f"{owner.__name__}({', '.join(parts)})"


def scalar(owner: type, attr: str, value: Any) -> str:
    text = shown(owner, attr, value)
    if type(value) is bytes and attr in text_fields(owner):
        return repr(text)
    if type(value) is bytes and not value:
        return "(none)"
    return str(text)


@pytest.fixture(scope="module")
def captures(tmp_path_factory: pytest.TempPathFactory) -> list[Path]:
    folder = tmp_path_factory.mktemp("formats")
    vehicle, flight = folder / "vehicle.log", folder / "flight.log"
    runpy.run_path(str(ROOT / "examples" / "make_vehicle_bus.py"))["write"](vehicle, 3.0)
    runpy.run_path(str(ROOT / "examples" / "make_capture.py"))["generate"](1 / 3, 10.0, 4).write(
        flight
    )
    return [vehicle, flight, ROOT / "examples" / "capture.log", ROOT / "tests/capture/data/odd.log"]


def test_every_message_has_the_general_text(captures: list[Path]) -> None:
    kinds = set()
    for path in captures:
        for record in capture.read(path):
            if record.message is not None:
                assert format_message(record.message) == general(record.message)
                kinds.add(type(record.message))
    assert len(kinds) > 20
