"""The built-in Veronte 4x layouts, written once as data.

Sources: the Veronte Autopilot 4x Software Manual (release 6.12), section 3 "CAN Bus
protocol": message-type table, sections 3.1.1-3.1.4; and Embention's public manuals (byte
order little-endian, bit 0 = least significant bit, PWM encoding, version request). The
codec compiles these layouts into its decode and encode functions, and the docs render
their tables from them.
"""

from __future__ import annotations

import functools
from collections.abc import Callable

from veronte4x.codec import messages as m
from veronte4x.codec.compiler import FrameLayout
from veronte4x.codec.fields import ByteOrder, Field, FieldKind, constant, float32
from veronte4x.codec.pwm import PWM_COMMANDS, PwmPacking

MANUAL = "Veronte Autopilot 4x Software Manual"
"""The manual the public layouts come from, by its title."""
MANUAL_TABLE = f'{MANUAL}, section 3 "CAN Bus protocol", message-type table'
AUTOPILOTS = ("AP1", "AP2", "AP3", "external AP")
"""The autopilots by the index Status, Score and the flags give them (4x Software Manual,
section 3.1)."""
AUTOPILOT_FIELDS = frozenset({"selected", "autopilot"})
"""The fields that hold an autopilot's index: Status ``selected``, Score ``autopilot``."""
for _message in (m.Status, m.Score):  # the class's fact, read by `veronte4x.values.name_of`
    _message._NAMED_FIELDS_ = dict.fromkeys(
        AUTOPILOT_FIELDS & set(_message.__dataclass_fields__), AUTOPILOTS
    )

_ARBITRATION = constant(0x00, 8, "message type t_arbitration", "command")
_FF_HEADER = constant(0xFF, 8, "0xFF header", "header")


def _flag(attr: str, description: str, index: int | None = None) -> Field:
    return Field(FieldKind.BOOL, 1, attr, index, description=description)


_STATUS_BYTES_0_3 = (
    _ARBITRATION,
    _FF_HEADER,
    Field(
        FieldKind.UNSIGNED,
        7,
        "selected",
        maximum=3,
        description="selected AP: 0 = AP1, 1 = AP2, 2 = AP3, 3 = external AP",
    ),
    _flag("arbitrating", "arbitration OFF/ON"),
    *(_flag("alive", f"{ap} alive", i) for i, ap in enumerate(AUTOPILOTS)),
    *(_flag("ready", f"{ap} ready", i) for i, ap in enumerate(AUTOPILOTS)),
)

STATUS_FLAGS: tuple[tuple[str, str], ...] = (
    ("cbit_ok", "CBIT: system error; fails if any item of byte 4 fails"),
    ("pbit_ok", "PBIT: system boot OK"),
    ("pdi_ok", "PDI OK: fails on an error in the configuration files"),
    ("memory_ok", "memory allocation OK"),
    ("can_a_ok", "CAN A OK"),
    ("can_b_ok", "CAN B OK"),
    ("cio_low_ok", "CIO low task OK"),
    ("cio_high_ok", "CIO high task OK"),
    ("power_ok", "power OK: all power indicators are OK"),
    ("bus_a_voltage_ok", "A bus voltage OK"),
    ("bus_b_voltage_ok", "B bus voltage OK"),
    ("arbiter_voltage_ok", "arbiter voltage OK"),
    ("ap1_voltage_ok", "AP1 voltage OK"),
    ("ap2_voltage_ok", "AP2 voltage OK"),
    ("ap3_voltage_ok", "AP3 voltage OK"),
    ("normal_mode", "arbiter mode: 1 = Normal, 0 = Maintenance"),
)
"""The flags of Status bytes 4 and 5, bit 0 first (4x Software Manual, section 3.1.1)."""

STATUS_4X = FrameLayout(
    m.Status,
    (*_STATUS_BYTES_0_3, *(_flag(attr, text) for attr, text in STATUS_FLAGS)),
    source=f"{MANUAL}, section 3.1.1 Status Message (6 bytes, Autopilot 4x)",
    title="Status (4x, 6 bytes)",
)

STATUS_CEX = FrameLayout(
    m.Status,
    _STATUS_BYTES_0_3,
    implied=tuple((attr, None) for attr, _ in STATUS_FLAGS),
    source="Embention's public manuals: the CEX arbiter sends only bytes 0-3 of the Status",
    title="Status (CEX, 4 bytes)",
    implied_text="None like cbit_ok (the 4-byte CEX form), or set every flag (the 6-byte 4x form)",
)

SCORE = FrameLayout(
    m.Score,
    (
        _ARBITRATION,
        Field(
            FieldKind.UNSIGNED,
            8,
            "autopilot",
            maximum=3,
            description="autopilot: 0 = AP1, 1 = AP2, 2 = AP3, 3 = external AP",
        ),
        float32("score", "arbitration score, single-precision float; lower is better"),
    ),
    source=f"{MANUAL}, section 3.1.2 Score Message",
)

READY = FrameLayout(
    m.Ready,
    (
        _ARBITRATION,
        _FF_HEADER,
        _flag("ready", "Ready (1) / Not Ready (0)"),
        constant(0, 7, "unused bits of byte 2, zero", "reserved"),
    ),
    source=f"{MANUAL}, section 3.1.3 Ready Message; Embention's 1x template sends 00 FF 01",
)

ARBITRATION_VARIABLE = FrameLayout(
    m.ArbitrationVariable,
    (
        _ARBITRATION,
        Field(
            FieldKind.UNSIGNED, 8, "number", maximum=31, description="arbitration variable number"
        ),
        float32("value", "arbitration variable value, single-precision float"),
    ),
    source=f"{MANUAL}, section 3.1.4 Arbitration Message (numbers 0..31: at most 32 variables)",
)

VERSION_REQUEST = FrameLayout(
    m.VersionRequest,
    (constant(0x01, 8, "message type t_version", "command"),),
    source=f"{MANUAL_TABLE}; Embention's templates: the request is the single byte 01",
)

VERSION_RESPONSE = FrameLayout(
    m.VersionResponse,
    (
        constant(0x01, 8, "message type t_version", "command"),
        Field(
            FieldKind.UNSIGNED, 8, "application_code", description="application code (9 = CEXv2)"
        ),
        Field(FieldKind.BYTES, 48, "rest", description="version and the rest, layout not public"),
    ),
    source=(
        f"{MANUAL_TABLE}; Embention's public manuals: byte 1 application code, the rest not public"
    ),
)


ARBITRATION_AND_VERSION: tuple[FrameLayout, ...] = (
    STATUS_4X,
    STATUS_CEX,
    SCORE,
    READY,
    ARBITRATION_VARIABLE,
    VERSION_REQUEST,
    VERSION_RESPONSE,
)
"""The layouts of the arbitration and version messages, the same whatever a codec's choices."""


def _pwm(packing: PwmPacking) -> FrameLayout:
    values = tuple(
        Field(
            FieldKind.UNSIGNED, 12, "values", i, description=f"channel first_channel + {i}, 0..4095"
        )
        for i in range(4)
    )
    command = Field(
        FieldKind.MAPPED,
        8,
        "first_channel",
        mapping=tuple((wire, first) for first, wire in PWM_COMMANDS.items()),
        description="message type, which names the first channel: "
        + ", ".join(f"{wire} = PWMs {first}-{first + 3}" for first, wire in PWM_COMMANDS.items()),
    )
    order = ByteOrder.LITTLE if packing is PwmPacking.LSB_FIRST else ByteOrder.BIG
    return FrameLayout(
        m.PwmSet,
        (command, *values),
        byte_order=order,
        source=(
            f"{MANUAL_TABLE}; four 12-bit values; the packing ({packing.value}) is not public: "
            "an option"
        ),
        title=f"PwmSet ({packing.value})",
    )


PWM_SET: dict[PwmPacking, FrameLayout] = {packing: _pwm(packing) for packing in PwmPacking}
"""The PWM set layout of each packing; one layout serves the five PWM commands."""

PWM_FORMAT = "<xBBBBBB"
"""The `struct` format that reads a 7-byte PWM frame's bytes 1-6 as ``b1`` .. ``b6``."""

PWM_VALUES = "(_first[b2][b1], _second[b2][b3], _first[b5][b4], _second[b5][b6])"
"""The four values of a PWM frame from ``b1`` .. ``b6`` and the `pwm_tables` of its packing
(``_first``, ``_second``): the same values as `PWM_SET`, for the codec's fast path."""

PwmTable = tuple[tuple[int, ...], ...]
"""Indexed by a middle byte (2 or 5), then by its neighbour: a 12-bit value."""


@functools.cache
def pwm_tables(packing: PwmPacking) -> tuple[PwmTable, PwmTable]:
    """The two tables of `PWM_VALUES` for a packing, built on first use.

    Every 12-bit value spans one whole byte and half of a middle byte (2 or 5), so a value
    is a table entry indexed by the middle byte, then the whole one: two tuple lookups
    instead of shifts, masks and new int objects. The middle byte's other half does not
    matter, so its 256 rows are 16 shared tuples (about 70 kB for both tables).
    """
    numbers = tuple(range(1 << 12))  # one int object per value, shared by every row

    def table(value: Callable[[int, int], int], half: Callable[[int], int]) -> PwmTable:
        rows = [
            tuple(numbers[value(nibble, whole)] for whole in range(256)) for nibble in range(16)
        ]
        return tuple(rows[half(middle)] for middle in range(256))

    def low(byte: int) -> int:
        return byte & 0xF

    def high(byte: int) -> int:
        return byte >> 4

    if packing is PwmPacking.LSB_FIRST:
        # Little-endian word: a value is a whole byte plus the middle byte's low nibble
        # above it (b1, b2 & 0xF), or the middle byte's high nibble plus a whole byte above.
        return (
            table(lambda nibble, whole: whole | nibble << 8, low),
            table(lambda nibble, whole: nibble | whole << 4, high),
        )
    # Big-endian word: a whole byte above the middle byte's high nibble, or the middle
    # byte's low nibble above a whole byte.
    return (
        table(lambda nibble, whole: whole << 4 | nibble, high),
        table(lambda nibble, whole: nibble << 8 | whole, low),
    )


OPAQUE_CLASSES: tuple[type[m.OpaqueMessage], ...] = (
    m.ScorpionEscTelemetry,
    m.JetiEscTelemetry,
    m.JetiBecTelemetry1,
    m.JetiBecTelemetry2,
    m.JetiTemperature,
    m.McuCommand,
    m.MaintenanceCommand,
    m.StickSelection,
    m.McuTelemetry1,
    m.McuTelemetry2,
)


def _opaque(cls: type[m.OpaqueMessage]) -> FrameLayout:
    assert cls.COMMAND is not None
    return FrameLayout(
        cls,
        (
            constant(cls.COMMAND, 8, "message type", "command"),
            Field(
                FieldKind.BYTES,
                56,
                "payload",
                description="payload, layout not public: kept exactly",
            ),
        ),
        source=f"{MANUAL_TABLE}; no public source gives this payload's layout",
    )


OPAQUE: dict[int, FrameLayout] = {
    cls.COMMAND: _opaque(cls) for cls in OPAQUE_CLASSES if cls.COMMAND is not None
}
"""Layouts of the commands whose payload is kept as raw bytes, by command byte."""

RESERVED_COMMANDS = frozenset({4, 14, 15})
"""Reserved in the Software Manual's message-type table."""
