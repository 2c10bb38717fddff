"""The generated fast `decode` against the checked one it falls back to, and proof that the
fast path is the one taken for ordinary frames."""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable
from typing import Any

import pytest
from hypothesis import given
from hypothesis import strategies as st

from tests.codec.strategies import MESSAGES
from tests.soak import differential
from veronte4x import codec
from veronte4x.codec import layouts
from veronte4x.codegen import slot_builder

CODECS = {
    "lsb_first": codec.Codec(),
    "msb_first": codec.Codec(pwm_packing=codec.PwmPacking.MSB_FIRST),
    "declared": codec.Codec(
        layouts=[codec.Layout(9, "Temperatures", [codec.unsigned("a", 8), codec.signed("b", 8)])]
    ),
}


def _outcome(function: Callable[..., Any], data: Any, **kwargs: Any) -> tuple[str, Any]:
    try:
        message = function(data, **kwargs)
    except Exception as error:  # the comparison needs the exception itself
        return type(error).__name__, str(error)
    # NaN never equals itself: compare the repr, which shows the exact class and fields.
    return "ok", repr(message)


# Frames near the built-in layouts: the real command bytes and headers, any tail.
_HEADS = st.sampled_from([b"", b"\x00", b"\x00\xff", b"\x01", b"\x02", b"\x0b", b"\x09", b"\x05"])
_FRAMES = st.one_of(
    st.binary(max_size=10),
    st.tuples(_HEADS, st.binary(max_size=8)).map(b"".join),
)


@pytest.mark.parametrize("name", CODECS)
@differential(400)
@given(data=_FRAMES, sender=st.sampled_from(codec.Sender), excess=st.booleans())
def test_fast_decode_agrees_with_the_checked_decode(
    name: str, data: bytes, sender: codec.Sender, excess: bool
) -> None:
    c = CODECS[name]
    fast = _outcome(c.decode, data, sender=sender, allow_excess=excess)
    checked = _outcome(c._checked, data, sender=sender, allow_excess=excess)
    assert fast == checked
    # bytearray and memoryview give the same as bytes.
    assert _outcome(c.decode, bytearray(data), sender=sender, allow_excess=excess) == fast
    assert _outcome(c.decode, memoryview(data), sender=sender, allow_excess=excess) == fast


def _views(data: bytes) -> list[object]:
    """Memoryviews of ``data`` whose items are not its bytes: other formats, two dimensions."""
    views = [memoryview(data).cast("c"), memoryview(data).cast("b")]
    if data and len(data) % 2 == 0:
        views += [memoryview(data).cast("H"), memoryview(data).cast("B", (2, len(data) // 2))]
    return views


@pytest.mark.parametrize("name", CODECS)
@differential(400)
@given(data=_FRAMES, sender=st.sampled_from(codec.Sender), excess=st.booleans())
def test_a_memoryview_of_any_format_or_shape_decodes_its_bytes(
    name: str, data: bytes, sender: codec.Sender, excess: bool
) -> None:
    c = CODECS[name]
    expected = _outcome(c.decode, data, sender=sender, allow_excess=excess)
    decoder = c.decoder(sender)
    for view in _views(data):
        assert _outcome(c.decode, view, sender=sender, allow_excess=excess) == expected
        assert _outcome(lambda d: decoder(d, excess), view) == expected


@pytest.mark.parametrize("name", CODECS)
@differential(400)
@given(data=_FRAMES, sender=st.sampled_from(codec.Sender), excess=st.booleans())
def test_a_senders_decoder_agrees_with_decode(
    name: str, data: bytes, sender: codec.Sender, excess: bool
) -> None:
    c = CODECS[name]
    expected = _outcome(c.decode, data, sender=sender, allow_excess=excess)
    decoder = c.decoder(sender)
    assert _outcome(lambda d: decoder(d, excess), data) == expected
    assert _outcome(lambda d: decoder(d, excess), bytearray(data)) == expected
    if not excess:
        assert _outcome(decoder, data) == expected  # allow_excess defaults to False


def _refuse(*args: Any, **kwargs: Any) -> Any:
    raise AssertionError("the checked decoder was called")


@pytest.mark.parametrize("name", ["Status", "Score", "Ready", "ArbitrationVariable", "PwmSet"])
@differential(100)
@given(data=st.data())
def test_ordinary_frames_take_the_fast_path(name: str, data: st.DataObject) -> None:
    message = data.draw(MESSAGES[name])
    if getattr(message, "cbit_ok", True) is None:
        return  # the 4-byte CEX Status is decoded by the checked path
    frame = codec.encode(message)
    sender = (
        codec.Sender.ARBITER
        if isinstance(message, (codec.Status, codec.Score))
        else codec.Sender.AUTOPILOT
    )
    with pytest.MonkeyPatch.context() as patch:
        patch.setitem(codec.decode.__globals__, "_checked", _refuse)
        decoded = codec.decode(frame, sender=sender)
    if isinstance(message, codec.Score) and math.isnan(message.score):
        return
    assert decoded == message


@pytest.mark.parametrize("name", ["lsb_first", "msb_first"])
def test_pwm_tables_give_every_value_of_the_checked_decode(name: str) -> None:
    """Every pair of a middle byte (2, 5) and its neighbours, in both halves of the frame."""
    c = CODECS[name]
    decode = c.decoder(codec.Sender.AUTOPILOT)
    for middle in range(256):
        for whole in range(256):
            frame = bytes((2, whole, middle, whole, whole, middle, whole))
            assert decode(frame, False) == c._checked(frame, sender=codec.Sender.AUTOPILOT)


@pytest.mark.parametrize(
    ("head", "tail", "sender"),
    [
        (b"\x00\xff", b"\x77\xff\xff", codec.Sender.ARBITER),  # Status: selected, arbitrating
        (b"\x00\xff", b"", codec.Sender.AUTOPILOT),  # Ready: the flag and 7 reserved bits
        (b"\x00", b"\x00\x00\x80\x3f", codec.Sender.ARBITER),  # Score's autopilot, or Status
        (b"\x00", b"\x00\x00\x80\x3f", codec.Sender.AUTOPILOT),  # ArbitrationVariable
    ],
)
def test_every_value_of_a_byte_of_several_fields(
    head: bytes, tail: bytes, sender: codec.Sender
) -> None:
    """The byte tables of the optimistic decoders, and the dispatch on byte 1, for all 256
    values of the byte."""
    for name, c in CODECS.items():
        for value in range(256):
            frame = head + bytes((value,)) + tail
            fast = _outcome(c.decode, frame, sender=sender)
            assert fast == _outcome(c._checked, frame, sender=sender), (name, frame)


def test_a_senders_decoder_takes_the_fast_path(monkeypatch: pytest.MonkeyPatch) -> None:
    decoder = codec.DEFAULT_CODEC.decoder(codec.Sender.AUTOPILOT)
    monkeypatch.setitem(decoder.__globals__, "_checked", _refuse)
    assert decoder(b"\x00\x01\x00\x00\x80\x3f", False) == codec.ArbitrationVariable(1, 1.0)
    assert decoder(b"\x00\xff\x01", False) == codec.Ready(True)


def test_opaque_frames_take_the_fast_path(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(codec.decode.__globals__, "_checked", _refuse)
    message = codec.decode(b"\x09\x01\x02", sender=codec.Sender.AUTOPILOT)
    assert message == codec.JetiTemperature(b"\x01\x02")
    assert type(message.payload) is bytes


def test_no_builder_under_a_frozen_base() -> None:
    """A builder must derive from a plain base: under a frozen one its stores would raise."""

    @dataclasses.dataclass(frozen=True, slots=True)
    class Base(codec.Message):
        x: int

    @dataclasses.dataclass(frozen=True, slots=True)
    class Child(Base):
        y: int

    assert slot_builder(Child) is None
    made = slot_builder(codec.Score)
    assert made is not None
    probe = made()
    probe.autopilot, probe.score = 1, 2.0
    probe.__class__ = codec.Score
    assert probe == codec.Score(1, 2.0)


def test_status_flags_decode_a_byte_at_a_time_and_each_tuple_is_checked_once() -> None:
    decode_source, encode_source = layouts.STATUS_4X.source_code
    lines = decode_source.splitlines()
    assert "    f4, f5, f6, f7, f8, f9, f10, f11 = _BITS[b3]" in lines
    assert "    f12, f13, f14, f15, f16, f17, f18, f19 = _BITS[b4]" in lines
    assert "    f20, f21, f22, f23, f24, f25, f26, f27 = _BITS[b5]" in lines
    checks = [
        line for line in encode_source.splitlines() if line.startswith(("def ", "    t_alive ="))
    ]
    assert checks == [
        "def encode_bits(m):",
        "    t_alive = m.alive",
        "def encode(m):",
        "    t_alive = m.alive",
    ]
