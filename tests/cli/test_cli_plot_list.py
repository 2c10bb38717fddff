"""``veronte4x plot`` and ``veronte4x list`` as subprocesses."""

from __future__ import annotations

import json
from pathlib import Path

from tests.client.cli_support import veronte4x
from veronte4x import dronecan
from veronte4x.dronecan import vertiq
from veronte4x.simulator import SimulatedEsc

CAPTURE = Path(__file__).resolve().parents[2] / "examples" / "capture.log"
PNG = b"\x89PNG\r\n\x1a\n"


def _esc_capture(path: Path) -> None:
    """Two simulated ESCs spinning up for 2 s, as a candump log."""
    escs = [SimulatedEsc(21, 0, telem_frequency=20), SimulatedEsc(22, 1, telem_frequency=20)]
    command = dronecan.encode(vertiq.raw_command([0.5, 0.8]), source_node_id=1, transfer_id=0)
    lines = []
    for step in range(200):
        now = step * 0.01
        if step == 10:
            for esc in escs:
                for frame in command:
                    esc.receive(frame.can_id, frame.data, now)
        for esc in escs:
            for frame in esc.poll(now):
                lines.append(f"({1000 + now:.6f}) can0 {frame.can_id:08X}#{frame.data.hex()}")
    path.write_text("\n".join(lines) + "\n")


def test_plot_esc_telemetry_to_png(tmp_path: Path) -> None:
    capture, image = tmp_path / "esc.log", tmp_path / "esc.png"
    _esc_capture(capture)
    result = veronte4x("plot", str(capture), "--kind", "esc", "--output", str(image))
    assert result.returncode == 0, result.stderr
    assert result.stderr == f"veronte4x: wrote {image}\n"
    assert image.read_bytes()[:8] == PNG


def test_plot_arbitration_to_png(tmp_path: Path) -> None:
    image = tmp_path / "arbitration.png"
    result = veronte4x("plot", str(CAPTURE), "--output", str(image))
    assert result.returncode == 0, result.stderr
    assert image.read_bytes()[:8] == PNG


def test_plot_missing_capture(tmp_path: Path) -> None:
    result = veronte4x("plot", str(tmp_path / "none.log"), "--output", str(tmp_path / "x.png"))
    assert result.returncode == 2
    assert result.stderr == f"veronte4x: {tmp_path / 'none.log'}: No such file or directory\n"


def test_list_text() -> None:
    result = veronte4x("list")
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    assert lines[0] == (
        "Veronte 4x (11-bit CAN IDs: arbiter 0FF, AP1 008, AP2 009, AP3 00A, external 00B)"
    )
    assert "  Score                    0  arbiter         6       command, autopilot, score" in (
        lines
    )
    assert (
        "  uavcan.protocol.file.Read                             response    48  0x8dcdca939f33f678"
        "  258" in lines
    )


def test_list_json_with_a_bus_map(tmp_path: Path) -> None:
    bus_map = tmp_path / "bus.toml"
    bus_map.write_text(
        "[veronte]\narbiter_id = 0x100\nautopilot_ids = [0x101, 0x102, 0x103, 0x104]\n\n"
        "[[veronte.layouts]]\ncommand = 9\nname = 'CellTemperature'\n"
        "fields = [{ kind = 'unsigned', name = 'celsius', bits = 8 }]\n"
    )
    result = veronte4x("list", "--bus-map", str(bus_map), "--json")
    assert result.returncode == 0, result.stderr
    listed = json.loads(result.stdout)
    assert listed["veronte"]["ids"]["arbiter"] == "100"
    by_command = {m["command"]: m for m in listed["veronte"]["messages"]}
    assert by_command[9]["message"] == "CellTemperature"
    assert by_command[9]["fields"] == ["command", "celsius"]
    assert {t["type"] for t in listed["dronecan"]} >= {
        "uavcan.protocol.param.ExecuteOpcode",
        "uavcan.protocol.file.Read",
    }
