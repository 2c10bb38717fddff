"""open_bus widens a udp_multicast bus's receive buffer: a burst of 8 nodes' file reads
(300+ datagrams) no longer overflows the default one, each lost frame a node's timeout."""

from __future__ import annotations

import os
import socket
from pathlib import Path

import can

from veronte4x.canbus import RECEIVE_BUFFER, open_bus, widen_receive_buffer

from .cli_support import GROUP, free_port


def _receive_buffer(bus: can.BusABC) -> int:
    with socket.socket(fileno=os.dup(bus.fileno())) as duplicate:
        size: int = duplicate.getsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF)
        return size


def _allowed() -> int:
    """What Linux grants a user at most: net.core.rmem_max, doubled for its bookkeeping."""
    limit = Path("/proc/sys/net/core/rmem_max")
    return 2 * min(RECEIVE_BUFFER, int(limit.read_text())) if limit.exists() else 0


def test_open_bus_widens_a_udp_multicast_bus_and_it_still_carries_frames() -> None:
    port = free_port()
    with can.Bus(interface="udp_multicast", channel=GROUP, port=port) as plain:
        default = _receive_buffer(plain)
        with open_bus("udp_multicast", GROUP, options={"port": port}) as bus:
            assert _receive_buffer(bus) >= max(default, _allowed())
            widen_receive_buffer(bus, 1024)  # never narrowed
            assert _receive_buffer(bus) >= max(default, _allowed())
            plain.send(can.Message(arbitration_id=0x10015514, data=b"\x01\xc0"))
            heard = bus.recv(600.0)  # a guard against a hang, not a timed assertion
            assert heard is not None and bytes(heard.data) == b"\x01\xc0"


def test_buses_without_a_datagram_socket_are_left_alone() -> None:
    with can.Bus(interface="virtual", channel="receive-buffer") as bus:
        widen_receive_buffer(bus)  # no fileno: nothing to do
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as stream:

        class StreamBus(can.BusABC):
            """A bus over a socket that is not a datagram one (as socketcan's is raw)."""

            def __init__(self) -> None:
                super().__init__(channel="stream")

            def send(self, msg: can.Message, timeout: float | None = None) -> None:
                raise NotImplementedError

            def fileno(self) -> int:
                return stream.fileno()

        before = stream.getsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF)
        widen_receive_buffer(StreamBus())
        assert stream.getsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF) == before
