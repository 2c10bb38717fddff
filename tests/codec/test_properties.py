"""Property-based round trips over every message type and every valid frame."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tests.codec.strategies import MESSAGES, VALID_FRAMES
from tests.soak import differential
from veronte4x import codec

PACKINGS = [codec.Codec(pwm_packing=p) for p in codec.PwmPacking]


@pytest.mark.parametrize("name", sorted(MESSAGES))
@pytest.mark.parametrize("packing_codec", PACKINGS, ids=lambda c: c.pwm_packing.value)
@differential(150)
@given(data=st.data())
def test_decode_encode_message(name: str, packing_codec: codec.Codec, data: st.DataObject) -> None:
    message = data.draw(MESSAGES[name])
    frame = packing_codec.encode(message)
    if isinstance(message, (codec.Status, codec.Score)):
        senders = [codec.Sender.ARBITER]
    elif isinstance(message, (codec.Ready, codec.ArbitrationVariable)):
        senders = [codec.Sender.AUTOPILOT]
    else:
        senders = list(codec.Sender)
    for sender in senders:
        assert packing_codec.decode(frame, sender=sender) == message


@pytest.mark.parametrize("name", sorted(VALID_FRAMES))
@pytest.mark.parametrize("packing_codec", PACKINGS, ids=lambda c: c.pwm_packing.value)
@differential(150)
@given(data=st.data())
def test_encode_decode_frame(name: str, packing_codec: codec.Codec, data: st.DataObject) -> None:
    sender, frames = VALID_FRAMES[name]
    frame = data.draw(frames)
    assert packing_codec.encode(packing_codec.decode(frame, sender=sender)) == frame


@settings(max_examples=1500)
@given(frame=st.binary(max_size=8), sender=st.sampled_from(codec.Sender))
def test_arbitrary_bytes_decode_or_raise_decode_error(frame: bytes, sender: codec.Sender) -> None:
    try:
        message = codec.decode(frame, sender=sender)
    except codec.DecodeError:
        return
    assert codec.encode(message) == frame


@settings(max_examples=800)
@given(frame=st.binary(max_size=10), sender=st.sampled_from(codec.Sender))
def test_arbitrary_bytes_with_excess_allowed(frame: bytes, sender: codec.Sender) -> None:
    try:
        message = codec.decode(frame, sender=sender, allow_excess=True)
    except codec.DecodeError:
        return
    assert frame.startswith(codec.encode(message))


_bad_float = st.one_of(st.floats(min_value=3.5e38), st.floats(max_value=-3.5e38)).filter(
    math.isfinite
)

OUT_OF_RANGE: dict[str, st.SearchStrategy[codec.Message]] = {
    "Status.selected": st.builds(
        codec.Status,
        selected=st.one_of(st.integers(max_value=-1), st.integers(min_value=4)),
        arbitrating=st.booleans(),
        alive=st.just((False,) * 4),
        ready=st.just((True,) * 4),
    ),
    "Score.autopilot": st.builds(
        codec.Score, autopilot=st.integers(min_value=4), score=st.floats(width=32)
    ),
    "Score.score": st.builds(codec.Score, autopilot=st.integers(0, 3), score=_bad_float),
    "ArbitrationVariable.number": st.builds(
        codec.ArbitrationVariable,
        number=st.one_of(st.integers(max_value=-1), st.integers(min_value=32)),
        value=st.floats(width=32),
    ),
    "PwmSet.values": st.builds(
        codec.PwmSet,
        first_channel=st.just(4),
        values=st.tuples(st.integers(0, 4095), st.integers(min_value=4096), st.just(0), st.just(0)),
    ),
    "PwmSet.first_channel": st.builds(
        codec.PwmSet,
        first_channel=st.integers().filter(lambda c: c not in (0, 4, 8, 12, 16)),
        values=st.just((0, 0, 0, 0)),
    ),
    "VersionResponse.rest": st.builds(
        codec.VersionResponse, application_code=st.just(1), rest=st.binary(min_size=7)
    ),
    "McuTelemetry1.payload": st.builds(codec.McuTelemetry1, payload=st.binary(min_size=8)),
}


@pytest.mark.parametrize("name", sorted(OUT_OF_RANGE))
@settings(max_examples=100)
@given(data=st.data())
def test_out_of_range_fields_raise_encode_error(name: str, data: st.DataObject) -> None:
    message = data.draw(OUT_OF_RANGE[name])
    with pytest.raises(codec.EncodeError) as err:
        codec.encode(message)
    assert f"{err.value.message_type}.{err.value.field}".startswith(name)
