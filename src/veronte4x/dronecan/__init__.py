"""DroneCAN (UAVCAN v0): CAN IDs, transfers, reassembly, and every type of the standard
``uavcan`` DSDL namespace (compiled from its DSDL, `standard`), Vertiq's ESCs first."""

from __future__ import annotations

from veronte4x.dronecan import standard, vertiq
from veronte4x.dronecan.builtin import from_builtin, to_builtin
from veronte4x.dronecan.can_id import (
    CanId,
    TransferKind,
    anonymous_can_id,
    message_can_id,
    parse_can_id,
    service_can_id,
)
from veronte4x.dronecan.codec import decode_payload
from veronte4x.dronecan.frame import TransferFrame
from veronte4x.dronecan.messages import (
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
    HandNamedMessage,
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
from veronte4x.dronecan.parser import DsdlError
from veronte4x.dronecan.reassembler import (
    TRANSFER_ID_TIMEOUT,
    TRANSFER_PROBLEMS,
    Problem,
    ProblemReport,
    Problems,
    Reassembler,
)
from veronte4x.dronecan.standard import *  # noqa: F403  (every standard type, generated)
from veronte4x.dronecan.transfer import DEFAULT_PRIORITY, Transfer, decode_frames, encode
from veronte4x.dronecan.typeset import TypeSet, default_types, load_dsdl, set_default_types
from veronte4x.errors import DecodeError, EncodeError, Veronte4xError

Frame = TransferFrame  # old name, kept as an alias
Message = HandNamedMessage  # old name, kept as an alias

__all__ = [
    "DEFAULT_PRIORITY",
    "TRANSFER_ID_TIMEOUT",
    "TRANSFER_PROBLEMS",
    "BeginFirmwareUpdateRequest",
    "BeginFirmwareUpdateResponse",
    "BooleanValue",
    "CanId",
    "DecodeError",
    "DsdlError",
    "Empty",
    "EncodeError",
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
    "Frame",  # old name, kept as an alias
    "GetNodeInfoRequest",
    "GetNodeInfoResponse",
    "GetSetRequest",
    "GetSetResponse",
    "HandNamedMessage",
    "HardwareVersion",
    "Health",
    "IntegerValue",
    "Message",  # old name, kept as an alias
    "Mode",
    "NodeStatus",
    "NumericValue",
    "Opcode",
    "Path",
    "Problem",
    "ProblemReport",
    "Problems",
    "RawCommand",
    "RealValue",
    "Reassembler",
    "RestartNodeRequest",
    "RestartNodeResponse",
    "SoftwareVersion",
    "SoftwareVersionFlag",
    "StringValue",
    "Temperature",
    "TemperatureErrorFlag",
    "Transfer",
    "TransferFrame",
    "TransferKind",
    "TypeSet",
    "Value",
    "Veronte4xError",
    "anonymous_can_id",
    "decode_frames",
    "decode_payload",
    "default_types",
    "encode",
    "from_builtin",
    "load_dsdl",
    "message_can_id",
    "parse_can_id",
    "service_can_id",
    "set_default_types",
    "standard",
    "to_builtin",
    "vertiq",
]
__all__ += standard.__all__
