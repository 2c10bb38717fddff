"""The ``mcast:`` bus of pydronecan and ArduPilot SITL: one CAN frame in one UDP datagram,
sans-IO (`encode` and `decode` of one datagram; the sockets are `veronte4x.mcastbus`).

The layout is that of pydronecan's driver (``dronecan/driver/mcast.py``, pydronecan 1.0.27,
github.com/dronecan/pydronecan commit 9e65bcca48cb6d428d80e23ed5a0993eff3ed528) and of
ArduPilot's SITL CAN transport (``libraries/AP_HAL_SITL/CAN_Multicast.cpp``, ArduPilot
commit 8fb26015e9bdba48692f362f73bb65fe5a2d68b4), little-endian, packed::

    magic   uint16  0x2934
    crc     uint16  CRC-16-CCITT-FALSE (init 0xFFFF) of every byte after it
    flags   uint16  bit 0: a CAN FD frame
    id      uint32  the identifier; bit 31: extended (29-bit) frame
    data    0 to 64 bytes, the rest of the datagram

Bus N is the group ``239.65.82.N``, port 57732 (`group`, `PORT`).

ArduPilot sends its ``AP_HAL::CANFrame`` identifier as it is, whose bit 30 flags a remote
frame and bit 29 an error frame (``libraries/AP_HAL/CANIface.h``): `decode` reads them so;
pydronecan masks both away. Both accept any data length up to 64 bytes; `decode` refuses,
with `DatagramError`, what is no CAN frame: more than 8 bytes in a classic frame, a CAN FD
length that no data length code gives, a standard identifier past 11 bits.
"""

from __future__ import annotations

import struct
from dataclasses import dataclass

from veronte4x.dronecan.crc import crc16
from veronte4x.errors import DecodeError, EncodeError

__all__ = [
    "GROUP_PREFIX",
    "MAGIC",
    "PORT",
    "DatagramError",
    "McastFrame",
    "decode",
    "encode",
    "group",
]

MAGIC = 0x2934
"""The first two bytes of every datagram (``MCAST_MAGIC``)."""
PORT = 57732
"""The UDP port of every bus (``MCAST_PORT``)."""
GROUP_PREFIX = "239.65.82."
"""The multicast group of bus N is this prefix and N (``MCAST_ADDRESS_BASE``)."""
FLAG_FD = 0x0001
"""``flags`` bit of a CAN FD frame (``MCAST_FLAG_CANFD``)."""
ID_EXTENDED = 1 << 31
ID_REMOTE = 1 << 30
ID_ERROR = 1 << 29
HEADER = struct.Struct("<HHHI")
"""magic, crc, flags, id: the 10 bytes before the data."""
MAX_DATAGRAM = HEADER.size + 64
"""The longest datagram: 64 bytes of CAN FD data after the header (``MCAST_MAX_PKT_LEN``)."""
FD_LENGTHS = frozenset((*range(9), 12, 16, 20, 24, 32, 48, 64))
"""The data lengths of a CAN FD frame (ISO 11898-1 data length codes 0 to 15)."""
_BODY = struct.Struct("<HI")


class DatagramError(DecodeError):
    """A datagram that is no ``mcast:`` CAN frame (too short, wrong magic or CRC, no CAN
    frame's length or identifier)."""

    def __init__(self, reason: str, data: bytes) -> None:
        super().__init__("mcast datagram", reason, data)


@dataclass(frozen=True, slots=True)
class McastFrame:
    """One CAN frame of an ``mcast:`` bus.

    Attributes:
        can_id: The 29-bit (extended) or 11-bit identifier.
        data: The data bytes: up to 8, or for CAN FD a length of `FD_LENGTHS`.
        extended: A 29-bit identifier (every DroneCAN frame).
        fd: A CAN FD frame.
        remote: A remote frame (ArduPilot's identifier bit 30).
        error: An error frame (ArduPilot's identifier bit 29).
    """

    can_id: int
    data: bytes
    extended: bool = True
    fd: bool = False
    remote: bool = False
    error: bool = False


def group(bus: int) -> str:
    """The multicast group of bus ``bus`` (0 to 255): ``239.65.82.<bus>``.

    Raises:
        ValueError: ``bus`` is not 0 to 255.
    """
    if not 0 <= bus <= 255:
        raise ValueError(f"mcast bus {bus} is not 0 to 255 (the last byte of 239.65.82.N)")
    return f"{GROUP_PREFIX}{bus}"


def encode(frame: McastFrame) -> bytes:
    """The datagram of one frame.

    Raises:
        EncodeError: The identifier or the data length is not that of a CAN frame.
    """
    width = 0x1FFF_FFFF if frame.extended else 0x7FF
    if not 0 <= frame.can_id <= width:
        raise EncodeError("McastFrame", "can_id", frame.can_id, f"0 to {width:#x}")
    length = len(frame.data)
    if length not in FD_LENGTHS if frame.fd else length > 8:
        allowed = "a CAN FD data length (0-8, 12, 16, 20, 24, 32, 48, 64)" if frame.fd else "0-8"
        raise EncodeError("McastFrame", "data", frame.data.hex(" "), f"{allowed} bytes")
    message_id = (
        frame.can_id
        | (ID_EXTENDED if frame.extended else 0)
        | (ID_REMOTE if frame.remote else 0)
        | (ID_ERROR if frame.error else 0)
    )
    body = _BODY.pack(FLAG_FD if frame.fd else 0, message_id) + bytes(frame.data)
    return struct.pack("<HH", MAGIC, crc16(body)) + body


def decode(datagram: bytes) -> McastFrame:
    """The frame of one datagram.

    Raises:
        DatagramError: It is shorter than the header or longer than 74 bytes, its magic or
            CRC is wrong, or it holds no CAN frame (see the module's docstring). Flags
            other than CAN FD are ignored, as by pydronecan and ArduPilot.
    """
    datagram = bytes(datagram)
    if len(datagram) < HEADER.size:
        raise DatagramError(f"{len(datagram)} bytes, under the 10 of the header", datagram)
    if len(datagram) > MAX_DATAGRAM:
        raise DatagramError(f"{len(datagram)} bytes, over the {MAX_DATAGRAM} of a frame", datagram)
    magic, crc, flags, message_id = HEADER.unpack_from(datagram)
    if magic != MAGIC:
        raise DatagramError(f"magic {magic:#06x}, not {MAGIC:#06x}", datagram)
    if crc != crc16(datagram[4:]):
        raise DatagramError(f"CRC {crc:#06x}, not {crc16(datagram[4:]):#06x}", datagram)
    data = datagram[HEADER.size :]
    fd = bool(flags & FLAG_FD)
    if len(data) not in FD_LENGTHS if fd else len(data) > 8:
        kind = "a CAN FD frame" if fd else "a classic frame"
        raise DatagramError(f"{len(data)} data bytes: no length of {kind}", datagram)
    extended = bool(message_id & ID_EXTENDED)
    can_id = message_id & 0x1FFF_FFFF
    if not extended and can_id > 0x7FF:
        raise DatagramError(f"standard identifier {can_id:#x} past 11 bits", datagram)
    return McastFrame(
        can_id, data, extended, fd, bool(message_id & ID_REMOTE), bool(message_id & ID_ERROR)
    )
