"""Every command of the README runs clean on the demo flight that `make demo` generates."""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest

ROOT = Path(__file__).resolve().parent.parent
README = (ROOT / "README.md").read_text()


def _blocks(language: str) -> list[str]:
    return re.findall(rf"```{language}\n(.*?)```", README, re.DOTALL)


def _commands() -> list[str]:
    """The ``veronte4x`` command lines of the README's bash blocks, comments removed."""
    lines = [
        line.split("  #")[0].strip() for block in _blocks("bash") for line in block.splitlines()
    ]
    return [line for line in lines if re.match(r"(\S+ .*\| )?veronte4x ", line)]


@pytest.fixture(scope="module")
def demo(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A checkout-like directory with the demo flight, as `make demo` writes it."""
    root = tmp_path_factory.mktemp("demo")
    (root / "examples").mkdir()
    shutil.copy(ROOT / "examples" / "arbiter.toml", root / "examples")
    subprocess.run(
        [sys.executable, str(ROOT / "examples" / "make_capture.py"), "examples/flight.log"],
        cwd=root,
        check=True,
        capture_output=True,
    )
    return root


def test_the_readme_has_the_commands() -> None:
    commands = _commands()
    for name in ("decode", "stats", "replay"):
        assert any(f"veronte4x {name} " in command for command in commands)


def _run(command: str, cwd: Path, pipefail: bool = True) -> subprocess.CompletedProcess[str]:
    path = os.pathsep.join([str(Path(sys.executable).parent), os.environ.get("PATH", "")])
    return subprocess.run(
        ["bash", "-o" if pipefail else "+o", "pipefail", "-c", command],
        cwd=cwd,
        env={**os.environ, "PATH": path},
        capture_output=True,
        text=True,
        check=False,
    )


SUMMARY = re.compile(
    r"veronte4x: (\d+ records, 0 undecoded, 0 bad \(skip\)"
    r"|\d+ decisions, 0 disagreements, 0 bad frames)"
)


@pytest.mark.parametrize("command", _commands())
def test_readme_command_runs_clean_on_the_demo_flight(command: str, demo: Path) -> None:
    """In full with every stage's exit code checked; as written (a `| head` that closes the
    pipe early) without a traceback or a message other than the summary."""
    as_written = _run(command, demo, pipefail=False)
    assert as_written.returncode == 0, as_written.stderr
    assert all(SUMMARY.fullmatch(line) for line in as_written.stderr.splitlines()), (
        as_written.stderr
    )
    full = _run(re.sub(r" \| head.*$", "", command), demo)
    assert full.returncode == 0, full.stderr
    if " stats " in command:
        assert "undecoded: 0, errors: 0" in full.stdout
        assert full.stderr == ""
    else:
        [summary] = full.stderr.splitlines()
        assert SUMMARY.fullmatch(summary), summary


def test_readme_python_runs(monkeypatch: pytest.MonkeyPatch) -> None:
    """Each Python block runs from the checkout and gives what its comments say."""
    from veronte4x import codec

    monkeypatch.chdir(ROOT)
    first, second = _blocks("python")
    names: dict[str, Any] = {}
    exec(compile(first, "README.md", "exec"), names)
    assert names["msg"] == codec.Ready(ready=True)

    names = {}
    exec(compile(second, "README.md", "exec"), names)
    assert "Status" in names["tables"]
    status = names["status"]
    columns = ["timestamp", "can_id", "selected", "arbitrating", "alive_2", "alive_3"]
    columns += ["ready_2", "ready_3", "cbit_ok", "normal_mode"]
    # examples/capture.log lines 18-19: 0FF#00FF8177FFFF (the 4x form) and 0FF#00FF8177
    # (the 1x form, no check bytes): AP2 selected, arbitrating, AP1-AP3 alive and ready.
    assert status[columns].to_numpy().tolist() == [
        [1763737200.25, 255, 1, True, True, False, True, False, True, True],
        [1763737200.251, 255, 1, True, True, False, True, False, None, None],
    ]
