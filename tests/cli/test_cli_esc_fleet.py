"""``veronte4x esc`` on many nodes at once (issue 22): node lists and ranges, parameter sets
saved and applied, a fleet firmware update; 8 simulated ESCs in another process on a
udp_multicast bus."""

from __future__ import annotations

import json
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

from tests.client.cli_support import ANSWER, bus_args, free_port, simulator, veronte4x
from veronte4x.dronecan.image_crc import crc64we

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib


@pytest.fixture(scope="module")
def bus() -> Iterator[list[str]]:
    port = free_port()
    with simulator(port, "--nodes", "21-28"):
        yield bus_args(port)


def _saved(bus: list[str], path: Path, nodes: str) -> Path:
    """``path``, where ``esc params --save`` wrote the parameters of ``nodes``."""
    assert veronte4x("esc", "params", nodes, "--save", str(path), *bus).returncode == 0
    return path


def _set(bus: list[str], node: str, name: str, value: str) -> None:
    """Set one parameter of one node with ``esc set``."""
    assert veronte4x("esc", "set", node, name, value, *bus).returncode == 0


def _get(bus: list[str], node: str, name: str) -> str:
    """What ``esc get`` prints of one parameter of one node."""
    return veronte4x("esc", "get", node, name, *bus).stdout


def test_a_range_read_at_once(bus: list[str]) -> None:
    result = veronte4x("esc", "get", "21-28", "esc_index", *bus)
    assert result.returncode == 0, result.stderr
    assert result.stdout.splitlines() == [
        f"node {21 + i}: esc_index = {i} (default {i}, range 0..19)" for i in range(8)
    ] + ["8 nodes: all succeeded"]
    data = json.loads(veronte4x("esc", "get", "all", "esc_index", *bus, "--json").stdout)
    assert [(row["node_id"], row["ok"], row["value"]) for row in data["nodes"]] == [
        (21 + i, True, i) for i in range(8)
    ]
    assert (data["total"], data["failed"]) == (8, [])


def test_a_node_that_does_not_answer_fails_alone(bus: list[str]) -> None:
    result = veronte4x(
        "esc", "get", "21,99,22", "esc_index", *bus, "--timeout", ANSWER, "--retries", "0"
    )
    assert result.returncode == 3
    assert result.stdout.splitlines() == [
        "node 21: esc_index = 0 (default 0, range 0..19)",
        "node 99: failed: did not answer uavcan.protocol.param.GetSet (sent once, "
        f"{ANSWER} s each); check the node id, the bus and the bit rate",
        "node 22: esc_index = 1 (default 1, range 0..19)",
        "3 nodes: 2 succeeded, 1 failed (99)",
    ]
    assert result.stderr == "veronte4x: 3 nodes: 2 succeeded, 1 failed (99)\n"


def test_bad_node_lists_are_usage_errors() -> None:
    for text, reason in (
        ("21-300", "node id 300 is out of range: 1..127"),
        ("28-21", "'28-21': a range goes up, e.g. 21-28"),
        ("21;22", "'21;22' is not a node list: give ids and ranges such as 21,22 or 21-28, or all"),
    ):
        result = veronte4x("esc", "info", text)
        assert result.returncode == 2
        assert result.stderr.splitlines()[-1].endswith(reason), result.stderr
    result = veronte4x("esc", "spin", "all", "--throttle", "0.1", "--duration", "1", "--yes",
                       *bus_args(free_port()))  # fmt: skip
    assert (result.returncode, result.stderr) == (
        2,
        "veronte4x: esc spin needs the nodes named: 'all' is refused\n",
    )


def test_parameters_saved_reviewed_and_restored(bus: list[str], tmp_path: Path) -> None:
    saved = tmp_path / "vehicle.toml"
    result = veronte4x("esc", "params", "21-24", "--save", str(saved), *bus)
    assert (result.returncode, result.stdout) == (
        0,
        f"saved 20 parameters of nodes 21, 22, 23, 24 to {saved}\n",
    )
    document = tomllib.loads(saved.read_text())
    assert document["format"] == "veronte4x-esc-parameters/1"
    node = document["node"][1]
    assert (node["node_id"], node["name"], node["unique_id"]) == (
        22,
        "iq_motion.esc",
        (b"veronte4x.sim\x00\x00\x16").hex(),
    )
    assert node["parameters"]["esc_index"] == {
        "type": "integer", "value": 1, "default": 1, "min": 0, "max": 19,
    }  # fmt: skip
    _set(bus, "22", "telem_frequency", "25")
    dry = veronte4x("esc", "apply", str(saved), "21-24", "--dry-run", *bus)
    assert (dry.returncode, dry.stdout) == (
        0,
        "node 22: telem_frequency 25 -> 10\ndry run: 1 parameter would change; none set\n",
    )
    assert "25 (default" in _get(bus, "22", "telem_frequency")
    applied = veronte4x("esc", "apply", str(saved), "21-24", *bus)
    assert applied.returncode == 0, applied.stderr
    assert applied.stdout.splitlines() == [
        "node 22: telem_frequency 25 -> 10",
        "node 21: as in the file, nothing set",
        "node 22: 1 set, read back and saved",
        "node 23: as in the file, nothing set",
        "node 24: as in the file, nothing set",
        "4 nodes: all succeeded",
    ]
    assert "= 10 (default" in _get(bus, "22", "telem_frequency")


def test_an_entry_that_names_no_parameter_is_never_applied(bus: list[str], tmp_path: Path) -> None:
    """A GetSet answer with an empty value names no parameter: such an entry (``type =
    "empty"``, as files written before could hold) loads, and apply leaves it alone."""
    saved = _saved(bus, tmp_path / "esc24.toml", "24")
    assert "empty" not in saved.read_text()
    with saved.open("a", encoding="utf-8") as file:
        file.write('ghost = { type = "empty", value = "" }\n')
    _set(bus, "24", "telem_frequency", "25")
    applied = veronte4x("esc", "apply", str(saved), "24", *bus)
    assert (applied.returncode, applied.stderr) == (0, "")
    assert applied.stdout.splitlines() == [
        "node 24: telem_frequency 25 -> 10",
        "node 24: 1 set, read back and saved",
        "1 node: succeeded",
    ]
    assert "= 10 (default" in _get(bus, "24", "telem_frequency")


def test_a_value_out_of_range_is_refused_before_anything_is_set(
    bus: list[str], tmp_path: Path
) -> None:
    saved = _saved(bus, tmp_path / "vehicle.toml", "25,26")
    text = saved.read_text()
    text = text.replace("zero_behavior = { type = \"integer\", value = 0,", "zero_behavior = "
                        "{ type = \"integer\", value = 1,", 1)  # fmt: skip
    text = text.replace("esc_index = { type = \"integer\", value = 5,", "esc_index = "
                        "{ type = \"integer\", value = 99,", 1)  # fmt: skip
    saved.write_text(text)
    result = veronte4x("esc", "apply", str(saved), "25,26", *bus)
    assert result.returncode == 2
    assert result.stderr == "veronte4x: node 26: 99 is out of range for esc_index: 0..19\n"
    after = _get(bus, "25", "zero_behavior")
    assert after == "zero_behavior = 0 (default 0, range 0..2)\n"  # 25 was not set either
    result = veronte4x("esc", "apply", str(saved), "25,99", *bus, "--timeout", "2",
                       "--retries", "0")  # fmt: skip
    assert result.returncode == 3
    assert result.stderr.splitlines()[-1] == (
        "veronte4x: nothing was set: every node must answer before any is changed"
    )


def test_a_saved_node_applied_to_a_replacement(bus: list[str], tmp_path: Path) -> None:
    saved = _saved(bus, tmp_path / "esc27.toml", "27")
    _set(bus, "27", "zero_behavior", "2")
    saved.write_text(saved.read_text().replace("value = 6,", "value = 7,"))  # esc_index 7
    result = veronte4x("esc", "apply", str(saved), "28", *bus, "--dry-run")
    assert result.stdout.splitlines() == [
        "node 28: the file's parameters of node 27",
        "dry run: 0 parameters would change; none set",
    ]
    many = veronte4x("esc", "apply", str(saved), "28,21", *bus, "--dry-run")
    assert (many.returncode, many.stderr) == (
        2,
        "veronte4x: the file has no parameters of node 28 (it has nodes 27); choose one with "
        "--from\n",
    )  # one node's parameters onto several would give them all its esc_index
    bad = veronte4x("esc", "apply", str(saved), "28", "--from", "21", *bus)
    assert (bad.returncode, bad.stderr) == (
        2,
        "veronte4x: the file has no parameters of node 21\n",
    )


def test_the_dronecan_gui_tools_parm_file_applied_to_one_node(
    bus: list[str], tmp_path: Path
) -> None:
    """A file as the GUI tool's "Save To File" writes it (``NAME VALUE`` lines, see
    tests/client/test_client_parmfile.py), then a Mission Planner style one restoring node 23."""
    parm = tmp_path / "esc23.parm"
    parm.write_text(
        "uavcan_node_id 23\nbit_rate 500000\nesc_index 2\nzero_behavior 1\ntelem_frequency 50\n"
    )
    dry = veronte4x("esc", "apply", str(parm), "23", "--dry-run", *bus)
    assert (dry.returncode, dry.stdout) == (
        0,
        "node 23: zero_behavior 0 -> 1\nnode 23: telem_frequency 10 -> 50\n"
        "dry run: 2 parameters would change; none set\n",
    )
    many = veronte4x("esc", "apply", str(parm), "21-24", *bus)
    assert (many.returncode, many.stderr) == (
        2,
        f"veronte4x: {parm} is a .parm file (the DroneCAN GUI tool's): it names no node, so it "
        "is applied to one node named alone, without --from\n",
    )
    applied = veronte4x("esc", "apply", str(parm), "23", *bus)
    assert applied.returncode == 0, applied.stderr
    assert applied.stdout.splitlines() == [
        "node 23: zero_behavior 0 -> 1",
        "node 23: telem_frequency 10 -> 50",
        "node 23: 2 set, read back and saved",
        "1 node: succeeded",
    ]
    assert _get(bus, "23", "telem_frequency").startswith("telem_frequency = 50 ")
    bad = tmp_path / "esc23-bad.parm"
    bad.write_text("zero_behavior 0\nesc_index 20\n")
    refused = veronte4x("esc", "apply", str(bad), "23", *bus)
    assert (refused.returncode, refused.stderr) == (
        2,
        "veronte4x: node 23: 20 is out of range for esc_index: 0..19\n",
    )
    restore = tmp_path / "esc23-defaults.parm"
    restore.write_text("# Mission Planner style\nzero_behavior,0\ntelem_frequency,10\n")
    back = veronte4x("esc", "apply", str(restore), "23", *bus)
    assert back.returncode == 0, back.stderr
    assert _get(bus, "23", "zero_behavior") == "zero_behavior = 0 (default 0, range 0..2)\n"


def test_a_fleet_firmware_update_skips_nodes_that_run_the_image(
    bus: list[str], tmp_path: Path
) -> None:
    image = bytes((i * 13 + 5) & 0xFF for i in range(3000))
    firmware = tmp_path / "esc-v2.bin"
    firmware.write_bytes(image)
    crc = f"{crc64we(image):#018x}"
    first = veronte4x("esc", "update", "21-24", str(firmware), *bus)
    assert first.returncode == 0, first.stderr
    assert first.stdout.splitlines() == [
        f"node {n}: updated with esc-v2.bin (3000 bytes, CRC-64-WE {crc}); the node reports "
        "the same CRC"
        for n in range(21, 25)
    ] + ["4 nodes: all succeeded"]
    again = veronte4x("esc", "update", "21-24", str(firmware), *bus, "--json")
    data = json.loads(again.stdout)
    assert [(r["node_id"], r["updated"]) for r in data["nodes"]] == [
        (n, False) for n in range(21, 25)
    ]
    forced = veronte4x("esc", "update", "21", str(firmware), "--force", *bus)
    assert forced.stdout.startswith("node 21: updated with esc-v2.bin")


def test_total_line_in_singular_and_plural() -> None:
    from veronte4x.cli.fleet import total

    assert total(1, []) == "1 node: succeeded"
    assert total(1, [21]) == "1 node: failed (21)"
    assert total(2, []) == "2 nodes: all succeeded"
    assert total(3, [21, 23]) == "3 nodes: 1 succeeded, 2 failed (21, 23)"
