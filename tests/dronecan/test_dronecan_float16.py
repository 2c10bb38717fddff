"""float16 and float32 bit patterns: rounding, saturation, and where dronecan differs."""

from __future__ import annotations

import math
import struct

from dronecan.transport import f16_from_f32, f32_from_f16
from hypothesis import given, settings
from hypothesis import strategies as st

import dronecan as reference
from veronte4x import dronecan
from veronte4x.dronecan.float16 import (
    FLOAT16_VALUES,
    float16_bits,
    float16_value,
    float32_bits,
    float32_value,
)


def test_round_to_nearest_ties_away_from_zero() -> None:
    # Examples of notes/dronecan-wire.md "Float16 and saturation".
    assert float16_bits(1 + 2**-11) == 0x3C01  # IEEE ties-to-even would give 0x3C00
    assert float16_bits(2049.0) == 0x6801  # 2049 -> 2050, not 2048
    assert float16_value(0x6801) == 2050.0
    assert float16_bits(2**-25) == 0x0001  # IEEE gives 0
    assert float16_bits(2.5 * 2**-24) == 0x0003
    assert float16_bits(-1e-8) == 0x8000  # underflow keeps the sign
    assert float16_bits(1 + 2**-11 - 2**-40) == 0x3C01  # double rounding through float32


def test_saturation_follows_the_spec() -> None:
    assert float16_bits(65504.0) == 0x7BFF
    assert float16_bits(65519.0) == 0x7BFF
    assert float16_bits(1e6) == 0x7BFF
    assert float16_bits(-1e6) == 0xFBFF
    assert float16_bits(math.inf) == 0x7C00
    assert float16_bits(-math.inf) == 0xFC00
    assert float16_bits(math.nan) == 0x7FFF
    assert float16_bits(-math.nan) == 0xFFFF
    assert float32_bits(1e39) == 0x7F7FFFFF
    assert float32_bits(math.inf) == 0x7F800000
    assert float32_bits(-math.inf) == 0xFF800000
    assert float32_bits(math.nan) == 0x7FC00000


def _reference_f16(value: float) -> int:
    """float16 bits as the dronecan package writes a field: clamp to +-65504, then round."""
    temperature = reference.uavcan.equipment.device.Temperature(temperature=value)
    payload = reference.transport.Transfer(payload=temperature, source_node_id=1).payload
    return int.from_bytes(payload[2:4], "little")


def test_dronecan_clamps_infinity_where_we_keep_it() -> None:
    # The documented difference: dronecan turns infinity into the largest finite value.
    assert _reference_f16(math.inf) == 0x7BFF
    assert _reference_f16(-math.inf) == 0xFBFF
    assert float16_bits(math.inf) == 0x7C00
    assert float16_bits(math.inf, dronecan_inf=True) == 0x7BFF
    assert float16_bits(-math.inf, dronecan_inf=True) == 0xFBFF
    assert float32_bits(math.inf, dronecan_inf=True) == 0x7F7FFFFF
    status = dronecan.EscStatus(0, math.inf, -math.inf, 1.0, 0, 0, 0)
    frames = dronecan.encode(status, source_node_id=1, transfer_id=0)
    back = dronecan.decode_frames(frames).message
    assert back.voltage == math.inf
    assert back.current == -math.inf


@settings(max_examples=500)
@given(st.floats(allow_infinity=False))
def test_float16_matches_dronecan_for_every_non_infinite_value(value: float) -> None:
    assert float16_bits(value) == _reference_f16(value)
    if abs(value) <= 65504 or math.isnan(value):
        assert float16_bits(value) == f16_from_f32(value)


@settings(max_examples=300)
@given(st.floats(allow_infinity=False, allow_nan=False))
def test_fast_path_rounds_like_the_reference(value: float) -> None:
    status = dronecan.Temperature(1, value, 0)
    data = dronecan.encode(status, source_node_id=1, transfer_id=0)[0].data
    assert int.from_bytes(data[2:4], "little") == _reference_f16(value)


def test_decoding_is_exact_for_every_pattern() -> None:
    """All 65,536 patterns, the sign of zero included, equal the dronecan package's."""
    for bits in range(0x10000):
        ours, theirs = FLOAT16_VALUES[bits], f32_from_f16(bits)
        assert (math.isnan(ours) and math.isnan(theirs)) or (
            ours == theirs and math.copysign(1.0, ours) == math.copysign(1.0, theirs)
        ), hex(bits)
    assert FLOAT16_VALUES[0x7C00] == math.inf
    assert FLOAT16_VALUES[0xFC00] == -math.inf
    assert math.isnan(FLOAT16_VALUES[0x7E00])


def test_float32_round_trip() -> None:
    for value in (0.0, -0.0, 1.5, -3.25e-30, 3.4e38):
        bits = float32_bits(value)
        assert bits == struct.unpack("<I", struct.pack("<f", value))[0]
        assert float32_value(bits) == struct.unpack("<f", struct.pack("<f", value))[0]
