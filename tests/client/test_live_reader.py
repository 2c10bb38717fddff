"""The live-bus reader: frames from a python-can bus, a duration, a stop event, bus failures.

(The channel name argument fills in frames that carry none, as udp_multicast's do; the
virtual interface names its channel itself.)
"""

from __future__ import annotations

import threading

import can
import pytest

from veronte4x.capture import Frame
from veronte4x.capture.readers.live import BusFailedError, read_bus


def test_frames_until_the_duration_ends() -> None:
    with (
        can.Bus(interface="virtual", channel="live-1") as bus,
        can.Bus(interface="virtual", channel="live-1") as other,
    ):
        other.send(can.Message(arbitration_id=0x10015515, data=b"\x01\x02", is_extended_id=True))
        other.send(can.Message(arbitration_id=0x0FF, data=b"\x01", is_extended_id=False))
        frames = list(read_bus(bus, "rig", duration=0.2))
    assert [(f.channel, f.can_id, f.data, f.extended) for f in frames] == [
        ("live-1", 0x10015515, b"\x01\x02", True),
        ("live-1", 0x0FF, b"\x01", False),
    ]
    assert all(isinstance(f, Frame) and f.timestamp is not None for f in frames)


def test_a_stop_event_ends_it() -> None:
    stop = threading.Event()
    stop.set()
    with can.Bus(interface="virtual", channel="live-2") as bus:
        assert list(read_bus(bus, stop=stop)) == []


def test_a_failing_bus_is_the_library_error() -> None:
    bus = can.Bus(interface="virtual", channel="live-3")
    bus.shutdown()
    with pytest.raises(BusFailedError, match=r"^the CAN bus failed: "):
        list(read_bus(bus, duration=0.2))
