"""Messages as flat dicts of their fields, the keys of `veronte4x.capture.fields`.

Tuples become ``name_0``, ``name_1``...; nested dataclasses (DroneCAN structs, a union's
member) flatten with dots (``status.uptime_sec``, ``value.value``), and an array of structs
or unions item by item (``commands_0.actuator_id``). What each leaf becomes is the
caller's (`Leaf`): its value for `veronte4x.capture.fields`, its readable form for
`veronte4x.capture.readable.readable_fields`.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable
from typing import Any

Leaf = Callable[[type, str, Any], Any]
"""A leaf's value from the class that holds it, its attribute name and its value."""

_FIELD_NAMES: dict[type, tuple[str, ...]] = {}


def field_names(cls: type) -> tuple[str, ...]:
    """A dataclass's field names, in order."""
    names = _FIELD_NAMES.get(cls)
    if names is None:  # dataclasses.fields() is slow: once per class
        names = _FIELD_NAMES[cls] = tuple(f.name for f in dataclasses.fields(cls))
    return names


def is_message(value: Any) -> bool:
    """Whether ``value`` is a message (a dataclass instance, not a class)."""
    return dataclasses.is_dataclass(value) and not isinstance(value, type)


def flatten(message: Any, leaf: Leaf) -> dict[str, Any]:
    """A message's fields as a flat dict, each leaf through ``leaf``; empty for anything
    that is no message."""
    out: dict[str, Any] = {}
    if is_message(message):
        _walk(message, "", leaf, out)
    return out


def _walk(message: Any, prefix: str, leaf: Leaf, out: dict[str, Any]) -> None:
    owner = type(message)
    for attr in field_names(owner):
        value = getattr(message, attr)
        name = prefix + attr
        if type(value) is tuple:
            for index, item in enumerate(value):
                if is_message(item):  # an array of structs or unions
                    _walk(item, f"{name}_{index}.", leaf, out)
                else:
                    out[f"{name}_{index}"] = leaf(owner, attr, item)
        elif is_message(value):
            _walk(value, name + ".", leaf, out)
        else:
            out[name] = leaf(owner, attr, value)
