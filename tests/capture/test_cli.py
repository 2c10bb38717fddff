"""The command line end to end, in a subprocess, on the example capture."""

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
    assert lines[2] == "1763737200.010000 can0 008 AP1       Ready(ready=True)"
    assert result.stderr == "veronte4x: 39 records, 0 undecoded, 1 bad (skip)\n"


def test_decode_jsonl_keeps_bad_frames() -> None:
    result = run("decode", str(EXAMPLE), "--output", "jsonl", "--on-error", "keep")
    rows = [json.loads(line) for line in result.stdout.splitlines()]
    assert len(rows) == 39
    assert rows[5] == {
        "timestamp": 1763737200.02,
        "channel": "can0",
        "can_id": 8,
        "sender": "AP1",
        "message": "ArbitrationVariable",
        "number": 0,
        "value": 0.11999999731779099,
    }
    assert rows[-2] == {
        "timestamp": 1763737200.5,
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
    assert lines[0] == "timestamp,channel,can_id,sender,message,error,detail,fields"
    assert lines[3] == '1763737200.01,can0,8,AP1,Ready,,,"{""ready"": true}"'


def test_decode_raise_stops_with_exit_code_1() -> None:
    result = run("decode", str(EXAMPLE), "--on-error", "raise")
    assert result.returncode == 1
    assert len(result.stdout.splitlines()) == 37
    assert "unknown command: frame.command: command byte 4" in result.stderr


def test_decode_from_stdin_as_a_filter() -> None:
    result = run("decode", "-", stdin="(1.0) can0 009#00FF01\n(2.0) can0 0FF#0003000000803F\n")
    assert result.stdout == ("1.000000 can0 009 AP2       Ready(ready=True)\n")
    assert result.stderr == "veronte4x: 2 records, 0 undecoded, 1 bad (skip)\n"


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
