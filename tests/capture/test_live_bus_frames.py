"""`read_bus` on real python-can buses: frames of a bus that names no channel take the name
given (udp_multicast's), and a stream without a duration runs until its stop event is set
by the code that reads it."""

from __future__ import annotations

import threading

import can

from tests.client.cli_support import GROUP, free_port
from veronte4x.capture import Frame
from veronte4x.capture.readers.live import read_bus


def test_frames_of_a_bus_without_channel_names_take_the_name_given() -> None:
    port = free_port()
    with (
        can.Bus(interface="udp_multicast", channel=GROUP, port=port) as bus,
        can.Bus(interface="udp_multicast", channel=GROUP, port=port) as other,
    ):
        other.send(can.Message(arbitration_id=0x009, data=b"\x00\xff\x01", is_extended_id=False))
        named = next(read_bus(bus, "rig", duration=30.0))
        other.send(can.Message(arbitration_id=0x009, data=b"\x00\xff\x00", is_extended_id=False))
        unnamed = next(read_bus(bus, duration=30.0))
    assert (named.channel, named.can_id, named.data) == ("rig", 0x009, b"\x00\xff\x01")
    assert (unnamed.channel, unnamed.data) == ("", b"\x00\xff\x00")


def test_without_a_duration_the_stream_runs_until_stopped() -> None:
    """The reader of a live monitor sets the stop event (Ctrl-C in another thread): the
    frames received before it are all given, and the stream then ends."""
    stop = threading.Event()
    got: list[Frame] = []
    with (
        can.Bus(interface="virtual", channel="live-until-stop") as bus,
        can.Bus(interface="virtual", channel="live-until-stop") as other,
    ):
        for i in range(3):
            other.send(can.Message(arbitration_id=0x100 + i, data=bytes([i]), is_extended_id=False))
        for frame in read_bus(bus, stop=stop):
            got.append(frame)
            if len(got) == 3:
                stop.set()  # no frame more is waited for
        assert [(f.channel, f.can_id, f.data) for f in got] == [
            ("live-until-stop", 0x100, b"\x00"),
            ("live-until-stop", 0x101, b"\x01"),
            ("live-until-stop", 0x102, b"\x02"),
        ]
        other.send(can.Message(arbitration_id=0x103, data=b"\x03", is_extended_id=False))
        assert list(read_bus(bus, stop=stop)) == []
        stop.clear()
        assert next(read_bus(bus, stop=stop)).can_id == 0x103  # left on the bus for the next
