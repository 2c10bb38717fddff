"""Values as machines and people read them: exact numbers or numbers for people (the rule of
`veronte4x.numbers`), enums by name, text as text, units, and times in ISO 8601.

The command line's JSON lines and CSV are written through `readable` (`readable_fields`:
the keys of `veronte4x.capture.fields`, exact values); its text, the monitor and the HTML
views through `shown`, which shows a float in its shortest form at the field's declared
width (`float_bits`).
"""

from __future__ import annotations

import enum
from typing import Any

from veronte4x.capture.flat import field_names, flatten, is_message
from veronte4x.codec.compiler import float32_fields as veronte_float32_fields
from veronte4x.dronecan.typeset import float16_fields, float32_fields, text_fields
from veronte4x.numbers import exact, for_people
from veronte4x.times import format_time
from veronte4x.units import unit

__all__ = [
    "float_bits",
    "format_message",
    "format_time",
    "hex_bytes",
    "readable",
    "readable_fields",
    "shown",
]


def float_bits(owner: type, attr: str) -> int:
    """The declared width of a float field, 16, 32 or 64 bits: float16 and float32 as the
    DroneCAN DSDL or the Veronte layout declares them; anything else (DBC signals, scaled
    Veronte fields) is a float64.

    Examples:
        >>> from veronte4x import codec, dronecan
        >>> float_bits(codec.Score, "score"), float_bits(dronecan.EscStatus, "temperature")
        (32, 16)
    """
    if attr in float16_fields(owner):
        return 16
    if attr in float32_fields(owner) or attr in veronte_float32_fields(owner):
        return 32
    return 64


def readable(owner: type, attr: str, value: Any) -> Any:
    """One field's value as machine formats write it: an enum's name, text as ``str``, other
    bytes in hex, a float exact (`veronte4x.numbers.exact`: non-finite ones as ``"NaN"``,
    ``"Infinity"``, ``"-Infinity"``); ints, bools and None unchanged."""
    kind = type(value)
    if kind is int or kind is bool or value is None:  # most fields: nothing to do
        return value
    if kind is float:
        return exact(value)
    if isinstance(value, enum.Enum):
        return value.name
    if kind is bytes:
        if attr in text_fields(owner):
            return value.decode("utf-8", "backslashreplace")
        return value.hex()
    return value


def shown(owner: type, attr: str, value: Any) -> Any:
    """One field's value as people read it: as `readable`, but a float in its shortest form
    at the field's declared width (`float_bits`, `veronte4x.numbers.for_people`)."""
    if type(value) is float:
        return for_people(value, float_bits(owner, attr))
    return readable(owner, attr, value)


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
    nested structures with dots); the values go through `readable`, exact.

    Examples:
        >>> from veronte4x import codec, dronecan
        >>> readable_fields(codec.ArbitrationVariable(number=0, value=0.10000000149011612))
        {'number': 0, 'value': 0.10000000149011612}
        >>> status = dronecan.NodeStatus(7, dronecan.Health.OK, dronecan.Mode.OPERATIONAL, 0, 0)
        >>> readable_fields(status)["health"]
        'OK'
    """
    return flatten(message, readable)


def format_message(message: Any) -> str:
    """A message on one line for people: its class, then every field as ``name=value``
    (`shown`), with units.

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
    text = shown(owner, attr, value)
    if type(value) is bytes and attr in text_fields(owner):
        return repr(text)
    if type(value) is bytes and not value:  # an empty array, as esc info shows one
        return "(none)"
    return str(text)
