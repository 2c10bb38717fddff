"""Convert messages to and from plain Python data (for JSON, logs, data frames)."""

from __future__ import annotations

import enum
import weakref
from typing import Any, TypeVar

from veronte4x.dronecan.definitions import DATA_TYPES, VALUE
from veronte4x.dronecan.schema import Array, Struct, Union
from veronte4x.dronecan.serializer import enum_table
from veronte4x.dronecan.transfer import Transfer
from veronte4x.dronecan.typeset import TypeSet, types_or_default
from veronte4x.errors import EncodeError, argument_type_error

T = TypeVar("T")


def _structs(t: Any, found: dict[type, Struct]) -> dict[type, Struct]:
    if isinstance(t, Struct):
        found[t.cls] = t
        for f in t.fields:
            _structs(f.type, found)
    elif isinstance(t, Union):
        for member in t.members:
            _structs(member.type, found)
    elif isinstance(t, Array):
        _structs(t.item, found)
    return found


_STRUCTS: dict[type, Struct] = {}
for _data_type in DATA_TYPES:
    _structs(_data_type.schema, _STRUCTS)
assert isinstance(VALUE, Union)
_MEMBERS = {member.cls for member in VALUE.members if not isinstance(member.type, Struct)}
_VENDOR_STRUCTS: weakref.WeakKeyDictionary[TypeSet, dict[type, Struct]] = (
    weakref.WeakKeyDictionary()
)


def _structs_of(types: TypeSet | None, where: str) -> dict[type, Struct]:
    """The struct schema of every class of a type set (nested types included)."""
    found = types_or_default(types, where)
    if found is TypeSet.standard():
        return _STRUCTS
    structs = _VENDOR_STRUCTS.get(found)
    if structs is None:
        structs = _VENDOR_STRUCTS[found] = dict(_STRUCTS)
        for data_type in found.data_types:
            _structs(data_type.schema, structs)
    return structs


def _convert(value: Any, t: Any) -> Any:
    if isinstance(t, Struct):
        return {f.name: _convert(getattr(value, f.name), f.type) for f in t.fields if f.name}
    if isinstance(t, Union):
        member = next((m for m in t.members if m.cls is value.__class__), None)
        if member is None:
            return value
        inner = value if isinstance(member.type, Struct) else value.value
        return {member.name: _convert(inner, member.type)}
    if isinstance(t, Array):
        if isinstance(t.item, (Struct, Union)):
            return [_convert(item, t.item) for item in value]
        return list(value)
    if isinstance(value, enum.Enum):
        return value.value
    return value


def to_builtin(value: Any, types: TypeSet | None = None) -> Any:
    """Return ``value`` as plain dicts, lists, ints, floats and bools.

    Structs become dicts keyed by DSDL field names (void fields left out), unions one-key
    dicts ``{member_name: value}`` (``{"empty": {}}`` for an empty value), byte and int
    arrays lists of ints, enums their int value. A `Transfer`
    becomes a dict of its fields with the message converted. Anything else is returned as is.

    Args:
        value: A message, a `Transfer`, or anything else.
        types: The `TypeSet` that knows the classes; None for the default set.
    """
    schema = _STRUCTS.get(type(value))
    if schema is None and types is not TypeSet.standard():
        schema = _structs_of(types, "to_builtin").get(type(value))
    if schema is not None:
        return _convert(value, schema)
    if type(value) in _MEMBERS:
        return _convert(value, VALUE)
    if isinstance(value, Transfer):
        out = value._asdict()
        out["message"] = to_builtin(value.message, types)
        out["kind"] = value.kind.name.lower()
        return out
    if isinstance(value, enum.Enum):
        return value.value
    return value


def _build(t: Any, data: Any, enum: type | None, path: str) -> Any:
    if isinstance(t, Struct):
        if not isinstance(data, dict):
            raise EncodeError(t.name, path, data, "a dict")
        values = {
            f.name: _build(f.type, data[f.name], f.enum, f.name)
            for f in t.fields
            if f.name and f.name in data
        }
        return t.cls(**values)
    if isinstance(t, Union):
        if not isinstance(data, dict) or len(data) != 1:
            raise EncodeError(t.name, path, data, "a one-key dict {member: value}")
        ((name, inner),) = data.items()
        for member in t.members:
            if member.name == name:
                value = _build(member.type, inner, None, name)
                return value if isinstance(member.type, Struct) else member.cls(value)
        raise EncodeError(t.name, path, data, ", ".join(mb.name for mb in t.members))
    if isinstance(t, Array):
        if t.is_bytes:
            try:
                return bytes(data.encode() if isinstance(data, str) else data)
            except (TypeError, ValueError):
                raise EncodeError(t.dsdl, path, data, "byte values 0..255") from None
        if isinstance(t.item, (Struct, Union)):
            return tuple(_build(t.item, item, None, f"{path}[{i}]") for i, item in enumerate(data))
        return tuple(data)
    if enum is not None and isinstance(data, int):
        return enum_table(enum, t.bits)[data] if 0 <= data < 1 << t.bits else data
    return data


def from_builtin(cls: type[T], data: dict[str, Any], types: TypeSet | None = None) -> T:
    """Build a message of class ``cls`` from plain data, the inverse of `to_builtin`.

    Missing keys take the class defaults; a ``str`` is accepted for a uint8 array (UTF-8).
    No range check is made here: `encode` does that.

    Args:
        cls: The class to build.
        data: Plain data, as `to_builtin` gives.
        types: The `TypeSet` that knows ``cls``; None for the default set.

    Raises:
        EncodeError: The data does not have the shape of ``cls``.
        TypeError: ``cls`` is not a DroneCAN message class, or ``data`` not a dict.
    """
    schema = _structs_of(types, "from_builtin").get(cls) if isinstance(cls, type) else None
    if schema is None:
        raise argument_type_error("from_builtin", "cls", "a DroneCAN message class", cls)
    if not isinstance(data, dict):
        raise argument_type_error("from_builtin", "data", "a dict", data)
    try:
        built: T = _build(schema, data, None, "")
    except (KeyError, TypeError) as error:
        raise EncodeError(
            schema.name, "", data, f"the fields of {cls.__name__} ({error})"
        ) from None
    return built
