"""`datagram_frame`, the live reader's fast way through a ``udp_multicast`` datagram, against
python-can's own: for any datagram and receive time, the frame python-can's
``UdpMulticastBus.recv`` and `frame_from_message` give, or the same failure.

python-can's ``recv`` runs as it is (``BusABC.recv``, ``_recv_internal``,
``unpack_message``, ``can.Message``'s checks); only its socket layer (``_multicast``, which
``_recv_internal`` asks for ``(data, address, receive time)``) is one datagram given here.
The socket side (select, recvmsg, the kernel's receive times) is read on a real bus in
``tests/capture/test_datagram_reader.py``.
"""

from __future__ import annotations

import math
import socket
import struct
from typing import Any

import can
import msgpack  # type: ignore[import-untyped]
import pytest
from can.interfaces.udp_multicast import UdpMulticastBus
from hypothesis import example, given
from hypothesis import strategies as st

from veronte4x.capture.frames import Frame
from veronte4x.capture.readers.live import (
    PACKED_FIELDS,
    SO_TIMESTAMPNS,
    BusFailedError,
    datagram_frame,
    receive_time,
)
from veronte4x.capture.readers.pythoncan import frame_from_message


class _OneDatagram:
    """python-can's socket layer holding one datagram received at ``timestamp``."""

    def __init__(self, data: bytes, timestamp: float) -> None:
        self.waiting: list[tuple[bytes, tuple[str, int], float]] = [
            (data, ("127.0.0.1", 43113), timestamp)
        ]

    def recv(self, timeout: float | None) -> tuple[bytes, tuple[str, int], float] | None:
        return self.waiting.pop() if self.waiting else None

    def shutdown(self) -> None:
        pass


def python_can(data: bytes, timestamp: float, fd: bool, unnamed: str) -> Frame | str | None:
    """What python-can's ``recv`` makes of the datagram, as `read_bus` turns a message into
    a frame: the frame, None for none, or the error ``read_bus`` raises."""
    bus = UdpMulticastBus.__new__(UdpMulticastBus)
    can.BusABC.__init__(bus, channel=None)  # type: ignore[arg-type]
    bus._can_protocol = can.CanProtocol.CAN_FD if fd else can.CanProtocol.CAN_20
    bus._multicast = _OneDatagram(data, timestamp)  # type: ignore[assignment]
    try:
        message = bus.recv(timeout=0.0)
    except can.CanError as error:
        return f"the CAN bus failed: {error}"
    finally:
        bus.shutdown()
    if message is None:
        return None
    frame = frame_from_message(message)
    return frame if frame.channel or not unnamed else frame._replace(channel=unnamed)


def ours(data: bytes, timestamp: float, fd: bool, unnamed: str) -> Frame | str | None:
    try:
        return datagram_frame(data, timestamp, fd, unnamed)
    except BusFailedError as error:
        return str(error)


def same(left: object, right: object) -> bool:
    """Equal, field by field of the same types (NaN equal to NaN)."""
    if isinstance(left, Frame) and isinstance(right, Frame):
        return all(
            type(a) is type(b) and (a == b or (a != a and b != b))
            for a, b in zip(left, right, strict=True)
        )
    return left == right


def packed(message: can.Message) -> bytes:
    """The datagram python-can sends for ``message`` (``pack_message``)."""
    from can.interfaces.udp_multicast.utils import pack_message

    return pack_message(message)


scalars = st.one_of(
    st.none(),
    st.booleans(),
    st.integers(-(2**40), 2**40),
    st.floats(allow_nan=True),
    st.text(max_size=4),
    st.binary(max_size=9),
)
"""Any msgpack value a field might be given instead of its own."""
ids = st.one_of(
    st.integers(0, 0x7FF),
    st.integers(0, 0x1FFFFFFF),
    st.sampled_from([-1, 0x800, 0x1FFFFFFF, 0x20000000, 2**63]),
)
lengths = st.sampled_from([0, 1, 7, 8, 9, 12, 64, 65])


@st.composite
def fields(draw: st.DrawFn) -> dict[str, Any]:
    """A msgpack map as python-can packs one, its values often right and sometimes not."""
    data = draw(st.one_of(lengths.flatmap(lambda n: st.binary(min_size=n, max_size=n)), scalars))
    size = len(data) if isinstance(data, bytes) else 0
    flag = st.one_of(st.just(False), st.just(True), scalars)
    packed: dict[str, Any] = {
        "timestamp": draw(st.floats(allow_nan=False, allow_infinity=False)),
        "arbitration_id": draw(st.one_of(ids, scalars)),
        "is_extended_id": draw(st.one_of(st.booleans(), scalars)),
        "is_remote_frame": draw(st.one_of(st.just(False), flag)),
        "is_error_frame": draw(st.one_of(st.just(False), flag)),
        "channel": draw(st.one_of(st.none(), st.sampled_from(["", "can0", "vcan1"]), scalars)),
        "dlc": draw(st.one_of(st.just(size), lengths, scalars)),
        "data": data,
        "is_fd": draw(st.one_of(st.just(False), flag)),
        "bitrate_switch": draw(st.one_of(st.just(False), flag)),
        "error_state_indicator": draw(st.one_of(st.just(False), flag)),
    }
    for name in draw(st.sets(st.sampled_from(sorted(PACKED_FIELDS)), max_size=2)):
        del packed[name]
    extra = draw(st.sampled_from([None, "is_rx", "check", "flags", "channel"]))
    if extra is not None:
        packed[extra] = draw(scalars)
    return packed


def _mapped(packed: dict[str, Any]) -> bytes:
    return bytes(msgpack.packb(packed, use_bin_type=True))


datagrams = st.one_of(
    fields().map(_mapped),
    fields().map(_mapped).flatmap(lambda d: st.integers(0, len(d)).map(lambda n: d[:n])),
    st.binary(max_size=40),
    st.one_of(scalars, st.lists(scalars, max_size=3)).map(
        lambda value: bytes(msgpack.packb(value, use_bin_type=True))
    ),
)
"""Datagrams: python-can-like maps, cut short, any bytes, and msgpack values not maps."""
times = st.one_of(
    st.floats(0.0, 2e9),
    st.floats(allow_nan=True, allow_infinity=True),
    st.sampled_from([0.0, -0.0, -1e-9, math.inf, math.nan, 1_700_000_000.123456]),
)


CLASSIC = packed(can.Message(arbitration_id=0x10015515, data=b"\x01\x02", is_extended_id=True))


@given(datagrams, times, st.booleans(), st.sampled_from(["", "rig"]))
@example(CLASSIC, 1_700_000_000.5, False, "")
@example(CLASSIC, math.inf, False, "")  # an infinite receive time: python-can's check fails
@example(CLASSIC, -1.0, True, "rig")
def test_any_datagram_is_what_python_can_makes_of_it(
    data: bytes, timestamp: float, fd: bool, unnamed: str
) -> None:
    expected = python_can(data, timestamp, fd, unnamed)
    assert same(ours(data, timestamp, fd, unnamed), expected), (data, expected)


MESSAGES = [
    can.Message(arbitration_id=0x008, data=bytes.fromhex("00008FC2F53D"), is_extended_id=False),
    can.Message(arbitration_id=0x1FFFFFFF, data=bytes(8), is_extended_id=True, channel="can1"),
    can.Message(arbitration_id=0x7FF, is_extended_id=False, is_remote_frame=True, dlc=3),
    can.Message(arbitration_id=0x00000080, is_error_frame=True, data=bytes(8)),
    can.Message(arbitration_id=0x123, data=bytes(range(64)), is_fd=True, bitrate_switch=True),
    can.Message(arbitration_id=0x123, data=bytes(12), is_fd=True, error_state_indicator=True),
    can.Message(arbitration_id=0x10, data=b"", is_extended_id=False, channel=3),
]
"""Each kind of frame python-can sends: classic standard and extended, remote, error, FD
with BRS and ESI, a channel that is not a string."""


@pytest.mark.parametrize("message", MESSAGES, ids=lambda m: repr(m)[:60])
@pytest.mark.parametrize("fd", [True, False])
def test_each_kind_of_frame_python_can_sends(message: can.Message, fd: bool) -> None:
    data = packed(message)
    expected = python_can(data, 1_700_000_000.25, fd, "rig")
    assert expected is None if message.is_fd and not fd else isinstance(expected, Frame)
    assert same(ours(data, 1_700_000_000.25, fd, "rig"), expected)


def _stamp(seconds: int, nanoseconds: int) -> list[tuple[int, int, bytes]]:
    return [(socket.SOL_SOCKET, SO_TIMESTAMPNS, struct.pack("@ll", seconds, nanoseconds))]


def test_receive_times_as_python_can_reads_them() -> None:
    assert receive_time(_stamp(1_700_000_000, 250_000_000)) == 1_700_000_000 + 0.25
    assert receive_time(_stamp(0, 999_999_999)) == 999_999_999 * 1.0e-9
    failures = [
        ([], "Only requested a single extra field but got a different amount"),
        (_stamp(1, 0) * 2, "Only requested a single extra field but got a different amount"),
        ([(socket.SOL_SOCKET, 29, bytes(16))], "received control message type that was not "
         "requested"),
        (_stamp(1, 1_000_000_000), "Timestamp nanoseconds field was out of range: 1000000000 "
         "not less than 1e9"),
    ]  # fmt: skip
    for ancillary, reason in failures:
        with pytest.raises(BusFailedError) as raised:
            receive_time(ancillary)
        assert str(raised.value) == f"the CAN bus failed: {reason}"
