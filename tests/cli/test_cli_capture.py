"""The command line end to end, in a subprocess, on the example capture."""

import csv
import io
import json
import subprocess
import sys
from pathlib import Path

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "capture.log"


def run(*args: str, stdin: str | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "veronte4x", *args],
        input=stdin,
        capture_output=True,
        text=True,
        check=False,
    )


def test_decode_text_skips_and_counts_bad_frames() -> None:
    result = run("decode", str(EXAMPLE))
    assert result.returncode == 0
    lines = result.stdout.splitlines()
    assert len(lines) == 38
    assert lines[2] == "2025-11-21T15:00:00.010000Z can0 008 AP1       Ready(ready=True)"
    assert lines[5] == (
        "2025-11-21T15:00:00.020000Z can0 008 AP1       ArbitrationVariable(number=0, value=0.12)"
    )
    assert result.stderr == "veronte4x: 39 records, 0 undecoded, 1 bad (skip)\n"


def test_decode_relative_time() -> None:
    text = run("decode", str(EXAMPLE), "--time", "relative").stdout.splitlines()
    assert text[0].startswith("0.000000 can0 0FF arbiter   VersionRequest()")
    assert text[2] == "0.010000 can0 008 AP1       Ready(ready=True)"
    rows = run("decode", str(EXAMPLE), "--time", "relative", "--output", "jsonl").stdout
    assert [json.loads(line)["timestamp"] for line in rows.splitlines()[:3]] == [0.0, 0.001, 0.01]
    csv_lines = run("decode", str(EXAMPLE), "--time", "relative", "--output", "csv").stdout
    assert csv_lines.splitlines()[3].startswith("0.01,can0,8,AP1,Ready,")


def test_decode_jsonl_keeps_bad_frames() -> None:
    result = run("decode", str(EXAMPLE), "--output", "jsonl", "--on-error", "keep")
    rows = [json.loads(line) for line in result.stdout.splitlines()]
    assert len(rows) == 39
    assert rows[5] == {
        "timestamp": "2025-11-21T15:00:00.020000Z",
        "channel": "can0",
        "can_id": 8,
        "sender": "AP1",
        "message": "ArbitrationVariable",
        "number": 0,
        "value": 0.11999999731779099,  # the exact float32; text shows 0.12
    }
    assert rows[-2] == {
        "timestamp": "2025-11-21T15:00:00.500000Z",
        "channel": "can0",
        "can_id": 255,
        "sender": "arbiter",
        "message": None,
        "error": "unknown command",
        "detail": "frame.command: command byte 4 is reserved or unknown (data: 04 01)",
        "data": "0401",
    }
    status = next(row for row in rows if row["message"] == "Status")
    assert status["alive_0"] is True and status["alive_3"] is False
    assert status["normal_mode"] is True


def test_decode_csv() -> None:
    result = run("decode", str(EXAMPLE), "--output", "csv")
    lines = result.stdout.splitlines()
    header = lines[0].split(",")
    assert header[:8] == ["timestamp", "channel", "can_id", "sender", "message", "error",
                          "detail", "data"]  # fmt: skip
    rows = list(csv.DictReader(io.StringIO(result.stdout)))
    assert len(header) == len(set(header)) == len(rows[0])
    assert rows[2] == dict.fromkeys(header, "") | {
        "timestamp": "2025-11-21T15:00:00.010000Z", "channel": "can0", "can_id": "8",
        "sender": "AP1",
        "message": "Ready", "ready": "True",
    }  # fmt: skip
    variable = rows[5]
    assert (variable["message"], variable["number"], variable["value"]) == (
        "ArbitrationVariable",
        "0",
        "0.11999999731779099",
    )
    status = next(row for row in rows if row["message"] == "Status")
    assert (status["alive_0"], status["alive_3"], status["selected"]) == ("True", "False", "1")


def test_decode_raise_stops_with_exit_code_1() -> None:
    result = run("decode", str(EXAMPLE), "--on-error", "raise")
    assert result.returncode == 1
    assert len(result.stdout.splitlines()) == 37
    assert "unknown command: frame.command: command byte 4" in result.stderr


def test_decode_from_stdin_as_a_filter() -> None:
    result = run("decode", "-", stdin="(1.0) can0 009#00FF01\n(2.0) can0 0FF#0003000000803F\n")
    assert result.stdout == ("1.000000 can0 009 AP2       Ready(ready=True)\n")
    assert result.stderr == "veronte4x: 2 records, 0 undecoded, 1 bad (skip)\n"


def test_decode_csv_from_stdin_has_the_columns_of_what_came() -> None:
    stdin = "(1.0) can0 009#00FF01\n(2.0) can0 008#0000CDCCCC3D\n(3.0) can0 123#01\n"
    result = run("decode", "-", "--output", "csv", stdin=stdin)
    assert result.stdout.splitlines() == [
        "timestamp,channel,can_id,sender,message,error,detail,data,ready,number,value",
        "1.0,can0,9,AP2,Ready,,,,True,,",
        "2.0,can0,8,AP1,ArbitrationVariable,,,,,0,0.10000000149011612",
        "3.0,can0,291,unknown,,,11-bit CAN ID 0x123,01,,,",
    ]
    assert result.stderr == "veronte4x: 3 records, 1 undecoded, 0 bad (skip)\n"


def test_stats() -> None:
    result = run("stats", str(EXAMPLE))
    assert result.returncode == 0
    assert "records: 39, undecoded: 0, errors: 1" in result.stdout
    assert "  ArbitrationVariable                  12" in result.stdout
    assert "  external                              3" in result.stdout
    assert "  unknown command                       1" in result.stdout


def test_usage_errors_exit_2() -> None:
    missing = run("decode", "no/such/file.log")
    assert missing.returncode == 2
    assert "No such file or directory" in missing.stderr
    assert run("frobnicate").returncode == 2


def test_foreign_traffic_is_undecoded_not_bad() -> None:
    stdin = (
        "(1.0) can0 123#0102\n"  # 11-bit ID outside the bus map
        "(2.0) can0 1004D42A#C0\n"  # DroneCAN data type 1236, no codec
        "(3.0) can0 009#00FF01\n"
    )
    result = run("decode", "-", "--on-error", "raise", stdin=stdin)
    assert result.returncode == 0
    assert result.stdout.splitlines()[:2] == [
        "1.000000 can0 123 unknown   unknown: 11-bit CAN ID 0x123 [01 02]",
        "2.000000 can0 1004D42A node 42   unknown: DroneCAN data type 1236 [c0]",
    ]
    assert result.stderr == "veronte4x: 3 records, 2 undecoded, 0 bad (raise)\n"
    stats = run("stats", "-", stdin=stdin)
    assert "records: 3, undecoded: 2, errors: 0" in stats.stdout
    assert "  DroneCAN data type 1236               1" in stats.stdout


def test_jsonl_non_finite_floats_are_strings() -> None:
    stdin = "(1.0) can0 008#00000000C07F\n(2.0) can0 008#00010000807F\n"
    rows = [
        json.loads(line)
        for line in run("decode", "-", "--output", "jsonl", stdin=stdin).stdout.splitlines()
    ]
    assert [row["value"] for row in rows] == ["NaN", "Infinity"]


def test_an_array_of_structs_is_written_field_by_field() -> None:
    """actuator.ArrayCommand: each command's fields, as ``commands_0.actuator_id``...; JSON
    lines ended in a TypeError traceback (a struct object is no JSON), CSV gave its repr."""
    stdin = "(1.000000) can0 1003F205#01000038C0\n"  # actuator 1, UNITLESS, 0.5
    expected = {"commands_0.actuator_id": 1, "commands_0.command_type": "UNITLESS",
                "commands_0.command_value": 0.5}  # fmt: skip
    jsonl = run("decode", "-", "--output", "jsonl", stdin=stdin)
    assert (jsonl.returncode, jsonl.stderr) == (
        0,
        "veronte4x: 1 record, 0 undecoded, 0 bad (skip)\n",
    )
    row = json.loads(jsonl.stdout)
    assert {key: row[key] for key in row if key.startswith("commands")} == expected
    table = list(
        csv.DictReader(io.StringIO(run("decode", "-", "--output", "csv", stdin=stdin).stdout))
    )
    assert [{key: row[key] for key in row if key.startswith("commands")} for row in table] == [
        {key: str(value) for key, value in expected.items()}
    ]
    text = run("decode", "-", stdin=stdin).stdout
    assert text.endswith(
        " ArrayCommand(commands=(ActuatorCommand(actuator_id=1, command_type=UNITLESS, "
        "command_value=0.5)))\n"
    )


def test_version() -> None:
    result = run("--version")
    assert (result.returncode, result.stdout, result.stderr) == (0, "veronte4x 0.1.0\n", "")
