"""``veronte4x esc`` refuses what is ambiguous and leaves motors stopped (issue 20, items 1,
3, 4, 5, 10 and 16), as subprocesses on a udp_multicast bus with simulated ESCs."""

from __future__ import annotations

import json
import re
import signal
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

from tests.client.cli_support import (
    bus_args,
    free_port,
    listening,
    simulator,
    stopped_for_good,
    veronte4x,
    wait_for_status,
)


@pytest.fixture(scope="module")
def bus() -> Iterator[list[str]]:
    port = free_port()
    with simulator(port, "--nodes", "21,22"):
        yield bus_args(port)


def _until_spinning(bus: list[str], node: int) -> None:
    with listening(bus) as listener:
        wait_for_status(listener, {node}, lambda status: status.power_rating_pct == 50)


def _spin(*args: str) -> subprocess.Popen[str]:
    return subprocess.Popen(
        [sys.executable, "-m", "veronte4x", "esc", "spin", *args, "--yes"],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )


def test_an_empty_parameter_name_is_refused(bus: list[str]) -> None:
    result = veronte4x("esc", "set", "21", "", "5", *bus)
    assert (result.returncode, result.stdout) == (2, "")
    assert result.stderr == (
        "veronte4x: an empty parameter name is refused (DroneCAN would read index 0, "
        "uavcan_node_id); give the name, or the index explicitly\n"
    )
    index = veronte4x("esc", "get", "21", "0", *bus)
    assert index.returncode == 2
    assert index.stderr == (
        "veronte4x: '0' is an index, not a parameter name; add --by-index to use it as one\n"
    )
    result = veronte4x("esc", "get", "21", "0", "--by-index", *bus)
    assert (result.returncode, result.stdout) == (
        0,
        "uavcan_node_id = 21 (default 21, range 1..127)\n",
    )  # unchanged
    result = veronte4x("esc", "get", "21", "x", "--by-index", *bus)
    assert (result.returncode, result.stderr) == (
        2,
        "veronte4x: --by-index needs a whole number, not 'x'\n",
    )


def test_a_value_that_does_not_parse_is_a_usage_error(bus: list[str]) -> None:
    result = veronte4x("esc", "set", "21", "esc_index", "abc", *bus)
    assert (result.returncode, result.stderr) == (
        2,
        "veronte4x: node 21: esc_index takes an integer, not 'abc'\n",
    )


def test_node_ids_out_of_range_in_plain_words() -> None:
    result = veronte4x("esc", "info", "200")
    assert result.returncode == 2
    assert result.stderr.splitlines()[-1] == (
        "veronte4x esc info: error: argument NODES: node id 200 is out of range: 1..127"
    )
    result = veronte4x("esc", "nodes", "--node-id", "0")
    assert result.returncode == 2
    assert result.stderr.splitlines()[-1].endswith("node id 0 is out of range: 1..127")
    result = veronte4x("esc", "spin", "21", "--throttle", "2", "--duration", "1", "--yes",
                       *bus_args(free_port()), "--timeout", "0.1", "--retries", "0")  # fmt: skip
    assert (result.returncode, result.stderr) == (2, "veronte4x: --throttle 2 is outside -1..1\n")
    result = veronte4x("esc", "spin", "21", "--throttle", "0.1", "--duration", "1", "--yes",
                       "--rate", "0", *bus_args(free_port()))  # fmt: skip
    assert (result.returncode, result.stderr) == (2, "veronte4x: --rate 0 must be above 0\n")
    for duration in ("inf", "nan", "0"):  # an endless spin is refused before anything is sent
        result = veronte4x("esc", "spin", "21", "--throttle", "0.1", "--duration", duration,
                           "--yes", *bus_args(free_port()))  # fmt: skip
        assert (result.returncode, result.stderr) == (
            2,
            f"veronte4x: --duration {duration} must be a finite number of seconds above 0\n",
        )
    result = veronte4x("esc", "info", "21", "--timeout", "nan", *bus_args(free_port()))
    assert (result.returncode, result.stderr) == (
        2,
        "veronte4x: request.timeout = nan: expected a finite number of seconds above 0\n",
    )


def test_empty_oversized_and_missing_images_are_refused(bus: list[str], tmp_path: Path) -> None:
    empty = veronte4x("esc", "update", "21", "/dev/null", *bus)
    assert (empty.returncode, empty.stderr) == (
        2,
        "veronte4x: the firmware image is empty (0 bytes); nothing was sent\n",
    )
    image = tmp_path / "big.bin"
    image.write_bytes(bytes(101))
    big = veronte4x("esc", "update", "21", str(image), "--max-image-size", "100", *bus)
    assert (big.returncode, big.stderr) == (
        2,
        f"veronte4x: {image} has more than 100 bytes, the firmware image limit; nothing was "
        "sent (raise --max-image-size if the image is right)\n",
    )
    one = veronte4x("esc", "update", "21", str(image), "--max-image-size", "1", *bus)
    assert (one.returncode, one.stderr) == (
        2,
        f"veronte4x: {image} has more than 1 byte, the firmware image limit; nothing was "
        "sent (raise --max-image-size if the image is right)\n",
    )
    missing = veronte4x("esc", "update", "21", str(tmp_path / "none.bin"), *bus)
    assert (missing.returncode, missing.stderr) == (
        2,
        f"veronte4x: {tmp_path / 'none.bin'}: No such file or directory\n",
    )
    info = json.loads(veronte4x("esc", "info", "21", *bus, "--json").stdout)
    assert (info["mode"], info["software_version"]["image_crc"]) == ("OPERATIONAL", None)


def test_a_killed_spin_leaves_no_motor_turning(bus: list[str]) -> None:
    """SIGKILL: the tool sends nothing more; the ESC's command timeout stops the motor."""
    spin = _spin("21", "--throttle", "0.5", "--duration", "30", *bus)
    _until_spinning(bus, 21)
    spin.send_signal(signal.SIGKILL)
    spin.communicate(timeout=10)
    assert spin.returncode == -signal.SIGKILL
    stopped_for_good(bus, {21})


def test_a_node_that_falls_silent_stops_every_motor() -> None:
    port = free_port()
    bus = bus_args(port)
    with simulator(port, "--nodes", "21"):
        with simulator(port, "--nodes", "22"):  # esc_index 0 too: one entry drives both
            spin = _spin("21", "22", "--throttle", "0.5", "--duration", "60", "--silence",
                         "2", *bus)  # fmt: skip
            _until_spinning(bus, 22)
        # node 22's simulator is gone
        _, stderr = spin.communicate(timeout=180)
        assert spin.returncode == 3
        assert stderr == (
            "veronte4x: node 22 fell silent: no esc.Status or NodeStatus for 2 s; every "
            "motor stopped: zero throttle sent to esc_index 0 (3 times)\n"
        )
        stopped_for_good(bus, {21})


def test_over_current_stops_every_motor(bus: list[str]) -> None:
    # --silence 30: a loaded machine may starve a simulator for longer than the default
    spin = _spin("21", "22", "--throttle", "0.4", "--duration", "60", "--max-current", "1",
                 "--silence", "30", *bus)  # fmt: skip
    _, stderr = spin.communicate(timeout=180)
    assert spin.returncode == 1
    assert re.fullmatch(
        r"veronte4x: node 2[12] reported \d+\.\d A, above the limit of 1 A; every motor "
        r"stopped: zero throttle sent to esc_index 0, 1 \(3 times\)\n",
        stderr,
    ), stderr
    stopped_for_good(bus, {21, 22})


def test_a_spin_confirms_the_zeros_on_exit(bus: list[str]) -> None:
    result = veronte4x("esc", "spin", "21", "--throttle", "0.2", "--duration", "0.3", "--yes",
                       *bus)  # fmt: skip
    assert result.returncode == 0, result.stderr
    assert result.stderr == "veronte4x: zero throttle sent to esc_index 0 (3 times)\n"


@pytest.mark.parametrize(
    ("content", "reason"),
    [
        (b"\xff\xfe\x00garbage", "'utf-8' codec can't decode byte 0xff in position 0"),
        (b"interface = virtual\n", "File contains no section headers."),
    ],
)
def test_a_can_config_that_is_not_an_utf8_ini_file(
    tmp_path: Path, content: bytes, reason: str
) -> None:
    config = tmp_path / "can.ini"
    config.write_bytes(content)
    for command in (["simulate", "esc"], ["esc", "nodes"]):
        result = veronte4x(*command, "--can-config", str(config))
        assert (result.returncode, result.stdout) == (2, "")
        assert result.stderr.startswith(
            f"veronte4x: python-can configuration file '{config}' is not a UTF-8 INI file "
            f"with a [default] section: {reason}"
        ), result.stderr
        assert len(result.stderr.splitlines()) == 1


def test_simulate_errors_in_plain_words() -> None:
    result = veronte4x("simulate", "esc", "--telem-frequency", "5000", "--interface", "virtual")
    assert (result.returncode, result.stderr) == (
        2,
        "veronte4x: --telem-frequency 5000 is refused: a whole number in 0..1000\n",
    )
    result = veronte4x("simulate", "esc", "--response-delay", "-0.5", "--interface", "virtual")
    assert result.returncode == 2
    assert result.stderr.splitlines()[-1].endswith(
        "argument --response-delay: -0.5 must be a finite number, 0 or above"
    ), result.stderr
