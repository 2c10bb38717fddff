"""Bad frames and bad messages: the exact errors, and the frame-length policy."""

import math

import pytest

from veronte4x import codec
from veronte4x.codec import Sender

ARB, AP = Sender.ARBITER, Sender.AUTOPILOT


@pytest.mark.parametrize(
    ("hex_data", "sender", "error"),
    [
        ("", AP, "frame: 0 bytes; a frame has 1 to 8 (data: empty)"),
        ("00", AP, "frame: an arbitration frame has at least 2 bytes (data: 00)"),
        ("00ff", AP, "Ready: 2 bytes; the layout has 3 (data: 00 ff)"),
        ("00ff0100", AP, "Ready: 4 bytes; the layout has 3 (data: 00 ff 01 00)"),
        ("00ff02", AP, "Ready.reserved: expected 0x0, got 0x1 (data: 00 ff 02)"),
        ("00ff00", ARB, "Status: 3 bytes; 4 (CEX form) or 6 (4x form) expected (data: 00 ff 00)"),
        (
            "00ff000000",
            ARB,
            "Status: 5 bytes; 4 (CEX form) or 6 (4x form) expected (data: 00 ff 00 00 00)",
        ),
        ("00ff00000000aa", ARB, "Status: 7 bytes; the layout has 6 (data: 00 ff 00 00 00 00 aa)"),
        ("0004000000", ARB, "Score: 5 bytes; the layout has 6 (data: 00 04 00 00 00)"),
        ("000400000000", ARB, "Score.autopilot: 4 out of range 0..3 (data: 00 04 00 00 00 00)"),
        (
            "002000000000",
            AP,
            "ArbitrationVariable.number: 32 out of range 0..31 (data: 00 20 00 00 00 00)",
        ),
        (
            "02000000000000ff",
            AP,
            "PwmSet: 8 bytes; the layout has 7 (data: 02 00 00 00 00 00 00 ff)",
        ),
        ("0200", AP, "PwmSet: 2 bytes; the layout has 7 (data: 02 00)"),
        ("02", AP, "PwmSet: 1 byte; the layout has 7 (data: 02)"),
        (
            "050102030405060708",
            AP,
            "ScorpionEscTelemetry: 9 bytes; the layout has 1 to 8 "
            "(data: 05 01 02 03 04 05 06 07 08)",
        ),
    ],
)
def test_decode_errors(hex_data: str, sender: Sender, error: str) -> None:
    with pytest.raises(codec.DecodeError) as err:
        codec.decode(bytes.fromhex(hex_data), sender=sender)
    assert str(err.value) == error
    assert err.value.data == bytes.fromhex(hex_data)


@pytest.mark.parametrize("command", [4, 14, 15, 20, 0x7F, 0xFF])
def test_reserved_and_unknown_commands_carry_command_and_data(command: int) -> None:
    data = bytes([command, 1, 2])
    with pytest.raises(codec.UnknownCommandError) as err:
        codec.decode(data, sender=AP)
    assert err.value.command == command
    assert err.value.data == data
    assert isinstance(err.value, codec.DecodeError)
    assert str(err.value) == (
        f"frame.command: command byte {command} is reserved or unknown (data: {data.hex(' ')})"
    )


def test_allow_excess_ignores_padding_past_the_layout() -> None:
    padded = bytes.fromhex("00ff0100000000 00".replace(" ", ""))
    assert codec.decode(padded, sender=AP, allow_excess=True) == codec.Ready(ready=True)
    status = codec.decode(bytes.fromhex("00ff8133ffff0000"), sender=ARB, allow_excess=True)
    assert isinstance(status, codec.Status)
    assert status.normal_mode is True
    cex = codec.decode(bytes.fromhex("00ff813300"), sender=ARB, allow_excess=True)
    assert isinstance(cex, codec.Status)
    assert cex.normal_mode is None
    pwm = codec.decode(bytes.fromhex("0201000000000099"), sender=ARB, allow_excess=True)
    assert pwm == codec.PwmSet(0, (1, 0, 0, 0))


@pytest.mark.parametrize("sender", [AP, ARB])
def test_allow_excess_ignores_bytes_past_a_layout_with_a_tail(sender: codec.Sender) -> None:
    """A Version response holds at most 8 bytes (a 6-byte tail): a 9th is excess."""
    data = bytes.fromhex("0107010203040506") + b"\x99"
    expected = codec.VersionResponse(application_code=7, rest=bytes.fromhex("010203040506"))
    assert codec.decode(data, sender=sender, allow_excess=True) == expected
    assert codec.DEFAULT_CODEC.decoder(sender)(data, True) == expected
    with pytest.raises(codec.DecodeError, match="9 bytes; the layout has 2 to 8"):
        codec.decode(data, sender=sender)


def test_short_frames_never_decode_even_with_allow_excess() -> None:
    with pytest.raises(codec.DecodeError, match="2 bytes; the layout has 3"):
        codec.decode(b"\x00\xff", sender=AP, allow_excess=True)


@pytest.mark.parametrize(
    ("message", "error"),
    [
        (codec.Score(autopilot=4, score=0.0), "Score.autopilot = 4: expected an int in 0..3"),
        (codec.Score(autopilot=0, score="1"), "Score.score = '1': expected a float"),  # type: ignore[arg-type]
        (
            codec.Score(autopilot=0, score=1e39),
            "Score.score = 1e+39: expected a float within the float32 range",
        ),
        (
            codec.ArbitrationVariable(number=32, value=0.0),
            "ArbitrationVariable.number = 32: expected an int in 0..31",
        ),
        (
            codec.ArbitrationVariable(number=True, value=0.0),
            "ArbitrationVariable.number = True: expected an int in 0..31",
        ),
        (codec.Ready(ready=1), "Ready.ready = 1: expected a bool"),  # type: ignore[arg-type]
        (
            codec.Status(selected=4, arbitrating=False, alive=(False,) * 4, ready=(False,) * 4),
            "Status.selected = 4: expected an int in 0..3",
        ),
        (
            codec.Status(selected=0, arbitrating=False, alive=[False] * 4, ready=(False,) * 4),  # type: ignore[arg-type]
            "Status.alive = [False, False, False, False]: expected a tuple of 4 values",
        ),
        (
            codec.VersionResponse(application_code=256),
            "VersionResponse.application_code = 256: expected an int in 0..255",
        ),
        (
            codec.VersionResponse(application_code=9, rest=b"1234567"),
            "VersionResponse.rest = b'1234567': expected bytes of length 0..6",
        ),
        (
            codec.StickSelection(payload=b"12345678"),
            "StickSelection.payload = b'12345678': expected bytes of length 0..7",
        ),
        (
            codec.StickSelection(payload="1"),  # type: ignore[arg-type]
            "StickSelection.payload = '1': expected bytes of length 0..7",
        ),
    ],
)
def test_encode_errors(message: codec.Message, error: str) -> None:
    with pytest.raises(codec.EncodeError) as err:
        codec.encode(message)
    assert str(err.value) == error


def test_encoding_a_foreign_object() -> None:
    with pytest.raises(TypeError, match=r"^encode\(\): message must be a Veronte message, not str"):
        codec.encode("x")  # type: ignore[arg-type]
    declared = codec.Layout(20, "Other", [codec.unsigned("a", 8)])
    with pytest.raises(codec.EncodeError, match=r"^Other\.message = "):
        codec.encode(declared.message_class(a=1))


def test_infinities_and_nans_are_float32_values() -> None:
    assert codec.encode(codec.Score(0, math.inf)) == bytes.fromhex("00000000807f")
    assert codec.encode(codec.Score(0, -math.inf)) == bytes.fromhex("0000000080ff")
    assert codec.encode(codec.Score(0, math.nan)) == bytes.fromhex("00000000c07f")


@pytest.mark.parametrize("pattern", ["0100807f", "ffffffff", "0000c0ff", "0100c07f", "ffffbf7f"])
def test_nan_payloads_survive_a_round_trip(pattern: str) -> None:
    data = bytes.fromhex("0001" + pattern)
    message = codec.decode(data, sender=AP)
    assert isinstance(message, codec.ArbitrationVariable)
    assert math.isnan(message.value)
    assert codec.encode(message) == data
