"""``veronte4x esc`` and ``veronte4x simulate esc`` as subprocesses on a udp_multicast bus.

The simulator runs in one process and each command in another, as on a bench. Exit codes
and the first line of standard error are asserted; after every error the node is checked
to be left safe (still answering, motors stopped).
"""

from __future__ import annotations

import json
import re
import signal
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

from tests.client.cli_support import (
    HANG_GUARD,
    bus_args,
    free_port,
    listening,
    simulator,
    stopped_for_good,
    veronte4x,
    veronte4x_all,
    wait_for_status,
)
from veronte4x.dronecan.image_crc import crc64we
from veronte4x.simulator.motor import MotorModel


@pytest.fixture(scope="module")
def bus() -> Iterator[list[str]]:
    port = free_port()
    with simulator(port, "--nodes", "21,22"):
        yield bus_args(port)


def test_nodes(bus: list[str]) -> None:
    result = veronte4x("esc", "nodes", *bus, "--json")
    assert result.returncode == 0, result.stderr
    nodes = json.loads(result.stdout)
    assert [(n["node_id"], n["name"], n["health"], n["mode"]) for n in nodes] == [
        (21, "iq_motion.esc", "OK", "OPERATIONAL"),
        (22, "iq_motion.esc", "OK", "OPERATIONAL"),
    ]


def test_info_and_params(bus: list[str]) -> None:
    info, params = veronte4x_all(
        ["esc", "info", "21", *bus, "--node-id", "120"],
        ["esc", "params", "22", *bus, "--json", "--node-id", "121"],
    )
    assert info.returncode == 0, info.stderr
    assert info.stdout.splitlines()[0] == "node 21: iq_motion.esc"
    assert params.returncode == 0, params.stderr
    assert [(p["name"], p["value"], p["min"], p["max"]) for p in json.loads(params.stdout)] == [
        ("uavcan_node_id", 22, 1, 127),
        ("bit_rate", 500000, 10000, 1000000),
        ("esc_index", 1, 0, 19),
        ("zero_behavior", 0, 0, 2),
        ("telem_frequency", 10, 0, 1000),
    ]


def test_set_save_get(bus: list[str]) -> None:
    result = veronte4x("esc", "set", "22", "zero_behavior", "1", *bus)
    assert (result.returncode, result.stdout) == (
        0,
        "zero_behavior = 1 (default 0, range 0..2)\n",
    )
    assert veronte4x("esc", "save", "22", *bus).stdout == "node 22: parameters saved\n"
    result = veronte4x("esc", "get", "22", "zero_behavior", *bus, "--json")
    assert json.loads(result.stdout)["value"] == 1


def test_errors_are_one_line_with_their_exit_code(bus: list[str]) -> None:
    out_of_range, bad_name, no_node, unconfirmed = veronte4x_all(
        ["esc", "set", "21", "esc_index", "20", *bus, "--node-id", "120"],
        ["esc", "get", "21", "esc_idx", *bus, "--node-id", "121"],
        ["esc", "info", "99", *bus, "--timeout", "0.2", "--retries", "0", "--node-id", "122"],
        ["esc", "spin", "21", "--throttle", "0.2", "--duration", "1", *bus],
    )
    assert out_of_range.returncode == 4
    assert out_of_range.stderr == ("veronte4x: node 21: 20 is out of range for esc_index: 0..19\n")
    assert bad_name.returncode == 4
    assert bad_name.stderr == "veronte4x: node 21 has no parameter 'esc_idx'\n"
    assert no_node.returncode == 3
    assert no_node.stderr == (
        "veronte4x: node 99 did not answer uavcan.protocol.GetNodeInfo (sent once, 0.2 s "
        "each); check the node id, the bus and the bit rate\n"
    )
    assert unconfirmed.returncode == 2
    assert unconfirmed.stderr.startswith("veronte4x: esc spin moves motors: add --yes")
    result = veronte4x("esc", "get", "21", "esc_index", *bus)
    assert result.stdout == "esc_index = 0 (default 0, range 0..19)\n"  # unchanged


def test_update_then_info_reports_the_image_crc(bus: list[str], tmp_path: Path) -> None:
    image = bytes((i * 31 + 7) & 0xFF for i in range(2500))
    firmware = tmp_path / "esc.bin"
    firmware.write_bytes(image)
    result = veronte4x("esc", "update", "21", str(firmware), *bus)
    assert result.returncode == 0, result.stderr
    crc = f"{crc64we(image):#018x}"
    assert result.stdout == (
        f"node 21: updated with esc.bin (2500 bytes, CRC-64-WE {crc}); "
        "the node reports the same CRC\n"
    )
    assert result.stderr.splitlines()[-1] == "node 21: done, 2500 of 2500 bytes"
    info = json.loads(veronte4x("esc", "info", "21", *bus, "--json").stdout)
    assert info["software_version"]["image_crc"] == crc


def test_spin_then_the_motors_stop(bus: list[str]) -> None:
    """Both motors turn at their commanded speed (seen on the bus), SIGTERM stops the spin
    with zero throttle, and both report no drive after it.

    Throttle 0.4 commands 40 % of the simulated motor's 10,000 rpm: the test waits until
    each ESC reports that speed within 1 %, however long a loaded machine takes (the speed
    settles in about a second of the simulator's time)."""
    commanded = 0.4 * MotorModel().max_rpm
    with listening(bus) as listener:
        process = subprocess.Popen(
            [sys.executable, "-m", "veronte4x", "esc", "spin", "21", "22", "--throttle", "0.4",
             "--duration", "600", "--yes", *bus],
            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
        )  # fmt: skip
        try:
            wait_for_status(
                listener, {21, 22}, lambda status: abs(status.rpm - commanded) <= commanded / 100
            )
            process.send_signal(signal.SIGTERM)
            out, err = process.communicate(timeout=HANG_GUARD)
        finally:
            process.kill()
            process.wait()
    assert (process.returncode, out, err) == (
        130,
        "",
        "veronte4x: interrupted; zero throttle sent to esc_index 0, 1 (3 times)\n",
    )
    stopped_for_good(bus, {21, 22})


def test_a_spin_that_ends_says_what_it_did(bus: list[str]) -> None:
    result = veronte4x("esc", "spin", "21", "--throttle", "0.4", "--duration", "0.3", "--yes", *bus)
    assert result.returncode == 0, result.stderr
    assert re.fullmatch(
        r"node 21 \(esc_index 0\): throttle 0\.4 for 0\.3 s, "
        r"(peak -?\d+ rpm|no telemetry); zero throttle sent\n",
        result.stdout,
    ), result.stdout
    assert result.stderr == "veronte4x: zero throttle sent to esc_index 0 (3 times)\n"


def test_restart(bus: list[str]) -> None:
    result = veronte4x("esc", "restart", "22", *bus)
    assert (result.returncode, result.stdout) == (0, "node 22: restarting\n")


def test_node_that_stops_answering_mid_update(tmp_path: Path) -> None:
    port = free_port()
    firmware = tmp_path / "esc.bin"
    firmware.write_bytes(bytes(2000))
    with simulator(port, "--nodes", "21", "--stall-update-at", "512"):
        result = veronte4x(
            "esc", "update", "21", str(firmware), *bus_args(port), "--read-timeout", "1"
        )
    assert result.returncode == 3
    assert result.stderr.splitlines()[-1] == (
        "veronte4x: node 21 stopped reading the image at byte 512 of 2000 (nothing for 1 s)"
    )


def test_no_node_on_the_bus() -> None:
    result = veronte4x("esc", "nodes", *bus_args(free_port()), "--timeout", "0.3")
    assert result.returncode == 3
    assert result.stderr == (
        "veronte4x: no node on the bus within 0.3 s; check --interface, --channel and --bitrate\n"
    )


def test_bus_that_cannot_be_opened() -> None:
    result = veronte4x("esc", "nodes", "--interface", "no_such_interface", "--channel", "x")
    assert result.returncode == 2
    assert result.stderr.startswith(
        "veronte4x: cannot open the CAN bus (interface no_such_interface, channel x): "
    )
    assert len(result.stderr.splitlines()) == 1


def test_a_killed_spin_stops_the_motors(bus: list[str]) -> None:
    spin = subprocess.Popen(
        [sys.executable, "-m", "veronte4x", "esc", "spin", "21", "--throttle", "0.5",
         "--duration", "600", "--yes", *bus],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )  # fmt: skip
    try:
        with listening(bus) as listener:  # until the spin has started
            wait_for_status(listener, {21}, lambda status: status.power_rating_pct == 50)
        spin.send_signal(signal.SIGTERM)
        _, stderr = spin.communicate(timeout=HANG_GUARD)
    finally:
        spin.kill()
        spin.wait()
    assert spin.returncode == 130
    assert stderr == "veronte4x: interrupted; zero throttle sent to esc_index 0 (3 times)\n"
    stopped_for_good(bus, {21})
