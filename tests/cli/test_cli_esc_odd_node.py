"""``veronte4x esc`` against nodes unlike the simulated Vertiq ESC, of the test's own on the
udp_multicast bus, in a thread (real frames through the real encoder, the CLI as a
subprocess): node 30 sends NodeStatus but does not answer GetNodeInfo, and its one
parameter, ``esc_index``, is a real number with no default and no range; node 31 answers
everything but keeps its ``esc_index`` whatever it is set to (a set it does not take).
"""

from __future__ import annotations

import json
import re
import threading
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import can
import pytest

from tests.client.cli_support import GROUP, bus_args, free_port, veronte4x
from veronte4x import dronecan

ODD = 30
STUBBORN = 31
LONG_UP = 4_000_000_000
"""Node 30's uptime at the start, seconds: near the end of its uint32 counter."""


def _parameter(node: int, request: dronecan.GetSetRequest, kept: int) -> object:
    """Node 30's real ``esc_index`` without range, node 31's integer one that keeps
    ``kept``; an empty response (the end of the list) for anything else."""
    if request.name != b"esc_index" and (request.name or request.index != 0):
        return dronecan.GetSetResponse()
    if node == ODD:
        return dronecan.GetSetResponse(value=dronecan.RealValue(1.5), name=b"esc_index")
    return dronecan.GetSetResponse(
        value=dronecan.IntegerValue(kept),
        default_value=dronecan.IntegerValue(kept),
        max_value=dronecan.IntegerValue(19),
        min_value=dronecan.IntegerValue(0),
        name=b"esc_index",
    )


def _serve(port: int, stop: threading.Event) -> None:
    """Both nodes' NodeStatus every 0.1 s, and their answers."""
    reassembler = dronecan.Reassembler()
    transfer_id = 0
    with can.Bus(interface="udp_multicast", channel=GROUP, port=port) as bus:

        def send(message: object, node: int, transfer_id: int, **route: Any) -> None:
            for frame in dronecan.encode(message, source_node_id=node, transfer_id=transfer_id,
                                         **route):  # fmt: skip
                bus.send(can.Message(arbitration_id=frame.can_id, data=frame.data))

        uptime = 0.0
        while not stop.is_set():
            for node in (ODD, STUBBORN):
                since = int(uptime) + (LONG_UP if node == ODD else 0)
                send(dronecan.NodeStatus(uptime_sec=since), node, transfer_id % 32)
            transfer_id += 1
            uptime += 0.1
            while (frame := bus.recv(0.1)) is not None:
                if not frame.is_extended_id:
                    continue
                transfer = reassembler.feed(frame.arbitration_id, bytes(frame.data), uptime)
                if transfer is None or transfer.destination_node_id not in (ODD, STUBBORN):
                    continue
                node = transfer.destination_node_id
                request = transfer.message
                if isinstance(request, dronecan.GetSetRequest):
                    answer = _parameter(node, request, kept=1)
                elif isinstance(request, dronecan.GetNodeInfoRequest) and node == STUBBORN:
                    answer = dronecan.GetNodeInfoResponse(
                        status=dronecan.NodeStatus(uptime_sec=int(uptime)),
                        hardware_version=dronecan.HardwareVersion(unique_id=bytes(15) + b"\x1f"),
                        name=b"stubborn.esc",
                    )
                else:
                    continue  # node 30 never tells its name
                route = {
                    "priority": transfer.priority,
                    "destination_node_id": transfer.source_node_id,
                }
                send(answer, node, transfer.transfer_id, **route)


@pytest.fixture(scope="module")
def bus() -> Iterator[list[str]]:
    port = free_port()
    stop = threading.Event()
    thread = threading.Thread(target=_serve, args=(port, stop), daemon=True)
    thread.start()
    try:
        yield bus_args(port)
    finally:
        stop.set()
        thread.join()


def test_a_node_that_does_not_tell_its_name(bus: list[str]) -> None:
    result = veronte4x("esc", "nodes", *bus, "--retries", "0")
    assert (result.returncode, result.stderr) == (0, ""), result.stderr
    lines = result.stdout.splitlines()
    assert lines[0] == (
        "node  name          health    mode                   uptime         seen  vendor"
    )  # the uptime column as wide as node 30's ten digits
    rest = r"  (?= *\d+\.\d s)[ \d.]{5} s ago  0x0000"
    assert re.fullmatch(
        r"  30  \?             OK        OPERATIONAL      4000\d{6} s" + rest, lines[1]
    ), lines
    assert re.fullmatch(
        r"  31  stubborn\.esc  OK        OPERATIONAL      (?= *\d+ s)[ \d]{10} s" + rest, lines[2]
    ), lines
    assert len(lines) == 3
    assert {len(line) for line in lines} == {len(lines[0])}, lines


def test_a_parameter_with_no_default_and_no_range(bus: list[str]) -> None:
    result = veronte4x("esc", "params", str(ODD), *bus)
    assert (result.returncode, result.stderr) == (0, ""), result.stderr
    assert result.stdout.splitlines() == [
        "index  name            value     default  range",
        "    0  esc_index         1.5           -  -",
    ]
    result = veronte4x("esc", "get", str(ODD), "esc_index", *bus)
    assert result.stdout == "esc_index = 1.5 (default -, range -)\n"  # it said 'None'


def test_spin_refuses_an_esc_index_that_is_not_a_whole_number(bus: list[str]) -> None:
    result = veronte4x(
        "esc", "spin", str(ODD), "--throttle", "0.1", "--duration", "1", "--yes", *bus
    )
    assert (result.returncode, result.stdout, result.stderr) == (
        2,
        "",
        "veronte4x: node 30 reports esc_index 1.5, not a number\n",
    )


def test_apply_onto_a_node_that_does_not_take_the_value(bus: list[str], tmp_path: Path) -> None:
    saved = tmp_path / "stubborn.toml"
    result = veronte4x("esc", "params", str(STUBBORN), *bus, "--save", str(saved))
    assert result.returncode == 0, result.stderr
    text = saved.read_text(encoding="utf-8")
    saved.write_text(text.replace("value = 1,", "value = 2,"), encoding="utf-8")
    refused = veronte4x("esc", "apply", str(saved), str(STUBBORN), *bus)
    assert (refused.returncode, refused.stderr) == (
        2,
        "veronte4x: node 30's esc_index cannot be read, so it may hold the same one "
        "(reports esc_index 1.5, not a number); add --allow-unknown-index 30 if it drives no "
        "motor; nothing was sent\n",
    )  # node 30's real esc_index says nothing of the RawCommand entry it reads
    unknown = ("--allow-unknown-index", str(ODD))
    result = veronte4x("esc", "apply", str(saved), str(STUBBORN), *bus, *unknown)
    assert (result.returncode, result.stdout.splitlines(), result.stderr) == (
        4,
        [
            "node 31: esc_index 1 -> 2",
            "node 31: failed after setting nothing: kept esc_index at 1 instead of 2; not saved",
            "1 node: failed (31)",
        ],
        "veronte4x: 1 node: failed (31)\n",  # it said nothing there before
    )
    result = veronte4x("esc", "apply", str(saved), str(STUBBORN), *bus, *unknown, "--json")
    assert result.returncode == 4
    assert json.loads(result.stdout) == {
        "nodes": [
            {
                "node_id": 31,
                "ok": False,
                "set": [],
                "error": "node 31 kept esc_index at 1 instead of 2",
            }
        ],
        "total": 1,
        "failed": [31],
    }
    assert result.stderr == "veronte4x: 1 node: failed (31)\n"
