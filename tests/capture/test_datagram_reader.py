"""`read_bus` on a real ``udp_multicast`` bus, read straight from its socket
(`DatagramReader`): every frame another process sends arrives, in order, with its values
(the sender: ``tests/capture/datagram_kinds.py``).

Run where the test group stays on loopback (``tests/on_loopback``). The sender sends in
chunks and waits for the test to have read each, so that no receive buffer overflows
whatever its size: the verdicts wait for frames, never for a time.
"""

from __future__ import annotations

import contextlib
import socket
import subprocess
import sys
import threading
import time
from collections.abc import Iterator
from pathlib import Path

import can
import pytest

from tests.capture.datagram_kinds import CHUNK, message
from tests.client.cli_support import GROUP, free_port
from veronte4x.canbus import open_bus
from veronte4x.capture.frames import Frame
from veronte4x.capture.readers.live import BusFailedError, BusLoss, DatagramReader, read_bus
from veronte4x.capture.readers.pythoncan import frame_from_message
from veronte4x.cli.buses import open_bus as open_guarded_bus

pytestmark = pytest.mark.skipif(sys.platform != "linux", reason="read from its socket on Linux")

GUARD = 600.0
"""A guard against a hang, not a timed assertion."""
ROOT = Path(__file__).resolve().parent.parent.parent


def expected(count: int) -> list[Frame]:
    """The frames of the sender's messages as `read_bus` gives them, times aside."""
    frames = [frame_from_message(message(i)) for i in range(count)]
    return [f if f.channel else f._replace(channel="rig") for f in frames]


@pytest.fixture
def port() -> int:
    return free_port()


def test_every_frame_another_process_sends_arrives_in_order(port: int) -> None:
    count = 12 * CHUNK
    loss = BusLoss()
    before = time.time()
    bus = open_guarded_bus(interface="udp_multicast", channel=GROUP, options={"port": port})
    try:
        reader = DatagramReader.of(bus)
        assert reader is not None  # the guarded bus of the command line is read from its socket
        reader.close()
        got = _read_from_sender(bus, count, port, loss)
    finally:
        bus.shutdown()
    after = time.time()
    assert [f._replace(timestamp=None) for f in got] == [
        f._replace(timestamp=None) for f in expected(count)
    ]
    stamps = [f.timestamp for f in got if type(f.timestamp) is float]
    assert len(stamps) == count
    assert before <= stamps[0] and stamps == sorted(stamps) and stamps[-1] <= after
    assert (loss.counted, loss.frames) == (True, 0)


def _read_from_sender(bus: object, count: int, port: int, loss: BusLoss) -> list[Frame]:
    """The frames read while another process sends ``count`` of them, chunk by chunk."""
    stop = threading.Event()
    frames = read_bus(bus, "rig", duration=GUARD, stop=stop, loss=loss)
    sender = subprocess.Popen(
        [sys.executable, "-m", "tests.capture.datagram_kinds", str(count), str(port)],
        cwd=ROOT,
        stdin=subprocess.PIPE,
        text=True,
    )
    assert sender.stdin is not None
    got: list[Frame] = []
    try:
        for frame in frames:
            got.append(frame)
            if len(got) % CHUNK == 0:
                sender.stdin.write("\n")
                sender.stdin.flush()
            if len(got) == count:
                stop.set()
    finally:
        sender.stdin.close()
        assert sender.wait(timeout=GUARD) == 0
    return got


@pytest.fixture
def sender(port: int) -> Iterator[can.BusABC]:
    with can.Bus(interface="udp_multicast", channel=GROUP, port=port) as bus:
        yield bus


def test_a_frame_is_taken_from_the_bus_only_when_asked_for(port: int, sender: can.BusABC) -> None:
    with open_bus("udp_multicast", GROUP, options={"port": port}) as bus:
        for can_id in (0x101, 0x102, 0x103):
            sender.send(can.Message(arbitration_id=can_id, is_extended_id=False))
        with contextlib.closing(read_bus(bus, duration=GUARD)) as first:
            assert next(first).can_id == 0x101
        with contextlib.closing(read_bus(bus, duration=GUARD)) as second:
            assert [next(second).can_id, next(second).can_id] == [0x102, 0x103]


def test_a_datagram_that_is_not_a_python_can_message_is_the_library_error(
    port: int, sender: can.BusABC
) -> None:
    with (
        open_bus("udp_multicast", GROUP, options={"port": port}) as bus,
        socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as raw,
    ):
        sender.send(can.Message(arbitration_id=0x101, is_extended_id=False))
        frames = read_bus(bus, duration=GUARD)
        assert next(frames).can_id == 0x101
        raw.sendto(b"\xc1 not msgpack", (GROUP, port))
        with pytest.raises(BusFailedError) as raised:
            next(frames)
    assert str(raised.value) == "the CAN bus failed: could not unpack received message"
