"""Captures that are not what they seem, through every command, as subprocesses: a cut gzip
file (told the same way by every command), gzip under any name or on standard input, files
with no CAN frame at all, and captures whose time steps back."""

from __future__ import annotations

import gzip
import random
from pathlib import Path

import pytest

from tests.inputs.support import EXAMPLES, candump, run

ARBITER = str(EXAMPLES / "arbiter.toml")
CAPTURE = EXAMPLES / "capture.log"


@pytest.mark.parametrize("command", ["decode", "stats", "replay", "plot", "monitor"])
def test_every_command_tells_a_cut_gzip_file(tmp_path: Path, command: str) -> None:
    path = tmp_path / "cut.log.gz"
    whole = gzip.compress(candump(2000).encode())
    path.write_bytes(whole[: len(whole) // 2])
    decoded = run("decode", str(path))
    line = len(decoded.stdout.splitlines()) + 1
    cut = f"veronte4x: {path}: the gzip data ends early, at line {line}: the file is truncated"
    extra = {"replay": ["--config", ARBITER], "plot": ["--output", str(tmp_path / "p.png")]}
    result = run(command, str(path), *extra.get(command, []))
    assert cut in result.stderr.splitlines(), result.stderr
    assert result.returncode == (2 if command == "plot" else 0)  # plot: Ready frames only


@pytest.mark.parametrize("name", ["flight.log", "flight.txt", "flight", "flight.log.gz"])
def test_gzip_is_known_by_its_first_bytes(tmp_path: Path, name: str) -> None:
    path = tmp_path / name
    path.write_bytes(gzip.compress(CAPTURE.read_bytes()))
    reference = run("decode", str(CAPTURE))
    result = run("decode", str(path))
    assert (result.returncode, result.stdout, result.stderr) == (
        0,
        reference.stdout,
        reference.stderr,
    )


def test_plain_text_named_gz_is_read_as_text(tmp_path: Path) -> None:
    path = tmp_path / "flight.log.gz"
    path.write_bytes(CAPTURE.read_bytes())
    assert run("decode", str(path)).stdout == run("decode", str(CAPTURE)).stdout


@pytest.mark.parametrize("command", ["decode", "stats"])
def test_gzip_on_standard_input(command: str) -> None:
    reference = run(command, "-", stdin=CAPTURE.read_bytes())
    result = run(command, "-", stdin=gzip.compress(CAPTURE.read_bytes()))
    assert (result.returncode, result.stdout, result.stderr) == (
        0,
        reference.stdout,
        reference.stderr,
    )
    assert "records: 39" in reference.stdout or "39 records" in reference.stderr


def test_a_cut_gzip_on_standard_input() -> None:
    whole = gzip.compress(candump(2000).encode())
    result = run("decode", "-", stdin=whole[: len(whole) // 2])
    assert result.returncode == 0
    line = len(result.stdout.splitlines()) + 1
    assert 100 < line < 2000
    assert result.stderr.splitlines()[0] == (
        f"veronte4x: standard input: the gzip data ends early, at line {line}: "
        "the file is truncated"
    )


def _random_bytes() -> bytes:
    return random.Random(20).randbytes(3000)


NOT_CAPTURES = {
    "random.log": _random_bytes(),
    "notes.txt": b"Flight 12, 21 Nov\nbattery swapped at 14:02\nwind 5 m/s\n",
}


@pytest.mark.parametrize("name", sorted(NOT_CAPTURES))
@pytest.mark.parametrize("command", ["decode", "stats", "replay", "plot", "monitor"])
def test_a_file_with_no_frame_is_not_a_capture(tmp_path: Path, name: str, command: str) -> None:
    path = tmp_path / name
    path.write_bytes(NOT_CAPTURES[name])
    lines = len(NOT_CAPTURES[name].decode("utf-8", "replace").split())
    extra = {"replay": ["--config", ARBITER], "plot": ["--output", str(tmp_path / "p.png")]}
    result = run(command, str(path), *extra.get(command, []))
    assert result.returncode == 2
    [line] = result.stderr.splitlines()
    assert line.startswith(f"veronte4x: {path} is not a capture of any known format: none of ")
    assert line.endswith(" lines is a CAN frame; give candump text or a log python-can reads")
    assert lines > 0
    assert not (tmp_path / "p.png").exists()


def test_no_frame_on_standard_input() -> None:
    result = run("stats", "-", stdin=b"hello\nworld\n")
    assert result.returncode == 2
    assert result.stderr == (
        "veronte4x: standard input is not a capture of any known format: none of its 2 "
        "lines is a CAN frame; give candump text or a log python-can reads\n"
    )


def test_mostly_bad_lines_are_said_in_the_summary(tmp_path: Path) -> None:
    path = tmp_path / "mixed.log"
    path.write_text("junk\n" * 3 + candump(2))
    result = run("decode", str(path))
    assert result.returncode == 0
    assert result.stderr == (
        "veronte4x: 5 records, 0 undecoded, 3 bad (skip); 3 of 5 lines are not CAN frames: "
        f"is {path} a capture?\n"
    )
    stats = run("stats", str(path))
    assert stats.stderr == f"veronte4x: 3 of 5 lines are not CAN frames: is {path} a capture?\n"


def test_an_empty_capture_is_a_capture(tmp_path: Path) -> None:
    path = tmp_path / "quiet.log"
    path.write_text("")
    result = run("decode", str(path))
    assert (result.returncode, result.stderr) == (
        0,
        "veronte4x: 0 records, 0 undecoded, 0 bad (skip)\n",
    )


def _lines() -> list[str]:
    return CAPTURE.read_text().splitlines(keepends=True)


def test_replay_takes_lines_swapped_100_us_apart(tmp_path: Path) -> None:
    lines = _lines()
    lines[3], lines[4] = (
        "(1763737200.012000) can0 00A#00FF01\n",
        "(1763737200.011900) can0 009#00FF01\n",
    )
    path = tmp_path / "swapped.log"
    path.write_text("".join(lines))
    result = run("replay", str(path), "--config", ARBITER)
    reference = run("replay", str(CAPTURE), "--config", ARBITER)
    assert result.returncode == reference.returncode == 1
    assert reference.stderr.endswith(" bad frame\n")  # one, as the summary counts it
    assert result.stderr == reference.stderr.replace(
        " bad frame\n", " bad frame, 1 frame out of time order (taken late)\n"
    )


def test_replay_of_two_logs_joined_restarts_the_model(tmp_path: Path) -> None:
    path = tmp_path / "joined.log"
    path.write_text(CAPTURE.read_text() * 2)
    result = run("replay", str(path), "--config", ARBITER)
    reference = run("replay", str(CAPTURE), "--config", ARBITER)
    assert result.returncode == 1
    once = reference.stdout.splitlines()
    assert result.stdout.splitlines() == [
        *once,
        "2025-11-21T15:00:00.000000Z  RESTART     the capture's time steps back 0.501000 s "
        "(from 2025-11-21T15:00:00.501000Z): the model starts again, as at boot",
        *once,
    ]
    assert result.stderr == (
        "veronte4x: 28 decisions, 14 disagreements, 2 bad frames, 1 restart (the time steps back)\n"
    )


def test_replay_of_a_shuffled_capture_is_refused(tmp_path: Path) -> None:
    lines = _lines() * 20
    random.Random(3).shuffle(lines)
    path = tmp_path / "shuffled.log"
    path.write_text("".join(lines))
    result = run("replay", str(path), "--config", ARBITER)
    assert result.returncode == 5
    assert result.stdout == ""
    assert result.stderr == (
        f"veronte4x: {path} is not in time order (11 steps back in 22 frames): replay needs "
        "it sorted by time; sort the capture first\n"
    )
