"""PWM set frames in both packings, and the microsecond helpers."""

import pytest

from veronte4x import codec
from veronte4x.codec import PwmPacking, PwmSet, layouts

LSB = codec.Codec(pwm_packing=PwmPacking.LSB_FIRST)
MSB = codec.Codec(pwm_packing=PwmPacking.MSB_FIRST)
MESSAGE = PwmSet(first_channel=0, values=(0x123, 0x456, 0x789, 0xABC))


def test_lsb_first_is_the_default() -> None:
    assert codec.DEFAULT_CODEC.pwm_packing is PwmPacking.LSB_FIRST


def test_lsb_first_packs_channel_0_in_the_low_bits_of_a_little_endian_word() -> None:
    data = bytes.fromhex("0223614589c7ab")
    assert LSB.encode(MESSAGE) == data
    assert LSB.decode(data, sender=codec.Sender.ARBITER) == MESSAGE


def test_msb_first_packs_channel_0_in_the_high_bits_of_a_big_endian_word() -> None:
    data = bytes.fromhex("02123456789abc")
    assert MSB.encode(MESSAGE) == data
    assert MSB.decode(data, sender=codec.Sender.ARBITER) == MESSAGE


@pytest.mark.parametrize(
    ("first_channel", "command"), [(0, 0x02), (4, 0x03), (8, 0x0B), (12, 0x0C), (16, 0x0D)]
)
@pytest.mark.parametrize("packing_codec", [LSB, MSB])
def test_first_channel_selects_the_command(
    first_channel: int, command: int, packing_codec: codec.Codec
) -> None:
    message = PwmSet(first_channel, (1, 2, 3, 4))
    data = packing_codec.encode(message)
    assert data[0] == command
    assert len(data) == 7
    assert packing_codec.decode(data, sender=codec.Sender.AUTOPILOT) == message


def test_single_channel_positions() -> None:
    assert LSB.encode(PwmSet(0, (0, 1, 0, 0))) == bytes.fromhex("02001000000000")
    assert MSB.encode(PwmSet(0, (0, 1, 0, 0))) == bytes.fromhex("02000001000000")
    assert LSB.encode(PwmSet(0, (0, 0, 0, 0x800))) == bytes.fromhex("02000000000080")
    assert MSB.encode(PwmSet(0, (0x800, 0, 0, 0))) == bytes.fromhex("02800000000000")


@pytest.mark.parametrize(
    ("message", "error"),
    [
        (PwmSet(0, (4096, 0, 0, 0)), "PwmSet.values[0] = 4096: expected an int in 0..4095"),
        (PwmSet(0, (0, 0, 0, -1)), "PwmSet.values[3] = -1: expected an int in 0..4095"),
        (PwmSet(2, (0, 0, 0, 0)), "PwmSet.first_channel = 2: expected one of 0, 4, 8, 12, 16"),
        (PwmSet(0, (0, 0, 0)), "PwmSet.values = (0, 0, 0): expected a tuple of 4 values"),  # type: ignore[arg-type]
        (PwmSet(0, (0, 0, 0, 1.0)), "PwmSet.values[3] = 1.0: expected an int in 0..4095"),  # type: ignore[arg-type]
    ],
)
def test_out_of_range(message: PwmSet, error: str) -> None:
    with pytest.raises(codec.EncodeError) as err:
        codec.encode(message)
    assert str(err.value) == error


def test_microseconds_default_900_to_2100() -> None:
    assert codec.to_microseconds(0) == 900.0
    assert codec.to_microseconds(4095) == 2100.0
    assert codec.to_microseconds(2048) == pytest.approx(1500.1465, abs=1e-4)
    assert codec.from_microseconds(900.0) == 0
    assert codec.from_microseconds(2100.0) == 4095
    assert codec.from_microseconds(1500.0) == 2048
    assert all(codec.from_microseconds(codec.to_microseconds(v)) == v for v in range(4096))


def test_microseconds_custom_range() -> None:
    assert codec.to_microseconds(4095, min_us=1000, max_us=2000) == 2000.0
    assert codec.from_microseconds(1500, min_us=1000, max_us=2000) == 2048
    with pytest.raises(codec.EncodeError, match=r"expected a pulse in 1000\.\.2000 us"):
        codec.from_microseconds(2000.5, min_us=1000, max_us=2000)
    with pytest.raises(codec.EncodeError, match=r"expected an int in 0\.\.4095"):
        codec.to_microseconds(4096)


@pytest.mark.parametrize("packing", list(PwmPacking))
def test_the_command_field_names_the_channels_of_each_command(packing: PwmPacking) -> None:
    """The description that the documentation's layout tables show."""
    assert layouts.PWM_SET[packing].fields[0].description == (
        "message type, which names the first channel: 2 = PWMs 0-3, 3 = PWMs 4-7, "
        "11 = PWMs 8-11, 12 = PWMs 12-15, 13 = PWMs 16-19"
    )
