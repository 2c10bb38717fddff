"""A writer of ArduPilot DataFlash logs for the tests, from the format as ArduPilot documents
it (``libraries/AP_Logger/LogStructure.h``: ``A3 95``, the type, the packed little-endian
fields; an ``FMT`` message of 89 bytes per type) and ``CANF``/``CAFD`` as
``libraries/AP_CANManager/LogStructure.h`` lays them out and ``can_logging_callback`` fills
them (``Id`` with ``AP_HAL::CANFrame``'s flags, the FD ``DLC`` as a code).

pymavlink 2.4.50's ``DFReader_binary`` reads a log written here with the same ``CANF`` and
``CAFD`` field values (checked outside the suite, as pymavlink is no dependency).
"""

from __future__ import annotations

import struct
from collections.abc import Iterable

from veronte4x.capture.frames import Frame, micros

FORMAT = struct.Struct("<BB4s16s64s")
CANF = (60, "CANF", "QBIBBBBBBBBB", "TimeUS,Bus,Id,DLC,B0,B1,B2,B3,B4,B5,B6,B7")
CAFD = (61, "CAFD", "QBIBQQQQQQQQ", "TimeUS,Bus,Id,DLC,D0,D1,D2,D3,D4,D5,D6,D7")
PARM = (64, "PARM", "QNf", "TimeUS,Name,Value")
_CODES = {"Q": "Q", "B": "B", "I": "I", "N": "16s", "f": "f"}
FD_CODES = {n: c for c, n in enumerate((0, 1, 2, 3, 4, 5, 6, 7, 8, 12, 16, 20, 24, 32, 48, 64))}


def _struct(fields: str) -> struct.Struct:
    return struct.Struct("<" + "".join(_CODES[c] for c in fields))


def fmt_message(kind: int, name: str, fields: str, labels: str) -> bytes:
    """The ``FMT`` message of a type."""
    length = 3 + _struct(fields).size
    body = FORMAT.pack(kind, length, name.encode(), fields.encode(), labels.encode())
    return b"\xa3\x95\x80" + body


FMT_OF_FMT = b"\xa3\x95\x80" + FORMAT.pack(
    128, 89, b"FMT", b"BBnNZ", b"Type,Length,Name,Format,Columns"
)
"""The ``FMT`` message of ``FMT``, with which every log starts."""


def header() -> bytes:
    """The ``FMT`` of ``FMT``, then those of ``PARM``, ``CANF`` and ``CAFD``."""
    return FMT_OF_FMT + b"".join(fmt_message(*t) for t in (PARM, CANF, CAFD))


def parm(time_us: int, name: str, value: float) -> bytes:
    """A ``PARM`` message: something that is no CAN frame, as a real log has plenty of."""
    return b"\xa3\x95" + bytes((PARM[0],)) + _struct(PARM[2]).pack(time_us, name.encode(), value)


def can_message(frame: Frame, bus: int) -> bytes:
    """The ``CANF`` (or, for CAN FD, ``CAFD``) message of a frame on ``bus``."""
    assert frame.timestamp is not None
    time_us = micros(frame.timestamp)
    assert time_us is not None
    ident = frame.can_id | (1 << 31 if frame.extended else 0)
    ident |= (1 << 30 if frame.remote else 0) | (1 << 29 if frame.error else 0)
    if frame.fd:
        words = struct.unpack("<8Q", frame.data.ljust(64, b"\0"))
        fields = (time_us, bus, ident, FD_CODES[len(frame.data)], *words)
        return b"\xa3\x95" + bytes((CAFD[0],)) + _struct(CAFD[2]).pack(*fields)
    dlc = frame.dlc if frame.remote else len(frame.data)
    body = _struct(CANF[2]).pack(time_us, bus, ident, dlc, *frame.data.ljust(8, b"\0"))
    return b"\xa3\x95" + bytes((CANF[0],)) + body


def dataflash_log(frames: Iterable[Frame]) -> bytes:
    """A log of the frames, each on the bus its channel names (``can1`` is bus 1), with a
    ``PARM`` message after every third frame."""
    out = [header()]
    for index, frame in enumerate(frames):
        out.append(can_message(frame, int(frame.channel.removeprefix("can"))))
        if index % 3 == 2:
            out.append(parm(index, "CAN_P1_OPTIONS", 1.0))
    return b"".join(out)
