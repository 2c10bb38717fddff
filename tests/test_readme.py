"""Every command of the README runs clean on the demo flight that `make demo` generates."""

from __future__ import annotations

import os
import re
import shutil
import signal
import socket
import subprocess
import sys
import time
from pathlib import Path
from typing import Any

import pytest

from tests.extras_support import EXTRAS, distributions, modules

ROOT = Path(__file__).resolve().parent.parent
README = (ROOT / "README.md").read_text()


def _blocks(language: str) -> list[str]:
    return re.findall(rf"```{language}\n(.*?)```", README, re.DOTALL)


BENCH = "# the ground station in two minutes\n"
"""The first line of the README's block that runs on a bus rather than the demo flight."""


def _lines(block: str) -> list[str]:
    """A bash block's lines, comments and blank lines removed."""
    lines = [line.split("  #")[0].strip() for line in block.splitlines()]
    return [line for line in lines if line and not line.startswith("#")]


def _commands() -> list[str]:
    """The ``veronte4x`` command lines of the README's bash blocks on the demo flight,
    comments removed."""
    lines = [
        line for block in _blocks("bash") if not block.startswith(BENCH) for line in _lines(block)
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


NEEDS = re.compile(r"# needs (?:no extra|the (.+) extras?)\b")
MAKEFILE = (ROOT / "Makefile").read_text()
DEMO_EXTRAS = re.findall(
    r"^\$\(VENV\)/\.installed-run:.*\n\t.* -e '\.\[(.*)\]'$", MAKEFILE, re.MULTILINE
)[0].split(",")
"""The extras `make demo` installs (the Makefile's ``.installed-run``)."""


def _extras(block: str) -> list[str]:
    """The extras a snippet names on its first line: ``# needs no extra`` or ``# needs the
    arrow and pandas extras``."""
    found = NEEDS.match(block)
    assert found, f"a README snippet does not say which extras it needs:\n{block}"
    names = re.split(r", | and ", found.group(1)) if found.group(1) else []
    assert set(names) <= set(EXTRAS), names
    return names


GUARD = """
import importlib.abc, sys
ALLOWED = set(sys.argv[1].split(",")) | set(sys.stdlib_module_names)
class OnlyTheExtras(importlib.abc.MetaPathFinder):
    def find_spec(self, name, path=None, target=None):
        top = name.partition(".")[0]
        if top in ALLOWED or top.startswith("_"):
            return None
        raise ModuleNotFoundError(f"{name}: not in the extras the snippet names", name=name)
sys.meta_path.insert(0, OnlyTheExtras())
exec(compile(sys.stdin.read(), "README.md", "exec"), {"__name__": "__main__"})
"""


def test_every_readme_snippet_runs_in_make_demos_environment() -> None:
    """Each extra a snippet names is one that `make demo` installs."""
    installed = distributions(DEMO_EXTRAS)
    for block in _blocks("python"):
        assert distributions(_extras(block)) <= installed, block


@pytest.mark.parametrize("block", _blocks("python"))
def test_readme_python_runs_with_only_the_extras_it_names(block: str, demo: Path) -> None:
    """In the demo's directory, in a process where only the standard library, veronte4x
    and the modules of the extras the snippet names can be imported."""
    result = subprocess.run(
        [sys.executable, "-c", GUARD, ",".join(modules(_extras(block)))],
        input=block,
        cwd=demo,
        capture_output=True,
        text=True,
    )
    assert result.returncode == 0, result.stderr


def test_the_guard_refuses_what_the_extras_do_not_bring(demo: Path) -> None:
    result = subprocess.run(
        [sys.executable, "-c", GUARD, ",".join(modules([]))],
        input="import pyarrow\n",
        cwd=demo,
        capture_output=True,
        text=True,
    )
    assert "ModuleNotFoundError: pyarrow: not in the extras the snippet names" in result.stderr


def test_readme_python_gives_what_its_comments_say(
    demo: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The first block decodes ``Ready(ready=True)``; the second gives the demo flight's
    Status frames as a DataFrame, row for row those that `capture.read` decodes."""
    from veronte4x import capture, codec
    from veronte4x.codec.layouts import AUTOPILOTS

    monkeypatch.chdir(demo)
    first, second = _blocks("python")
    names: dict[str, Any] = {}
    exec(compile(first, "README.md", "exec"), names)
    assert names["msg"] == codec.Ready(ready=True)

    names = {}
    exec(compile(second, "README.md", "exec"), names)
    status = names["status"]
    expected = [
        record.message.selected
        for record in capture.read("examples/flight.log")
        if isinstance(record.message, codec.Status)
    ]
    assert len(expected) > 100
    assert status["selected"].tolist() == expected
    assert status["selected_name"].astype(str).tolist() == [AUTOPILOTS[i] for i in expected]


def test_make_demo_installs_the_bench_and_the_notebook() -> None:
    assert DEMO_EXTRAS == ["notebook", "bench"]


def _bench() -> list[str]:
    [block] = [block for block in _blocks("bash") if block.startswith(BENCH)]
    return _lines(block)


def _free_port() -> int:
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as sock:
        sock.bind(("", 0))
        port: int = sock.getsockname()[1]
        return port


HANG_GUARD = 600.0
"""Seconds before a command of the block counts as hung: a guard, not a timed assertion."""


def _wait_for_veronte_frames(port: int) -> None:
    """Until the bus carries a Veronte frame (11-bit ID): the playback has begun."""
    import can

    end = time.monotonic() + HANG_GUARD
    with can.Bus(interface="udp_multicast", channel=GROUP, port=port) as listener:
        while True:
            assert time.monotonic() < end, "the playback sent nothing"
            message = listener.recv(1.0)
            if message is not None and not message.is_extended_id:
                return


GROUP = "239.74.163.2"


def test_the_ground_station_block_runs_as_written(demo: Path) -> None:
    """Line by line, each command a subprocess (bash, with the block's variables) on a
    udp_multicast port of its own (``--bus-option port=N`` added to each); a line ending in
    ``&`` runs in the background until the block's ``kill`` (SIGTERM) of its jobs. Each
    foreground command exits 0 with the output its comment promises; the simulator exits 0
    on SIGTERM, the playback is ended by it."""
    port = _free_port()
    lines = _bench()
    variables = [line for line in lines if re.fullmatch(r"[A-Z]+=\".*\"", line)]
    assert GROUP in variables[0]
    jobs: list[subprocess.Popen[str]] = []
    done: dict[str, subprocess.CompletedProcess[str]] = {}
    path = os.pathsep.join([str(Path(sys.executable).parent), os.environ.get("PATH", "")])
    env = {**os.environ, "PATH": path}
    try:
        for line in lines:
            if line in variables:
                continue
            if line.startswith("kill "):
                ended = [jobs[int(job) - 1] for job in re.findall(r"%(\d+)", line)]
                for job in ended:
                    job.terminate()
                    job.communicate(timeout=HANG_GUARD)
                continue
            command = line.removesuffix("&").strip()
            script = f"{'; '.join(variables)}; exec {command} --bus-option port={port}"
            if line.endswith("&"):
                job = subprocess.Popen(
                    ["bash", "-c", script],
                    cwd=demo,
                    env=env,
                    stdout=subprocess.PIPE,
                    stderr=subprocess.PIPE,
                    text=True,
                )
                jobs.append(job)
                assert job.stderr is not None
                if " simulate " in command:  # written once its bus is open
                    first = job.stderr.readline()
                    assert first.startswith("veronte4x: simulating Vertiq ESC nodes 41"), first
                else:
                    _wait_for_veronte_frames(port)
                continue
            result = subprocess.run(
                ["bash", "-c", script],
                cwd=demo,
                env=env,
                capture_output=True,
                text=True,
                timeout=HANG_GUARD,
                check=False,
            )
            assert result.returncode == 0, (command, result.stderr)
            done[command.split(" $")[0]] = result
    finally:
        for job in jobs:
            if job.poll() is None:
                job.kill()
                job.communicate()
    simulator, playback = jobs
    assert simulator.returncode == 0
    assert playback.returncode == -signal.SIGTERM

    nodes = done["veronte4x esc nodes"].stdout.splitlines()
    assert nodes[0].split() == ["node", "name", "health", "mode", "uptime", "seen", "vendor"]
    assert [row.split()[:4] for row in nodes[1:]] == [
        [str(node), "iq_motion.esc", "OK", "OPERATIONAL"] for node in (41, 42, 43, 44)
    ]
    assert done["veronte4x esc get 41 esc_index"].stdout == (
        "esc_index = 0 (default 0, range 0..19)\n"
    )
    table = done["veronte4x monitor"].stdout.splitlines()
    assert any(row.startswith("arbiter: selected AP") for row in table), table
    seen = {tuple(row.split()[:3]) for row in table}
    assert {("arbiter", "Status", "0FF"), ("node", "10", "RawCommand")} <= seen
    assert {("node", str(node), "EscStatus") for node in (41, 42, 43, 44)} <= seen
