"""The ``mcast:`` bus (`veronte4x.mcastbus`) on the machine's loopback: two buses in this
process, and the command line beside pydronecan nodes in other processes (run under
``tests/on_loopback``). Each test has a bus number of its own; pydronecan's port is fixed."""

from __future__ import annotations

import os
import socket
import subprocess
import sys
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import can

from tests.client.cli_support import HANG_GUARD, free_port
from veronte4x import capture
from veronte4x.canbus import BusOpenError, open_bus
from veronte4x.dronecan import NodeStatus
from veronte4x.dronecan.mcast import McastFrame, encode, group

PEER = Path(__file__).with_name("pydronecan_mcast_peer.py")


def _receive(bus: can.BusABC) -> can.Message:
    """The next message, waiting as long as a guard allows (not a timed assertion)."""
    message = bus.recv(HANG_GUARD)
    assert message is not None, "nothing came"
    return message


def test_two_buses_hear_each_other_not_themselves_and_drop_what_is_no_frame() -> None:
    port = free_port()
    with (
        open_bus(interface="mcast", channel="3", options={"port": port}) as one,
        open_bus(interface="mcast", channel="3", options={"port": port}) as other,
        socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as raw,
    ):
        one.send(can.Message(arbitration_id=0x1001557F, data=b"\x01\x02\xc0"))
        heard = _receive(other)
        raw.connect((group(3), port))
        raw.send(b"\x34\x29garbage")
        raw.send(encode(McastFrame(0x7FF, b"", extended=False)))
        after = _receive(other)
        first = _receive(one)  # not its own frame: the raw socket's
        other.send(can.Message(arbitration_id=0x1234, data=bytes(range(12)), is_fd=True))
        back = _receive(one)
    assert (heard.arbitration_id, heard.data, heard.is_extended_id, heard.channel) == (
        0x1001557F,
        b"\x01\x02\xc0",
        True,
        "mcast:3",
    )
    assert (after.arbitration_id, after.is_extended_id, after.dlc) == (0x7FF, False, 0)
    assert first.arbitration_id == 0x7FF
    assert (back.arbitration_id, back.data, back.is_fd) == (0x1234, bytes(range(12)), True)


def test_a_channel_that_is_no_bus_number_is_one_line() -> None:
    try:
        open_bus(interface="mcast", channel="can0")
    except BusOpenError as error:
        assert str(error) == (
            "cannot open the CAN bus (interface mcast, channel can0): mcast channel 'can0' "
            "is no bus number 0 to 255"
        )
    else:
        raise AssertionError("opened")


@contextmanager
def _peer(*args: str) -> Iterator[subprocess.Popen[str]]:
    process = subprocess.Popen(
        [sys.executable, str(PEER), *args],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        yield process
    finally:
        process.terminate()
        process.communicate(timeout=HANG_GUARD)


@contextmanager
def _publishing_node(bus: str) -> Iterator[None]:
    """pydronecan's node 42 on mcast bus ``bus``, ready and sending NodeStatus every second."""
    with _peer(bus, "publish") as node:
        assert node.stdout is not None and node.stdout.readline() == "ready\n"
        yield


def _record(bus: str, to: str, out: Path) -> None:
    """``veronte4x record`` of two frames of the publishing node on mcast bus ``bus`` into
    ``out`` in the format ``to``; it succeeds with its one-line summary."""
    with _publishing_node(bus):
        recorded = subprocess.run(
            [sys.executable, "-m", "veronte4x", "record", "-i", "mcast", "-c", bus,
             "--count", "2", "--to", to, str(out)],
            capture_output=True, text=True, timeout=HANG_GUARD, check=False,
        )  # fmt: skip
    assert (recorded.returncode, recorded.stderr) == (
        0,
        f"veronte4x: 2 frames in {out}, 0 frames lost by the bus layer\n",
    )


def test_decode_reads_a_pydronecan_node() -> None:
    with _publishing_node("101"):
        decode = subprocess.Popen(
            [sys.executable, "-m", "veronte4x", "decode", "-i", "mcast", "-c", "101"],
            env={**os.environ, "PYTHONUNBUFFERED": "1"},  # each record as it comes
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
        )
        assert decode.stdout is not None
        try:
            line = decode.stdout.readline()  # pydronecan sends NodeStatus every second
        finally:
            decode.terminate()
            _, err = decode.communicate(timeout=HANG_GUARD)
    assert " mcast:101 " in line and " node 42 " in line and "NodeStatus(uptime_sec=" in line
    assert "Traceback" not in err


def test_a_pydronecan_node_sees_and_asks_the_simulated_esc() -> None:
    simulator = subprocess.Popen(
        [sys.executable, "-m", "veronte4x", "simulate", "esc", "--nodes", "21", "-i", "mcast",
         "-c", "102"],
        stderr=subprocess.PIPE,
        text=True,
    )  # fmt: skip
    try:
        assert simulator.stderr is not None
        assert simulator.stderr.readline().startswith("veronte4x: simulating Vertiq ESC nodes")
        watcher = subprocess.run(
            [sys.executable, str(PEER), "102", "watch", "21"],
            capture_output=True,
            text=True,
            timeout=HANG_GUARD,
            check=False,
        )
    finally:
        simulator.terminate()
        simulator.communicate(timeout=HANG_GUARD)
    assert watcher.returncode == 0, watcher.stderr
    lines = dict(line.split(" ", 1) for line in watcher.stdout.splitlines())
    assert lines["esc_status"] == "0 0"  # no error, not spinning
    assert lines["node_info"] == "iq_motion.esc"  # the simulated Vertiq module's name


def test_record_writes_what_pydronecan_plays_from_a_pydronecan_node(tmp_path: Path) -> None:
    out = tmp_path / "bus.can"
    _record("103", "pydronecan", out)
    from dronecan.driver.file import file as pydronecan_file

    player = pydronecan_file(os.fspath(out), readonly=True)
    played = []
    while (item := player._read_frame())[0] is not None:
        played.append((item[1], item[0].id, bytes(item[0].data), item[0].extended))
    player.close()
    player.file = None  # its __del__ would flush the closed file again
    assert [
        (can_id >> 8 & 0xFFFF, can_id & 0x7F, extended) for _, can_id, _, extended in played
    ] == [
        (341, 42, True),  # node 42's NodeStatus, every second
        (341, 42, True),
    ]
    records = list(capture.read(out))
    assert [(r.timestamp, r.can_id, r.node_id) for r in records] == [
        (stamp, can_id, 42) for stamp, can_id, _, _ in played
    ]
    assert all(isinstance(r.message, NodeStatus) for r in records)


def test_record_writes_candump_text_that_python_can_reads(tmp_path: Path) -> None:
    out = tmp_path / "bus.log"
    _record("104", "candump", out)
    read = [(m.timestamp, m.channel, m.arbitration_id, bytes(m.data)) for m in can.LogReader(out)]
    records = list(capture.read(out))
    assert [(r.timestamp, r.channel, r.can_id, r.data) for r in records] == read
    assert [(r.channel, r.node_id, type(r.message)) for r in records] == [
        ("mcast:104", 42, NodeStatus),
        ("mcast:104", 42, NodeStatus),
    ]
