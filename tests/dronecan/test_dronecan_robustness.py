"""Arbitrary input never raises anything but the library's own errors."""

from __future__ import annotations

import contextlib
import dataclasses
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from veronte4x import dronecan
from veronte4x.dronecan.definitions import DATA_TYPES

_ANYTHING = st.one_of(
    st.none(),
    st.booleans(),
    st.integers(-(2**70), 2**70),
    st.floats(),
    st.text(max_size=5),
    st.binary(max_size=300),
    st.lists(st.integers(-(2**20), 2**20), max_size=25).map(tuple),
    st.sampled_from([dronecan.Empty(), dronecan.IntegerValue(2**70), dronecan.RealValue(1.0)]),
)


@pytest.mark.parametrize("data_type", DATA_TYPES, ids=lambda t: f"{t.full_name}-{t.kind.name}")
@settings(max_examples=100)
@given(payload=st.binary(max_size=400))
def test_any_payload_decodes_or_raises_decode_error(data_type: Any, payload: bytes) -> None:
    try:
        message = dronecan.decode_payload(data_type.kind, data_type.data_type_id, payload)
    except dronecan.DecodeError as error:
        assert error.message_type is not None
        return
    assert type(message) is data_type.schema.cls


@pytest.mark.parametrize("data_type", DATA_TYPES, ids=lambda t: f"{t.full_name}-{t.kind.name}")
@settings(max_examples=100)
@given(data=st.data())
def test_any_field_values_encode_or_raise_encode_error(data_type: Any, data: Any) -> None:
    cls = data_type.schema.cls
    values = {f.name: data.draw(_ANYTHING, label=f.name) for f in dataclasses.fields(cls)}
    message = cls(**values)
    destination = None if data_type.kind is dronecan.TransferKind.MESSAGE else 9
    for saturate in (False, True):
        try:
            frames = dronecan.encode(
                message,
                source_node_id=1,
                transfer_id=0,
                destination_node_id=destination,
                saturate=saturate,
            )
        except dronecan.EncodeError:
            continue
        assert all(1 <= len(f.data) <= 8 for f in frames)


@settings(max_examples=200)
@given(
    can_id=st.integers(-(2**30), 2**30),
    frames=st.lists(st.binary(max_size=9), max_size=6),
)
def test_any_frames_decode_or_raise_decode_error(can_id: int, frames: list[bytes]) -> None:
    with contextlib.suppress(dronecan.DecodeError):
        dronecan.decode_frames([(can_id, data) for data in frames])


def test_too_many_frames_is_a_decode_error() -> None:
    can_id = dronecan.message_can_id(0, 1030, 1)
    with pytest.raises(dronecan.DecodeError):
        dronecan.decode_frames([(can_id, bytes(8))] * 70)
    with pytest.raises(dronecan.DecodeError):
        dronecan.decode_frames([])


def test_unknown_class_is_a_type_error_and_unknown_type_id_a_decode_error() -> None:
    with pytest.raises(TypeError, match=r"^encode\(\): message must be a DroneCAN message"):
        dronecan.encode(object(), source_node_id=1, transfer_id=0)
    with pytest.raises(dronecan.DecodeError):
        dronecan.decode_payload(dronecan.TransferKind.MESSAGE, 7, b"")
