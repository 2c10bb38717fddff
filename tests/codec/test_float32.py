"""binary32 bit patterns both ways: golden values, every class of pattern, NaN payloads."""

from __future__ import annotations

import math
import struct

import pytest
from hypothesis import given
from hypothesis import strategies as st

from veronte4x.codec.float32 import bits_from_float, float_from_bits

GOLDEN = [
    (0x0000_0000, 0.0),
    (0x8000_0000, -0.0),
    (0x3F80_0000, 1.0),
    (0xC020_0000, -2.5),
    (0x3DCC_CCCD, 0.10000000149011612),  # 0.1 rounded to binary32
    (0x0000_0001, 1.401298464324817e-45),  # the smallest subnormal
    (0x7F7F_FFFF, 3.4028234663852886e38),  # the largest finite
    (0x7F80_0000, math.inf),
    (0xFF80_0000, -math.inf),
]


@pytest.mark.parametrize(("bits", "value"), GOLDEN)
def test_golden_values_both_ways(bits: int, value: float) -> None:
    assert bits_from_float(value) == bits
    back = float_from_bits(bits)
    assert back == value
    assert math.copysign(1.0, back) == math.copysign(1.0, value)


def test_rounding_is_half_to_even_and_overflow_is_refused() -> None:
    one_and_a_half_ulp = 1.0 + 2.0**-24  # halfway between 1.0 and the next binary32
    assert bits_from_float(one_and_a_half_ulp) == 0x3F80_0000  # to the even neighbour
    assert bits_from_float(1.0 + 3 * 2.0**-24) == 0x3F80_0002
    with pytest.raises(OverflowError):
        bits_from_float(1e39)


def test_nan_payloads_and_signs_are_kept() -> None:
    for bits in (0x7FC0_0000, 0xFFC0_0000, 0x7F80_0001, 0xFFA0_0001, 0x7FFF_FFFF):
        value = float_from_bits(bits)
        assert math.isnan(value)
        assert bits_from_float(value) == bits
    assert bits_from_float(math.nan) == 0x7FC0_0000
    # A binary64 NaN whose payload lies below binary32's bits becomes a quiet NaN.
    low = struct.unpack("<d", struct.pack("<Q", 0x7FF0_0000_0000_0001))[0]
    assert bits_from_float(low) == 0x7FC0_0000


@given(st.integers(0, 2**32 - 1))
def test_every_bit_pattern_round_trips(bits: int) -> None:
    value = float_from_bits(bits)
    assert bits_from_float(value) == bits
    if not math.isnan(value):
        assert value == struct.unpack("<f", struct.pack("<I", bits))[0]
