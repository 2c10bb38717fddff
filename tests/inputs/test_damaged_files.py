"""Damaged BLF, MF4 and SQLite captures, written by python-can and then cut or overwritten:
a `SourceError` naming the file (exit 2 in the CLI) when nothing can be read, the frames
before the damage and a ``truncated`` record when some can."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.inputs.support import run
from veronte4x import capture
from veronte4x.capture import BadLine, Frame, open_frames
from veronte4x.errors import SourceError

can = pytest.importorskip("can")
FRAMES = 2000


def _write(path: Path) -> Path:
    with can.Logger(str(path)) as logger:
        for i in range(FRAMES):
            logger(
                can.Message(
                    timestamp=1_763_737_000 + i * 0.01,
                    arbitration_id=9,
                    is_extended_id=False,
                    data=b"\x00\xff\x01",
                    channel="can0",
                )
            )
    return path


def _damage(path: Path, how: str) -> Path:
    data = bytearray(path.read_bytes())
    if how == "zeroed header":
        data[:64] = bytes(64)
    elif how == "cut in half":
        del data[len(data) // 2 :]
    elif how == "overwritten":
        start = len(data) // 4
        data[start : start + 200] = bytes(b ^ 0xFF for b in data[start : start + 200])
    path.write_bytes(bytes(data))
    return path


UNREADABLE = [
    (".blf", "zeroed header", "Unexpected file format"),
    (".blf", "overwritten", "Error -3 while decompressing data: incorrect data check"),
    (".db", "zeroed header", "file is not a database"),
    (".db", "cut in half", "database disk image is malformed"),
    (".mf4", "zeroed header", "is not a valid ASAM MDF file"),
    (".mf4", "cut in half", ""),
    (".mf4", "overwritten", 'Expected "##CA" block'),
]


@pytest.mark.parametrize(("suffix", "how", "reason"), UNREADABLE)
def test_an_unreadable_file_is_a_source_error(
    tmp_path: Path, suffix: str, how: str, reason: str
) -> None:
    if suffix == ".mf4":
        pytest.importorskip("asammdf")
    path = _damage(_write(tmp_path / f"flight{suffix}"), how)
    kind = "SQLite (.db)" if suffix == ".db" else suffix[1:].upper()
    with pytest.raises(SourceError, match=f"^{path}: not a readable ") as raised:
        list(capture.read(path))
    assert reason in str(raised.value)
    assert str(raised.value).endswith(
        f"): the file is damaged or not {kind}; export or copy it again"
    )
    with pytest.raises(SourceError) as columnar:
        capture.read_tables(path)
    assert str(columnar.value) == str(raised.value)
    for command in ("decode", "stats", "replay", "plot", "monitor"):
        plot = ["--output", str(tmp_path / "plot.png")] if command == "plot" else []
        result = run(command, str(path), *plot)
        assert result.returncode == 2, (command, result.stderr)
        assert result.stderr == f"veronte4x: {raised.value}\n", command
        assert result.stdout == ""


def test_a_cut_blf_keeps_the_frames_before_the_cut(tmp_path: Path) -> None:
    path = _damage(_write(tmp_path / "flight.blf"), "cut in half")
    size = path.stat().st_size
    items = list(open_frames(path))
    frames = [item for item in items if isinstance(item, Frame)]
    assert 500 < len(frames) < FRAMES
    assert items[: len(frames)] == frames
    [cut] = items[len(frames) :]
    assert isinstance(cut, BadLine)
    reason = (
        f"{path}: the BLF file ends early, after message {len(frames)} ({size} of the "
        f"{size * 2} bytes its header gives): the file is truncated"
    )
    assert isinstance(cut, BadLine)
    assert cut.reason == reason
    records = list(capture.read(path))
    assert [r.error for r in records] == [None] * len(frames) + ["truncated"]
    tables = capture.read_tables(path)
    assert tables["Ready"].num_rows == len(frames)
    assert tables["errors"].column("detail").to_pylist() == [reason]
    for command in ("decode", "stats", "replay"):
        result = run(command, str(path))
        assert result.returncode == 0
        assert f"veronte4x: {reason}" in result.stderr.splitlines()
