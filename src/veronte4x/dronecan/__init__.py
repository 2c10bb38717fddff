"""DroneCAN (UAVCAN v0): CAN IDs, transfers, reassembly, and every type of the standard
``uavcan`` DSDL namespace (compiled from its DSDL, `standard`), Vertiq's ESCs first."""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:  # what the names below are, for type checkers
    from veronte4x.dronecan import standard as standard
    from veronte4x.dronecan import vertiq as vertiq
    from veronte4x.dronecan.builtin import from_builtin as from_builtin
    from veronte4x.dronecan.builtin import to_builtin as to_builtin
    from veronte4x.dronecan.can_id import (
        CanId as CanId,
    )
    from veronte4x.dronecan.can_id import (
        TransferKind as TransferKind,
    )
    from veronte4x.dronecan.can_id import (
        anonymous_can_id as anonymous_can_id,
    )
    from veronte4x.dronecan.can_id import (
        message_can_id as message_can_id,
    )
    from veronte4x.dronecan.can_id import (
        parse_can_id as parse_can_id,
    )
    from veronte4x.dronecan.can_id import (
        service_can_id as service_can_id,
    )
    from veronte4x.dronecan.codec import decode_payload as decode_payload
    from veronte4x.dronecan.frame import TransferFrame as TransferFrame
    from veronte4x.dronecan.messages import (
        BeginFirmwareUpdateRequest as BeginFirmwareUpdateRequest,
    )
    from veronte4x.dronecan.messages import (
        BeginFirmwareUpdateResponse as BeginFirmwareUpdateResponse,
    )
    from veronte4x.dronecan.messages import (
        BooleanValue as BooleanValue,
    )
    from veronte4x.dronecan.messages import (
        Empty as Empty,
    )
    from veronte4x.dronecan.messages import (
        EntryType as EntryType,
    )
    from veronte4x.dronecan.messages import (
        EntryTypeFlag as EntryTypeFlag,
    )
    from veronte4x.dronecan.messages import (
        EscStatus as EscStatus,
    )
    from veronte4x.dronecan.messages import (
        ExecuteOpcodeRequest as ExecuteOpcodeRequest,
    )
    from veronte4x.dronecan.messages import (
        ExecuteOpcodeResponse as ExecuteOpcodeResponse,
    )
    from veronte4x.dronecan.messages import (
        FileError as FileError,
    )
    from veronte4x.dronecan.messages import (
        FileErrorCode as FileErrorCode,
    )
    from veronte4x.dronecan.messages import (
        FileGetInfoRequest as FileGetInfoRequest,
    )
    from veronte4x.dronecan.messages import (
        FileGetInfoResponse as FileGetInfoResponse,
    )
    from veronte4x.dronecan.messages import (
        FileReadRequest as FileReadRequest,
    )
    from veronte4x.dronecan.messages import (
        FileReadResponse as FileReadResponse,
    )
    from veronte4x.dronecan.messages import (
        FirmwareUpdateError as FirmwareUpdateError,
    )
    from veronte4x.dronecan.messages import (
        GetNodeInfoRequest as GetNodeInfoRequest,
    )
    from veronte4x.dronecan.messages import (
        GetNodeInfoResponse as GetNodeInfoResponse,
    )
    from veronte4x.dronecan.messages import (
        GetSetRequest as GetSetRequest,
    )
    from veronte4x.dronecan.messages import (
        GetSetResponse as GetSetResponse,
    )
    from veronte4x.dronecan.messages import (
        HandNamedMessage as HandNamedMessage,
    )
    from veronte4x.dronecan.messages import (
        HardwareVersion as HardwareVersion,
    )
    from veronte4x.dronecan.messages import (
        Health as Health,
    )
    from veronte4x.dronecan.messages import (
        IntegerValue as IntegerValue,
    )
    from veronte4x.dronecan.messages import (
        Mode as Mode,
    )
    from veronte4x.dronecan.messages import (
        NodeStatus as NodeStatus,
    )
    from veronte4x.dronecan.messages import (
        NumericValue as NumericValue,
    )
    from veronte4x.dronecan.messages import (
        Opcode as Opcode,
    )
    from veronte4x.dronecan.messages import (
        Path as Path,
    )
    from veronte4x.dronecan.messages import (
        RawCommand as RawCommand,
    )
    from veronte4x.dronecan.messages import (
        RealValue as RealValue,
    )
    from veronte4x.dronecan.messages import (
        RestartNodeRequest as RestartNodeRequest,
    )
    from veronte4x.dronecan.messages import (
        RestartNodeResponse as RestartNodeResponse,
    )
    from veronte4x.dronecan.messages import (
        SoftwareVersion as SoftwareVersion,
    )
    from veronte4x.dronecan.messages import (
        SoftwareVersionFlag as SoftwareVersionFlag,
    )
    from veronte4x.dronecan.messages import (
        StringValue as StringValue,
    )
    from veronte4x.dronecan.messages import (
        Temperature as Temperature,
    )
    from veronte4x.dronecan.messages import (
        TemperatureErrorFlag as TemperatureErrorFlag,
    )
    from veronte4x.dronecan.messages import (
        Value as Value,
    )
    from veronte4x.dronecan.reassembler import (
        TRANSFER_ID_TIMEOUT as TRANSFER_ID_TIMEOUT,
    )
    from veronte4x.dronecan.reassembler import (
        TRANSFER_PROBLEMS as TRANSFER_PROBLEMS,
    )
    from veronte4x.dronecan.reassembler import (
        Problem as Problem,
    )
    from veronte4x.dronecan.reassembler import (
        ProblemReport as ProblemReport,
    )
    from veronte4x.dronecan.reassembler import (
        Problems as Problems,
    )
    from veronte4x.dronecan.reassembler import (
        Reassembler as Reassembler,
    )
    from veronte4x.dronecan.standard import *  # noqa: F403  (every standard type, generated)
    from veronte4x.dronecan.transfer import (
        DEFAULT_PRIORITY as DEFAULT_PRIORITY,
    )
    from veronte4x.dronecan.transfer import (
        Transfer as Transfer,
    )
    from veronte4x.dronecan.transfer import (
        decode_frames as decode_frames,
    )
    from veronte4x.dronecan.transfer import (
        encode as encode,
    )
    from veronte4x.dronecan.typeset import (
        TypeSet as TypeSet,
    )
    from veronte4x.dronecan.typeset import (
        default_types as default_types,
    )
    from veronte4x.dronecan.typeset import (
        load_dsdl as load_dsdl,
    )
    from veronte4x.dronecan.typeset import (
        set_default_types as set_default_types,
    )
    from veronte4x.errors import (
        DecodeError as DecodeError,
    )
    from veronte4x.errors import (
        DsdlError as DsdlError,
    )
    from veronte4x.errors import (
        EncodeError as EncodeError,
    )
    from veronte4x.errors import (
        Veronte4xError as Veronte4xError,
    )

_HOMES: dict[str, str] = {
    "BeginFirmwareUpdateRequest": "veronte4x.dronecan.messages",
    "BeginFirmwareUpdateResponse": "veronte4x.dronecan.messages",
    "BooleanValue": "veronte4x.dronecan.messages",
    "CanId": "veronte4x.dronecan.can_id",
    "DEFAULT_PRIORITY": "veronte4x.dronecan.transfer",
    "DecodeError": "veronte4x.errors",
    "DsdlError": "veronte4x.errors",
    "Empty": "veronte4x.dronecan.messages",
    "EncodeError": "veronte4x.errors",
    "EntryType": "veronte4x.dronecan.messages",
    "EntryTypeFlag": "veronte4x.dronecan.messages",
    "EscStatus": "veronte4x.dronecan.messages",
    "ExecuteOpcodeRequest": "veronte4x.dronecan.messages",
    "ExecuteOpcodeResponse": "veronte4x.dronecan.messages",
    "FileError": "veronte4x.dronecan.messages",
    "FileErrorCode": "veronte4x.dronecan.messages",
    "FileGetInfoRequest": "veronte4x.dronecan.messages",
    "FileGetInfoResponse": "veronte4x.dronecan.messages",
    "FileReadRequest": "veronte4x.dronecan.messages",
    "FileReadResponse": "veronte4x.dronecan.messages",
    "FirmwareUpdateError": "veronte4x.dronecan.messages",
    "GetNodeInfoRequest": "veronte4x.dronecan.messages",
    "GetNodeInfoResponse": "veronte4x.dronecan.messages",
    "GetSetRequest": "veronte4x.dronecan.messages",
    "GetSetResponse": "veronte4x.dronecan.messages",
    "HandNamedMessage": "veronte4x.dronecan.messages",
    "HardwareVersion": "veronte4x.dronecan.messages",
    "Health": "veronte4x.dronecan.messages",
    "IntegerValue": "veronte4x.dronecan.messages",
    "Mode": "veronte4x.dronecan.messages",
    "NodeStatus": "veronte4x.dronecan.messages",
    "NumericValue": "veronte4x.dronecan.messages",
    "Opcode": "veronte4x.dronecan.messages",
    "Path": "veronte4x.dronecan.messages",
    "Problem": "veronte4x.dronecan.reassembler",
    "ProblemReport": "veronte4x.dronecan.reassembler",
    "Problems": "veronte4x.dronecan.reassembler",
    "RawCommand": "veronte4x.dronecan.messages",
    "RealValue": "veronte4x.dronecan.messages",
    "Reassembler": "veronte4x.dronecan.reassembler",
    "RestartNodeRequest": "veronte4x.dronecan.messages",
    "RestartNodeResponse": "veronte4x.dronecan.messages",
    "SoftwareVersion": "veronte4x.dronecan.messages",
    "SoftwareVersionFlag": "veronte4x.dronecan.messages",
    "StringValue": "veronte4x.dronecan.messages",
    "TRANSFER_ID_TIMEOUT": "veronte4x.dronecan.reassembler",
    "TRANSFER_PROBLEMS": "veronte4x.dronecan.reassembler",
    "Temperature": "veronte4x.dronecan.messages",
    "TemperatureErrorFlag": "veronte4x.dronecan.messages",
    "Transfer": "veronte4x.dronecan.transfer",
    "TransferFrame": "veronte4x.dronecan.frame",
    "TransferKind": "veronte4x.dronecan.can_id",
    "TypeSet": "veronte4x.dronecan.typeset",
    "Value": "veronte4x.dronecan.messages",
    "Veronte4xError": "veronte4x.errors",
    "anonymous_can_id": "veronte4x.dronecan.can_id",
    "decode_frames": "veronte4x.dronecan.transfer",
    "decode_payload": "veronte4x.dronecan.codec",
    "default_types": "veronte4x.dronecan.typeset",
    "encode": "veronte4x.dronecan.transfer",
    "from_builtin": "veronte4x.dronecan.builtin",
    "load_dsdl": "veronte4x.dronecan.typeset",
    "message_can_id": "veronte4x.dronecan.can_id",
    "parse_can_id": "veronte4x.dronecan.can_id",
    "service_can_id": "veronte4x.dronecan.can_id",
    "set_default_types": "veronte4x.dronecan.typeset",
    "standard": "veronte4x.dronecan.standard",
    "to_builtin": "veronte4x.dronecan.builtin",
    "vertiq": "veronte4x.dronecan.vertiq",
}
"""The module each public name comes from (a module itself for ``standard`` and ``vertiq``);
every standard type comes from `veronte4x.dronecan.standard`. Imported on first use
(PEP 562), so that ``python -m veronte4x.dronecan.generate`` runs while ``standard.py`` is
stale or broken, and a submodule is imported without the classes."""


def __getattr__(name: str) -> Any:
    if name == "__all__":
        from veronte4x.dronecan import standard

        return [*_HOMES, *standard.__all__]
    home = _HOMES.get(name)
    if home is None:
        from veronte4x.dronecan import standard

        if name not in standard.__all__:
            raise AttributeError(f"module 'veronte4x.dronecan' has no attribute {name!r}")
        value = getattr(standard, name)
    elif home.removeprefix("veronte4x.dronecan.") == name:
        value = importlib.import_module(home)
    else:
        value = getattr(importlib.import_module(home), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted({*globals(), *__getattr__("__all__")})
