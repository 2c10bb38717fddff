"""One time form and one CAN ID form across the text outputs (issue 39, items 4 and 8):
``decode`` (text, JSON lines, CSV) and ``convert --to csv`` write Unix time as ISO 8601 in
UTC to the microsecond, the tables' time; ``--time seconds`` the reader's float itself; a
capture's own clock (time since boot) as seconds, never as 1970; CAN IDs as candump prints
them. The CLI runs as a subprocess, its exit code and standard error asserted."""

from __future__ import annotations

import csv
import io
import json
import subprocess
import sys
from pathlib import Path

import pytest

from veronte4x import capture
from veronte4x.capture.monitor import MonitorState, render_text

# (1763737200.0000005) has seven decimals: the reader keeps its microseconds beside the
# float (capture.frames.Seconds), rounded half to even to ...200.000000.
UNIX = (
    "(1763737200.0000005) can0 009#00FF01\n"
    "(1763737200.123456) can0 0FF#01\n"
    "(1763737200.2) can0 10015514#00000000000000C0\n"
    "(1763737200.3) can0 0FF#01\n"
    "(1763737200.4) can0 00000123#01\n"
)
BOOT = "(12.500000) can0 009#00FF01\n(12.600001) can0 009#00FF01\n"


def _run(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "veronte4x", *args], capture_output=True, text=True, check=False
    )


def _decode(log: Path, *options: str) -> list[str]:
    """The lines ``decode`` writes, bad records kept."""
    result = _run("decode", str(log), "--on-error", "keep", *options)
    assert (result.returncode, result.stderr.count("\n")) == (0, 1), result.stderr
    return result.stdout.splitlines()


@pytest.fixture
def unix(tmp_path: Path) -> Path:
    path = tmp_path / "unix.log"
    path.write_text(UNIX, encoding="ascii")
    return path


@pytest.fixture
def boot(tmp_path: Path) -> Path:
    path = tmp_path / "boot.log"
    path.write_text(BOOT, encoding="ascii")
    return path


def test_every_output_writes_iso_utc_to_the_microsecond_of_the_tables(unix: Path) -> None:
    tables = capture.read_tables([unix])
    expected = sorted(
        stamp.strftime("%Y-%m-%dT%H:%M:%S.%fZ")
        for table in tables.values()
        for stamp in table.column("timestamp").to_pylist()
    )
    rows = [json.loads(line) for line in _decode(unix, "--output", "jsonl")]
    cells = list(csv.DictReader(io.StringIO("\n".join(_decode(unix, "--output", "csv")))))
    text = [line.split(" ")[0] for line in _decode(unix)]
    assert sorted(row["timestamp"] for row in rows) == expected
    assert [row["timestamp"] for row in cells] == [row["timestamp"] for row in rows] == text
    assert text[:2] == ["2025-11-21T15:00:00.000000Z", "2025-11-21T15:00:00.123456Z"]


def test_time_seconds_writes_the_float_as_read(unix: Path) -> None:
    records = list(capture.read(unix))
    rows = [json.loads(line) for line in _decode(unix, "--output", "jsonl", "--time", "seconds")]
    assert [repr(row["timestamp"]) for row in rows] == [repr(r.timestamp) for r in records]
    assert rows[0]["timestamp"] == 1763737200.0000005
    cells = csv.DictReader(
        io.StringIO("\n".join(_decode(unix, "--output", "csv", "--time", "seconds")))
    )
    assert [row["timestamp"] for row in cells] == [repr(r.timestamp) for r in records]
    assert _decode(unix, "--time", "seconds")[1].startswith("1763737200.123456 can0 0FF")


def test_a_clock_since_boot_stays_seconds_in_every_output(boot: Path, tmp_path: Path) -> None:
    assert [json.loads(line)["timestamp"] for line in _decode(boot, "--output", "jsonl")] == [
        12.5,
        12.600001,
    ]
    assert [line.split(",")[0] for line in _decode(boot, "--output", "csv")] == [
        "timestamp",
        "12.5",
        "12.600001",
    ]
    assert _decode(boot)[0] == "12.500000 can0 009 AP2       Ready(ready=True)"
    out = tmp_path / "boot.csv"
    result = _run("convert", str(boot), "--to", "csv", str(out), "--every", "50ms")
    assert (result.returncode, result.stderr) == (0, f"veronte4x: 3 rows, 2 columns, in {out}\n")
    assert [line.split(",")[0] for line in out.read_text().splitlines()] == [
        '"time"',
        "12.5",
        "12.55",
        "12.6",
    ]


@pytest.mark.parametrize("command", ["decode", "replay"])
def test_the_old_relative_time_option_names_the_new_one(unix: Path, command: str) -> None:
    result = _run(command, str(unix), "--relative-time")
    assert (result.returncode, result.stdout) == (2, "")
    assert result.stderr == "veronte4x: --relative-time is now --time relative\n"


def test_replay_takes_the_same_time_forms(unix: Path) -> None:
    forms = {}
    for form in ("timestamp", "relative", "seconds"):
        result = _run("replay", str(unix), "--time", form)
        assert result.returncode == 0, result.stderr
        forms[form] = result.stdout.splitlines()[0].split()[0]
    assert forms == {
        "timestamp": "2025-11-21T15:00:00.000000Z",
        "relative": "0.000000",
        "seconds": "1763737200.000000",
    }


def test_can_ids_print_as_candump_prints_them_and_line_up(unix: Path) -> None:
    lines = _decode(unix, "--time", "relative")
    ids = [line.split()[2] for line in lines]
    assert ids == ["009", "0FF", "10015514", "0FF", "00000123"]
    # From the first 29-bit ID on, an 11-bit ID is indented to its width, as candump does.
    assert lines[3].startswith("0.300000 can0      0FF arbiter   VersionRequest()")
    assert lines[2].index(" node 20") == lines[3].index(" arbiter") == lines[4].index(" missed")


def test_a_29_bit_id_below_0x800_keeps_its_8_digits_in_every_output(tmp_path: Path) -> None:
    """A record holds no IDE bit: where the bus map leaves 29-bit frames undecoded, their
    detail (``29-bit CAN ID 0x7f``) tells ``decode``'s text and the record's HTML that
    ``0000007F`` is not ``07F``; the rates of ``stats`` read the frame's own flag."""
    log = tmp_path / "small.log"
    log.write_text("(1.000000) can0 0000007F#01\n(1.010000) can0 07F#02\n", encoding="ascii")
    bus_map = tmp_path / "map.toml"
    bus_map.write_text("[dronecan]\nenabled = false\n", encoding="ascii")
    lines = _decode(log, "--bus-map", str(bus_map))
    assert [line.split()[2] for line in lines] == ["0000007F", "07F"]
    assert lines[1].startswith("1.010000 can0      07F unknown")

    result = _run("stats", str(log), "--bus-map", str(bus_map), "--rates")
    assert (result.returncode, result.stderr) == (0, "")
    rates = result.stdout.split("rates:\n")[1].splitlines()[:2]
    assert rates == [
        "  can0 0000007F: 1 at -, jitter -, longest gap -",
        "  can0 07F: 1 at -, jitter -, longest gap -",
    ]

    wide, narrow = capture.read(log, capture.BusMap(dronecan=False))
    assert "<td>0000007F</td>" in wide._repr_html_()
    assert "<td>07F</td>" in narrow._repr_html_()

    state = MonitorState()
    for record in (wide, narrow):
        state.add(record)
    table = render_text(state, "", None).splitlines()[3:]
    assert [line.split()[-5] for line in table] == ["07F", "0000007F"]


def test_json_lines_and_csv_give_the_autopilots_name_beside_its_index(tmp_path: Path) -> None:
    """As the tables do (``selected_name`` beside ``selected``): 1 is AP2, not AP1."""
    log = tmp_path / "arbiter.log"
    log.write_text(
        "(1763737200.002115) can0 0FF#00FF8177FFFF\n(1763737200.002345) can0 0FF#0001224FB13C\n",
        encoding="ascii",
    )
    result = _run("decode", str(log), "--output", "jsonl")
    assert result.returncode == 0, result.stderr
    rows = [json.loads(line) for line in result.stdout.splitlines()]
    assert [(r["message"], r.get("selected"), r.get("selected_name")) for r in rows] == [
        ("Status", 1, "AP2"),
        ("Score", None, None),
    ]
    assert (rows[1]["autopilot"], rows[1]["autopilot_name"]) == (1, "AP2")
    result = _run("decode", str(log), "--output", "csv")
    assert result.returncode == 0, result.stderr
    [row, *_] = csv.DictReader(io.StringIO(result.stdout))
    assert (row["selected"], row["selected_name"]) == ("1", "AP2")
