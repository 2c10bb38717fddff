"""A fleet firmware update through a bus cut in mid-update (issue 41, item 6): simulated
ESCs, a relay and ``veronte4x esc update`` are three processes on two udp_multicast buses.
The relay passes the nodes' first file.Read request, then nothing either way: until the
nodes have asked 8 times more (the bus is back well within the retry budgets given:
the update finishes), or for good (each node fails with one line within the update's
timeouts, and every motor reports 0 rpm). The cut and its end are events counted by the
relay, not times."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from veronte4x.dronecan.image_crc import crc64we

from .cli_support import (
    bus_args,
    free_port,
    listening,
    relay,
    simulator,
    veronte4x,
    wait_for_status,
)

IMAGE = bytes((i * 13 + 5) & 0xFF for i in range(600))
"""Two full reads and a short one: no node finishes on the one read that passes."""

NODES = range(21, 25)

GENEROUS = ("--retries", "30", "--start-timeout", "60", "--read-timeout", "60")
"""Budgets far above the cut (8 reads asked again, 0.1 s apart): the bus comes back
within them however loaded the machine."""

SHORT = ("--start-timeout", "3", "--read-timeout", "3", "--restart-timeout", "3")
"""Budgets for a bus that never comes back: any length gives the same verdict."""

FAILED = re.compile(
    r"node (\d+): failed: (accepted the update but did not read the image within 3 s"
    r"|stopped reading the image at byte \d+ of 600 \(nothing for 3 s\)"
    r"|did not answer uavcan\.protocol\.file\.BeginFirmwareUpdate \(sent 3 times, 1 s each\);"
    r" check the node id, the bus and the bit rate)"
)
"""The line of a node whose update the cut stopped, in whichever phase."""


@pytest.mark.parametrize("back", [True, False], ids=["back", "gone"])
def test_a_fleet_update_through_a_bus_cut(back: bool, tmp_path: Path) -> None:
    firmware = tmp_path / "esc-v4.bin"
    firmware.write_bytes(IMAGE)
    esc_port, tool_port = free_port(), free_port()
    with (
        simulator(esc_port, "--nodes", "21-24", "--file-timeout", "0.1"),
        relay(esc_port, tool_port, 0.0, 3, cut=(1, 8 if back else -1)) as lines,
    ):
        result = veronte4x(
            "esc",
            "update",
            "21-24",
            str(firmware),
            *bus_args(tool_port),
            *(GENEROUS if back else SHORT),
        )
        if not back:  # the nodes, on their side of the cut: no motor turns
            with listening(bus_args(esc_port)) as listener:
                wait_for_status(listener, set(NODES), lambda status: status.rpm == 0)
    assert "cut after 1 reads" in lines
    if back:
        assert "restored after 8 reads lost" in lines
        assert result.returncode == 0, result.stderr
        crc = f"{crc64we(IMAGE):#018x}"
        assert result.stdout.splitlines() == [
            f"node {n}: updated with esc-v4.bin (600 bytes, CRC-64-WE {crc}); the node "
            "reports the same CRC"
            for n in NODES
        ] + ["4 nodes: all succeeded"]
        return
    assert not [line for line in lines if line.startswith("restored")]
    assert result.returncode == 3, result.stderr
    *each, total = result.stdout.splitlines()
    assert total == "4 nodes: 0 succeeded, 4 failed (21, 22, 23, 24)"
    matched = [FAILED.fullmatch(line) for line in each]
    assert all(matched), each
    assert [int(m.group(1)) for m in matched if m] == list(NODES)
    assert [line for line in each if "stopped reading the image at byte 256 of 600" in line]
