"""Usage errors and plain output of the commands that share the bus and capture options,
as a person meets them: a bad ``--bus-option``, a value python-can cannot take, a command
with no source, ``simulate``'s arguments, ``plot`` with no display, ``play --channel-map``,
and the rates report over remote frames. Each command runs as a subprocess: its exit code,
its exact lines on standard error, no traceback."""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
from pathlib import Path

import can
import pytest

from tests.client.cli_support import (
    GROUP,
    HANG_GUARD,
    bus_args,
    free_port,
    simulator,
    veronte4x,
)
from veronte4x.canbus import open_bus
from veronte4x.cli.options import NO_SOURCE, add_bus_options, bus_settings

CAPTURE = Path(__file__).resolve().parents[2] / "examples" / "capture.log"


@pytest.mark.parametrize("option", ["port", "=43113"])
def test_a_bus_option_that_is_not_key_value(option: str) -> None:
    result = veronte4x("esc", "nodes", "--interface", "udp_multicast", "--bus-option", option)
    assert (result.returncode, result.stdout, result.stderr) == (
        2,
        "",
        f"veronte4x: --bus-option {option!r} is not KEY=VALUE\n",
    )


def test_a_bus_option_true_or_false_reaches_the_bus() -> None:
    """``fd=false`` is python-can's ``fd=False``: the bus opens, and no node answers."""
    result = veronte4x("esc", "nodes", *bus_args(free_port()), "--bus-option", "fd=false",
                       "--timeout", "0.3")  # fmt: skip
    assert (result.returncode, result.stdout, result.stderr) == (
        3,
        "",
        "veronte4x: no node on the bus within 0.3 s; check --interface, --channel and --bitrate\n",
    )


@pytest.mark.parametrize(("text", "fd"), [("false", False), ("TRUE", True)])
def test_a_bus_option_true_or_false_reaches_the_bus_as_a_bool(text: str, fd: bool) -> None:
    """The command line's ``fd=...`` opens a udp_multicast bus of that protocol."""
    parser = argparse.ArgumentParser()
    add_bus_options(parser)
    args = parser.parse_args([*bus_args(free_port()), "--bus-option", f"fd={text}"])
    settings = bus_settings(args)
    assert settings["options"]["fd"] is fd
    with open_bus(**settings) as bus:
        assert bus.protocol == (can.CanProtocol.CAN_FD if fd else can.CanProtocol.CAN_20)


def test_a_bus_option_the_interface_cannot_take_is_one_line() -> None:
    """``hop_limit=x`` stays text (not a number), which udp_multicast packs as an integer:
    python-can's ``struct.error`` was a traceback with exit code 1."""
    result = veronte4x("esc", "nodes", *bus_args(free_port()), "--bus-option", "hop_limit=x")
    assert (result.returncode, result.stdout) == (2, "")
    assert result.stderr.splitlines()[0] == (
        f"veronte4x: cannot open the CAN bus (interface udp_multicast, channel {GROUP}): "
        "required argument is not an integer"
    )
    assert "Traceback" not in result.stderr
    # python-can logs "UdpMulticastBus was not properly shut down" for its half-built bus.


@pytest.mark.parametrize("rates", [[], ["--rates"]])
def test_monitor_with_no_source(rates: list[str]) -> None:
    result = veronte4x("monitor", *rates)
    assert (result.returncode, result.stdout, result.stderr) == (
        2,
        "",
        f"veronte4x: {NO_SOURCE}\n",
    )


def test_the_rates_report_counts_remote_frames_in_the_load_only(tmp_path: Path) -> None:
    capture = tmp_path / "remote.log"
    capture.write_text(
        "(1.000000) can0 123#R\n(1.010000) can0 123#0102\n(1.020000) can0 123#0102\n",
        encoding="utf-8",
    )
    result = veronte4x("stats", str(capture), "--rates")
    assert result.returncode == 0, result.stderr
    assert result.stdout.splitlines()[-4:] == [
        "rates:",
        "  can0 123: 2 at 100 Hz, jitter -, longest gap 10 ms",
        "bus load (worst-case bit stuffing):",
        # 55 bits (remote, 11-bit ID) + 2 x 75 (2 data bytes) in 20 ms at 125 kbit/s
        "  can0: 3 frames, 8.2 % of 125 kbit/s (detected: the lowest that fits)",
    ]


@pytest.mark.parametrize(
    ("args", "line"),
    [
        (["--nodes", "all"], "argument --nodes: name the simulated nodes, e.g. 21,22 or 21-28"),
        (["--command-timeout", "x"], "argument --command-timeout: 'x' is not a number"),
        (
            ["--command-timeout", "inf"],
            "argument --command-timeout: inf must be a finite number, 0 or above",
        ),
        (
            ["--response-delay", "nan"],
            "argument --response-delay: nan must be a finite number, 0 or above",
        ),
    ],
)
def test_simulate_arguments(args: list[str], line: str) -> None:
    result = veronte4x("simulate", "esc", *args, "--interface", "virtual")
    assert (result.returncode, result.stdout) == (2, "")
    assert result.stderr.splitlines()[-1] == f"veronte4x simulate esc: error: {line}"


def test_simulate_takes_a_delay_and_no_command_timeout() -> None:
    port = free_port()
    options = ["--nodes", "23", "--command-timeout", "0", "--response-delay", "0.05"]
    with simulator(port, *options):
        result = veronte4x("esc", "get", "23", "esc_index", *bus_args(port))
    assert (result.returncode, result.stdout, result.stderr) == (
        0,
        "esc_index = 0 (default 0, range 0..19)\n",
        "",
    )


@pytest.mark.parametrize("backend", ["Agg", "pdf", "svg"])
def test_plot_without_a_display(backend: str) -> None:
    """No ``--output`` and no window (a non-interactive matplotlib backend, Agg or a file
    format's): say how to get a file. With ``pdf`` the command said nothing and exited 0.

    Not reached here: ``cli/plot.py:67`` (``plt.figure``/``plt.show``, a window), which needs
    a display that the test machines have not.
    """
    env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY")}
    result = subprocess.run(
        [sys.executable, "-m", "veronte4x", "plot", str(CAPTURE)],
        capture_output=True,
        text=True,
        timeout=HANG_GUARD,
        check=False,
        env={**env, "MPLBACKEND": backend},
    )
    assert (result.returncode, result.stdout, result.stderr) == (
        2,
        "",
        "veronte4x: no display for a window; give --output FILE.png\n",
    )


def test_play_with_a_channel_map_sends_onto_the_mapped_channel() -> None:
    port = free_port()
    with can.Bus(interface="udp_multicast", channel=GROUP, port=port) as listener:
        options = ["--bus-option", f"port={port}", "--channel-map", f"can0={GROUP}"]
        result = veronte4x("play", str(CAPTURE), "-i", "udp_multicast", *options, "--speed", "10")
        assert result.returncode == 0, result.stderr
        assert result.stderr.startswith("veronte4x: sent 39 frames in ")
        received: list[int] = []
        while len(received) < 39 and (message := listener.recv(5.0)) is not None:
            received.append(message.arbitration_id)
    sent = [int(line.split()[2].split("#")[0], 16) for line in CAPTURE.read_text().splitlines()]
    assert received == sent[: len(received)]
    assert len(received) == 39


def test_play_with_a_channel_map_that_is_not_captured_equals_sent() -> None:
    result = veronte4x("play", str(CAPTURE), "-i", "udp_multicast", "--channel-map", "can0")
    assert (result.returncode, result.stdout, result.stderr) == (
        2,
        "",
        "veronte4x: --channel-map 'can0': expected CAPTURED=SENT, e.g. can0=vcan1\n",
    )


@pytest.mark.parametrize(
    ("arguments", "line"),
    [
        (
            ("--to", "pydronecan", "out.can"),
            "record reads a live bus: give --interface and --channel (e.g. --interface mcast "
            "--channel 0) or --can-config FILE",
        ),
        (
            ("--to", "asc", "out.asc", "-i", "mcast"),
            "--to asc: record writes pydronecan or candump",
        ),
    ],
)
def test_record_without_a_bus_or_with_a_format_it_does_not_write(
    tmp_path: Path, arguments: tuple[str, ...], line: str
) -> None:
    result = subprocess.run(
        [sys.executable, "-m", "veronte4x", "record", *arguments],
        capture_output=True, text=True, timeout=HANG_GUARD, check=False, cwd=tmp_path,
    )  # fmt: skip
    assert (result.returncode, result.stdout, result.stderr) == (2, "", f"veronte4x: {line}\n")
    assert list(tmp_path.iterdir()) == []  # no file left behind


def test_record_a_count_of_no_frames() -> None:
    result = veronte4x("record", "--count", "0", "--to", "pydronecan", "out.can")
    assert result.returncode == 2
    assert result.stderr.endswith(
        "veronte4x record: error: argument --count: '0' is not a number of frames (1 or more)\n"
    )


def test_record_onto_a_bus_that_cannot_be_opened_leaves_the_file_as_it_was(
    tmp_path: Path,
) -> None:
    """An existing file keeps its bytes (the bus failed before any frame); a new one is not
    left behind empty."""
    kept = tmp_path / "flight.can"
    kept.write_bytes(b"an earlier recording")
    for out in (kept, tmp_path / "new.can"):
        result = subprocess.run(
            [sys.executable, "-m", "veronte4x", "record", "-i", "socketcan", "-c", "nosuch0",
             "--to", "pydronecan", str(out)],
            capture_output=True, text=True, timeout=HANG_GUARD, check=False,
        )  # fmt: skip
        assert (result.returncode, result.stdout) == (2, "")
        assert result.stderr.startswith("veronte4x: cannot open the CAN bus"), result.stderr
    assert kept.read_bytes() == b"an earlier recording"
    assert list(tmp_path.iterdir()) == [kept]
