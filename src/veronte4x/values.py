"""One field's value as machines and people read it, from the facts its class carries.

A field's Python annotation cannot say everything a reader needs: a ``float`` may be a
float16, a float32 or a float64 on the wire, and ``bytes`` may be text. A message class says
so in class attributes, each a frozenset of attribute names (absent when empty):

- ``_FLOAT16_FIELDS_``, ``_FLOAT32_FIELDS_``: the floats the DroneCAN DSDL or the Veronte
  layout declares ``float16`` or ``float32``; every other float is a float64 (a DBC signal,
  a scaled Veronte field);
- ``_TEXT_FIELDS_``: the ``bytes`` attributes that hold text
  (`veronte4x.dronecan.generate.is_text`);
- ``_NAMED_FIELDS_`` (a mapping, not a frozenset): the integer attributes whose values have
  names, to those names by value: a Veronte message's autopilot index (Status ``selected``,
  Score ``autopilot``) to `veronte4x.codec.layouts.AUTOPILOTS`, the one home of the names.

`veronte4x.dronecan.generate` writes the first three in the body of every DroneCAN class
it generates (ahead of time or at run time), and
`veronte4x.codec.compiler.FrameLayout` on the Veronte messages it lays out (the names end
in an underscore, as nunavut's generated metadata does, so no DSDL name can collide). Since
the facts are on the class, showing a message (`veronte4x.display`) loads nothing of the
type system that made it.

The rules for numbers are those of `veronte4x.numbers`. `veronte4x.capture.readable` gives
the same functions, with the ones for whole messages.
"""

from __future__ import annotations

import enum
from typing import Any

from veronte4x.numbers import exact, for_people

__all__ = ["float_bits", "name_of", "readable", "shown", "text_fields"]

_NONE: frozenset[str] = frozenset()


def text_fields(owner: type) -> frozenset[str]:
    """The attributes of a message class that hold text (its ``_TEXT_FIELDS_``)."""
    found: frozenset[str] = getattr(owner, "_TEXT_FIELDS_", _NONE)
    return found


def name_of(owner: type, attr: str, value: Any) -> str | None:
    """The name of an integer field's value, where its class gives names (its
    ``_NAMED_FIELDS_``): ``AP2`` for a Status whose ``selected`` is 1; else None.

    Examples:
        >>> from veronte4x import codec
        >>> name_of(codec.Status, "selected", 1), name_of(codec.Score, "score", 1)
        ('AP2', None)
    """
    names = getattr(owner, "_NAMED_FIELDS_", {}).get(attr)
    if names is None or type(value) is not int or not 0 <= value < len(names):
        return None
    name: str = names[value]
    return name


def float_bits(owner: type, attr: str) -> int:
    """The declared width of a float field, 16, 32 or 64 bits: float16 and float32 as the
    DroneCAN DSDL or the Veronte layout declares them (the class's ``_FLOAT16_FIELDS_`` and
    ``_FLOAT32_FIELDS_``); anything else is a float64.

    Examples:
        >>> from veronte4x import codec, dronecan
        >>> float_bits(codec.Score, "score"), float_bits(dronecan.EscStatus, "temperature")
        (32, 16)
    """
    if attr in getattr(owner, "_FLOAT16_FIELDS_", _NONE):
        return 16
    if attr in getattr(owner, "_FLOAT32_FIELDS_", _NONE):
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
