"""``veronte4x esc`` as a person reads it: the text tables, the lines of every action, its
usage errors, ``--json`` where the other tests read the text, and Ctrl-C while it waits.

Each command runs as a subprocess against ``veronte4x simulate esc`` on a udp_multicast bus
of its own, as on a bench.
"""

from __future__ import annotations

import json
import re
import signal
import subprocess
import sys
import time
from collections.abc import Iterator
from pathlib import Path

import can
import pytest

from tests.client.cli_support import (
    ANSWER,
    GROUP,
    HANG_GUARD,
    bus_args,
    free_port,
    simulator,
    veronte4x,
)

PARAMS_21 = [
    "index  name                  value     default  range",
    "    0  uavcan_node_id           21          21  1..127",
    "    1  bit_rate             500000      500000  10000..1000000",
    "    2  esc_index                 0           0  0..19",
    "    3  zero_behavior             0           0  0..2",
    "    4  telem_frequency          10          10  0..1000",
]
"""``esc params 21`` of a simulated node 21 with its defaults."""


@pytest.fixture(scope="module")
def bus() -> Iterator[list[str]]:
    """Simulated nodes 21 and 22; the tests here leave their parameters as they were."""
    port = free_port()
    with simulator(port, "--nodes", "21,22"):
        yield bus_args(port)


def _saved(bus: list[str], path: Path) -> str:
    result = veronte4x("esc", "params", "21,22", *bus, "--save", str(path), "--json")
    assert result.returncode == 0, result.stderr
    assert json.loads(result.stdout) == {"file": str(path), "nodes": [21, 22], "parameters": 10}
    return path.read_text(encoding="utf-8")


def test_nodes_as_a_table(bus: list[str]) -> None:
    result = veronte4x("esc", "nodes", *bus)
    assert (result.returncode, result.stderr) == (0, ""), result.stderr
    lines = result.stdout.splitlines()
    assert lines[0] == (
        "node  name           health    mode                uptime         seen  vendor"
    )
    # Each number fills its column exactly, so the rows line up with the header.
    row = (
        r"  {}  iq_motion\.esc  OK        OPERATIONAL      (?= *\d+ s)[ \d]{{7}} s  "
        r"(?= *\d+\.\d s)[ \d.]{{5}} s ago  0x0000"
    )
    assert all(
        re.fullmatch(row.format(n), line) for n, line in zip((21, 22), lines[1:], strict=True)
    ), lines
    assert {len(line) for line in lines} == {len(lines[0])}, lines


def test_params_as_tables(bus: list[str]) -> None:
    one = veronte4x("esc", "params", "21", *bus)
    assert (one.returncode, one.stdout.splitlines()) == (0, PARAMS_21), one.stderr
    both = veronte4x("esc", "params", "21,22", *bus)
    assert both.returncode == 0, both.stderr
    lines = both.stdout.splitlines()
    assert lines[:7] == ["node 21:", *PARAMS_21]
    assert lines[7:9] == ["node 22:", PARAMS_21[0]]
    assert lines[9:11] == [
        "    0  uavcan_node_id           22          22  1..127",
        "    1  bit_rate             500000      500000  10000..1000000",
    ]
    assert lines[11] == "    2  esc_index                 1           1  0..19"
    assert lines[-1] == "2 nodes: all succeeded"


def test_params_saved_as_text_and_a_node_that_does_not_answer(
    bus: list[str], tmp_path: Path
) -> None:
    saved = tmp_path / "escs.toml"
    result = veronte4x("esc", "params", "21,22", *bus, "--save", str(saved))
    assert (result.returncode, result.stderr) == (0, ""), result.stderr
    assert result.stdout == f"saved 10 parameters of nodes 21, 22 to {saved}\n"
    result = veronte4x("esc", "params", "21", *bus, "--save", str(saved))
    assert result.stdout == f"saved 5 parameters of node 21 to {saved}\n"
    saved.unlink()
    failed = veronte4x(
        "esc", "params", "21,99", *bus, "--save", str(saved), "--timeout", ANSWER, "--retries", "0"
    )
    assert (failed.returncode, failed.stdout) == (3, "")
    assert failed.stderr.splitlines() == [
        "veronte4x: node 99: did not answer uavcan.protocol.GetNodeInfo (sent once, "
        f"{ANSWER} s each); check the node id, the bus and the bit rate",
        f"veronte4x: nothing written to {saved}: 2 nodes: 1 succeeded, 1 failed (99)",
    ]
    assert not saved.exists()  # nothing lost, nothing half written


def test_erase(bus: list[str]) -> None:
    result = veronte4x("esc", "erase", "22", *bus)
    assert (result.returncode, result.stdout) == (
        0,
        "node 22: stored parameters erased (defaults after a restart)\n",
    )


def test_update_skips_a_node_that_runs_the_image(bus: list[str], tmp_path: Path) -> None:
    firmware = tmp_path / "esc.bin"
    firmware.write_bytes(bytes((i * 7 + 3) & 0xFF for i in range(1200)))
    first = veronte4x("esc", "update", "22", str(firmware), *bus, "--json")
    assert first.returncode == 0, first.stderr
    crc = json.loads(first.stdout)["image_crc64we"]
    again = veronte4x("esc", "update", "22", str(firmware), *bus)
    assert (again.returncode, again.stderr) == (0, "")
    assert again.stdout == (
        f"node 22: skipped, it runs esc.bin already (image CRC {crc}); --force updates anyway\n"
    )


def test_update_refuses_a_path_too_long_for_a_file_request(bus: list[str], tmp_path: Path) -> None:
    firmware = tmp_path / "esc.bin"
    firmware.write_bytes(bytes(100))
    result = veronte4x("esc", "update", "21", str(firmware), "--path", "é" * 101, *bus)
    assert (result.returncode, result.stdout, result.stderr) == (
        2,
        "",
        "veronte4x: the path the node is told to read has more than 200 bytes; "
        "give a shorter one with --path\n",
    )


def test_apply_dry_run_as_json_and_from_another_node(bus: list[str], tmp_path: Path) -> None:
    text = _saved(bus, tmp_path / "saved.toml")
    changed = tmp_path / "changed.toml"
    changed.write_text(
        text.replace(
            'zero_behavior = { type = "integer", value = 0',
            'zero_behavior = { type = "integer", value = 2',
        ),
        encoding="utf-8",
    )
    result = veronte4x("esc", "apply", str(changed), "21,22", *bus, "--dry-run", "--json")
    assert (result.returncode, result.stderr) == (0, ""), result.stderr
    assert json.loads(result.stdout) == {
        "21": [{"name": "zero_behavior", "current": 0, "wanted": 2}],
        "22": [{"name": "zero_behavior", "current": 0, "wanted": 2}],
    }
    from_21 = ("esc", "apply", str(changed), "22", "--from", "21", *bus, "--dry-run")
    refused = veronte4x(*from_21)  # node 21's esc_index onto node 22: both would turn
    assert (refused.returncode, refused.stderr) == (
        2,
        "veronte4x: node 21 has esc_index 0 already: giving it to node 22 too would make "
        "RawCommand turn both; add --allow-shared-index to give it anyway; nothing was sent\n",
    )
    result = veronte4x(*from_21, "--allow-shared-index")
    assert (result.returncode, result.stderr) == (0, ""), result.stderr
    assert result.stdout.splitlines() == [
        "node 22: esc_index 1 -> 0",
        "node 22: zero_behavior 0 -> 2",
        "node 22: the file's parameters of node 21",
        "dry run: 2 parameters would change; none set",
    ]
    after = veronte4x("esc", "get", "22", "zero_behavior", *bus)
    assert after.stdout == "zero_behavior = 0 (default 0, range 0..2)\n"  # nothing was set


def test_apply_as_json(tmp_path: Path) -> None:
    port = free_port()
    with simulator(port, "--nodes", "21,22"):
        bus = bus_args(port)
        text = _saved(bus, tmp_path / "saved.toml")
        set_ = veronte4x("esc", "set", "22", "zero_behavior", "1", *bus)
        assert set_.returncode == 0, set_.stderr
        result = veronte4x("esc", "apply", str(tmp_path / "saved.toml"), "21,22", *bus, "--json")
        assert (result.returncode, result.stderr) == (0, ""), result.stderr
        assert json.loads(result.stdout) == {
            "nodes": [
                {"node_id": 21, "ok": True, "set": []},
                {"node_id": 22, "ok": True, "set": ["zero_behavior"]},
            ],
            "total": 2,
            "failed": [],
        }
        after = veronte4x("esc", "get", "22", "zero_behavior", *bus)
        assert after.stdout == "zero_behavior = 0 (default 0, range 0..2)\n"
        assert 'zero_behavior = { type = "integer", value = 0' in text


def test_apply_refuses_a_file_of_another_kind_of_node(bus: list[str], tmp_path: Path) -> None:
    text = _saved(bus, tmp_path / "saved.toml")
    other = tmp_path / "other.toml"
    other.write_text(text.replace('"iq_motion.esc"', '"other.esc"'), encoding="utf-8")
    result = veronte4x("esc", "apply", str(other), "21", *bus)
    assert (result.returncode, result.stdout, result.stderr) == (
        2,
        "",
        "veronte4x: node 21 is 'iq_motion.esc', the file's node 21 is 'other.esc': not applied\n",
    )


def test_apply_refuses_a_file_that_is_not_utf8(bus: list[str], tmp_path: Path) -> None:
    binary = tmp_path / "params.toml"
    binary.write_bytes(b'node_id = "\xff\xfe"\n')
    result = veronte4x("esc", "apply", str(binary), "21", *bus)
    assert (result.returncode, result.stdout, result.stderr) == (
        2,
        "",
        f"veronte4x: {binary} is not a UTF-8 text file\n",
    )


def test_node_ids_that_are_not_numbers() -> None:
    result = veronte4x("esc", "nodes", "--node-id", "abc")
    assert (result.returncode, result.stdout) == (2, "")
    assert result.stderr.splitlines()[-1] == (
        "veronte4x esc nodes: error: argument --node-id: 'abc' is not a node id (1..127)"
    )
    result = veronte4x("esc", "apply", "saved.toml", "21", "--from", "x")
    assert result.returncode == 2
    assert result.stderr.splitlines()[-1] == (
        "veronte4x esc apply: error: argument --from: 'x' is not a node id (1..127)"
    )


def test_spin_as_json(bus: list[str]) -> None:
    result = veronte4x(
        "esc", "spin", "21", "22", "--throttle", "0.3", "--duration", "0.6", "--yes", "--json",
        *bus,
    )  # fmt: skip
    assert result.returncode == 0, result.stderr
    rows = json.loads(result.stdout)
    assert [(r["node_id"], r["esc_index"], r["throttle"]) for r in rows] == [
        (21, 0, 0.3),
        (22, 1, 0.3),
    ]
    # How much telemetry a 0.6 s spin sees depends on the machine's load; that the motors
    # reach their speed is test_cli_esc.py's test_spin_then_the_motors_stop, seen on the bus.
    assert all(
        isinstance(r["telemetry"], int) and (r["peak_rpm"] is None) == (r["telemetry"] == 0)
        for r in rows
    )
    assert result.stderr == "veronte4x: zero throttle sent to esc_index 0, 1 (3 times)\n"


def test_ctrl_c_while_waiting_for_an_answer() -> None:
    """Ctrl-C once the request is on the bus: one line, exit code 130, no traceback."""
    port = free_port()
    with can.Bus(interface="udp_multicast", channel=GROUP, port=port) as listener:
        command = [sys.executable, "-m", "veronte4x", "esc", "info", "21", *bus_args(port)]
        process = subprocess.Popen(
            [*command, "--timeout", "600", "--retries", "0", "--node-id", "120"],
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
        )
        try:
            end = time.monotonic() + HANG_GUARD
            while time.monotonic() < end:  # the tool's request: it waits for the answer now
                message = listener.recv(1.0)
                if message is not None and message.arbitration_id & 0x7F == 120:
                    break
                assert process.poll() is None, process.communicate()
            process.send_signal(signal.SIGINT)
            out, err = process.communicate(timeout=HANG_GUARD)
        finally:
            process.kill()
            process.wait()
    assert (process.returncode, out, err) == (130, "", "veronte4x: interrupted\n")
