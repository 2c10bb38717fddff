"""A new user's first hour (issue 39): a command that opens a bus when nothing names one, and
the small outputs that said less than they should. Each command runs as a subprocess: its exit
code and its exact lines."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from tests.client.cli_support import HANG_GUARD
from veronte4x.cli.buses import NO_BUS


def _run(
    *args: str, env: dict[str, str] | None = None, cwd: Path | None = None
) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "veronte4x", *args],
        capture_output=True,
        text=True,
        env=env,
        cwd=cwd,
        timeout=HANG_GUARD,
        check=False,
    )


def _no_python_can_config(home: Path) -> dict[str, str]:
    """The environment with a home of its own and no ``CAN_*`` variable: python-can's
    configuration names no bus."""
    env = {k: v for k, v in os.environ.items() if not k.startswith("CAN_")}
    return {**env, "HOME": str(home)}


@pytest.mark.parametrize(
    "command", [["esc", "nodes"], ["esc", "get", "21", "esc_index"], ["simulate", "esc"]]
)
def test_a_command_with_no_bus_says_which_options_name_one(
    command: list[str], tmp_path: Path
) -> None:
    result = _run(*command, env=_no_python_can_config(tmp_path), cwd=tmp_path)
    assert (result.returncode, result.stdout, result.stderr) == (2, "", f"veronte4x: {NO_BUS}\n")
    assert "--interface and --channel" in NO_BUS
    assert "~/.canrc" in NO_BUS


def test_python_can_configuration_names_the_bus(tmp_path: Path) -> None:
    """``CAN_INTERFACE`` or ``~/.canrc`` is a bus the user named: the command opens it."""
    env = {**_no_python_can_config(tmp_path), "CAN_INTERFACE": "virtual"}
    result = _run("esc", "nodes", "--timeout", "0.2", env=env, cwd=tmp_path)
    assert (result.returncode, result.stdout) == (3, "")
    assert result.stderr.startswith("veronte4x: no node on the bus within 0.2 s"), result.stderr

    (tmp_path / ".canrc").write_text("[default]\ninterface = virtual\n")
    result = _run("esc", "nodes", "--timeout", "0.2", env=_no_python_can_config(tmp_path))
    assert (result.returncode, result.stdout) == (3, "")
    assert result.stderr.startswith("veronte4x: no node on the bus within 0.2 s"), result.stderr
