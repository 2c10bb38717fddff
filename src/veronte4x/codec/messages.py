"""The Veronte 4x CAN messages as frozen, slotted dataclasses.

One class per message of the CAN table of the Veronte Autopilot 4x Software Manual
(release 6.12, section 3 "CAN Bus protocol"). Constructors do not validate, so decoding stays
cheap; `encode`
validates every field and raises `EncodeError`. The wire layouts live in
`veronte4x.codec.layouts`.
"""

from __future__ import annotations

import enum
from collections.abc import Mapping
from dataclasses import dataclass
from typing import ClassVar

from veronte4x.display import HtmlDisplay

Flags4 = tuple[bool, bool, bool, bool]
"""Four flags, one per autopilot (AP1, AP2, AP3, external)."""


class Sender(enum.Enum):
    """Who sent a frame: it decides between Status/Ready and Score/ArbitrationVariable."""

    ARBITER = "arbiter"
    AUTOPILOT = "autopilot"


class Message(HtmlDisplay):
    """Base class of every Veronte 4x message; each message is a frozen, slotted dataclass.

    The base itself holds nothing: a plain slotted class, so that the decoders can build
    messages through a class of identical layout (see `veronte4x.codec.compiler`). It
    gives Jupyter an HTML table of the fields (`veronte4x.display.HtmlDisplay`), which
    loads no DroneCAN, capture or client module.

    Attributes:
        COMMAND: The message type (byte 0 of the frame), or ``None`` where it depends
            on a field (PwmSet).
    """

    __slots__ = ()

    COMMAND: ClassVar[int | None] = None
    _FLOAT32_FIELDS_: ClassVar[frozenset[str]] = frozenset()
    """The attributes its layouts declare float32 (a scaled integer field is a float64),
    written by `veronte4x.codec.compiler.FrameLayout`; read by `veronte4x.values`."""
    _NAMED_FIELDS_: ClassVar[Mapping[str, tuple[str, ...]]] = {}
    """The attributes that hold an autopilot's index, to the autopilots' names, written by
    `veronte4x.codec.layouts`; read by `veronte4x.values.name_of`."""


@dataclass(frozen=True, slots=True)
class Status(Message):
    """Status, arbiter to autopilots (cmd 0, header 0xFF; 4x Software Manual, section 3.1.1).

    The 4x arbiter sends 6 bytes; the CEX arbiter only bytes 0-3, so for that form every
    flag of bytes 4-5 is ``None``. Flags are True when the item is OK.

    Attributes:
        selected: Selected autopilot: 0 = AP1, 1 = AP2, 2 = AP3, 3 = external.
        arbitrating: Arbitration on.
        alive: AP1, AP2, AP3, external alive.
        ready: AP1, AP2, AP3, external ready.
        cbit_ok: CBIT, system OK (fails if any item of byte 4 fails).
        pbit_ok: PBIT, system boot OK.
        pdi_ok: Configuration files OK.
        memory_ok: Memory allocation OK.
        can_a_ok: CAN A OK.
        can_b_ok: CAN B OK.
        cio_low_ok: CIO low-priority task OK.
        cio_high_ok: CIO high-priority task OK.
        power_ok: All power indicators OK.
        bus_a_voltage_ok: A bus voltage OK.
        bus_b_voltage_ok: B bus voltage OK.
        arbiter_voltage_ok: Arbiter voltage OK.
        ap1_voltage_ok: AP1 voltage OK.
        ap2_voltage_ok: AP2 voltage OK.
        ap3_voltage_ok: AP3 voltage OK.
        normal_mode: Arbiter mode: True = Normal, False = Maintenance.
    """

    COMMAND: ClassVar[int | None] = 0

    selected: int
    arbitrating: bool
    alive: Flags4
    ready: Flags4
    cbit_ok: bool | None = None
    pbit_ok: bool | None = None
    pdi_ok: bool | None = None
    memory_ok: bool | None = None
    can_a_ok: bool | None = None
    can_b_ok: bool | None = None
    cio_low_ok: bool | None = None
    cio_high_ok: bool | None = None
    power_ok: bool | None = None
    bus_a_voltage_ok: bool | None = None
    bus_b_voltage_ok: bool | None = None
    arbiter_voltage_ok: bool | None = None
    ap1_voltage_ok: bool | None = None
    ap2_voltage_ok: bool | None = None
    ap3_voltage_ok: bool | None = None
    normal_mode: bool | None = None


@dataclass(frozen=True, slots=True)
class Score(Message):
    """Score of one autopilot, arbiter to autopilots (cmd 0; 4x Software Manual, section 3.1.2).

    Attributes:
        autopilot: 0 = AP1, 1 = AP2, 2 = AP3, 3 = external.
        score: float32 score; lower is better.
    """

    COMMAND: ClassVar[int | None] = 0

    autopilot: int
    score: float


@dataclass(frozen=True, slots=True)
class Ready(Message):
    """Ready or Not Ready, autopilot to arbiter (cmd 0, header 0xFF; 4x Software Manual, section
    3.1.3).

    Attributes:
        ready: True for Ready, False for Not Ready.
    """

    COMMAND: ClassVar[int | None] = 0

    ready: bool


@dataclass(frozen=True, slots=True)
class ArbitrationVariable(Message):
    """One arbitration variable, autopilot to arbiter (cmd 0; 4x Software Manual, section 3.1.4).

    Attributes:
        number: Variable number, 0..31.
        value: float32 value.
    """

    COMMAND: ClassVar[int | None] = 0

    number: int
    value: float


@dataclass(frozen=True, slots=True)
class VersionRequest(Message):
    """Version request: the single byte ``01`` (cmd 1, t_version)."""

    COMMAND: ClassVar[int | None] = 1


@dataclass(frozen=True, slots=True)
class VersionResponse(Message):
    """Version response (cmd 1, t_version): frames of 2 bytes or more.

    Attributes:
        application_code: Byte 1 (9 = CEXv2 in Embention's manuals).
        rest: Bytes 2.., kept exactly: their layout is not public.
    """

    COMMAND: ClassVar[int | None] = 1

    application_code: int
    rest: bytes = b""


@dataclass(frozen=True, slots=True)
class PwmSet(Message):
    """Four PWM outputs (cmd 2, 3, 11, 12, 13: t_pwm_0_3_set .. t_pwm_16_19_set).

    Attributes:
        first_channel: 0, 4, 8, 12 or 16; it selects the command byte.
        values: Four normalised values 0..4095 for channels first_channel..+3.
    """

    first_channel: int
    values: tuple[int, int, int, int]


@dataclass(frozen=True, slots=True)
class OpaqueMessage(Message):
    """A message whose payload layout is not public: its 0..7 payload bytes, kept exactly.

    Declare a `veronte4x.codec.Layout` for the command to get named fields instead.

    Attributes:
        payload: Bytes 1.. of the frame.
    """

    payload: bytes = b""


@dataclass(frozen=True, slots=True)
class ScorpionEscTelemetry(OpaqueMessage):
    """Scorpion Tribunus ESC telemetry (cmd 5, t_esc_tm)."""

    COMMAND: ClassVar[int | None] = 5


@dataclass(frozen=True, slots=True)
class JetiEscTelemetry(OpaqueMessage):
    """Jeti ESC telemetry (cmd 6, t_esc_tm2)."""

    COMMAND: ClassVar[int | None] = 6


@dataclass(frozen=True, slots=True)
class JetiBecTelemetry1(OpaqueMessage):
    """Jeti BEC telemetry 1 (cmd 7, t_bec_tm1)."""

    COMMAND: ClassVar[int | None] = 7


@dataclass(frozen=True, slots=True)
class JetiBecTelemetry2(OpaqueMessage):
    """Jeti BEC telemetry 2 (cmd 8, t_bec_tm2)."""

    COMMAND: ClassVar[int | None] = 8


@dataclass(frozen=True, slots=True)
class JetiTemperature(OpaqueMessage):
    """Jeti temperature sensor telemetry (cmd 9, t_temp_tm)."""

    COMMAND: ClassVar[int | None] = 9


@dataclass(frozen=True, slots=True)
class McuCommand(OpaqueMessage):
    """Lift MCU battery command (cmd 10, t_mcu_cmd)."""

    COMMAND: ClassVar[int | None] = 10


@dataclass(frozen=True, slots=True)
class MaintenanceCommand(OpaqueMessage):
    """Command to go to Maintenance mode (cmd 16, t_cmd_maint)."""

    COMMAND: ClassVar[int | None] = 16


@dataclass(frozen=True, slots=True)
class StickSelection(OpaqueMessage):
    """Command for stick selection (cmd 17, t_stick_sel)."""

    COMMAND: ClassVar[int | None] = 17


@dataclass(frozen=True, slots=True)
class McuTelemetry1(OpaqueMessage):
    """Lift MCU telemetry 1 (cmd 18, t_mcu_tm1)."""

    COMMAND: ClassVar[int | None] = 18


@dataclass(frozen=True, slots=True)
class McuTelemetry2(OpaqueMessage):
    """Lift MCU telemetry 2 (cmd 19, t_mcu_tm2)."""

    COMMAND: ClassVar[int | None] = 19
