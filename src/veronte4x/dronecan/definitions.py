"""The standard DroneCAN types as data: fields in wire order, ids, signatures.

Everything here was compiled ahead of time from the DSDL of the standard ``uavcan``
namespace shipped with the package, into `veronte4x.dronecan.standard_data` (field lists,
default data type ids, and the 64-bit data type signatures, computed from the normalized
definitions as the DroneCAN specification (section "Data type signature") defines them):
importing parses no DSDL. The classes are those of `veronte4x.dronecan.standard`. The
serializers run from these definitions; the docs tables are generated from them too.
"""

from __future__ import annotations

from veronte4x.dronecan import standard_data
from veronte4x.dronecan.can_id import TransferKind
from veronte4x.dronecan.schema import DataType, Struct, Union

__all__ = ["DATA_TYPES", "NESTED_SIGNATURES", "NUMERIC_VALUE", "RAW_COMMAND", "VALUE", "DataType"]

_FIRST = (
    "uavcan.protocol.NodeStatus",
    "uavcan.equipment.esc.Status",
    "uavcan.equipment.device.Temperature",
    "uavcan.equipment.esc.RawCommand",
    "uavcan.protocol.GetNodeInfo",
    "uavcan.protocol.param.GetSet",
    "uavcan.protocol.RestartNode",
    "uavcan.protocol.file.BeginFirmwareUpdate",
    "uavcan.protocol.param.ExecuteOpcode",
    "uavcan.protocol.file.GetInfo",
    "uavcan.protocol.file.Read",
)
"""The types of Vertiq's DroneCAN support document in its order, then the ground
station's: they keep the first places (and indexes) they had before the DSDL compiler."""


def _order(t: DataType) -> tuple[int, str, int]:
    first = _FIRST.index(t.full_name) if t.full_name in _FIRST else len(_FIRST)
    return first, t.full_name, t.kind.value


DATA_TYPES: tuple[DataType, ...] = tuple(sorted(standard_data.DATA_TYPES, key=_order))
"""Every top-level type of the standard set (messages, requests and responses): those of
Vertiq's DroneCAN support document first, then the ground station's, then the rest by
full name."""

FAST_MODULES: dict[tuple[str, TransferKind], str] = {
    (t.full_name, t.kind): module
    for t, module in zip(standard_data.DATA_TYPES, standard_data.FAST_MODULES, strict=True)
}
"""The module of the fast paths of each of `DATA_TYPES` (`veronte4x.dronecan.fast`), by
full name and kind."""

NESTED_SIGNATURES: dict[str, int] = standard_data.NESTED_SIGNATURES
"""Signatures of the nested types (documentation only: they do not appear on the wire)."""


def _schema(full_name: str, kind: TransferKind = TransferKind.MESSAGE) -> Struct:
    return next(t.schema for t in DATA_TYPES if t.full_name == full_name and t.kind is kind)


RAW_COMMAND = _schema("uavcan.equipment.esc.RawCommand")
"""``uavcan.equipment.esc.RawCommand``."""

_GET_SET_RESPONSE = _schema("uavcan.protocol.param.GetSet", TransferKind.RESPONSE)
_VALUE, _NUMERIC_VALUE = _GET_SET_RESPONSE.fields[1].type, _GET_SET_RESPONSE.fields[5].type
assert isinstance(_VALUE, Union) and isinstance(_NUMERIC_VALUE, Union)
VALUE: Union = _VALUE
"""The union ``uavcan.protocol.param.Value``."""
NUMERIC_VALUE: Union = _NUMERIC_VALUE
"""The union ``uavcan.protocol.param.NumericValue``."""
