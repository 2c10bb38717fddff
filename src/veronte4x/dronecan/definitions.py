"""The DroneCAN types as data: fields in wire order, ids, signatures.

Field lists are those of the DSDL files of the public ``dronecan/DSDL`` repository (b4653c7);
ids, 64-bit data type signatures and CRC seeds are those of as libcanard and the dronecan package
implement it. The CRC seeds are recomputed from the signatures at import time. The serializers
run from these definitions; the docs tables are generated from them too.
"""

from __future__ import annotations

from dataclasses import dataclass

from veronte4x.dronecan import messages as m
from veronte4x.dronecan.can_id import TransferKind
from veronte4x.dronecan.crc import signature_seed
from veronte4x.dronecan.schema import Array, Field, Member, Scalar, Struct, Union, max_bits


def _u(bits: int) -> Scalar:
    return Scalar("uint", bits)


def _i(bits: int) -> Scalar:
    return Scalar("int", bits)


_F16 = Scalar("float", 16)
_F32 = Scalar("float", 32)
_U8 = _u(8)

NODE_STATUS = Struct(
    "uavcan.protocol.NodeStatus",
    m.NodeStatus,
    (
        Field("uptime_sec", _u(32)),
        Field("health", _u(2), m.Health),
        Field("mode", _u(3), m.Mode),
        Field("sub_mode", _u(3)),
        Field("vendor_specific_status_code", _u(16)),
    ),
)

ESC_STATUS = Struct(
    "uavcan.equipment.esc.Status",
    m.EscStatus,
    (
        Field("error_count", _u(32)),
        Field("voltage", _F16),
        Field("current", _F16),
        Field("temperature", _F16),
        Field("rpm", _i(18)),
        Field("power_rating_pct", _u(7)),
        Field("esc_index", _u(5)),
    ),
)

TEMPERATURE = Struct(
    "uavcan.equipment.device.Temperature",
    m.Temperature,
    (Field("device_id", _u(16)), Field("temperature", _F16), Field("error_flags", _U8)),
)

RAW_COMMAND = Struct(
    "uavcan.equipment.esc.RawCommand",
    m.RawCommand,
    (Field("cmd", Array(_i(14), 20, dynamic=True)),),
)

SOFTWARE_VERSION = Struct(
    "uavcan.protocol.SoftwareVersion",
    m.SoftwareVersion,
    (
        Field("major", _U8),
        Field("minor", _U8),
        Field("optional_field_flags", _U8),
        Field("vcs_commit", _u(32)),
        Field("image_crc", _u(64)),
    ),
)

HARDWARE_VERSION = Struct(
    "uavcan.protocol.HardwareVersion",
    m.HardwareVersion,
    (
        Field("major", _U8),
        Field("minor", _U8),
        Field("unique_id", Array(_U8, 16, dynamic=False)),
        Field("certificate_of_authenticity", Array(_U8, 255, dynamic=True)),
    ),
)

GET_NODE_INFO_REQUEST = Struct("uavcan.protocol.GetNodeInfo.Request", m.GetNodeInfoRequest, ())

GET_NODE_INFO_RESPONSE = Struct(
    "uavcan.protocol.GetNodeInfo.Response",
    m.GetNodeInfoResponse,
    (
        Field("status", NODE_STATUS),
        Field("software_version", SOFTWARE_VERSION),
        Field("hardware_version", HARDWARE_VERSION),
        Field("name", Array(_U8, 80, dynamic=True)),
    ),
)

EMPTY = Struct("uavcan.protocol.param.Empty", m.Empty, ())

_EMPTY_MEMBER = Member("empty", EMPTY, m.Empty)
_INTEGER_MEMBER = Member("integer_value", _i(64), m.IntegerValue)
_REAL_MEMBER = Member("real_value", _F32, m.RealValue)

VALUE = Union(
    "uavcan.protocol.param.Value",
    (
        _EMPTY_MEMBER,
        _INTEGER_MEMBER,
        _REAL_MEMBER,
        Member("boolean_value", _U8, m.BooleanValue),
        Member("string_value", Array(_U8, 128, dynamic=True), m.StringValue),
    ),
)

NUMERIC_VALUE = Union(
    "uavcan.protocol.param.NumericValue", (_EMPTY_MEMBER, _INTEGER_MEMBER, _REAL_MEMBER)
)

GET_SET_REQUEST = Struct(
    "uavcan.protocol.param.GetSet.Request",
    m.GetSetRequest,
    (
        Field("index", _u(13)),
        Field("value", VALUE),
        Field("name", Array(_U8, 92, dynamic=True)),
    ),
)

GET_SET_RESPONSE = Struct(
    "uavcan.protocol.param.GetSet.Response",
    m.GetSetResponse,
    (
        Field("", Scalar("void", 5)),
        Field("value", VALUE),
        Field("", Scalar("void", 5)),
        Field("default_value", VALUE),
        Field("", Scalar("void", 6)),
        Field("max_value", NUMERIC_VALUE),
        Field("", Scalar("void", 6)),
        Field("min_value", NUMERIC_VALUE),
        Field("name", Array(_U8, 92, dynamic=True)),
    ),
)

RESTART_NODE_REQUEST = Struct(
    "uavcan.protocol.RestartNode.Request",
    m.RestartNodeRequest,
    (Field("magic_number", _u(40)),),
)

RESTART_NODE_RESPONSE = Struct(
    "uavcan.protocol.RestartNode.Response",
    m.RestartNodeResponse,
    (Field("ok", Scalar("bool", 1)),),
)

PATH = Struct("uavcan.protocol.file.Path", m.Path, (Field("path", Array(_U8, 200, dynamic=True)),))

BEGIN_FIRMWARE_UPDATE_REQUEST = Struct(
    "uavcan.protocol.file.BeginFirmwareUpdate.Request",
    m.BeginFirmwareUpdateRequest,
    (Field("source_node_id", _U8), Field("image_file_remote_path", PATH)),
)

BEGIN_FIRMWARE_UPDATE_RESPONSE = Struct(
    "uavcan.protocol.file.BeginFirmwareUpdate.Response",
    m.BeginFirmwareUpdateResponse,
    (
        Field("error", _U8, m.FirmwareUpdateError),
        Field("optional_error_message", Array(_U8, 127, dynamic=True)),
    ),
)

EXECUTE_OPCODE_REQUEST = Struct(
    "uavcan.protocol.param.ExecuteOpcode.Request",
    m.ExecuteOpcodeRequest,
    (Field("opcode", _U8, m.Opcode), Field("argument", _i(48))),
)

EXECUTE_OPCODE_RESPONSE = Struct(
    "uavcan.protocol.param.ExecuteOpcode.Response",
    m.ExecuteOpcodeResponse,
    (Field("argument", _i(48)), Field("ok", Scalar("bool", 1))),
)

FILE_ERROR = Struct("uavcan.protocol.file.Error", m.FileErrorCode, (Field("value", _i(16)),))

ENTRY_TYPE = Struct("uavcan.protocol.file.EntryType", m.EntryType, (Field("flags", _U8),))

FILE_GET_INFO_REQUEST = Struct(
    "uavcan.protocol.file.GetInfo.Request", m.FileGetInfoRequest, (Field("path", PATH),)
)

FILE_GET_INFO_RESPONSE = Struct(
    "uavcan.protocol.file.GetInfo.Response",
    m.FileGetInfoResponse,
    (Field("size", _u(40)), Field("error", FILE_ERROR), Field("entry_type", ENTRY_TYPE)),
)

FILE_READ_REQUEST = Struct(
    "uavcan.protocol.file.Read.Request",
    m.FileReadRequest,
    (Field("offset", _u(40)), Field("path", PATH)),
)

FILE_READ_RESPONSE = Struct(
    "uavcan.protocol.file.Read.Response",
    m.FileReadResponse,
    (Field("error", FILE_ERROR), Field("data", Array(_U8, 256, dynamic=True))),
)


@dataclass(frozen=True)
class DataType:
    """A top-level type: what goes on the wire for one class.

    Attributes:
        full_name: DSDL full name, e.g. ``uavcan.protocol.NodeStatus``.
        kind: Message, request or response.
        data_type_id: The default data type id.
        signature: The 64-bit data type signature (one for both halves of a service).
        crc_seed: The transfer CRC after the signature (precomputed).
        schema: The struct definition.
        max_payload: Largest payload in bytes, with TAO.
    """

    full_name: str
    kind: TransferKind
    data_type_id: int
    signature: int
    schema: Struct

    @property
    def crc_seed(self) -> int:
        """The transfer CRC after the signature (precomputed)."""
        return _SEEDS[self.signature]

    @property
    def max_payload(self) -> int:
        """Largest payload in bytes, with TAO."""
        return (max_bits(self.schema, tao=True) + 7) // 8


_MSG = TransferKind.MESSAGE
_REQ = TransferKind.REQUEST
_RESP = TransferKind.RESPONSE

DATA_TYPES: tuple[DataType, ...] = (
    DataType("uavcan.protocol.NodeStatus", _MSG, 341, 0x0F0868D0C1A7C6F1, NODE_STATUS),
    DataType("uavcan.equipment.esc.Status", _MSG, 1034, 0xA9AF28AEA2FBB254, ESC_STATUS),
    DataType("uavcan.equipment.device.Temperature", _MSG, 1110, 0x70261C28A94144C6, TEMPERATURE),
    DataType("uavcan.equipment.esc.RawCommand", _MSG, 1030, 0x217F5C87D7EC951D, RAW_COMMAND),
    DataType("uavcan.protocol.GetNodeInfo", _REQ, 1, 0xEE468A8121C46A9E, GET_NODE_INFO_REQUEST),
    DataType("uavcan.protocol.GetNodeInfo", _RESP, 1, 0xEE468A8121C46A9E, GET_NODE_INFO_RESPONSE),
    DataType("uavcan.protocol.param.GetSet", _REQ, 11, 0xA7B622F939D1A4D5, GET_SET_REQUEST),
    DataType("uavcan.protocol.param.GetSet", _RESP, 11, 0xA7B622F939D1A4D5, GET_SET_RESPONSE),
    DataType("uavcan.protocol.RestartNode", _REQ, 5, 0x569E05394A3017F0, RESTART_NODE_REQUEST),
    DataType("uavcan.protocol.RestartNode", _RESP, 5, 0x569E05394A3017F0, RESTART_NODE_RESPONSE),
    DataType(
        "uavcan.protocol.file.BeginFirmwareUpdate",
        _REQ,
        40,
        0xB7D725DF72724126,
        BEGIN_FIRMWARE_UPDATE_REQUEST,
    ),
    DataType(
        "uavcan.protocol.file.BeginFirmwareUpdate",
        _RESP,
        40,
        0xB7D725DF72724126,
        BEGIN_FIRMWARE_UPDATE_RESPONSE,
    ),
    DataType(
        "uavcan.protocol.param.ExecuteOpcode",
        _REQ,
        10,
        0x3B131AC5EB69D2CD,
        EXECUTE_OPCODE_REQUEST,
    ),
    DataType(
        "uavcan.protocol.param.ExecuteOpcode",
        _RESP,
        10,
        0x3B131AC5EB69D2CD,
        EXECUTE_OPCODE_RESPONSE,
    ),
    DataType("uavcan.protocol.file.GetInfo", _REQ, 45, 0x5004891EE8A27531, FILE_GET_INFO_REQUEST),
    DataType("uavcan.protocol.file.GetInfo", _RESP, 45, 0x5004891EE8A27531, FILE_GET_INFO_RESPONSE),
    DataType("uavcan.protocol.file.Read", _REQ, 48, 0x8DCDCA939F33F678, FILE_READ_REQUEST),
    DataType("uavcan.protocol.file.Read", _RESP, 48, 0x8DCDCA939F33F678, FILE_READ_RESPONSE),
)
"""Every top-level type: those of Vertiq's DroneCAN support document in its order, then
the ground station's (ExecuteOpcode, file.GetInfo, file.Read)."""

NESTED_SIGNATURES: dict[str, int] = {
    "uavcan.protocol.SoftwareVersion": 0xDD46FD376527FEA1,
    "uavcan.protocol.HardwareVersion": 0x0AD5C4C933F4A0C4,
    "uavcan.protocol.param.Value": 0x29F14BF484727267,
    "uavcan.protocol.param.NumericValue": 0x0DA6D6FEA22E3587,
    "uavcan.protocol.param.Empty": 0x6C4D0E8EF37361DF,
    "uavcan.protocol.file.Path": 0x12AEFC50878A43E2,
    "uavcan.protocol.file.Error": 0xA83071FFEA4FAE15,
    "uavcan.protocol.file.EntryType": 0x6924572FBB2086E5,
}
"""Signatures of the nested types (documentation only: they do not appear on the wire)."""

_SEEDS = {t.signature: signature_seed(t.signature) for t in DATA_TYPES}
