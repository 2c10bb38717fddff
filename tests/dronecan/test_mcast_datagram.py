"""The ``mcast:`` datagram against pydronecan's own driver (golden vectors both ways, made by
``make_mcast_vectors.py``), round trips, and arbitrary datagrams."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given
from hypothesis import strategies as st

from veronte4x.dronecan.mcast import (
    FD_LENGTHS,
    DatagramError,
    McastFrame,
    decode,
    encode,
    group,
)
from veronte4x.errors import EncodeError

VECTORS = json.loads((Path(__file__).parent / "data" / "pydronecan_mcast.json").read_text())

REFUSED_BY_VERONTE4X = {
    "3429c7a200007f550190000000000000000000": "9 data bytes: no length of a classic frame",
    "34298cfa01007f55019000000000000000000000": "10 data bytes: no length of a CAN FD frame",
    "3429b1a7000000080000": "standard identifier 0x800 past 11 bits",
}
"""Datagrams pydronecan hands on that hold no CAN frame (the module's docstring says so)."""


def _frame(vector: dict[str, Any]) -> McastFrame:
    return McastFrame(
        vector["can_id"], bytes.fromhex(vector["data"]), vector["extended"], vector["fd"]
    )


@pytest.mark.parametrize("vector", VECTORS["send"], ids=lambda v: v["datagram"][:24])
def test_encode_gives_the_datagram_pydronecan_sends(vector: dict[str, Any]) -> None:
    assert encode(_frame(vector)).hex() == vector["datagram"]
    assert decode(bytes.fromhex(vector["datagram"])) == _frame(vector)


@pytest.mark.parametrize("vector", VECTORS["receive"], ids=lambda v: v["datagram"][:24])
def test_decode_accepts_what_pydronecan_receives(vector: dict[str, Any]) -> None:
    datagram = bytes.fromhex(vector["datagram"])
    expected = vector["pydronecan"]
    if expected is None or vector["datagram"] in REFUSED_BY_VERONTE4X:
        with pytest.raises(DatagramError) as refused:
            decode(datagram)
        assert REFUSED_BY_VERONTE4X.get(vector["datagram"], "") in str(refused.value)
        return
    frame = decode(datagram)
    # pydronecan masks ArduPilot's remote and error bits (30, 29) away; decode keeps them
    assert (frame.can_id, frame.data, frame.extended, frame.fd) == (
        expected["can_id"],
        bytes.fromhex(expected["data"]),
        expected["extended"],
        expected["fd"],
    )
    message_id = int.from_bytes(datagram[6:10], "little")
    assert (frame.remote, frame.error) == (bool(message_id >> 30 & 1), bool(message_id >> 29 & 1))


frames = st.builds(
    lambda extended, fd, identifier, data, remote, error: McastFrame(
        identifier & (0x1FFF_FFFF if extended else 0x7FF), data, extended, fd, remote, error
    ),
    st.booleans(),
    st.booleans(),
    st.integers(0, 0x1FFF_FFFF),
    st.binary(max_size=8),
    st.booleans(),
    st.booleans(),
) | st.builds(
    McastFrame,
    st.integers(0, 0x1FFF_FFFF),
    st.sampled_from(sorted(FD_LENGTHS)).flatmap(lambda n: st.binary(min_size=n, max_size=n)),
    st.just(True),
    st.just(True),
)


@given(frames)
def test_round_trip(frame: McastFrame) -> None:
    assert decode(encode(frame)) == frame


@st.composite
def damaged(draw: st.DrawFn) -> bytes:
    """A valid datagram with one bit flipped."""
    raw = bytearray(encode(draw(frames)))
    bit = draw(st.integers(0, len(raw) * 8 - 1))
    raw[bit // 8] ^= 1 << bit % 8
    return bytes(raw)


@given(st.binary(max_size=80) | damaged())
def test_any_datagram_gives_a_frame_or_a_datagram_error(datagram: bytes) -> None:
    try:
        frame = decode(datagram)
    except DatagramError as error:
        assert error.data == datagram
        return
    assert encode(frame)[6:] == datagram[6:]  # flags other than CAN FD are ignored


@pytest.mark.parametrize(
    ("frame", "field"),
    [
        (McastFrame(0x2000_0000, b""), "can_id"),
        (McastFrame(0x800, b"", extended=False), "can_id"),
        (McastFrame(1, bytes(9)), "data"),
        (McastFrame(1, bytes(9), fd=True), "data"),
    ],
)
def test_encode_refuses_what_is_no_can_frame(frame: McastFrame, field: str) -> None:
    with pytest.raises(EncodeError) as refused:
        encode(frame)
    assert refused.value.field == field


def test_bus_groups() -> None:
    assert (group(0), group(255)) == ("239.65.82.0", "239.65.82.255")
    with pytest.raises(ValueError, match="256 is not 0 to 255"):
        group(256)
