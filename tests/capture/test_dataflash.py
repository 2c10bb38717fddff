"""ArduPilot DataFlash logs (``.bin``) as a capture: their ``CANF`` and ``CAFD`` messages give
the same frames and records as the same frames in candump form, through every entry point."""

from __future__ import annotations

import gzip
import struct
import subprocess
import sys
from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

from tests.capture.columnar_support import assert_same_tables
from tests.capture.dataflash_support import (
    FMT_OF_FMT,
    dataflash_log,
    fmt_message,
    header,
    parm,
)
from veronte4x import capture
from veronte4x.capture.frames import BadLine, Frame, Truncation, micros
from veronte4x.capture.readers.dataflash import parse_dataflash
from veronte4x.errors import SourceError

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "capture.log"
_TIMEOUT = 600  # a hang guard, not a timed assertion

ODD = f"""\
(1.000000) can0 123#1122
(1.000100) can1 1001552A#05000000000000C3
(1.000200) can0 123#R
(1.000250) can1 1ABCDEF0#R8
(1.000300) can1 20000080#0000000000000004
(1.000400) can0 123##0112233445566778899AABBCC
(1.000500) can1 10003C2A##0{bytes(range(64)).hex().upper()}
(1.000600) can0 7FF##0
"""


def _frames(path: Path) -> list[Frame | BadLine]:
    return list(capture.open_frames(path))


def _pair(tmp_path: Path, text: str) -> tuple[Path, Path]:
    """A candump file and the DataFlash log of its frames."""
    same = tmp_path / "same.log"
    same.write_text(text)
    frames = [f for f in capture.open_frames(same) if isinstance(f, Frame)]
    log = tmp_path / "00000042.BIN"
    log.write_bytes(dataflash_log(frames))
    return same, log


def test_a_dataflash_log_reads_as_its_frames_in_candump_form(tmp_path: Path) -> None:
    same, log = _pair(tmp_path, EXAMPLE.read_text())
    assert capture.source.resolve(log).format == "dataflash"
    expected = [f for f in _frames(same) if isinstance(f, Frame)]
    assert _frames(log) == expected
    records = list(capture.read(log))
    assert records == [r for r in capture.read(same) if r.error != "bad line"]
    assert_same_tables(capture.read_tables(log), capture.tables_from_records(records))
    packed = tmp_path / "flight.bin.gz"
    packed.write_bytes(gzip.compress(log.read_bytes()))
    assert list(capture.read(packed)) == records
    assert list(capture.read(log, channel="can1")) == []


def test_remote_error_and_fd_frames_on_two_buses(tmp_path: Path) -> None:
    """Bus 1 is can1; ArduPilot's Id flags give extended, remote and error frames; a CAFD
    message's DLC is a CAN FD code (9 is 12 bytes, 15 is 64)."""
    same, log = _pair(tmp_path, ODD)
    frames = _frames(log)
    assert frames == _frames(same)
    assert [(f.channel, f.remote, f.error, f.fd, len(f.data)) for f in frames] == [  # type: ignore[union-attr]
        ("can0", False, False, False, 2),
        ("can1", False, False, False, 8),
        ("can0", True, False, False, 0),
        ("can1", True, False, False, 0),
        ("can1", False, True, False, 8),
        ("can0", False, False, True, 12),
        ("can1", False, False, True, 64),
        ("can0", False, False, True, 0),
    ]
    assert frames[3].dlc == 8  # type: ignore[union-attr]


def test_damage_is_skipped_counted_and_a_cut_is_a_truncation(tmp_path: Path) -> None:
    same, log = _pair(tmp_path, ODD)
    frames = [f for f in _frames(same) if isinstance(f, Frame)]
    good = log.read_bytes()
    start = len(header())
    first = good.index(b"\xa3\x95", start + 1)  # after the first CANF message
    junk = b"\x00\xa3\x00" + bytes(range(20))
    damaged = tmp_path / "damaged.bin"
    damaged.write_bytes(good[:first] + junk + good[first:])
    read = _frames(damaged)
    assert read[0] == frames[0] and read[2:] == frames[1:]
    assert read[1] == BadLine(
        6, junk[-16:].hex(" "), "23 bytes are no DataFlash message of a described type"
    )
    cut = tmp_path / "cut.bin"
    cut.write_bytes(good[:-7])
    read = _frames(cut)
    assert read[:-1] == frames[:-1]
    assert read[-1] == Truncation(
        len(frames) + 6,
        "",
        f"{cut}: the DataFlash log ends early, in message {len(frames) + 6} (its first 74 "
        "bytes): the file is truncated; the frames before were read",
    )
    [*_, bad] = capture.read(cut)
    assert bad.error == "truncated"


def test_what_is_no_dataflash_log(tmp_path: Path) -> None:
    """A .bin that does not start as a DataFlash log: candump text in it is read as candump
    text; other bytes are refused with a line that says what the file is not."""
    text = tmp_path / "text.bin"
    text.write_text(EXAMPLE.read_text())
    assert capture.source.resolve(text).format == "candump"
    other = tmp_path / "other.bin"
    other.write_bytes(bytes(range(256)) * 4)
    with pytest.raises(SourceError) as raised:
        list(capture.read(other))
    assert str(raised.value) == (
        f"{other}: not a DataFlash log (it does not start with the FMT message a3 95 80 80 59): "
        "the file is damaged or in another format"
    )
    assert list(parse_dataflash(iter([b""]), "empty.bin")) == []


def test_fields_are_found_by_the_logs_own_fmt() -> None:
    """A log whose CANF has its fields in other places (a future layout, a new label) is read
    by its FMT; a CANF whose FMT lacks a field is left unread, as any other message."""
    moved = ("QBBIB" + "B" * 8, "TimeUS,X,Bus,Id,DLC,B0,B1,B2,B3,B4,B5,B6,B7")
    log = header() + fmt_message(60, "CANF", *moved)
    body = b"\xa3\x95\x3c" + (5_000_000).to_bytes(8, "little") + b"\x09\x02"
    body += (0x123).to_bytes(4, "little") + b"\x02\xaa\xbb" + bytes(6)
    log += body + parm(1, "X", 2.0)
    assert list(parse_dataflash(iter([log[:100], log[100:]]), "x")) == [
        Frame(5.0, "can2", 0x123, b"\xaa\xbb")
    ]
    lacking = header() + fmt_message(60, "CANF", "QBI", "TimeUS,Bus,Id") + body[:16]
    assert list(parse_dataflash(iter([lacking]), "x")) == []


SCRIPT_CANF = ("QIBIBBBBBBBB", "TimeUS,Id,DLC,FC,B0,B1,B2,B3,B4,B5,B6,B7")
"""The CANF of ArduPilot's Lua scripts (CAN_logger.lua): ``logger:write("CANF",
'Id,DLC,FC,B0,...,B7', 'IBIBBBBBBBB', ...)``, with the ``TimeUS`` that ``logger:write``
puts first."""


def test_the_canf_of_a_lua_script_reads_with_no_bus(tmp_path: Path) -> None:
    same = [f._replace(channel="") for f in capture.open_frames(EXAMPLE) if type(f) is Frame]
    body = struct.Struct("<QIBI8B")
    log = FMT_OF_FMT + fmt_message(60, "CANF", *SCRIPT_CANF)
    for count, frame in enumerate(same):
        assert frame.timestamp is not None
        ident = frame.can_id | (1 << 31 if frame.extended else 0)
        fields = (micros(frame.timestamp), ident, len(frame.data), count)
        log += b"\xa3\x95\x3c" + body.pack(*fields, *frame.data.ljust(8, b"\0"))
    path = tmp_path / "00000007.BIN"
    path.write_bytes(log)
    assert _frames(path) == same
    expected = [r._replace(channel="") for r in capture.read(EXAMPLE)]
    assert list(capture.read(path)) == expected
    assert_same_tables(capture.read_tables(path), capture.tables_from_records(expected))


_classic = st.builds(
    lambda ext, ident, data, bus, us: Frame(
        us / 1_000_000, f"can{bus}", ident & (0x1FFFFFFF if ext else 0x7FF), data, ext
    ),
    st.booleans(),
    st.integers(0, 0x1FFFFFFF),
    st.binary(max_size=8),
    st.integers(0, 2),
    st.integers(0, 2**44),
)


@given(st.lists(_classic, max_size=12), st.integers(1, 300))
def test_frames_round_trip_in_chunks_of_any_size(frames: list[Frame], size: int) -> None:
    log = dataflash_log(frames)
    chunks = iter([log[i : i + size] for i in range(0, len(log), size)])
    assert list(parse_dataflash(chunks, "x")) == frames


def test_the_command_line_decodes_a_dataflash_log(tmp_path: Path) -> None:
    same, log = _pair(tmp_path, EXAMPLE.read_text())

    def decode(path: Path) -> subprocess.CompletedProcess[str]:
        return subprocess.run(
            [sys.executable, "-m", "veronte4x", "decode", str(path), "--output", "jsonl"],
            capture_output=True, text=True, timeout=_TIMEOUT, check=False,
        )  # fmt: skip

    done, expected = decode(log), decode(same)
    assert (done.returncode, expected.returncode) == (0, 0), done.stderr + expected.stderr
    assert done.stdout == expected.stdout and '"Status"' in done.stdout
