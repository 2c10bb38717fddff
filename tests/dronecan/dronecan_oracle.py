"""Bridges to the ``dronecan`` package, the reference implementation (tests only)."""

from __future__ import annotations

from typing import Any

import dronecan as dc
from dronecan import transport
from veronte4x import dronecan as v4
from veronte4x.dronecan.definitions import DATA_TYPES

KINDS = {
    "message": v4.TransferKind.MESSAGE,
    "request": v4.TransferKind.REQUEST,
    "response": v4.TransferKind.RESPONSE,
}

CLASS_OF = {(t.full_name, t.kind): t.schema.cls for t in DATA_TYPES}


def reference_object(full_name: str, kind: v4.TransferKind, fields: dict[str, Any]) -> Any:
    """A ``dronecan`` message/request/response object filled from plain data."""
    data_type = dc.TYPENAMES[full_name]
    if kind is v4.TransferKind.MESSAGE:
        obj = data_type()
    else:
        obj = data_type(_mode="request" if kind is v4.TransferKind.REQUEST else "response")
    _fill(obj, fields)
    return obj


def _fill(obj: Any, fields: dict[str, Any]) -> None:
    for name, value in fields.items():
        if isinstance(value, dict):
            inner = getattr(obj, name)
            if dc.is_union(inner):
                ((member, member_value),) = value.items()
                if isinstance(member_value, dict):
                    _fill(getattr(inner, member), member_value)
                else:
                    setattr(inner, member, member_value)
            else:
                _fill(inner, value)
        elif isinstance(value, list) and value and isinstance(value[0], dict):
            array = getattr(obj, name)
            del array[:]
            for item_fields in value:
                item = array.new_item()
                _fill(item, item_fields)
                array.append(item)
        elif isinstance(value, list) and isinstance(getattr(obj, name), transport.ArrayValue):
            array = getattr(obj, name)
            if len(array) and len(array) == len(value):  # a static array: fill in place
                for i, item in enumerate(value):
                    array[i] = item
            else:
                setattr(obj, name, value)
        else:
            setattr(obj, name, value)


def reference_builtin(obj: Any) -> Any:
    """Plain data of a ``dronecan`` object, shaped as :func:`veronte4x.dronecan.to_builtin`."""
    if isinstance(obj, transport.CompoundValue):
        if dc.is_union(obj):
            member = dc.get_active_union_field(obj) or next(iter(dc.get_fields(obj)))
            return {member: reference_builtin(dc.get_fields(obj)[member])}
        return {
            name: reference_builtin(value)
            for name, value in dc.get_fields(obj).items()
            if not name.startswith("_void")
        }
    if isinstance(obj, transport.ArrayValue):
        return [reference_builtin(item) for item in obj]
    if isinstance(obj, transport.PrimitiveValue):
        return obj.value
    return obj


def reference_frames(
    obj: Any,
    source: int,
    destination: int | None,
    transfer_id: int,
    priority: int,
    kind: v4.TransferKind,
) -> list[tuple[int, bytes]]:
    """Frames of ``obj`` as the ``dronecan`` package builds them."""
    t = transport.Transfer(
        transfer_id=transfer_id,
        source_node_id=source,
        dest_node_id=destination,
        payload=obj,
        transfer_priority=priority,
        service_not_message=kind is not v4.TransferKind.MESSAGE,
        request_not_response=kind is v4.TransferKind.REQUEST,
    )
    return [(f.message_id, bytes(f.bytes)) for f in t.to_frames()]


def reference_decode(frames: list[tuple[int, bytes]]) -> Any:
    """Decode frames with the ``dronecan`` package; return its payload object."""
    t = transport.Transfer()
    t.from_frames([transport.Frame(can_id, data) for can_id, data in frames])
    return t.payload
