"""Layouts declared by the user for the commands whose payload is not public."""

import dataclasses
import math
from typing import Any

import pytest

from veronte4x import codec
from veronte4x.codec import ByteOrder, Linear
from veronte4x.codec.compiler import FrameLayout
from veronte4x.codec.float32 import bits_from_float

ESC = codec.Layout(
    5,
    "EscTelemetry",
    [
        codec.unsigned("throttle", 8, scale=Linear(0, 200, 0.0, 100.0)),
        codec.skip(4),
        codec.signed("current", 12),
        codec.float32("voltage"),
    ],
)


def test_generated_class_is_a_frozen_slotted_message() -> None:
    cls = ESC.message_class
    assert cls.__name__ == "EscTelemetry"
    assert cls.COMMAND == 5
    assert codec.DeclaredMessage in cls.__mro__
    assert codec.Message in cls.__mro__
    assert [f.name for f in dataclasses.fields(cls)] == ["throttle", "current", "voltage"]
    msg = cls(throttle=50.0, current=-3, voltage=12.5)
    assert not hasattr(msg, "__dict__")
    with pytest.raises(AttributeError):
        msg.current = 1


def test_little_endian_both_ways() -> None:
    # byte 1: throttle 100 (= 50 %); byte 2 low nibble: padding, high nibble and byte 3:
    # current -3 as 12 bits (0xFFD) -> D0 FF; bytes 4-7: 12.5 as float32 LE.
    data = bytes.fromhex("0564d0ff00004841")
    msg = ESC.message_class(throttle=50.0, current=-3, voltage=12.5)
    assert ESC.decode(data) == msg
    assert ESC.encode(msg) == data


def test_big_endian_both_ways() -> None:
    layout = codec.Layout(
        9,
        "Temperature",
        [codec.unsigned("sensor", 4), codec.signed("celsius", 12), codec.unsigned("flags", 8)],
        byte_order=ByteOrder.BIG,
    )
    data = bytes.fromhex("093ff681")
    msg = layout.message_class(sensor=3, celsius=-10, flags=0x81)
    assert layout.decode(data) == msg
    assert layout.encode(msg) == data


def test_codec_dispatches_declared_layouts_both_ways() -> None:
    custom = codec.Codec(layouts=[ESC])
    data = bytes.fromhex("0564d0ff00004841")
    msg = custom.decode(data, sender=codec.Sender.AUTOPILOT)
    assert type(msg) is ESC.message_class
    assert custom.encode(msg) == data
    # The default codec still keeps the bytes raw.
    assert codec.decode(data, sender=codec.Sender.AUTOPILOT) == codec.ScorpionEscTelemetry(
        payload=data[1:]
    )


def test_padding_is_ignored_on_decode_and_zero_on_encode() -> None:
    data = bytes.fromhex("05640fff00004841")  # padding nibble 0xF, current 0xFF0 = -16
    msg = ESC.decode(data)
    assert msg == ESC.message_class(throttle=50.0, current=-16, voltage=12.5)
    assert ESC.encode(msg) == bytes.fromhex("056400ff00004841")


def test_constant_mismatch_is_a_decode_error() -> None:
    layout = codec.Layout(7, "Bec", [codec.constant(0xA5, 8), codec.unsigned("volts", 8)])
    assert layout.decode(b"\x07\xa5\x10") == layout.message_class(volts=16)
    assert layout.encode(layout.message_class(volts=16)) == b"\x07\xa5\x10"
    with pytest.raises(codec.DecodeError) as err:
        layout.decode(b"\x07\xa6\x10")
    assert str(err.value) == "Bec.constant: expected 0xa5, got 0xa6 (data: 07 a6 10)"


def test_scaled_field_range() -> None:
    layout = codec.Layout(6, "Rpm", [codec.unsigned("rpm", 8, scale=Linear(0, 255, 0, 5100))])
    assert layout.decode(b"\x06\xff") == layout.message_class(rpm=5100.0)
    assert layout.encode(layout.message_class(rpm=20.0)) == b"\x06\x01"
    for bad in (5200.0, -30.0, math.inf, math.nan):
        with pytest.raises(codec.EncodeError, match=r"Rpm\.rpm = .*: expected a number in"):
            layout.encode(layout.message_class(rpm=bad))


@pytest.mark.parametrize(
    ("args", "message"),
    [
        ((0, "Bad", []), "Bad: command 0 has a public layout"),
        ((2, "Bad", []), "Bad: command 2 has a public layout"),
    ],
)
def test_public_commands_cannot_be_redeclared(args: tuple, message: str) -> None:  # type: ignore[type-arg]
    with pytest.raises(codec.LayoutError, match=message):
        codec.Codec(layouts=[codec.Layout(*args)])


@pytest.mark.parametrize(
    ("fields", "message"),
    [
        ([codec.unsigned("a", 57)], "do not fit a 8-byte frame"),
        ([codec.unsigned("a", 8), codec.unsigned("a", 8)], "declared twice"),
        ([codec.unsigned("class", 8)], "not a valid field name"),
        ([codec.constant(256, 8)], "does not fit 8 bits"),
        ([codec.constant(2, 1)], "constant 2 does not fit 1 bit$"),
        ([codec.unsigned("a", 0)], "has 0 bits"),
    ],
)
def test_bad_layouts(fields: list[codec.Field], message: str) -> None:
    with pytest.raises(codec.LayoutError, match=message):
        codec.Layout(5, "Bad", fields)


@pytest.mark.parametrize(
    ("args", "message"),
    [
        ((5, "Bad", [codec.unsigned("a", 8, scale=codec.Linear(3, 3, 0.0, 1.0))]), "empty compr"),
        ((5, "Bad", [codec.Field(codec.FieldKind.BOOL, 1, "a")]), "field a cannot be declared"),
        ((5, "Bad", [codec.Field(codec.FieldKind.UNSIGNED, 8, "a", 0)]), "cannot be declared"),
        ((5, "_x y", []), "'_x y' is not a valid class name"),
        ((5, "class", []), "'class' is not a valid class name"),
        ((256, "Bad", []), "command 256 is not a byte"),
        ((-1, "Bad", []), "command -1 is not a byte"),
        ((5, "Bad", [codec.unsigned("_a", 8)]), "'_a' is not a valid field name"),
        ((5, "Bad", [codec.unsigned("a", 28), codec.signed("b", 29)]), "do not fit"),
    ],
)
def test_layout_validation_errors(args: tuple[Any, ...], message: str) -> None:
    with pytest.raises(codec.LayoutError, match=message):
        codec.Layout(*args)


def test_frame_layout_checks() -> None:
    """The checks of the layout compiler itself, on layouts only the built-ins can make."""
    FieldKind, Field = codec.FieldKind, codec.Field
    for fields, message in (
        ((Field(FieldKind.FLOAT32, 16, "score"),), "float32 field score must have 32 bits"),
        ((Field(FieldKind.MAPPED, 2, "ready", mapping=((4, True),)),), "does not fit"),
        ((Field(FieldKind.BYTES, 8, "ready"), Field(FieldKind.BOOL, 1, "ready")), "must come last"),
        ((Field(FieldKind.BOOL, 1, "ready"), Field(FieldKind.BYTES, 8, "ready")), "byte-aligned"),
        ((Field(FieldKind.UNSIGNED, 8, "ready"), Field(FieldKind.BYTES, 64, "ready")), "overflow"),
    ):
        with pytest.raises(codec.LayoutError, match=message):
            FrameLayout(codec.Ready, fields).check()


def test_a_big_endian_nan_before_another_field_keeps_its_payload() -> None:
    """The NaN path re-reads exactly the float's four bytes, not the field after them."""
    layout = codec.Layout(
        9, "Reading", [codec.float32("value"), codec.unsigned("tag", 8)], byte_order=ByteOrder.BIG
    )
    data = bytes.fromhex("097fa0000155")
    dispatching = codec.Codec(layouts=[layout])
    decoded: list[Any] = [
        layout.decode(data),
        dispatching.decode(data, sender=codec.Sender.AUTOPILOT),
    ]
    for message in decoded:
        assert bits_from_float(message.value) == 0x7FA0_0001
        assert message.tag == 0x55
        assert layout.encode(message) == data


def test_a_byte_past_the_layout_is_refused_unless_allowed() -> None:
    """A mutation survivor: ``Layout.decode``'s ``allow_excess`` defaulting to True."""
    data = bytes.fromhex("0564d0ff00004841") + b"\x00"
    with pytest.raises(codec.DecodeError) as refused:
        ESC.decode(data)
    assert str(refused.value) == (
        "EscTelemetry: 9 bytes; the layout has 8 (data: 05 64 d0 ff 00 00 48 41 00)"
    )
    assert ESC.decode(data, allow_excess=True) == ESC.message_class(50.0, -3, 12.5)
