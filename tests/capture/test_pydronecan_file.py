"""pydronecan's capture files: the bytes its own ``fileout:`` driver wrote (golden vectors,
``tests/dronecan/make_mcast_vectors.py``) read back, the same frames and records as in
candump form, ``convert --to pydronecan`` read by pydronecan's ``filein:`` driver, and
arbitrary bytes giving frames and bad lines."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

from tests.capture.columnar_support import assert_same_tables
from veronte4x import capture
from veronte4x.capture.frames import BadLine, Frame, Truncation
from veronte4x.capture.readers.pydronecan import parse_pydronecan, record, write
from veronte4x.dronecan.mcast import FD_LENGTHS
from veronte4x.errors import SourceError

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "capture.log"
VECTORS = json.loads((ROOT / "tests" / "dronecan" / "data" / "pydronecan_mcast.json").read_text())
FILE = VECTORS["file"]
_TIMEOUT = 600  # a hang guard, not a timed assertion


def _golden(tmp_path: Path, name: str = "frames") -> Path:
    path = tmp_path / name
    path.write_bytes(bytes.fromhex(FILE["bytes"]))
    return path


def test_the_file_pydronecan_wrote_reads_as_pydronecan_reads_it(tmp_path: Path) -> None:
    path = _golden(tmp_path)
    assert capture.source.resolve(path).format == "pydronecan"
    frames = list(capture.open_frames(path))
    assert [(f.timestamp, f.can_id, f.data.hex(), f.extended, f.fd) for f in frames] == [  # type: ignore[union-attr]
        (v["timestamp"], v["can_id"], v["data"], v["extended"], v["fd"]) for v in FILE["read_back"]
    ]
    assert {f.channel for f in frames} == {""}  # type: ignore[union-attr]
    assert b"".join(record(f) for f in frames) == path.read_bytes()  # type: ignore[arg-type]


@pytest.mark.parametrize("name", ["frames.bin", "frames.log", "frames"])
def test_the_content_settles_the_format_whatever_the_suffix(tmp_path: Path, name: str) -> None:
    assert capture.source.resolve(_golden(tmp_path, name)).format == "pydronecan"


def test_the_same_frames_and_records_as_in_candump_form(tmp_path: Path) -> None:
    same = [f._replace(channel="") for f in capture.open_frames(EXAMPLE) if type(f) is Frame]
    path = tmp_path / "flight.can"
    assert write(path, same) == len(same) == 39
    assert list(capture.open_frames(path)) == same
    expected = [r._replace(channel="") for r in capture.read(EXAMPLE)]
    assert list(capture.read(path)) == expected
    assert_same_tables(capture.read_tables(path), capture.tables_from_records(expected))


frames = st.builds(
    lambda t, extended, identifier, data: Frame(
        t / 1e6, "", identifier & (0x1FFF_FFFF if extended else 0x7FF), data, extended
    ),
    st.integers(0, 1 << 52),
    st.booleans(),
    st.integers(0, 0x1FFF_FFFF),
    st.binary(max_size=8),
) | st.builds(
    lambda t, identifier, data: Frame(t / 1e6, "", identifier, data, True, fd=True),
    st.integers(0, 1 << 52),
    st.integers(0, 0x1FFF_FFFF),
    st.sampled_from(sorted(FD_LENGTHS)).flatmap(lambda n: st.binary(min_size=n, max_size=n)),
)


@given(st.lists(frames, max_size=5), st.integers(1, 90))
def test_round_trip_in_chunks_of_any_size(written: list[Frame], size: int) -> None:
    raw = b"".join(record(f) for f in written)
    chunks = [raw[i : i + size] for i in range(0, len(raw), size)]
    assert list(parse_pydronecan(chunks, "x")) == written


@given(st.binary(max_size=120), st.integers(0, 200))
def test_arbitrary_bytes_give_frames_and_bad_lines(junk: bytes, at: int) -> None:
    good = bytes.fromhex(FILE["bytes"])
    at = min(at, len(good))
    items = list(parse_pydronecan([good[:at] + junk + good[at:]], "x"))
    assert all(type(i) in (Frame, BadLine, Truncation) for i in items)
    assert isinstance(items[-1], Frame) or not junk or at == len(good)


def test_damage_is_skipped_counted_and_a_cut_is_a_truncation() -> None:
    good = bytes.fromhex(FILE["bytes"])
    frames = list(parse_pydronecan([good], "x"))
    second = len(record(frames[0]))  # type: ignore[arg-type]
    junk = b"\x34\x29" + bytes(range(21))
    read = list(parse_pydronecan([good[:second] + junk + good[second:]], "x"))
    assert read[0] == frames[0] and read[2:] == frames[1:]
    assert read[1] == BadLine(2, junk[-16:].hex(" "), "23 bytes are no pydronecan record")
    flipped = bytearray(good)
    flipped[second + 20] ^= 0x01  # the second record's one data byte: its CRC fails
    read = list(parse_pydronecan([bytes(flipped)], "x"))
    assert read[0] == frames[0] and read[2:] == frames[2:]
    assert read[1].reason == "21 bytes are no pydronecan record"  # type: ignore[union-attr]
    read = list(parse_pydronecan([good[:-3]], "cut"))
    assert read[:-1] == frames[:-1]
    assert read[-1] == Truncation(
        len(frames),
        good[-record(frames[-1]).__len__() :][:16].hex(" "),  # type: ignore[arg-type]
        f"cut: the last record ends early ({len(record(frames[-1])) - 3} of its bytes): the "  # type: ignore[arg-type]
        "file is truncated; the frames before were read",
    )


@pytest.mark.parametrize(
    ("frame", "reason"),
    [
        (Frame(None, "", 1, b""), "a frame at None s: a pydronecan capture holds times of 0 s"),
        (Frame(-1.0, "", 1, b""), "a frame at -1.0 s"),
        (Frame(1.0, "", 1, b"", remote=True), "data frames only"),
        (Frame(1.0, "", 1, bytes(9)), "a frame of 9 data bytes is no CAN frame"),
    ],
)
def test_what_the_file_cannot_hold_is_refused(tmp_path: Path, frame: Frame, reason: str) -> None:
    path = tmp_path / "out"
    with pytest.raises(SourceError, match=reason.replace("(", r"\(")):
        write(path, [Frame(0.5, "", 1, b""), frame])
    assert not path.exists()


def test_convert_writes_what_pydronecan_plays(tmp_path: Path) -> None:
    out = tmp_path / "flight.can"
    converted = subprocess.run(
        [sys.executable, "-m", "veronte4x", "convert", str(EXAMPLE), "--to", "pydronecan",
         str(out)],
        capture_output=True, text=True, timeout=_TIMEOUT, check=False,
    )  # fmt: skip
    assert (converted.returncode, converted.stderr) == (0, f"veronte4x: 39 frames in {out}\n")
    from dronecan.driver.file import file as pydronecan_file

    player = pydronecan_file(os.fspath(out), readonly=True)
    played = []
    while (item := player._read_frame())[0] is not None:
        played.append((item[1], item[0].id, bytes(item[0].data), item[0].extended))
    player.close()
    player.file = None  # its __del__ would flush the closed file again
    assert played == [
        (f.timestamp, f.can_id, f.data, f.extended)
        for f in capture.open_frames(EXAMPLE)
        if type(f) is Frame
    ]


def test_convert_notes_the_channels_it_merges(tmp_path: Path) -> None:
    two = tmp_path / "two.log"
    two.write_text("(1.000000) can0 123#11\n(1.000100) can1 1001552A#05000000000000C3\n")
    out = tmp_path / "two.can"
    converted = subprocess.run(
        [sys.executable, "-m", "veronte4x", "convert", str(two), "--to", "pydronecan", str(out)],
        capture_output=True, text=True, timeout=_TIMEOUT, check=False,
    )  # fmt: skip
    assert (converted.returncode, converted.stderr) == (
        0,
        f"veronte4x: 2 frames in {out}\n"
        "veronte4x: note: the frames of 2 channels (can0, can1) are in one file, which names "
        "no bus; --only-channel CHANNEL writes one\n",
    )
    one = subprocess.run(
        [sys.executable, "-m", "veronte4x", "convert", str(two), "--to", "pydronecan", str(out),
         "--only-channel", "can1"],
        capture_output=True, text=True, timeout=_TIMEOUT, check=False,
    )  # fmt: skip
    assert (one.returncode, one.stderr) == (0, f"veronte4x: 1 frame in {out}\n")
