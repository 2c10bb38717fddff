"""ArduPilot DataFlash logs (``.bin``): the CAN frames of their ``CANF`` and ``CAFD`` messages.

ArduPilot logs every frame of a CAN interface whose ``CAN_Pn_OPTIONS`` asks for it
(``LOG_ALL_FRAMES``), classic frames as ``CANF`` and CAN FD frames as ``CAFD``
(ArduPilot ``libraries/AP_CANManager/LogStructure.h``, written by
``AP_CANManager::can_logging_callback``)::

    CANF  QBIBBBBBBBBB  TimeUS,Bus,Id,DLC,B0,B1,B2,B3,B4,B5,B6,B7
    CAFD  QBIBQQQQQQQQ  TimeUS,Bus,Id,DLC,D0,D1,D2,D3,D4,D5,D6,D7

The log (``libraries/AP_Logger/LogStructure.h``) is a run of messages, each the bytes
``A3 95``, its type, then its fields, little-endian, packed; an ``FMT`` message (type 128,
89 bytes: type, length, name, format, labels) describes each type before its first
message. The fields are found here by the labels of the log's own ``FMT``, not assumed.

- ``Id`` is the frame's identifier with ArduPilot's flags (``AP_HAL::CANFrame``,
  ``libraries/AP_HAL/CANIface.h``): bit 31 an extended frame, bit 30 a remote frame, bit 29
  an error frame.
- ``DLC`` is the data length code: in ``CANF`` the length (at most 8), in ``CAFD`` the
  CAN FD code (9 is 12 bytes ... 15 is 64), the data the first bytes of ``D0`` to ``D7``.
  ``CAFD`` carries no bit rate switch or error state flag: both read as False.
- ``Bus`` is the index of the CAN interface (0 for ``CAN_P1``), the channel named as
  candump names interfaces: bus 0 is ``can0``, bus 1 ``can1``.
- ``TimeUS`` is microseconds since the flight controller booted: the frames' timestamps
  are those seconds since boot, not Unix time (the log's GPS messages would give UTC;
  veronte4x does not join them), so text output shows them as seconds.

ArduPilot's Lua scripts that log the frames of a scripting CAN driver
(``libraries/AP_Scripting/examples/CAN_logger.lua`` and the CAN drivers among the
scripts, before ArduPilot replaced them with ``CAN_Pn_OPTIONS``) write another ``CANF``,
``Id,DLC,FC,B0..B7`` (``IBIBBBBBBBB``, ``FC`` a frame count), to which ``logger:write``
puts ``TimeUS`` first: it names no bus, so its frames' channel is ``""``.

Bytes that are no message of a type the log describes (a corrupt block) are skipped to the
next ``A3 95`` and counted as one `BadLine`, as pymavlink skips them; a message cut by the
end of the file ends the frames with a `Truncation`.
"""

from __future__ import annotations

import struct
from collections.abc import Iterator
from dataclasses import dataclass
from typing import TYPE_CHECKING

from veronte4x.capture.frames import BadLine, Frame, Truncation, micros_seconds
from veronte4x.errors import SourceError

if TYPE_CHECKING:
    from veronte4x.capture.source import Source

HEADER = b"\xa3\x95"
"""The two bytes that start every message (``HEAD_BYTE1``, ``HEAD_BYTE2``)."""
FORMAT_TYPE = 128
"""The type of ``FMT`` messages (``LOG_FORMAT_MSG``)."""
FORMAT = struct.Struct("<BB4s16s64s")
"""An ``FMT`` message after its header: type, length, name, format, labels."""
FORMAT_LENGTH = 3 + FORMAT.size
"""An ``FMT`` message's length with its header: 89."""
MAGIC = HEADER + bytes((FORMAT_TYPE, FORMAT_TYPE, FORMAT_LENGTH))
"""How a log starts: the ``FMT`` message that describes ``FMT`` itself."""

SIZES = {
    **dict.fromkeys("bBM", 1),
    **dict.fromkeys("hHcCg", 2),
    **dict.fromkeys("iIfeELn", 4),
    **dict.fromkeys("dqQ", 8),
    "N": 16,
    "Z": 64,
    "a": 64,
}
"""Bytes of each format character (``LogStructure.h``'s list; ``g``, a float16, as
pymavlink reads it)."""

FLAG_EXTENDED = 1 << 31
FLAG_REMOTE = 1 << 30
FLAG_ERROR = 1 << 29
_EXTENDED_MASK = 0x1FFF_FFFF
_STANDARD_MASK = 0x7FF
FD_LENGTHS = (0, 1, 2, 3, 4, 5, 6, 7, 8, 12, 16, 20, 24, 32, 48, 64)
"""The data length of each CAN FD data length code (ISO 11898-1)."""
_CAN_TYPES = ("CANF", "CAFD")
"""The messages of CAN frames: classic, and CAN FD."""
_CHUNK = 1 << 20


@dataclass(frozen=True, slots=True)
class _CanLayout:
    """Where a ``CANF`` or ``CAFD`` message holds a frame, from its ``FMT``."""

    fields: struct.Struct
    """TimeUS, Bus (where the message has it), Id and DLC, from the message's start (its
    header included)."""
    data: int
    """The offset of the data bytes."""
    fd: bool


def sniff(head: bytes) -> bool:
    """Whether a file starts as a DataFlash log: with the ``FMT`` message of ``FMT``."""
    return head.startswith(MAGIC)


def frames(source: Source) -> Iterator[Frame | BadLine]:
    """The CAN frames of a DataFlash log, gzipped or not: the reader registry's ``frames``.

    Raises:
        SourceError: The file does not start as a DataFlash log (raised by the stream).
    """
    from veronte4x.capture.source import Truncated, read_chunks

    chunks = read_chunks(source, _CHUNK)
    try:
        yield from parse_dataflash(chunks, source.path)
    except Truncated as cut:
        yield Truncation(cut.line_number, "", f"{source.path}: the gzip data ends early: the "
                         "file is truncated; the frames before were read")  # fmt: skip


def parse_dataflash(chunks: Iterator[bytes], path: str) -> Iterator[Frame | BadLine]:
    """The frames of a DataFlash log's bytes, given in chunks of any size.

    A `BadLine`'s number is that of the message it stands in place of (1-based); an empty
    input gives no frame.

    Raises:
        SourceError: The bytes do not start as a DataFlash log.
    """
    lengths = {FORMAT_TYPE: FORMAT_LENGTH}
    layouts: dict[int, _CanLayout] = {}
    buffer, at, number, skipped, checked = b"", 0, 0, 0, False
    for chunk in chunks:
        buffer = buffer[at:] + chunk
        at = 0
        if not checked and len(buffer) >= len(MAGIC):
            _check(buffer, path)
            checked = True
        end = len(buffer)
        while end - at >= 3:
            kind = buffer[at + 2]
            length = lengths.get(kind)
            if buffer[at] != 0xA3 or buffer[at + 1] != 0x95 or length is None:
                found = buffer.find(HEADER, at + 1)
                step = (found if found >= 0 else end - 1) - at  # the last byte may start one
                skipped += step
                at += step
                continue
            if end - at < length:
                break
            if skipped:
                number += 1
                yield _skipped(number, skipped, buffer[at - min(skipped, 16) : at])
                skipped = 0
            number += 1
            if kind == FORMAT_TYPE:
                _describe(buffer, at, lengths, layouts)
            else:
                layout = layouts.get(kind)
                if layout is not None:
                    yield _frame(buffer, at, layout)
            at += length
    tail = buffer[at:]
    if tail and not checked:
        _check(tail, path)
    cut = tail[:2] == HEADER[: len(tail)] and (len(tail) < 3 or tail[2] in lengths)
    if skipped and not cut:
        skipped, tail = skipped + len(tail), b""
    if skipped:
        number += 1
        yield _skipped(number, skipped, buffer[at - min(skipped, 16) : at + len(tail)])
    if tail:
        yield Truncation(
            number + 1,
            "",
            f"{path}: the DataFlash log ends early, in message {number + 1} (its first "
            f"{len(tail)} bytes): the file is truncated; the frames before were read",
        )


def _check(head: bytes, path: str) -> None:
    if not sniff(head):
        raise SourceError(
            f"{path}: not a DataFlash log (it does not start with the FMT message "
            f"{MAGIC.hex(' ')}): the file is damaged or in another format"
        )


def _skipped(number: int, count: int, tail: bytes) -> BadLine:
    """The `BadLine` of ``count`` bytes that are no message, shown by their last 16."""
    return BadLine(
        number, tail[-16:].hex(" "), f"{count} bytes are no DataFlash message of a described type"
    )


def _describe(
    buffer: bytes, at: int, lengths: dict[int, int], layouts: dict[int, _CanLayout]
) -> None:
    """Take in an ``FMT`` message: the length of its type, and the layout of CAN frames."""
    kind, length, name, format_, labels = FORMAT.unpack_from(buffer, at + 3)
    if kind == FORMAT_TYPE or length < 3:
        return
    lengths[kind] = length
    layouts.pop(kind, None)
    text = name.rstrip(b"\0").decode("ascii", "replace")
    if text in _CAN_TYPES:
        layout = _layout(
            format_.rstrip(b"\0").decode("ascii", "replace"),
            labels.rstrip(b"\0").decode("ascii", "replace").split(","),
            length,
            fd=text == "CAFD",
        )
        if layout is not None:
            layouts[kind] = layout


def _layout(format_: str, labels: list[str], length: int, fd: bool) -> _CanLayout | None:
    """The layout of a CAN frame message, or None where its ``FMT`` lacks a field."""
    offsets, codes, at = {}, {}, 3
    for char, label in zip(format_, labels, strict=False):  # a log may label fewer
        size = SIZES.get(char)
        if size is None:
            return None
        offsets[label], codes[label] = at, char
        at += size
    wanted: tuple[str, ...] = ("TimeUS", "Bus", "Id", "DLC")
    kinds = "QBIB"
    if "Bus" not in offsets and not fd:  # a Lua script's CANF
        wanted, kinds = ("TimeUS", "Id", "DLC"), "QIB"
    first, data_bytes = ("D0", 64) if fd else ("B0", 8)
    if any(label not in offsets for label in (*wanted, first)):
        return None
    places = [offsets[label] for label in wanted]
    if [codes[label] for label in wanted] != list(kinds) or places != sorted(places):
        return None
    if offsets[first] + data_bytes > length:
        return None
    spec, position = "<", 0
    for label, code in zip(wanted, kinds, strict=True):
        spec += f"{offsets[label] - position}x{code}"
        position = offsets[label] + SIZES[code]
    return _CanLayout(struct.Struct(spec), offsets[first], fd)


def _frame(buffer: bytes, at: int, layout: _CanLayout) -> Frame:
    values = layout.fields.unpack_from(buffer, at)
    if len(values) == 4:
        time_us, bus, ident, dlc = values
        channel = f"can{bus}"
    else:  # a Lua script's CANF: no bus
        (time_us, ident, dlc), channel = values, ""
    extended = bool(ident & FLAG_EXTENDED)
    can_id = ident & (_EXTENDED_MASK if extended else _STANDARD_MASK)
    start = at + layout.data
    timestamp = micros_seconds(time_us)
    if ident & FLAG_REMOTE:
        return Frame(timestamp, channel, can_id, b"", extended, remote=True, dlc=dlc)
    size = FD_LENGTHS[dlc & 0xF] if layout.fd else min(dlc, 8)
    data = bytes(buffer[start : start + size])
    if ident & FLAG_ERROR:
        return Frame(timestamp, channel, can_id, data, extended, error=True)
    return Frame(timestamp, channel, can_id, data, extended, fd=layout.fd)
