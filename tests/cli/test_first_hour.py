"""A new user's first hour (issue 39): a command that opens a bus when nothing names one, and
the small outputs that said less than they should. Each command runs as a subprocess: its exit
code and its exact lines."""

from __future__ import annotations

import json
import os
import random
import re
import subprocess
import sys
from pathlib import Path

import pytest

from tests.client.cli_support import HANG_GUARD, bus_args, free_port, simulator
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


@pytest.fixture(scope="module")
def flight_start(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The first 2,000 lines of the demo flight (`examples/make_capture.py`): the autopilots,
    the arbiter and four Vertiq ESCs, their GetNodeInfo answers among them."""
    directory = tmp_path_factory.mktemp("flight")
    subprocess.run(
        [sys.executable, str(CAPTURE.parent / "make_capture.py"), "flight.log"],
        cwd=directory,
        check=True,
        capture_output=True,
        timeout=HANG_GUARD,
    )
    lines = (directory / "flight.log").read_text().splitlines(keepends=True)
    start = directory / "start.log"
    start.write_text("".join(lines[:2000]))
    return start


def test_decode_shows_an_empty_certificate_as_none(flight_start: Path) -> None:
    result = _run("decode", str(flight_start))
    assert result.returncode == 0, result.stderr
    answers = [line for line in result.stdout.splitlines() if "GetNodeInfoResponse(" in line]
    assert len(answers) == 4
    assert all("certificate_of_authenticity=(none))" in line for line in answers), answers[0]


def test_decode_with_a_channel_the_capture_does_not_have_says_which_it_has() -> None:
    result = _run("decode", str(CAPTURE), "--only-channel", "can9")
    assert (result.returncode, result.stdout) == (0, "")
    assert result.stderr.splitlines() == [
        "veronte4x: 0 records, 0 undecoded, 0 bad (skip)",
        f"veronte4x: no frame of {CAPTURE} is on channel can9: its channels are can0; give one "
        "of them to --only-channel, or leave it out",
    ]
    result = _run("decode", str(CAPTURE), "--only-channel", "can0")
    assert result.stderr.splitlines() == ["veronte4x: 39 records, 0 undecoded, 1 bad (skip)"]


def test_replay_of_a_capture_without_veronte_traffic_says_so(
    flight_start: Path, tmp_path: Path
) -> None:
    escs = tmp_path / "escs.log"
    lines = flight_start.read_text().splitlines(keepends=True)
    escs.write_text("".join(line for line in lines if re.search(r" [0-9A-F]{8}#", line)))
    config = CAPTURE.parent / "arbiter.toml"
    result = _run("replay", str(escs), "--config", str(config))
    assert (result.returncode, result.stdout) == (0, "\n")
    assert result.stderr.splitlines() == [
        "veronte4x: 0 decisions, 0 disagreements, 0 bad frames",
        "veronte4x: no frame has a Veronte 4x CAN ID (autopilots 008, 009, 00A, 00B, arbiter "
        "0FF): is this a 4x capture? Other IDs: give the vehicle's --config (or --bus-map)",
    ]
    result = _run("replay", str(CAPTURE), "--config", str(config), "--only-channel", "can9")
    assert result.stderr.splitlines()[-1] == (
        f"veronte4x: no frame of {CAPTURE} is on channel can9: its channels are can0; give one "
        "of them to --only-channel, or leave it out"
    )
    result = _run("replay", str(CAPTURE), "--config", str(config))
    assert "Veronte 4x CAN ID" not in result.stderr


@pytest.mark.skipif(not Path("/dev/full").exists(), reason="no /dev/full")
@pytest.mark.parametrize("command", [["decode"], ["stats"], ["decode", "--output", "jsonl"]])
def test_a_full_standard_output_is_named(command: list[str]) -> None:
    with open("/dev/full", "w") as full:
        result = subprocess.run(
            [sys.executable, "-m", "veronte4x", command[0], str(CAPTURE), *command[1:]],
            stdout=full,
            stderr=subprocess.PIPE,
            text=True,
            timeout=HANG_GUARD,
            check=False,
        )
    assert (result.returncode, result.stderr) == (
        2,
        "veronte4x: standard output: No space left on device\n",
    )


def test_esc_apply_of_a_broken_file_names_it(tmp_path: Path) -> None:
    """The file is read before any node is asked: no simulator is needed to see it refused."""
    broken = tmp_path / "saved.toml"
    broken.write_text("x = [\n")
    result = _run("esc", "apply", str(broken), "21", *bus_args(free_port()))
    assert (result.returncode, result.stdout) == (2, "")
    assert result.stderr == (
        f"veronte4x: {broken}: not a TOML file: Invalid value (at end of document)\n"
    )
    parm = tmp_path / "saved.parm"
    parm.write_text("# only a comment\n")
    result = _run("esc", "apply", str(parm), "21", *bus_args(free_port()))
    assert (result.returncode, result.stderr) == (
        2,
        f"veronte4x: {parm}: the .parm file holds no parameter line (NAME VALUE)\n",
    )


def test_esc_get_json_has_no_null_index_and_info_shows_the_certificate() -> None:
    port = free_port()
    with simulator(port, "--nodes", "21"):
        got = _run("esc", "get", "21", "esc_index", "--json", *bus_args(port))
        by_index = _run("esc", "get", "21", "0", "--by-index", "--json", *bus_args(port))
        info = _run("esc", "info", "21", *bus_args(port))
    assert (got.returncode, got.stderr) == (0, "")
    assert json.loads(got.stdout) == {
        "name": "esc_index",
        "value": 0,
        "default": 0,
        "min": 0,
        "max": 19,
    }
    assert by_index.returncode == 0, by_index.stderr
    assert json.loads(by_index.stdout)["index"] == 0
    assert info.returncode == 0, info.stderr
    [hardware] = [line for line in info.stdout.splitlines() if line.startswith("  hardware")]
    assert hardware.endswith(", certificate of authenticity (none)"), hardware


def test_a_conversion_summary_rounds_its_time_for_people(tmp_path: Path) -> None:
    from veronte4x import capture

    summary = capture.to_parquet([CAPTURE], tmp_path / "dataset")
    assert repr(summary) == (
        f"Summary(files=1, frames=39, records={summary.records!r}, "
        f"seconds={summary.seconds:.3g}, truncated=[])"
    )
    assert summary.seconds > 0 and repr(summary.seconds) not in repr(summary)
    html = summary._repr_html_()
    assert "<caption" in html and ">Summary</caption>" in html
    assert "<th>frames</th><td>39</td>" in html
    assert f"<th>seconds</th><td>{summary.seconds:.3g} s</td>" in html
    assert all(
        f"<td>{kind}</td><td>{rows}</td>" in html
        for kind, rows in summary.records.items()
        if kind != "errors"
    )


def test_a_jitter_below_a_millisecond_is_shown_in_microseconds(tmp_path: Path) -> None:
    """Periods of 10.05 and 9.95 ms: a standard deviation of 57.735 µs (``5.774e-02 ms``
    before)."""
    times = ["0.000000", "0.010050", "0.020000", "0.030050", "0.040000"]
    capture_file = tmp_path / "steady.log"
    capture_file.write_text("".join(f"({t}) can0 123#01\n" for t in times))
    result = _run("stats", str(capture_file), "--rates")
    assert result.returncode == 0, result.stderr
    assert "  can0 123: 5 at 100 Hz, jitter 57.74 µs, longest gap 10.05 ms" in (
        result.stdout.splitlines()
    )


HIDING = r"""
import importlib.abc, runpy, sys
hidden = set(sys.argv.pop(1).split(","))

class NotInstalled(importlib.abc.MetaPathFinder):
    def find_spec(self, name, path=None, target=None):
        if name.partition(".")[0] in hidden:
            raise ModuleNotFoundError(f"No module named {name!r}", name=name)
        return None

sys.meta_path.insert(0, NotInstalled())
sys.argv[0] = "veronte4x"
runpy.run_module("veronte4x", run_name="__main__", alter_sys=True)
"""
"""``python -m veronte4x`` in a process where the modules of its first argument (``can,msgpack``)
are not installed: a finder in front of ``sys.meta_path`` refuses them."""

UDP = ["--interface", "udp_multicast", "--channel", "239.74.163.9"]


@pytest.mark.parametrize(
    "command",
    [
        ["esc", "nodes", *UDP],
        ["simulate", "esc", "--nodes", "41", *UDP],
        ["monitor", *UDP, "--duration", "0.1"],
        ["play", str(CAPTURE), *UDP],
        ["decode", *UDP, "--duration", "0.1"],
    ],
)
@pytest.mark.parametrize("hidden", ["can,msgpack", "msgpack"])
def test_a_udp_multicast_bus_names_the_one_extra_that_brings_all_it_needs(
    command: list[str], hidden: str
) -> None:
    """Without python-can, the error names ``bench`` (python-can and msgpack) rather than
    ``can``, after which a second install would still be missing msgpack."""
    result = subprocess.run(
        [sys.executable, "-c", HIDING, hidden, *command],
        capture_output=True,
        text=True,
        timeout=HANG_GUARD,
        check=False,
    )
    missing = hidden.partition(",")[0]
    assert (result.returncode, result.stdout, result.stderr) == (
        2,
        "",
        f"veronte4x: python-can's udp_multicast bus needs the '{missing}' package: "
        "pip install 'veronte4x[bench]'\n",
    )


@pytest.mark.parametrize(
    ("command", "needs"),
    [
        (["esc", "nodes"], "veronte4x esc"),
        (["simulate", "esc", "--nodes", "41"], "veronte4x simulate"),
        (["monitor", "--interface", "virtual", "--duration", "0.1"], "a live CAN bus"),
        (["esc", "nodes", "--interface", "virtual"], "a live CAN bus"),
    ],
)
def test_another_bus_without_python_can_names_the_can_extra(command: list[str], needs: str) -> None:
    result = subprocess.run(
        [sys.executable, "-c", HIDING, "can", *command],
        capture_output=True,
        text=True,
        timeout=HANG_GUARD,
        check=False,
    )
    assert (result.returncode, result.stdout, result.stderr) == (
        2,
        "",
        f"veronte4x: {needs} needs the 'can' package: pip install 'veronte4x[can]'\n",
    )


@pytest.mark.parametrize(
    "command",
    [["--to", "csv", "no/out.csv", "--every", "1s"], ["--to", "pydronecan", "no/out.log"]],
)
def test_convert_into_a_missing_directory_is_refused_before_reading(
    command: list[str], tmp_path: Path
) -> None:
    """Before any frame is read (the capture does not even exist): the file is written last,
    and its temporary file's name was all the error said."""
    result = _run("convert", *command, "missing.log", cwd=tmp_path)
    assert (result.returncode, result.stdout) == (2, "")
    assert result.stderr == (
        f"veronte4x: --to {command[1]} {command[2]}: no directory no; create it first\n"
    )
    assert list(tmp_path.iterdir()) == []


def test_a_broken_toml_file_is_named_by_every_command_that_reads_one(tmp_path: Path) -> None:
    broken = tmp_path / "broken.toml"
    broken.write_text("x = [\n")
    result = _run("stats", str(CAPTURE), "--bus-map", str(broken))
    assert (result.returncode, result.stdout, result.stderr) == (
        2,
        "",
        f"veronte4x: {broken}: not a TOML file: Invalid value (at end of document); fix the "
        "bus map (see 'The bus map' in the captures docs)\n",
    )
    result = _run("replay", str(CAPTURE), "--config", str(broken))
    assert (result.returncode, result.stdout) == (2, "")
    assert result.stderr.startswith(f"veronte4x: {broken}: not TOML: Invalid value"), result.stderr
    assert result.stderr.count("\n") == 1


def test_stats_plot_and_monitor_with_a_channel_the_capture_lacks_say_which_it_has(
    tmp_path: Path,
) -> None:
    hint = (
        f"veronte4x: no frame of {CAPTURE} is on channel can9: its channels are can0; give one "
        "of them to --only-channel, or leave it out"
    )
    result = _run("stats", str(CAPTURE), "--only-channel", "can9")
    assert (result.returncode, result.stderr) == (0, hint + "\n")
    assert result.stdout.startswith("records: 0, undecoded: 0, errors: 0\n")
    assert _run("stats", str(CAPTURE), "--only-channel", "can0").stderr == ""
    result = _run("plot", str(CAPTURE), "--only-channel", "can9", "--output", "p.png", cwd=tmp_path)
    assert (result.returncode, result.stdout) == (2, "")
    assert result.stderr == hint.replace("veronte4x: ", "veronte4x: nothing to plot: ") + "\n"
    assert list(tmp_path.iterdir()) == []
    result = _run("monitor", str(CAPTURE), "--only-channel", "can9")
    assert (result.returncode, result.stderr) == (0, "veronte4x: 0 records, 0 bad\n" + hint + "\n")
