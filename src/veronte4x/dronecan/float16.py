"""IEEE binary16 and binary32 bit patterns as DroneCAN writes them.

Rounding follows libcanard and the ``dronecan`` package: the value is first rounded to
float32 (ties to even), then to float16 with round to nearest, ties away from zero. Out-of-range
values follow the spec's
saturated cast mode (spec 3 "Cast mode"): a finite value beyond the largest finite
float16 (65504) becomes +-65504, while infinity and NaN are kept. NaN is written as
0x7FFF (0xFFFF with the sign bit set), as both reference implementations do.

The ``dronecan`` package differs for infinity: it clamps it to 65504 (0x7BFF). Pass
``dronecan_inf=True`` to `float16_bits` to get its behaviour.
"""

from __future__ import annotations

import math
import struct

MAX_FLOAT16 = 65504.0
"""Largest finite float16."""

MAX_FLOAT32 = struct.unpack("<f", b"\xff\xff\x7f\x7f")[0]
"""Largest finite float32."""

_F32 = struct.Struct("<f")
_U32 = struct.Struct("<I")

FLOAT16_VALUES: tuple[float, ...] = struct.unpack("<65536e", struct.pack("<65536H", *range(65536)))
"""The float value of every float16 bit pattern, indexed by the pattern (exact)."""


def float16_bits(value: float, dronecan_inf: bool = False) -> int:
    """Return the float16 bit pattern of ``value`` (see the module docstring for rounding)."""
    if value != value:  # NaN
        return 0xFFFF if math.copysign(1.0, value) < 0 else 0x7FFF
    if value > MAX_FLOAT16:
        return 0x7BFF if value != math.inf or dronecan_inf else 0x7C00
    if value < -MAX_FLOAT16:
        return 0xFBFF if value != -math.inf or dronecan_inf else 0xFC00
    bits: int = _U32.unpack(_F32.pack(value))[0]
    sign = (bits >> 16) & 0x8000
    magnitude = bits & 0x7FFFFFFF
    if magnitude >= 0x38800000:  # normal float16 range: rebias exponent 127 -> 15
        return sign | ((magnitude - 0x38000000 + 0x1000) >> 13)
    exponent = magnitude >> 23
    if exponent < 102:  # below half of the smallest subnormal: underflows to signed zero
        return sign
    # Subnormal: units of 2**-24; shift the 24-bit significand, rounding half away from zero.
    shift = 126 - exponent
    significand = (magnitude & 0x7FFFFF) | 0x800000
    return sign | ((significand + (1 << (shift - 1))) >> shift)


def float16_value(bits: int) -> float:
    """Return the float value of a float16 bit pattern (exact; inf and NaN kept)."""
    return FLOAT16_VALUES[bits]


def float32_bits(value: float, dronecan_inf: bool = False) -> int:
    """Return the float32 bit pattern of ``value``: IEEE round-half-even, spec saturation.

    Finite values beyond the largest float32 become +-FLT_MAX, infinity is kept (the
    ``dronecan`` package clamps it to FLT_MAX too; ``dronecan_inf=True`` does the same) and
    NaN is 0x7FC00000.
    """
    if value != value:
        return 0x7FC00000
    if value > MAX_FLOAT32:
        return 0x7F7FFFFF if value != math.inf or dronecan_inf else 0x7F800000
    if value < -MAX_FLOAT32:
        return 0xFF7FFFFF if value != -math.inf or dronecan_inf else 0xFF800000
    bits: int = _U32.unpack(_F32.pack(value))[0]
    return bits


def float32_value(bits: int) -> float:
    """Return the float value of a float32 bit pattern."""
    value: float = _F32.unpack(_U32.pack(bits))[0]
    return value


_F64 = struct.Struct("<d")
_U64 = struct.Struct("<Q")


def float64_bits(value: float) -> int:
    """Return the float64 bit pattern of ``value`` (NaN and infinity kept as they are)."""
    bits: int = _U64.unpack(_F64.pack(value))[0]
    return bits


def float64_value(bits: int) -> float:
    """Return the float value of a float64 bit pattern."""
    value: float = _F64.unpack(_U64.pack(bits))[0]
    return value
