"""The DroneCAN types veronte4x had before the DSDL compiler, under their names of before.

The eight types of Vertiq's DroneCAN support document, plus the services a ground station
needs to configure and update them (``param.ExecuteOpcode``, ``file.GetInfo``,
``file.Read``). They are the generated classes of `veronte4x.dronecan.standard` (one
definition each, from the DSDL; the names are kept by `veronte4x.dronecan.generate`'s
``HAND_NAMES``), re-exported here; import any type from `veronte4x.dronecan`.

Field names are exactly those of the DSDL files; DSDL constants are class attributes or
enums. Constructors do not validate, so decoding stays cheap; `veronte4x.dronecan.encode`
checks every field and raises `EncodeError`. uint8 arrays are ``bytes``, the int14 array
of RawCommand a tuple of ints. Unions (``param.Value`` and ``param.NumericValue``) hold
one of the member classes `Empty`, `IntegerValue`, `RealValue`, `BooleanValue` and
`StringValue`; the class says which member is set.
"""

from __future__ import annotations

from typing import TypeAlias

from veronte4x.dronecan.standard import (
    BeginFirmwareUpdateRequest,
    BeginFirmwareUpdateResponse,
    BooleanValue,
    Empty,
    EntryType,
    EntryTypeFlag,
    EscStatus,
    ExecuteOpcodeRequest,
    ExecuteOpcodeResponse,
    FileError,
    FileErrorCode,
    FileGetInfoRequest,
    FileGetInfoResponse,
    FileReadRequest,
    FileReadResponse,
    FirmwareUpdateError,
    GetNodeInfoRequest,
    GetNodeInfoResponse,
    GetSetRequest,
    GetSetResponse,
    HardwareVersion,
    Health,
    IntegerValue,
    Mode,
    NodeStatus,
    NumericValue,
    Opcode,
    Path,
    RawCommand,
    RealValue,
    RestartNodeRequest,
    RestartNodeResponse,
    SoftwareVersion,
    SoftwareVersionFlag,
    StringValue,
    Temperature,
    TemperatureErrorFlag,
    Value,
)

__all__ = [
    "BeginFirmwareUpdateRequest",
    "BeginFirmwareUpdateResponse",
    "BooleanValue",
    "Empty",
    "EntryType",
    "EntryTypeFlag",
    "EscStatus",
    "ExecuteOpcodeRequest",
    "ExecuteOpcodeResponse",
    "FileError",
    "FileErrorCode",
    "FileGetInfoRequest",
    "FileGetInfoResponse",
    "FileReadRequest",
    "FileReadResponse",
    "FirmwareUpdateError",
    "GetNodeInfoRequest",
    "GetNodeInfoResponse",
    "GetSetRequest",
    "GetSetResponse",
    "HandNamedMessage",
    "HardwareVersion",
    "Health",
    "IntegerValue",
    "Mode",
    "NodeStatus",
    "NumericValue",
    "Opcode",
    "Path",
    "RawCommand",
    "RealValue",
    "RestartNodeRequest",
    "RestartNodeResponse",
    "SoftwareVersion",
    "SoftwareVersionFlag",
    "StringValue",
    "Temperature",
    "TemperatureErrorFlag",
    "Value",
]

HandNamedMessage: TypeAlias = (
    NodeStatus
    | EscStatus
    | Temperature
    | RawCommand
    | GetNodeInfoRequest
    | GetNodeInfoResponse
    | GetSetRequest
    | GetSetResponse
    | RestartNodeRequest
    | RestartNodeResponse
    | BeginFirmwareUpdateRequest
    | BeginFirmwareUpdateResponse
    | ExecuteOpcodeRequest
    | ExecuteOpcodeResponse
    | FileGetInfoRequest
    | FileGetInfoResponse
    | FileReadRequest
    | FileReadResponse
)
"""Any top-level message, request or response class of this module: the types veronte4x
named by hand before the DSDL compiler (every other type is in `veronte4x.dronecan.standard`;
a Veronte message is a `veronte4x.codec.Message`)."""
