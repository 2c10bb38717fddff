"""IEEE-754 binary32 conversions that keep every bit pattern, NaN payloads included.

Veronte floats are little-endian binary32 ("Endianness is Little Endian for all messages",
Embention's manuals).
CPython's ``struct`` quiets signalling NaNs on the way through a C ``float``, so a frame
carrying one would not re-encode to the same bytes. These helpers route NaNs through their
bit patterns instead; every other value goes through ``struct``.
"""

from __future__ import annotations

import struct

_F32 = struct.Struct("<f")
_U32 = struct.Struct("<I")
_F64 = struct.Struct("<d")
_U64 = struct.Struct("<Q")

_QUIET_BIT_32 = 0x0040_0000


def float_from_bits(bits: int) -> float:
    """Return the value of a binary32 bit pattern, as a Python float.

    A NaN becomes a binary64 NaN whose sign and payload carry the binary32 ones, so that
    `bits_from_float` gives the same pattern back.
    """
    if bits & 0x7F80_0000 != 0x7F80_0000 or not bits & 0x007F_FFFF:
        value: float = _F32.unpack(_U32.pack(bits))[0]
        return value
    wide = (bits & 0x8000_0000) << 32 | 0x7FF0_0000_0000_0000 | (bits & 0x007F_FFFF) << 29
    nan: float = _F64.unpack(_U64.pack(wide))[0]
    return nan


def bits_from_float(value: float) -> int:
    """Return the binary32 bit pattern of a float (round half to even).

    Raises:
        OverflowError: The value is finite but beyond the binary32 range.
    """
    if value == value:
        bits: int = _U32.unpack(_F32.pack(value))[0]
        return bits
    wide: int = _U64.unpack(_F64.pack(value))[0]
    payload = (wide >> 29) & 0x007F_FFFF or _QUIET_BIT_32
    return (wide >> 32) & 0x8000_0000 | 0x7F80_0000 | payload
