"""Values as machines and people read them: exact numbers or numbers for people (the rule of
`veronte4x.numbers`), enums by name, text as text, units, and times in ISO 8601.

The command line's JSON lines and CSV are written through `readable` (`readable_fields`:
the keys of `veronte4x.capture.fields`, exact values); its text, the monitor and the HTML
views through `shown`, which shows a float in its shortest form at the field's declared
width (`float_bits`). The three read the facts a message class carries (`veronte4x.values`,
their home, below every protocol so that a message's HTML view needs no capture module).
"""

from __future__ import annotations

from typing import Any

from veronte4x.capture.flat import field_names, flatten, is_message
from veronte4x.times import format_time
from veronte4x.units import unit
from veronte4x.values import float_bits, readable, shown, text_fields

__all__ = [
    "can_id_text",
    "float_bits",
    "format_message",
    "format_time",
    "hex_bytes",
    "readable",
    "readable_fields",
    "shown",
]


def can_id_text(can_id: int, extended: bool = False) -> str:
    """A CAN ID as candump prints it: upper-case hex, 3 digits for an 11-bit ID, 8 for a
    29-bit one (``extended``, or any ID above 0x7FF) with its leading zeros (can-utils
    ``lib.c``, ``sprint_long_canframe``).

    Examples:
        >>> can_id_text(0x8), can_id_text(0x5040601), can_id_text(0x10, extended=True)
        ('008', '05040601', '00000010')
    """
    return f"{can_id:08X}" if extended or can_id > 0x7FF else f"{can_id:03X}"


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
    for attr, symbol in _plan(owner, top, prefix):
        value = getattr(message, attr)
        kind = type(value)
        if kind is int or kind is bool:  # most fields: as `_scalar` shows them, sooner
            text = f"{value}{symbol}"
        elif kind is float:
            text = f"{shown(owner, attr, value)}{symbol}"
        elif kind is tuple:
            text = "(" + ", ".join(_item(owner, attr, item, top, prefix) for item in value) + ")"
        elif is_message(value):
            text = _format(value, top, f"{prefix}{attr}.")
        else:
            text = _scalar(owner, attr, value) + symbol
        parts.append(f"{attr}={text}")
    return f"{owner.__name__}({', '.join(parts)})"


_PLANS: dict[tuple[type, str, str], tuple[tuple[str, str], ...]] = {}


def _plan(owner: type, top: str, prefix: str) -> tuple[tuple[str, str], ...]:
    """Each field of ``owner`` (within ``top`` at ``prefix``) with the text after a scalar
    value of it: its unit (`` V``) or nothing; made once per class and place."""
    key = (owner, top, prefix)
    plan = _PLANS.get(key)
    if plan is None:
        units = ((attr, unit(top, prefix + attr)) for attr in field_names(owner))
        plan = _PLANS[key] = tuple((attr, "" if u is None else f" {u}") for attr, u in units)
    return plan


def _item(owner: type, attr: str, item: Any, top: str, prefix: str) -> str:
    kind = type(item)
    if kind is int or kind is bool:
        return str(item)
    if kind is float:
        return str(shown(owner, attr, item))
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
