"""A streaming parser for can-utils ``candump`` text, both the log form and the human view.

Log form (``candump -L``, can-utils ``lib.c`` ``snprintf_canframe``)::

    (1436509052.249713) can0 0FF#00FF8177FFFF          classic, 11-bit ID (3 hex digits)
    (1436509052.249713) can0 1004D42A#C0 R             29-bit ID (8 hex digits), RX/TX flag
    (1436509052.249713) can0 123#R  /  123#R3          remote frame, optional DLC
    (1436509052.249713) can0 123##1DEADBEEF            CAN FD, flags nibble then data
    (1436509052.249713) can0 20000080#0000000000000000 error frame (CAN_ERR_FLAG set)
    (1436509052.249713) can0 123#1122334455667788_E    classic frame with a raw DLC

Human view (``candump can0``, with or without ``-t`` timestamps and ``-a`` ASCII)::

    (1436509052.249713)  can0  0FF   [6]  00 FF 81 77 FF FF
    (2015-07-10 08:17:32.249713)  can0  0FF   [2]  23 41   '#A'
      can0  123   [2]  remote request
      can0  20000004   [8]  00 04 00 00 00 00 00 00   ERRORFRAME

A line that is neither gives a `BadLine` with the reason; the stream goes on.
"""

from __future__ import annotations

import datetime as _dt
import math
from collections.abc import Iterable, Iterator
from typing import TYPE_CHECKING

from veronte4x.capture.frames import BadLine, Frame, Seconds, micros, text_seconds
from veronte4x.capture.readers.registry import SNIFF_BYTES
from veronte4x.errors import SourceError

if TYPE_CHECKING:
    from veronte4x.capture.decoder import CaptureDecoder
    from veronte4x.capture.records import Record
    from veronte4x.capture.source import Source

CAN_ERR_FLAG = 0x2000_0000
"""Error-frame flag of a SocketCAN identifier (linux/can.h)."""
CANFD_BRS = 0x01
"""Bit rate switch in a CAN FD frame's flags nibble (linux/can.h)."""
CANFD_ESI = 0x02
"""Error state indicator in a CAN FD frame's flags nibble (linux/can.h)."""

_ID_MASK = 0x1FFF_FFFF
_SAFE = 8_589_934_592.0
"""2**33 seconds: below, a float of six decimals gives back their microseconds."""
_MAX_IDENTIFIERS = 65_536


class Identifiers(dict[str | bytes, int]):
    """The CAN ID of each identifier text of the log form, as `str` or ASCII `bytes`: a dict
    lookup per line instead of `int`, and only 3 or 8 ASCII hex digits pass (`int` alone
    would take ``0x12345``, ``+1234567`` or ``1_234567``).

    A text that is no identifier raises `ValueError`. Up to 65,536 texts are remembered
    (a bus holds far fewer distinct IDs); beyond, they are converted each time.
    """

    def __missing__(self, ident: str | bytes) -> int:
        if len(ident) not in (3, 8) or not _is_hex(ident):
            raise ValueError(f"identifier {ident!r} is not 3 or 8 hex digits")
        can_id = int(ident, 16)
        if len(self) < _MAX_IDENTIFIERS:
            self[ident] = can_id
        return can_id


def frames(source: Source) -> Iterator[Frame | BadLine]:
    """The frames of candump text (a file, gzip or not, or standard input), the reader
    registry's ``frames``; a `Truncation` last where gzip data ends early."""
    from veronte4x.capture.source import Truncated, open_lines

    with open_lines(source) as lines:
        try:
            yield from parse_candump(lines)
        except Truncated as cut:
            yield cut.bad_line()


def records(source: Source, decoder: CaptureDecoder, channel: str | None) -> Iterator[Record]:
    """The records of candump text, parsed as bytes (`CaptureDecoder.decode_chunks`)."""
    from veronte4x.capture.source import read_chunks

    return decoder.decode_chunks(read_chunks(source), channel)


_SNIFF_LINES = 8


def sniff(head: bytes) -> bool:
    """Whether most of the first complete lines of a file are candump frames (a capture may
    start with a bad line; other text or binary data has none or few)."""
    lines = head.decode("utf-8", "replace").splitlines()
    if len(head) == SNIFF_BYTES and len(lines) > 1:
        lines.pop()  # cut by the sniff, not by the file
    numbered = [(n, line) for n, line in enumerate(lines, 1) if line.strip()][:_SNIFF_LINES]
    found = sum(isinstance(parse_line(text, n), Frame) for n, text in numbered)
    return found * 2 > len(numbered)


def parse_candump(
    lines: Iterable[str], channel: str | None = None, first_line: int = 1
) -> Iterator[Frame | BadLine]:
    """Parse candump lines into frames, yielding a `BadLine` for every line that is not one.

    Args:
        lines: Lines of text, with or without line breaks.
        channel: Keep only frames of this interface (None keeps all).
        first_line: The line number of the first line.
    """
    fromhex = bytes.fromhex
    new = tuple.__new__  # NamedTuple's own __new__ is a Python function: skip it on the hot path
    identifiers = Identifiers()
    for number, line in enumerate(lines, first_line):
        parts = line.split()
        # Fast path: the log form with a plain classic frame, the bulk of any capture.
        # Anything else (remote, FD, error frames, odd lines) goes to parse_line.
        if len(parts) == 3:
            stamp, interface, body = parts
            ident, separator, data = body.partition("#")
            size = len(ident)
            if separator and stamp[0] == "(" and stamp[-1] == ")" and (size == 3 or size == 8):
                try:
                    can_id = identifiers[ident]
                    text = stamp[1:-1]
                    seconds = float(text)
                    # candump's own "%010lu.%06lu": the float gives back its microseconds.
                    if not (
                        len(text) == 17
                        and text[10] == "."
                        and seconds < _SAFE
                        and text[11:].isdigit()
                    ):
                        seconds = text_seconds(text, seconds)
                    frame = (seconds, interface, can_id, fromhex(data), size == 8)
                except ValueError:
                    pass
                else:
                    # frame[0] - frame[0] is 0.0 for a finite time only (not nan or inf).
                    if not can_id & CAN_ERR_FLAG and frame[0] - frame[0] == 0.0:
                        if channel is None or interface == channel:
                            yield new(Frame, (*frame, False, False, False, False, False, 0))
                        continue
        if parts:
            result = parse_line(line, number, parts)
            if isinstance(result, BadLine) or channel is None or result.channel == channel:
                yield result


def log_line(frame: Frame) -> str:
    """The ``candump -L`` line of a frame (without its newline), as can-utils writes it and
    `parse_line` reads it back: an error frame's identifier with ``CAN_ERR_FLAG``, in 8
    digits (so it reads back as extended); a remote frame's DLC where it asks for 1 to 8.

    Raises:
        SourceError: The frame has no timestamp, one before 1970 or past the year 9999, or
            a channel that is empty or holds a space.
    """
    stamp = None if frame.timestamp is None else micros(frame.timestamp)
    if stamp is None or stamp < 0:
        raise SourceError(f"a frame at {frame.timestamp} s: candump text needs a time since 1970")
    if not frame.channel or any(c.isspace() for c in frame.channel):
        raise SourceError(f"a frame on channel {frame.channel!r}: candump text needs a name")
    seconds, fraction = divmod(stamp, 1_000_000)
    if frame.error:
        ident = f"{frame.can_id | CAN_ERR_FLAG:08X}"
    else:
        ident = f"{frame.can_id:08X}" if frame.extended else f"{frame.can_id:03X}"
    if frame.remote:
        body = "R" + (str(frame.dlc) if 0 < frame.dlc <= 8 else "")
    elif frame.fd:
        flags = (CANFD_BRS if frame.brs else 0) | (CANFD_ESI if frame.esi else 0)
        body = f"#{flags:X}{frame.data.hex().upper()}"
    else:
        body = frame.data.hex().upper()
    return f"({seconds:010d}.{fraction:06d}) {frame.channel} {ident}#{body}"


def parse_line(line: str, number: int, parts: list[str] | None = None) -> Frame | BadLine:
    """Parse one candump line of any form; a line that is no frame gives a `BadLine`.

    Args:
        line: The line.
        number: Its 1-based line number, for the `BadLine`.
        parts: ``line.split()``, if the caller has it already.
    """
    if parts is None:
        parts = line.split()
    try:
        # The shape decides, not a '#' anywhere: the human view's ASCII column (candump -a)
        # may hold one. The log form's third token is ID#DATA; the human view's is an ID.
        if parts[0][0] == "(" and len(parts) > 2 and "#" in parts[2]:
            result = _log_line(parts)
        else:
            result = _human_line(parts, line)
    except (ValueError, IndexError) as error:
        result = f"not a candump frame: {error}"
    if isinstance(result, str):
        return BadLine(number, line.rstrip("\r\n"), result)
    return result


def _log_line(parts: list[str]) -> Frame | str:
    """Parse the log form in full: remote, FD, error frames, raw DLC, direction flag."""
    if len(parts) == 4 and parts[3] in ("R", "T"):
        parts = parts[:3]
    if len(parts) != 3:
        return "expected '(timestamp) interface ID#DATA'"
    stamp, interface, frame = parts
    if not (stamp.startswith("(") and stamp.endswith(")")):
        return "timestamp not in parentheses"
    timestamp = text_seconds(stamp[1:-1])
    if not math.isfinite(timestamp):
        return f"timestamp {stamp} is not a finite number"
    ident, _, data = frame.partition("#")
    if len(ident) not in (3, 8) or not _is_hex(ident):
        return f"identifier {ident!r} is not 3 or 8 hex digits"
    raw_id = int(ident, 16)
    extended = len(ident) == 8
    if data.startswith("#"):
        if len(data) < 2:
            return "CAN FD frame without its flags nibble"
        flags = int(data[1], 16)
        payload = bytes.fromhex(data[2:])
        return Frame(
            timestamp,
            interface,
            raw_id & _ID_MASK,
            payload,
            extended,
            fd=True,
            brs=bool(flags & CANFD_BRS),
            esi=bool(flags & CANFD_ESI),
        )
    if data[:1] in ("R", "r"):
        if data[1:] and not data[1:].isdigit():
            return f"remote frame with a bad length {data[1:]!r}"
        asked = int(data[1:] or "0")
        return Frame(timestamp, interface, raw_id & _ID_MASK, b"", extended, remote=True, dlc=asked)
    if "_" in data:
        data, _, dlc = data.partition("_")
        int(dlc, 16)
    payload = bytes.fromhex(data)
    if raw_id & CAN_ERR_FLAG:
        return Frame(timestamp, interface, raw_id & _ID_MASK, payload, extended, error=True)
    return Frame(timestamp, interface, raw_id, payload, extended)


def _human_line(parts: list[str], line: str) -> Frame | str:
    """Parse the human view: ``[(timestamp)] interface ID [len] bytes...``."""
    timestamp: float | None = None
    if parts[0].startswith("("):
        text = line.strip()
        stamp, _, rest = text[1:].partition(")")
        timestamp = _human_timestamp(stamp)
        if timestamp is None:
            return f"unreadable timestamp {stamp!r}"
        parts = rest.split()
    if len(parts) < 3:
        return "expected 'interface ID [length] data'"
    interface, ident, length = parts[0], parts[1], parts[2]
    if not (length.startswith("[") and length.endswith("]")):
        return "no '[length]' after the identifier"
    try:
        raw_id = int(ident, 16)
        size = int(length[1:-1])
    except ValueError:
        return f"bad identifier {ident!r} or length {length!r}"
    if len(ident) not in (3, 8) or not _is_hex(ident):
        return f"identifier {ident!r} is not 3 or 8 hex digits"
    extended = len(ident) == 8
    tokens = parts[3:]
    if tokens[:2] == ["remote", "request"]:
        return Frame(timestamp, interface, raw_id & _ID_MASK, b"", extended, remote=True, dlc=size)
    error = bool(raw_id & CAN_ERR_FLAG)
    hexbytes = []
    for token in tokens:
        if len(token) != 2 or not _is_hex(token):
            break
        hexbytes.append(token)
    if len(hexbytes) != size:
        return f"length {size} but {len(hexbytes)} data bytes"
    return Frame(
        timestamp,
        interface,
        raw_id & _ID_MASK if error else raw_id,
        bytes.fromhex("".join(hexbytes)),
        extended,
        fd=size > 8,
        error=error,
    )


def _human_timestamp(stamp: str) -> float | None:
    """Seconds from ``1436509052.249713``, ``000.000000`` or ``2015-07-10 08:17:32.249713``."""
    try:
        seconds = text_seconds(stamp)
    except ValueError:
        pass
    else:
        return seconds if math.isfinite(seconds) else None
    try:
        moment = _dt.datetime.strptime(stamp.strip(), "%Y-%m-%d %H:%M:%S.%f")
    except ValueError:
        return None
    moment = moment.replace(tzinfo=_dt.timezone.utc)
    seconds = moment.timestamp()
    exact = (moment - _EPOCH) // _dt.timedelta(microseconds=1)
    return seconds if micros(seconds) == exact else Seconds(seconds, exact)


_EPOCH = _dt.datetime(1970, 1, 1, tzinfo=_dt.timezone.utc)


_HEX_DIGITS = "0123456789abcdefABCDEF"
_HEX_BYTES = _HEX_DIGITS.encode()


def _is_hex(token: str | bytes) -> bool:
    if isinstance(token, bytes):
        return bool(token) and not token.strip(_HEX_BYTES)
    return bool(token) and not token.strip(_HEX_DIGITS)
