"""The command line's error paths, in a subprocess: the exit code and the first line of stderr.

Every failure is one line naming what was wrong and what to do, with the documented exit code,
and keeps the output written before it.
"""

from __future__ import annotations

import gzip
import os
import signal
import subprocess
import sys
from pathlib import Path

import pytest

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "capture.log"
LINES = "".join(f"({i}.0) can0 009#00FF01\n" for i in range(2000))


def run(
    *args: str, stdin: bytes | None = None, env: dict[str, str] | None = None
) -> subprocess.CompletedProcess[bytes]:
    return subprocess.run(
        [sys.executable, "-m", "veronte4x", *args],
        input=stdin,
        capture_output=True,
        check=False,
        env=env,
    )


def first_error_line(result: subprocess.CompletedProcess[bytes]) -> str:
    return result.stderr.decode().splitlines()[0]


def test_a_directory_is_a_usage_error(tmp_path: Path) -> None:
    for command in ("decode", "stats", "replay"):
        result = run(command, str(tmp_path))
        assert result.returncode == 2
        assert (
            first_error_line(result) == f"veronte4x: {tmp_path} is a directory: give a capture file"
        )


def test_an_unknown_format_is_a_usage_error(tmp_path: Path) -> None:
    path = tmp_path / "dump.dat"
    path.write_bytes(bytes(range(256)) * 8)
    result = run("decode", str(path))
    assert result.returncode == 2
    assert first_error_line(result) == (
        f"veronte4x: {path}: in no format veronte4x knows: its content is not candump or gvret or "
        "dataflash or pydronecan, "
        "and its suffix is none of .log, .txt, .candump, .asc, .bin, .blf, .csv, .db, .mf4, .trc; "
        "rename it to the suffix of its format, or convert it to candump text"
    )
    assert result.stdout == b""


def test_an_unknown_gzipped_format_and_an_empty_file(tmp_path: Path) -> None:
    packed = tmp_path / "dump.dat"
    packed.write_bytes(gzip.compress(bytes(range(256)) * 8))
    result = run("stats", str(packed))
    assert result.returncode == 2
    [line] = result.stderr.decode().splitlines()
    assert line.startswith(f"veronte4x: {packed}: in no format veronte4x knows: its gunzipped ")
    assert line.endswith("; rename it to the suffix of its format, or convert it to candump text")
    empty = tmp_path / "dump"
    empty.write_bytes(b"")
    result = run("decode", str(empty))
    assert result.returncode == 2
    assert result.stderr == f"veronte4x: {empty} is empty: give a capture file\n".encode()


@pytest.mark.parametrize("name", ["flight", "flight.bin", "flight.bin.gz", "flight.gz"])
def test_candump_is_recognised_by_its_content(tmp_path: Path, name: str) -> None:
    path = tmp_path / name
    text = EXAMPLE.read_bytes()
    path.write_bytes(gzip.compress(text) if name.endswith(".gz") else text)
    result = run("decode", str(path))
    assert result.returncode == 0
    assert result.stdout == run("decode", str(EXAMPLE)).stdout
    assert result.stderr == b"veronte4x: 39 records, 0 undecoded, 1 bad (skip)\n"


def test_a_missing_file(tmp_path: Path) -> None:
    result = run("stats", str(tmp_path / "no.log"))
    assert result.returncode == 2
    assert (
        first_error_line(result) == f"veronte4x: {tmp_path / 'no.log'}: No such file or directory"
    )


def test_a_truncated_gzip_keeps_the_frames_before_the_cut(tmp_path: Path) -> None:
    whole = gzip.compress(LINES.encode())
    path = tmp_path / "cut.log.gz"
    path.write_bytes(whole[: len(whole) // 2])
    result = run("decode", str(path))
    assert result.returncode == 0
    decoded = result.stdout.decode().splitlines()
    assert 100 < len(decoded) < 2000
    assert decoded[0] == "0.000000 can0 009 AP2       Ready(ready=True)"
    first, summary = result.stderr.decode().splitlines()
    assert first == (
        f"veronte4x: {path}: the gzip data ends early, at line {len(decoded) + 1}: "
        "the file is truncated"
    )
    assert summary == f"veronte4x: {len(decoded) + 1} records, 0 undecoded, 1 bad (skip)"
    stats = run("stats", str(path))
    assert stats.returncode == 0
    assert first_error_line(stats) == first
    assert b"  truncated  " in stats.stdout
    converted = run("convert", "--to", "parquet", str(tmp_path / "dataset"), str(path))
    assert converted.returncode == 0
    assert first_error_line(converted) == first


def test_a_non_utf8_byte_on_stdin_is_one_bad_line_under_a_strict_locale() -> None:
    env = {**os.environ, "LC_ALL": "C.UTF-8", "PYTHONIOENCODING": "utf-8:strict"}
    env.pop("PYTHONUTF8", None)
    stdin = b"(1.0) can0 009#00FF01\n(2.0) can0 \xff9#00FF01\n(3.0) can0 009#00FF01\n"
    result = run("decode", "-", stdin=stdin, env=env)
    assert result.returncode == 0
    assert len(result.stdout.splitlines()) == 2
    assert result.stderr == b"veronte4x: 3 records, 0 undecoded, 1 bad (skip)\n"


def test_a_missing_extra_names_the_install_command(tmp_path: Path) -> None:
    path = tmp_path / "capture.asc"
    path.write_text("date Mon Nov 23 11:00:00.000 am 2026\nbase hex  timestamps absolute\n")
    hide_can = (
        "import sys; sys.modules['can'] = None; from veronte4x.cli import main; sys.exit(main())"
    )
    result = subprocess.run(
        [sys.executable, "-c", hide_can, "decode", str(path)], capture_output=True, check=False
    )
    assert result.returncode == 2
    assert first_error_line(result) == (
        f"veronte4x: reading {path} needs the 'can' package: pip install 'veronte4x[can]'"
    )


def _interrupt(
    args: list[str], feed: bytes, *, fifo: Path | None = None, wait_output: bool
) -> subprocess.CompletedProcess[bytes]:
    """Start the CLI, give it some input, interrupt it with SIGINT as Ctrl-C does."""
    process = subprocess.Popen(
        [sys.executable, "-m", "veronte4x", *args],
        stdin=subprocess.PIPE,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
    )
    assert process.stdin is not None and process.stdout is not None
    head = b""
    if fifo is not None:
        # The open returns once the CLI has opened the capture, inside its main(); it then
        # reads what comes and waits for more, as on a live capture.
        with fifo.open("wb") as writer:
            writer.write(feed)
            writer.flush()
            process.send_signal(signal.SIGINT)
    else:
        process.stdin.write(feed)
        process.stdin.flush()
        if wait_output:
            head = os.read(process.stdout.fileno(), 1 << 16)
        process.send_signal(signal.SIGINT)
    out, err = process.communicate(timeout=600)  # a hang guard, not a timed assertion
    out = head + out
    return subprocess.CompletedProcess(args, process.returncode, out, err)


def test_ctrl_c_during_decode_of_stdin() -> None:
    result = _interrupt(["decode", "-"], LINES.encode(), wait_output=True)
    assert result.returncode == 130
    [line] = result.stderr.decode().splitlines()
    assert line.startswith("veronte4x: interrupted after ")
    assert line.endswith((" records, 0 undecoded, 0 bad", " 1 record, 0 undecoded, 0 bad"))
    assert result.stdout.startswith(b"0.000000 can0 009 AP2")
    records = int(line.split()[3])
    assert len(result.stdout.splitlines()) == records  # nothing decoded is lost


@pytest.mark.parametrize("command", ["decode", "stats", "replay"])
def test_ctrl_c_during_a_file(tmp_path: Path, command: str) -> None:
    fifo = tmp_path / "live.log"
    os.mkfifo(fifo)
    config = ["--config", str(EXAMPLE.with_name("arbiter.toml"))] if command == "replay" else []
    result = _interrupt([command, str(fifo), *config], LINES.encode(), fifo=fifo, wait_output=False)
    assert result.returncode == 130
    [line] = result.stderr.decode().splitlines()
    assert line.startswith("veronte4x: interrupted")


def test_a_pipe_without_a_suffix_is_read_whole() -> None:
    """/dev/stdin (like a shell's <(candump -L can0)) is not sniffed: nothing is lost."""
    result = run("decode", "/dev/stdin", stdin=LINES.encode())
    assert result.returncode == 0
    assert len(result.stdout.splitlines()) == 2000
