"""Values as people read them: shortest round-trip numbers, enums by name, text as text,
units, and times in ISO 8601.

The command line's text, JSON lines and CSV outputs are written through these functions;
`readable_fields` has the same keys as `veronte4x.capture.fields`, with readable values.
"""

from __future__ import annotations

import enum
from typing import Any

from veronte4x.capture.flat import field_names, flatten, is_message
from veronte4x.dronecan.typeset import float16_fields, text_fields
from veronte4x.numbers import shortest
from veronte4x.times import format_time
from veronte4x.units import unit

__all__ = [
    "format_message",
    "format_time",
    "hex_bytes",
    "readable",
    "readable_fields",
    "shortest",
]


def _float_bits(owner: type, attr: str) -> int:
    return 16 if attr in float16_fields(owner) else 32


def readable(owner: type, attr: str, value: Any) -> Any:
    """One field's value as people read it: an enum's name, text as ``str``, other bytes in
    hex, a float in its shortest round-trip form; ints, bools and None unchanged."""
    kind = type(value)
    if kind is int or kind is bool or value is None:  # most fields: nothing to do
        return value
    if kind is float:
        return shortest(value, _float_bits(owner, attr))
    if isinstance(value, enum.Enum):
        return value.name
    if kind is bytes:
        if attr in text_fields(owner):
            return value.decode("utf-8", "backslashreplace")
        return value.hex()
    return value


def hex_bytes(data: bytes) -> str:
    """Bytes no codec decoded, as ``decode`` and ``monitor`` show them: hex in brackets.

    Examples:
        >>> hex_bytes(bytes([1, 0xC0])), hex_bytes(b"")
        ('[01 c0]', '[]')
    """
    return f"[{data.hex(' ')}]"


def readable_fields(message: Any) -> dict[str, Any]:
    """A message's fields as a flat dict with readable values.

    The keys are those of `veronte4x.capture.fields` (tuples as ``name_0``, ``name_1``...,
    nested structures with dots); the values go through `readable`.

    Examples:
        >>> from veronte4x import codec, dronecan
        >>> readable_fields(codec.ArbitrationVariable(number=0, value=0.10000000149011612))
        {'number': 0, 'value': 0.1}
        >>> status = dronecan.NodeStatus(7, dronecan.Health.OK, dronecan.Mode.OPERATIONAL, 0, 0)
        >>> readable_fields(status)["health"]
        'OK'
    """
    return flatten(message, readable)


def format_message(message: Any) -> str:
    """A message on one line: its class, then every field as ``name=value``, with units.

    Examples:
        >>> from veronte4x import dronecan
        >>> format_message(dronecan.EscStatus(0, 16.203125, 2.5, 310.25, 1200, 40, 2))
        'EscStatus(error_count=0, voltage=16.2 V, current=2.5 A, temperature=310.2 K, \
rpm=1200 rpm, power_rating_pct=40 %, esc_index=2)'
    """
    return _format(message, type(message).__name__, "")


def _format(message: Any, top: str, prefix: str) -> str:
    owner = type(message)
    parts = []
    for attr in field_names(owner):
        value = getattr(message, attr)
        if is_message(value):
            text = _format(value, top, f"{prefix}{attr}.")
        elif type(value) is tuple:
            text = "(" + ", ".join(_item(owner, attr, item, top, prefix) for item in value) + ")"
        else:
            text = _scalar(owner, attr, value)
            symbol = unit(top, prefix + attr)
            if symbol is not None:
                text = f"{text} {symbol}"
        parts.append(f"{attr}={text}")
    return f"{owner.__name__}({', '.join(parts)})"


def _item(owner: type, attr: str, item: Any, top: str, prefix: str) -> str:
    if is_message(item):  # an array of structs or unions
        return _format(item, top, f"{prefix}{attr}.")
    return _scalar(owner, attr, item)


def _scalar(owner: type, attr: str, value: Any) -> str:
    shown = readable(owner, attr, value)
    if type(value) is bytes and attr in text_fields(owner):
        return repr(shown)
    return str(shown)
