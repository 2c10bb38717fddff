"""The DroneCAN types of Vertiq ESCs and of their ground station, as frozen, slotted dataclasses.

The eight types of the Vertiq document, plus the services a ground station needs to
configure and update them: ``param.ExecuteOpcode``, ``file.GetInfo`` and ``file.Read``.

Field names are exactly those of the DSDL files (the public ``dronecan/DSDL``
repository); each class docstring names its file. DSDL constants are class attributes
or enums. Constructors do not validate, so decoding stays cheap; `encode` checks every
field and raises `EncodeError`. uint8 arrays are ``bytes``,
the int14 array of RawCommand a tuple of ints.

Unions (``param.Value`` and ``param.NumericValue``) hold one of the member classes
`Empty`, `IntegerValue`, `RealValue`, `BooleanValue` and
`StringValue`; the class says which member is set.
"""

from __future__ import annotations

import enum
from dataclasses import dataclass
from typing import ClassVar, TypeAlias


class Health(enum.IntEnum):
    """``NodeStatus.health`` (DSDL constants ``HEALTH_*``)."""

    OK = 0
    WARNING = 1
    ERROR = 2
    CRITICAL = 3


class Mode(enum.IntEnum):
    """``NodeStatus.mode`` (DSDL constants ``MODE_*``); 4..6 are reserved and decode as int."""

    OPERATIONAL = 0
    INITIALIZATION = 1
    MAINTENANCE = 2
    SOFTWARE_UPDATE = 3
    OFFLINE = 7


class FirmwareUpdateError(enum.IntEnum):
    """``BeginFirmwareUpdate`` response ``error`` (DSDL constants ``ERROR_*``).

    Other values may be added by the spec; they decode as plain ints.
    """

    OK = 0
    INVALID_MODE = 1
    IN_PROGRESS = 2
    UNKNOWN = 255


class FileError(enum.IntEnum):
    """``uavcan.protocol.file.Error`` result codes (``file/Error.uavcan``, int16 ``value``).

    The ``value`` of `FileErrorCode`, the nested type that ``file.GetInfo`` and
    ``file.Read`` responses carry.
    """

    OK = 0
    UNKNOWN_ERROR = 32767
    NOT_FOUND = 2
    IO_ERROR = 5
    ACCESS_DENIED = 13
    IS_DIRECTORY = 21
    INVALID_VALUE = 22
    FILE_TOO_LARGE = 27
    OUT_OF_SPACE = 28
    NOT_IMPLEMENTED = 38


class Opcode(enum.IntEnum):
    """``param.ExecuteOpcode`` request ``opcode`` (DSDL constants ``OPCODE_*``)."""

    SAVE = 0
    """Save every parameter to non-volatile storage."""
    ERASE = 1
    """Clear the non-volatile storage; parameters go back to their defaults."""


class EntryTypeFlag(enum.IntFlag):
    """Bits of ``file.EntryType.flags`` (DSDL constants ``FLAG_*``)."""

    FILE = 1
    DIRECTORY = 2
    SYMLINK = 4
    READABLE = 8
    WRITEABLE = 16


class TemperatureErrorFlag(enum.IntFlag):
    """Bits of ``Temperature.error_flags`` (DSDL constants ``ERROR_FLAG_*``)."""

    OVERHEATING = 1
    OVERCOOLING = 2


class SoftwareVersionFlag(enum.IntFlag):
    """Bits of ``SoftwareVersion.optional_field_flags`` (``OPTIONAL_FIELD_FLAG_*``)."""

    VCS_COMMIT = 1
    IMAGE_CRC = 2


@dataclass(frozen=True, slots=True)
class NodeStatus:
    """``uavcan.protocol.NodeStatus``, message 341 (``protocol/341.NodeStatus.uavcan``)."""

    MAX_BROADCASTING_PERIOD_MS: ClassVar[int] = 1000
    MIN_BROADCASTING_PERIOD_MS: ClassVar[int] = 2
    OFFLINE_TIMEOUT_MS: ClassVar[int] = 3000

    uptime_sec: int
    health: Health
    mode: Mode | int
    sub_mode: int
    vendor_specific_status_code: int


@dataclass(frozen=True, slots=True)
class EscStatus:
    """``uavcan.equipment.esc.Status``, message 1034 (``equipment/esc/1034.Status.uavcan``).

    Vertiq (Vertiq's DroneCAN support document, section 1.2): temperature of the motor coils in
    kelvin,
    power_rating_pct is the PWM duty cycle, esc_index the sender's ESC index.
    """

    error_count: int
    voltage: float
    current: float
    temperature: float
    rpm: int
    power_rating_pct: int
    esc_index: int


@dataclass(frozen=True, slots=True)
class Temperature:
    """``uavcan.equipment.device.Temperature``, message 1110 (``1110.Temperature.uavcan``).

    Vertiq (Vertiq's DroneCAN support document, section 1.3): device_id is the ESC index,
    temperature that of the
    microcontroller in kelvin. ``error_flags`` bits: `TemperatureErrorFlag`.
    """

    ERROR_FLAG_OVERHEATING: ClassVar[int] = 1
    ERROR_FLAG_OVERCOOLING: ClassVar[int] = 2

    device_id: int
    temperature: float
    error_flags: int


@dataclass(frozen=True, slots=True)
class RawCommand:
    """``uavcan.equipment.esc.RawCommand``, message 1030 (``1030.RawCommand.uavcan``).

    ``cmd[i]`` is the int14 setpoint of ESC index i, -8192..8191, at most 20 entries.
    """

    cmd: tuple[int, ...]


@dataclass(frozen=True, slots=True)
class SoftwareVersion:
    """``uavcan.protocol.SoftwareVersion`` (nested; ``SoftwareVersion.uavcan``).

    ``optional_field_flags`` bits: `SoftwareVersionFlag`.
    """

    OPTIONAL_FIELD_FLAG_VCS_COMMIT: ClassVar[int] = 1
    OPTIONAL_FIELD_FLAG_IMAGE_CRC: ClassVar[int] = 2

    major: int
    minor: int
    optional_field_flags: int
    vcs_commit: int
    image_crc: int


@dataclass(frozen=True, slots=True)
class HardwareVersion:
    """``uavcan.protocol.HardwareVersion`` (nested; ``HardwareVersion.uavcan``).

    ``unique_id`` is exactly 16 bytes; ``certificate_of_authenticity`` at most 255.
    """

    major: int
    minor: int
    unique_id: bytes
    certificate_of_authenticity: bytes = b""


@dataclass(frozen=True, slots=True)
class GetNodeInfoRequest:
    """``uavcan.protocol.GetNodeInfo`` request, service 1 (``1.GetNodeInfo.uavcan``): empty."""


@dataclass(frozen=True, slots=True)
class GetNodeInfoResponse:
    """``uavcan.protocol.GetNodeInfo`` response, service 1 (``1.GetNodeInfo.uavcan``).

    ``name`` is at most 80 bytes; Vertiq nodes answer ``iq_motion.esc`` (Vertiq's DroneCAN support,
    2.1).
    """

    status: NodeStatus
    software_version: SoftwareVersion
    hardware_version: HardwareVersion
    name: bytes


@dataclass(frozen=True, slots=True)
class Empty:
    """``uavcan.protocol.param.Empty``: the union member that means "no value"."""


@dataclass(frozen=True, slots=True)
class IntegerValue:
    """Union member ``integer_value`` (int64) of ``param.Value`` and ``param.NumericValue``."""

    value: int


@dataclass(frozen=True, slots=True)
class RealValue:
    """Union member ``real_value`` (float32) of ``param.Value`` and ``param.NumericValue``."""

    value: float


@dataclass(frozen=True, slots=True)
class BooleanValue:
    """Union member ``boolean_value`` of ``param.Value``: a uint8 (0 false, non-zero true)."""

    value: int


@dataclass(frozen=True, slots=True)
class StringValue:
    """Union member ``string_value`` of ``param.Value``: at most 128 bytes."""

    value: bytes


Value: TypeAlias = Empty | IntegerValue | RealValue | BooleanValue | StringValue
"""``uavcan.protocol.param.Value`` (``param/Value.uavcan``): one of its five members."""

NumericValue: TypeAlias = Empty | IntegerValue | RealValue
"""``uavcan.protocol.param.NumericValue`` (``param/NumericValue.uavcan``)."""


@dataclass(frozen=True, slots=True)
class GetSetRequest:
    """``uavcan.protocol.param.GetSet`` request, service 11 (``param/11.GetSet.uavcan``).

    ``index`` is used only when ``name`` is empty; ``value`` other than `Empty` sets
    the parameter. ``name`` is at most 92 bytes.
    """

    index: int = 0
    value: Value = Empty()
    name: bytes = b""


@dataclass(frozen=True, slots=True)
class GetSetResponse:
    """``uavcan.protocol.param.GetSet`` response, service 11 (``param/11.GetSet.uavcan``).

    An empty ``value`` or ``name`` means there is no such parameter.
    """

    value: Value = Empty()
    default_value: Value = Empty()
    max_value: NumericValue = Empty()
    min_value: NumericValue = Empty()
    name: bytes = b""


@dataclass(frozen=True, slots=True)
class RestartNodeRequest:
    """``uavcan.protocol.RestartNode`` request, service 5 (``5.RestartNode.uavcan``)."""

    MAGIC_NUMBER: ClassVar[int] = 0xACCE551B1E

    magic_number: int


@dataclass(frozen=True, slots=True)
class RestartNodeResponse:
    """``uavcan.protocol.RestartNode`` response, service 5: ``ok`` when restarting."""

    ok: bool


@dataclass(frozen=True, slots=True)
class Path:
    """``uavcan.protocol.file.Path`` (nested; ``file/Path.uavcan``): at most 200 bytes."""

    SEPARATOR: ClassVar[int] = ord("/")

    path: bytes = b""


@dataclass(frozen=True, slots=True)
class BeginFirmwareUpdateRequest:
    """``uavcan.protocol.file.BeginFirmwareUpdate`` request, service 40.

    (``file/40.BeginFirmwareUpdate.uavcan``) ``source_node_id`` 0 means the caller.
    """

    source_node_id: int
    image_file_remote_path: Path


@dataclass(frozen=True, slots=True)
class BeginFirmwareUpdateResponse:
    """``uavcan.protocol.file.BeginFirmwareUpdate`` response, service 40.

    ``optional_error_message`` is at most 127 bytes.
    """

    error: FirmwareUpdateError | int
    optional_error_message: bytes = b""


@dataclass(frozen=True, slots=True)
class ExecuteOpcodeRequest:
    """``uavcan.protocol.param.ExecuteOpcode`` request, service 10.

    (``param/10.ExecuteOpcode.uavcan``) ``opcode`` is an `Opcode`; ``argument`` is reserved
    and kept zero.
    """

    opcode: Opcode | int
    argument: int = 0


@dataclass(frozen=True, slots=True)
class ExecuteOpcodeResponse:
    """``uavcan.protocol.param.ExecuteOpcode`` response, service 10.

    ``ok`` when the operation was performed; otherwise ``argument`` may hold an error code.
    """

    argument: int
    ok: bool


@dataclass(frozen=True, slots=True)
class FileErrorCode:
    """``uavcan.protocol.file.Error`` (nested; ``file/Error.uavcan``): an int16 result code.

    ``value`` compares equal to the `FileError` members.
    """

    value: int = 0


@dataclass(frozen=True, slots=True)
class EntryType:
    """``uavcan.protocol.file.EntryType`` (nested; ``file/EntryType.uavcan``).

    ``flags`` bits: `EntryTypeFlag`; zero when the entry does not exist.
    """

    flags: int = 0


@dataclass(frozen=True, slots=True)
class FileGetInfoRequest:
    """``uavcan.protocol.file.GetInfo`` request, service 45 (``file/45.GetInfo.uavcan``)."""

    path: Path


@dataclass(frozen=True, slots=True)
class FileGetInfoResponse:
    """``uavcan.protocol.file.GetInfo`` response, service 45: size in bytes (uint40)."""

    size: int
    error: FileErrorCode
    entry_type: EntryType


@dataclass(frozen=True, slots=True)
class FileReadRequest:
    """``uavcan.protocol.file.Read`` request, service 48 (``file/48.Read.uavcan``).

    Reads up to 256 bytes at ``offset`` (uint40) of the file at ``path``.
    """

    offset: int
    path: Path


@dataclass(frozen=True, slots=True)
class FileReadResponse:
    """``uavcan.protocol.file.Read`` response, service 48: at most 256 bytes of ``data``.

    Fewer than 256 bytes (possibly none) means the end of the file was reached.
    """

    MAX_DATA: ClassVar[int] = 256

    error: FileErrorCode
    data: bytes = b""


Message: TypeAlias = (
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
"""Any top-level message, request or response class of this package."""
