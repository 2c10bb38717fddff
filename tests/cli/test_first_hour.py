"""A new user's first hour (issue 39): a command that opens a bus when nothing names one, and
the small outputs that said less than they should. Each command runs as a subprocess: its exit
code and its exact lines."""

from __future__ import annotations

import os
import random
import re
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


CAPTURE = Path(__file__).resolve().parents[2] / "examples" / "capture.log"
"""A short capture with the arbiter's Status and Score frames."""


def _not_a_capture(directory: Path) -> Path:
    """5,000 random bytes named like a candump log: no line of them is a CAN frame."""
    path = directory / "noise.log"
    path.write_bytes(random.Random(39).randbytes(5000))
    return path


def test_plot_refuses_an_output_suffix_matplotlib_does_not_write_before_reading(
    tmp_path: Path,
) -> None:
    """Before any frame is read: the capture does not even exist."""
    result = _run("plot", str(tmp_path / "missing.log"), "--output", str(tmp_path / "p.bmp"))
    assert (result.returncode, result.stdout) == (2, "")
    assert result.stderr == (
        f"veronte4x: --output {tmp_path / 'p.bmp'}: matplotlib writes no .bmp image; give one "
        "of .avif, .eps, .gif, .jpeg, .jpg, .pdf, .pgf, .png, .ps, .raw, .rgba, .svg, .svgz, "
        ".tif, .tiff, .webp\n"
    )
    result = _run("plot", str(tmp_path / "missing.log"), "--output", str(tmp_path / "no" / "p.png"))
    assert (result.returncode, result.stderr) == (
        2,
        f"veronte4x: --output {tmp_path / 'no' / 'p.png'}: no directory {tmp_path / 'no'}\n",
    )
    assert list(tmp_path.iterdir()) == []


def test_plot_without_a_suffix_says_the_file_it_wrote(tmp_path: Path) -> None:
    result = _run("plot", str(CAPTURE), "--output", "noext", cwd=tmp_path)
    assert (result.returncode, result.stdout, result.stderr) == (
        0,
        "",
        "veronte4x: wrote noext.png\n",
    )
    assert [p.name for p in tmp_path.iterdir()] == ["noext.png"]
    assert (tmp_path / "noext.png").read_bytes().startswith(b"\x89PNG\r\n\x1a\n")


@pytest.mark.parametrize(
    "command",
    [
        ["stats"],
        ["convert", "--to", "parquet", "dataset"],
        ["convert", "--to", "csv", "out.csv", "--every", "1s"],
    ],
)
def test_convert_refuses_a_file_that_is_no_capture_as_every_command_does(
    command: list[str], tmp_path: Path
) -> None:
    noise = _not_a_capture(tmp_path)
    result = _run(*command, str(noise), cwd=tmp_path)
    assert (result.returncode, result.stdout) == (2, "")
    [line] = result.stderr.splitlines()
    assert re.fullmatch(
        rf"veronte4x: {re.escape(str(noise))} is not a capture of any known format: none of "
        r"its \d+ lines is a CAN frame; give candump text or a log python-can reads",
        line,
    ), line
    assert sorted(p.name for p in tmp_path.iterdir() if p.name != "dataset") == ["noise.log"]
    for written in tmp_path.glob("dataset/*"):
        pytest.fail(f"the refused conversion left {written}")
