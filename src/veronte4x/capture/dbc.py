"""Write the Veronte frames of a bus map as a DBC file, for cantools, SavvyCAN, asammdf, Vector.

One DBC message per Veronte CAN ID (the arbiter and the four autopilots), 8 bytes long,
with extended multiplexing (``SG_MUL_VAL_``) because one CAN ID carries several message
types: byte 0, the message type (``command``), is the multiplexor of every signal; for the
arbitration frames (command 0), byte 1 (``header``) is a second multiplexor that tells a
Status or Ready (0xFF) from the Score of an autopilot or an arbitration variable (its index).
Layouts come from the same data the codec compiles (`veronte4x.codec.layouts`, the bus
map's PWM packing and declared layouts), so the DBC and the codec cannot disagree on a bit.

What a DBC cannot say, and is therefore left out or only commented:

- a frame's length choosing its layout (the 4-byte CEX Status against the 6-byte 4x one):
  one signal set serves both, and a tool decoding a 4-byte Status (cantools with
  ``allow_truncated=True``) gets no flags where veronte4x gives None;
- constants, reserved bits and range limits (Status ``selected`` <= 3, arbitration
  variable numbers <= 31) that veronte4x checks: a DBC tool decodes what is there;
- payloads kept as raw bytes (the opaque commands, the version's ``rest``): no signal;
- DroneCAN: its CAN ID carries the source node and data type, and a transfer spans frames
  with a tail byte and a CRC, which no DBC can express.

The text is written here, with no dependency; the tests decode captures with cantools and
asammdf through it and compare every value with veronte4x's.
"""

from __future__ import annotations

import os
from collections.abc import Iterator
from dataclasses import dataclass

from veronte4x.capture.busmap import AUTOPILOT_NAMES, BusMap
from veronte4x.codec import layouts
from veronte4x.codec.compiler import FrameLayout, Placed
from veronte4x.codec.declared import Layout
from veronte4x.codec.fields import ByteOrder, FieldKind
from veronte4x.codec.pwm import PWM_COMMANDS

DBC_FRAME_BYTES = 8
"""Every Veronte message is declared 8 bytes long: shorter frames carry fewer signals."""

MESSAGE_NAMES = ("AP1", "AP2", "AP3", "ExternalAP")
"""DBC message and node names of the four autopilots (the arbiter's is ``Arbiter``)."""

_EXTENDED_FLAG = 0x80000000  # a DBC frame ID with bit 31 set is a 29-bit ID


@dataclass(frozen=True)
class Signal:
    """One DBC signal.

    Attributes:
        name: Signal name, unique in its message.
        start: DBC start bit (Intel: the LSB; Motorola: the MSB, in sawtooth numbering).
        bits: Width in bits.
        little_endian: Intel (``@1``) or Motorola (``@0``) byte order.
        signed: Two's complement.
        is_float: An IEEE-754 single (``SIG_VALTYPE_ 1``).
        factor: Physical units per raw step.
        offset: Physical value of raw 0.
        minimum: Smallest physical value.
        maximum: Largest physical value.
        multiplexer: The multiplexor signal this one depends on, or None.
        mux_value: The multiplexor's value that selects this signal.
        is_multiplexer: The signal is itself a multiplexor.
        comment: What the signal means and where its layout comes from.
        choices: Value table: raw value to name.
    """

    name: str
    start: int
    bits: int
    little_endian: bool = True
    signed: bool = False
    is_float: bool = False
    factor: float = 1.0
    offset: float = 0.0
    minimum: float = 0.0
    maximum: float = 0.0
    multiplexer: str | None = None
    mux_value: int = 0
    is_multiplexer: bool = False
    comment: str = ""
    choices: tuple[tuple[int, str], ...] = ()


def export_dbc(bus_map: BusMap | None = None) -> str:
    """The DBC text of a bus map's Veronte frames.

    Args:
        bus_map: CAN IDs, PWM packing and declared layouts; defaults to Embention's
            template IDs.

    Returns:
        The DBC file's text (ASCII).

    Examples:
        >>> from veronte4x.capture.dbc import export_dbc
        >>> text = export_dbc()
        >>> print(next(line for line in text.splitlines() if line.startswith("BO_ 255")))
        BO_ 255 Arbiter: 8 Arbiter
    """
    bus_map = bus_map or BusMap()
    nodes = ["Arbiter", *MESSAGE_NAMES]
    messages: list[tuple[int, str, list[Signal], str]] = [
        (
            bus_map.arbiter_id,
            "Arbiter",
            _signals(bus_map, arbiter=True),
            "Veronte 4x arbiter: Status, Score, version and PWM frames",
        )
    ]
    for index, can_id in enumerate(bus_map.autopilot_ids):
        messages.append(
            (
                can_id,
                MESSAGE_NAMES[index],
                _signals(bus_map, arbiter=False),
                f"Veronte Autopilot 1x {AUTOPILOT_NAMES[index]}: Ready, arbitration variables, "
                "version and PWM frames",
            )
        )
    flag = _EXTENDED_FLAG if bus_map.extended else 0
    out = [
        'VERSION ""',
        "",
        "NS_ :",
        "\tCM_",
        "\tVAL_",
        "\tSIG_VALTYPE_",
        "\tSG_MUL_VAL_",
        "",
        "BS_:",
        "",
        "BU_: " + " ".join(nodes),
        "",
    ]
    for can_id, name, signals, _ in messages:
        out.append(f"BO_ {can_id | flag} {name}: {DBC_FRAME_BYTES} {name}")
        out += [_signal_line(s) for s in signals]
        out.append("")
    out.append(
        f'CM_ "Veronte Autopilot 4x CAN frames, written by veronte4x from the {layouts.MANUAL}, '
        f'section 3 CAN Bus protocol; PWM packing {bus_map.pwm_packing.value}";'
    )
    for can_id, _, signals, comment in messages:
        out.append(f'CM_ BO_ {can_id | flag} "{_text(comment)}";')
        out += [
            f'CM_ SG_ {can_id | flag} {s.name} "{_text(s.comment)}";' for s in signals if s.comment
        ]
    for can_id, _, signals, _ in messages:
        for s in signals:
            if s.choices:
                pairs = " ".join(f'{value} "{_text(text)}"' for value, text in s.choices)
                out.append(f"VAL_ {can_id | flag} {s.name} {pairs} ;")
    for can_id, _, signals, _ in messages:
        out += [f"SIG_VALTYPE_ {can_id | flag} {s.name} : 1;" for s in signals if s.is_float]
    for can_id, _, signals, _ in messages:
        out += [
            f"SG_MUL_VAL_ {can_id | flag} {s.name} {s.multiplexer} {s.mux_value}-{s.mux_value};"
            for s in signals
            if s.multiplexer is not None
        ]
    return "\n".join(out) + "\n"


def write_dbc(path: str | os.PathLike[str], bus_map: BusMap | None = None) -> None:
    """Write `export_dbc`'s text to a file.

    Raises:
        OSError: The file cannot be written.
    """
    with open(path, "w", encoding="ascii", newline="\n") as file:
        file.write(export_dbc(bus_map))


def _signals(bus_map: BusMap, arbiter: bool) -> list[Signal]:
    """The signals of one Veronte CAN ID: the arbiter's or an autopilot's."""
    codec = bus_map.codec()
    names = command_names(codec.layouts)
    if arbiter:
        header_text = "0xFF for a Status, else the autopilot of a Score"
        header_choices = (*((i, f"Score {ap}") for i, ap in enumerate(layouts.AUTOPILOTS)),)
        header_choices += ((0xFF, "Status"),)
    else:
        header_text = "0xFF for a Ready, else the number of an arbitration variable"
        header_choices = ((0xFF, "Ready"),)
    signals = [
        Signal(
            "command",
            0,
            8,
            maximum=255,
            is_multiplexer=True,
            comment=f"message type (byte 0); {layouts.MANUAL_TABLE}",
            choices=tuple(sorted(names.items())),
        ),
        Signal(
            "header",
            8,
            8,
            maximum=255,
            multiplexer="command",
            mux_value=0,
            is_multiplexer=True,
            comment=f"byte 1 of an arbitration frame: {header_text}; {layouts.MANUAL}, "
            "sections 3.1.1-3.1.4",
            choices=header_choices,
        ),
    ]
    if arbiter:
        signals += _layout_signals(layouts.STATUS_4X, "header", 0xFF)
        for index, name in enumerate(AUTOPILOT_NAMES):
            signals += _layout_signals(layouts.SCORE, "header", index, suffix=f"_{name}")
    else:
        signals += _layout_signals(layouts.READY, "header", 0xFF)
        for number in range(32):
            signals += _layout_signals(
                layouts.ARBITRATION_VARIABLE, "header", number, rename=f"variable_{number}"
            )
    signals += _layout_signals(layouts.VERSION_RESPONSE, "command", 1)
    pwm = layouts.PWM_SET[bus_map.pwm_packing]
    for first, command in PWM_COMMANDS.items():
        signals += _layout_signals(pwm, "command", command, first_channel=first)
    for declared in codec.layouts:
        signals += _layout_signals(
            declared.frame, "command", declared.command, prefix=f"{declared.name}_"
        )
    return signals


def command_names(declared: tuple[Layout, ...] = ()) -> dict[int, str]:
    """Message type names by command byte (the ``command`` value table), with declared ones."""
    names = {0: "Arbitration", 1: "Version"}
    for first, command in PWM_COMMANDS.items():
        names[command] = f"PwmSet {first}-{first + 3}"
    for command, opaque in layouts.OPAQUE.items():
        names[command] = opaque.name
    for layout in declared:
        names[layout.command] = layout.name
    return names


def _layout_signals(
    layout: FrameLayout,
    multiplexer: str,
    mux_value: int,
    suffix: str = "",
    prefix: str = "",
    first_channel: int | None = None,
    rename: str | None = None,
) -> Iterator[Signal]:
    """The signals of a layout's fields, multiplexed by one value of ``multiplexer``."""
    for placed in layout.placed:
        field = placed.field
        if field.attr is None or field.kind is FieldKind.MAPPED:
            continue  # constants, padding, and the PWM command already in `command`
        if (multiplexer, field.attr) in (("header", "autopilot"), ("header", "number")):
            continue  # the header itself, named by the signal's suffix
        if first_channel is not None:
            name = f"pwm_{first_channel + (field.index or 0)}"
            comment = f"PWM output {first_channel + (field.index or 0)}, normalised 0..4095"
        else:
            name = rename or prefix + field.attr + suffix
            if field.index is not None:
                name += f"_{_index_name(field.attr, field.index)}"
            comment = field.description
        if layout.source:
            comment = f"{comment}; {layout.source}" if comment else layout.source
        yield _signal(layout, placed, name, multiplexer, mux_value, comment)


def _index_name(attr: str, index: int) -> str:
    return AUTOPILOT_NAMES[index] if attr in ("alive", "ready") else str(index)


def _signal(
    layout: FrameLayout,
    placed: Placed,
    name: str,
    multiplexer: str,
    mux_value: int,
    comment: str,
) -> Signal:
    field = placed.field
    little = layout.byte_order is ByteOrder.LITTLE
    if little:
        start = placed.shift
    else:
        msb = placed.shift + field.bits - 1  # bit number in the big-endian frame integer
        start = (layout.fixed_size - 1 - msb // 8) * 8 + msb % 8
    if field.kind is FieldKind.FLOAT32:
        return Signal(
            name,
            start,
            32,
            little_endian=little,
            signed=True,
            is_float=True,
            multiplexer=multiplexer,
            mux_value=mux_value,
            comment=comment,
        )
    signed = field.kind is FieldKind.SIGNED
    low = -(1 << (field.bits - 1)) if signed else 0
    high = (1 << (field.bits - 1)) - 1 if signed else (1 << field.bits) - 1
    if field.maximum is not None:
        high = field.maximum
    factor, offset = 1.0, 0.0
    if field.scale is not None:
        factor, offset = field.scale.factor, field.scale.offset
    ends = (low * factor + offset, high * factor + offset)
    choices: tuple[tuple[int, str], ...] = ()
    if field.attr in layouts.AUTOPILOT_FIELDS:
        choices = tuple(enumerate(layouts.AUTOPILOTS))
    return Signal(
        name,
        start,
        field.bits,
        little_endian=little,
        signed=signed,
        factor=factor,
        offset=offset,
        minimum=min(ends),
        maximum=max(ends),
        multiplexer=multiplexer,
        mux_value=mux_value,
        comment=comment,
        choices=choices,
    )


def _signal_line(s: Signal) -> str:
    if s.is_multiplexer:
        mux = "M" if s.multiplexer is None else f"m{s.mux_value}M"
    else:
        mux = f"m{s.mux_value}"
    order = "1" if s.little_endian else "0"
    sign = "-" if s.signed else "+"
    return (
        f" SG_ {s.name} {mux} : {s.start}|{s.bits}@{order}{sign} "
        f"({_number(s.factor)},{_number(s.offset)}) [{_number(s.minimum)}|{_number(s.maximum)}] "
        '"" Vector__XXX'
    )


def _number(value: float) -> str:
    """The shortest text that reads back as ``value`` (``1`` rather than ``1.0``)."""
    return str(int(value)) if float(value).is_integer() else repr(float(value))


def _text(text: str) -> str:
    """A DBC string: no double quotes inside, ASCII only."""
    return text.replace('"', "'").encode("ascii", "replace").decode("ascii")
