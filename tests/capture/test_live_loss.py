"""No silent loss on a live bus: the frames the kernel drops for a full receive buffer are
counted (`BusLoss`) and every live summary says how many.

The drops are made, not waited for: the reader is stopped (its buffer narrowed, or its
process sent SIGSTOP) while more frames are sent than its buffer holds, then it reads all
that is left. Every frame sent is then either read or counted lost: exactly.
"""

from __future__ import annotations

import json
import os
import queue
import shutil
import signal
import socket
import subprocess
import sys
import threading
from collections.abc import Iterator
from pathlib import Path

import can
import pytest

from tests.client.cli_support import GROUP, bus_args, free_port
from veronte4x.canbus import RECEIVE_BUFFER, open_bus
from veronte4x.capture.monitor import MonitorState
from veronte4x.capture.readers.live import BusLoss, read_bus
from veronte4x.sockets import SO_MEMINFO, frame_socket, kernel_drops

linux_only = pytest.mark.skipif(sys.platform != "linux", reason="Linux counts the drops")

FRAME = can.Message(arbitration_id=0x008, data=bytes.fromhex("00008FC2F53D"), is_extended_id=False)
"""An ArbitrationVariable of AP1: one frame, one record."""
LAST = can.Message(arbitration_id=0x009, data=bytes.fromhex("0000CDCCCC3D"), is_extended_id=False)
"""Sent after the others: once read, every frame before it was read or dropped."""
HOLDS = 2 * RECEIVE_BUFFER // 512
"""More frames than a widened buffer holds (the kernel counts some 800 bytes a frame)."""
GUARD = 600.0
"""A guard against a hang, not a timed assertion."""


@pytest.fixture
def sender() -> Iterator[tuple[can.BusABC, int]]:
    port = free_port()
    with can.Bus(interface="udp_multicast", channel=GROUP, port=port) as bus:
        yield bus, port


def test_a_bus_without_a_socket_does_not_count() -> None:
    loss = BusLoss()
    with can.Bus(interface="virtual", channel="live-loss") as bus:
        stop = threading.Event()
        stop.set()
        assert list(read_bus(bus, stop=stop, loss=loss)) == []
    assert (loss.counted, loss.frames, loss.text()) == (False, 0, None)


@linux_only
def test_what_the_kernel_drops_is_counted(sender: tuple[can.BusABC, int]) -> None:
    tx, port = sender
    loss = BusLoss()
    with (
        can.Bus(interface="udp_multicast", channel=GROUP, port=port) as rx,
        frame_socket(rx) as narrow,  # type: ignore[union-attr]
    ):
        narrow.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
        stop = threading.Event()
        frames = read_bus(rx, duration=GUARD, stop=stop, loss=loss)
        tx.send(FRAME)
        assert next(frames).can_id == FRAME.arbitration_id  # reading began: counting too
        assert (loss.counted, loss.frames) == (True, 0)
        sent = 1000
        for _ in range(sent):  # on loopback each is in the buffer, or dropped, once sent
            tx.send(FRAME)
        read = 0
        for _ in frames:
            read += 1
            if _queued(narrow) == 0:
                stop.set()
    assert 0 < loss.frames == sent - read
    assert loss.text() == f"{loss.frames} frames lost by the bus layer"


def _queued(frames: socket.socket) -> int:
    """Bytes waiting in a socket's receive buffer (``SK_MEMINFO_RMEM_ALLOC``)."""
    raw = frames.getsockopt(socket.SOL_SOCKET, SO_MEMINFO, 36)
    return int.from_bytes(raw[:4], sys.byteorder)


@linux_only
def test_open_bus_counts_from_zero_on_its_socket(sender: tuple[can.BusABC, int]) -> None:
    _, port = sender
    with open_bus("udp_multicast", GROUP, options={"port": port}) as bus:
        duplicate = frame_socket(bus)
        assert duplicate is not None
        with duplicate:
            assert kernel_drops(duplicate) == 0


def test_the_monitor_summary_says_the_loss() -> None:
    loss = BusLoss()
    state = MonitorState(loss=loss)
    assert state.summary() == "0 records, 0 bad"  # not counted: nothing said
    loss.counted, loss.frames = True, 1
    assert state.summary() == "0 records, 0 bad, 1 frame lost by the bus layer"
    assert MonitorState().summary() == "0 records, 0 bad"


class _Lines:
    """The lines a process writes on standard output, gathered by a thread."""

    def __init__(self, process: subprocess.Popen[str]) -> None:
        self.lines: queue.Queue[str] = queue.Queue()
        assert process.stdout is not None
        stream = process.stdout
        threading.Thread(target=lambda: [*map(self.lines.put, stream)], daemon=True).start()
        self.seen: list[str] = []

    def until(self, can_id: int, send: can.BusABC, message: can.Message) -> int:
        """Send ``message`` until a record of ``can_id`` comes out; return how many were
        sent. Each is sent once the one before has had long to come out: when one does,
        none was sent after it."""
        sent = 0
        while True:
            send.send(message)
            sent += 1
            try:
                while True:
                    line = self.lines.get(timeout=2.0)  # a retry, not a verdict
                    self.seen.append(line)
                    if json.loads(line)["can_id"] == can_id:
                        return sent
            except queue.Empty:
                assert sent < 300, "the reader never read"


@linux_only
@pytest.mark.skipif(not hasattr(signal, "SIGSTOP"), reason="needs SIGSTOP")
def test_decode_on_a_live_bus_says_every_frame_it_lost(sender: tuple[can.BusABC, int]) -> None:
    """Across processes: decode is stopped while more frames come than its buffer holds;
    its summary counts exactly the frames it never read."""
    tx, port = sender
    command = [sys.executable, "-m", "veronte4x", "decode", "--output", "jsonl"]
    process = subprocess.Popen(
        [*command, *bus_args(port)],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        lines = _Lines(process)
        lines.until(FRAME.arbitration_id, tx, FRAME)  # listening: those sent before were not
        listening = len(lines.seen)  # heard at all, and none was sent after the last read
        os.kill(process.pid, signal.SIGSTOP)
        for _ in range(HOLDS):
            tx.send(FRAME)
        os.kill(process.pid, signal.SIGCONT)
        sent = HOLDS + lines.until(LAST.arbitration_id, tx, LAST)
        process.send_signal(signal.SIGINT)
        _, errors = process.communicate(timeout=GUARD)
    finally:
        process.kill()
    records = len(lines.seen) + lines.lines.qsize()
    lost = sent - (records - listening)
    assert lost > 0
    # Ctrl-C ends the stream (exit 0, "(skip)") or, landing between records, the command
    # (exit 130, "interrupted after"): the counts are the same either way.
    counts = f"{records} records, 0 undecoded, 0 bad, {lost} frames lost by the bus layer"
    assert errors.splitlines()[-1] in (
        f"veronte4x: {counts} (skip)",
        f"veronte4x: interrupted after {counts}",
    )
    assert process.returncode == (0 if errors.endswith("(skip)\n") else 130)


AS_ROOT = hasattr(os, "geteuid") and os.geteuid() == 0


def _rmem_max() -> int:
    limit = Path("/proc/sys/net/core/rmem_max")
    return int(limit.read_text()) if limit.exists() else 0


@linux_only
@pytest.mark.skipif(
    not 0 < _rmem_max() < RECEIVE_BUFFER, reason="needs a net.core.rmem_max under 16 MiB"
)
@pytest.mark.skipif(AS_ROOT and shutil.which("setpriv") is None, reason="root needs setpriv")
def test_a_receive_buffer_smaller_than_asked_for_is_said() -> None:
    """Without CAP_NET_ADMIN the kernel gives a socket at most net.core.rmem_max: every
    summary says so beside the loss it counts."""
    port = free_port()
    drop = ["setpriv", "--bounding-set=-net_admin"] if AS_ROOT else []  # no SO_RCVBUFFORCE
    command = [*drop, sys.executable, "-m", "veronte4x", "decode", *bus_args(port)]
    done = subprocess.run(
        [*command, "--duration", "0.1"], capture_output=True, text=True, timeout=GUARD
    )
    given = f"{_rmem_max() / 2**20:.3g} MiB" if _rmem_max() >= 2**20 else None
    assert done.returncode == 0, done.stderr
    said = done.stderr.splitlines()[-1]
    assert said.startswith("veronte4x: 0 records, 0 undecoded, 0 bad, 0 frames lost by the bus ")
    assert said.endswith(
        ", not the 16 MiB asked for: the system's limit, net.core.rmem_max on Linux) (skip)"
    )
    assert given is None or f"a receive buffer of {given}," in said


def test_the_receive_buffer_is_said_only_where_it_is_short() -> None:
    loss = BusLoss()
    loss.counted = True
    assert loss.text() == "0 frames lost by the bus layer"
    loss.short_buffer = (212_992, RECEIVE_BUFFER)
    assert loss.text() == (
        "0 frames lost by the bus layer (a receive buffer of 208 KiB, not the 16 MiB asked "
        "for: the system's limit, net.core.rmem_max on Linux)"
    )
