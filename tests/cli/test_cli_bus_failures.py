"""A python-can bus that fails while a command uses it: one line, exit code 2, no traceback.

The bus is a python-can interface of the test's own, registered in the CLI's process: it
gives a few frames (or takes a few), then raises what the interface of a real adapter may
raise: python-can's ``CanOperationError``, an ``OSError`` of a device gone, or a driver's
own exception.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

pytest.importorskip("can")

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "capture.log"

FAILING_BUS = """
import os
import can


class FailingBus(can.BusABC):
    def __init__(self, channel=None, **kwargs):
        super().__init__(channel=channel, **kwargs)
        self.channel_info = "failing"
        self.left = 3

    def _fail(self):
        kind = os.environ["FAIL_KIND"]
        if kind == "can":
            raise can.CanOperationError("the interface went away")
        if kind == "os":
            raise OSError(19, "No such device")
        raise RuntimeError("driver crashed")

    def _recv_internal(self, timeout):
        if self.left <= 0:
            self._fail()
        self.left -= 1
        return can.Message(arbitration_id=9, data=b"\\0\\xff\\1", is_extended_id=False), False

    def send(self, msg, timeout=None):
        if self.left <= 0:
            self._fail()
        self.left -= 1
"""

RUN_CLI = """
import sys
import can.interfaces, can.util
can.interfaces.BACKENDS["failing"] = ("failing_bus", "FailingBus")
can.util.VALID_INTERFACES = frozenset({*can.util.VALID_INTERFACES, "failing"})
from veronte4x.__main__ import script
sys.argv[0] = "veronte4x"
script()
"""

REASONS = {
    "can": "the interface went away",
    "os": "No such device",
    "other": "RuntimeError: driver crashed",
}


def run_on_failing_bus(tmp_path: Path, kind: str, *args: str) -> subprocess.CompletedProcess[str]:
    (tmp_path / "failing_bus.py").write_text(FAILING_BUS)
    env = {**os.environ, "FAIL_KIND": kind, "PYTHONPATH": str(tmp_path)}
    return subprocess.run(
        [sys.executable, "-c", RUN_CLI, *args],
        capture_output=True,
        text=True,
        check=False,
        env=env,
        stdin=subprocess.DEVNULL,
    )


@pytest.mark.parametrize("kind", sorted(REASONS))
def test_decode_of_a_live_bus_that_fails(tmp_path: Path, kind: str) -> None:
    result = run_on_failing_bus(tmp_path, kind, "decode", "--interface", "failing")
    assert result.returncode == 2
    assert result.stderr == f"veronte4x: the CAN bus failed: {REASONS[kind]}\n"
    assert len(result.stdout.splitlines()) == 3  # the frames before the failure are kept


@pytest.mark.parametrize(
    ("args", "line"),
    [
        (["monitor", "--interface", "failing"], "the CAN bus failed: RuntimeError: driver crashed"),
        (
            ["play", str(EXAMPLE), "--interface", "failing"],
            "the CAN bus failed sending frame 4: RuntimeError: driver crashed",
        ),
        (
            ["esc", "nodes", "--interface", "failing"],
            "the CAN bus failed: RuntimeError: driver crashed",
        ),
    ],
)
def test_other_commands_on_a_bus_that_fails(tmp_path: Path, args: list[str], line: str) -> None:
    result = run_on_failing_bus(tmp_path, "other", *args)
    assert result.returncode == 2
    assert result.stderr.splitlines()[-1] == f"veronte4x: {line}"
    assert "Traceback" not in result.stderr


def test_simulate_on_a_bus_that_fails(tmp_path: Path) -> None:
    result = run_on_failing_bus(tmp_path, "os", "simulate", "esc", "--interface", "failing")
    assert result.returncode == 2
    assert result.stderr.splitlines() == [
        "veronte4x: simulating Vertiq ESC nodes 21 (esc_index 0); Ctrl-C stops",
        "veronte4x: the CAN bus failed: No such device",
    ]
