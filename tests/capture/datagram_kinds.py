"""The frames `tests/capture/test_datagram_reader.py` has another process send: each kind
python-can sends, in turn (run as ``python -m tests.capture.datagram_kinds COUNT PORT``)."""

from __future__ import annotations

import sys

import can

from tests.client.cli_support import GROUP

CHUNK = 100
"""Frames sent before the sender waits for a line on its standard input (the reader has
read them): no receive buffer overflows, whatever its size."""


def message(i: int) -> can.Message:
    """The ``i``-th frame: classic standard and extended (a channel named), remote, error,
    CAN FD with BRS and with ESI, in turn."""
    kind = i % 6
    if kind == 0:
        return can.Message(arbitration_id=0x008, data=i.to_bytes(2, "big"), is_extended_id=False)
    if kind == 1:
        return can.Message(arbitration_id=0x1FFFFFFF, data=i.to_bytes(8, "big"), channel="can1")
    if kind == 2:
        return can.Message(
            arbitration_id=i % 0x800, is_extended_id=False, is_remote_frame=True, dlc=i % 9
        )
    if kind == 3:
        return can.Message(arbitration_id=0x00000080, is_error_frame=True, data=bytes(8))
    if kind == 4:
        return can.Message(
            arbitration_id=0x123, data=i.to_bytes(64, "big"), is_fd=True, bitrate_switch=True
        )
    return can.Message(
        arbitration_id=0x18FF0000 + i,
        data=i.to_bytes(12, "big"),
        is_fd=True,
        error_state_indicator=True,
    )


def send(count: int, port: int) -> None:
    """Send ``count`` frames on the group's bus at ``port``, a line of standard input
    awaited after each `CHUNK`."""
    with can.Bus(interface="udp_multicast", channel=GROUP, port=port) as bus:
        for i in range(count):
            bus.send(message(i))
            if (i + 1) % CHUNK == 0:
                sys.stdin.readline()


if __name__ == "__main__":
    send(int(sys.argv[1]), int(sys.argv[2]))
