"""Files python-can reads, damaged: refused before the first frame, a Truncation after some,
and the channel filter."""

from __future__ import annotations

from pathlib import Path

import can
import pytest

from veronte4x.capture.frames import Frame, Truncation
from veronte4x.capture.readers.pythoncan import read_with_python_can
from veronte4x.errors import SourceError


def _blf(path: Path, count: int) -> Path:
    with can.BLFWriter(str(path)) as writer:
        for number in range(count):
            channel = "0" if number % 2 else "1"
            message = can.Message(
                timestamp=1.0 + number, arbitration_id=number, data=bytes([number]), channel=channel
            )
            writer.on_message_received(message)
    return path


def test_a_file_that_is_not_its_format_is_refused_in_one_sentence(tmp_path: Path) -> None:
    garbage = tmp_path / "garbage.blf"
    garbage.write_bytes(b"not a BLF file at all" * 10)
    with pytest.raises(SourceError, match=r"garbage\.blf: not a readable BLF file \(") as error:
        list(read_with_python_can(garbage))
    assert str(error.value).endswith("the file is damaged or not BLF; export or copy it again")
    assert error.value.__context__ is None


def test_a_blf_file_cut_short_ends_with_a_truncation(tmp_path: Path) -> None:
    whole = _blf(tmp_path / "whole.blf", 50)
    assert len(list(read_with_python_can(whole))) == 50
    cut = tmp_path / "cut.blf"
    data = whole.read_bytes()
    cut.write_bytes(data[: len(data) * 2 // 3])
    items = list(read_with_python_can(cut))
    *read, last = items
    assert all(isinstance(item, Frame) for item in read)
    assert isinstance(last, Truncation)
    assert "cut.blf" in last.reason and ("truncated" in last.reason or "damaged" in last.reason)


def test_the_channel_filter(tmp_path: Path) -> None:
    path = _blf(tmp_path / "two.blf", 6)
    every = list(read_with_python_can(path))
    kept = list(read_with_python_can(path, channel=every[0].channel))  # type: ignore[union-attr]
    assert len(every) == 6
    assert [f.can_id for f in kept] == [0, 2, 4]  # type: ignore[union-attr]


_CSV_HEAD = "timestamp,arbitration_id,extended,remote,error,dlc,data\n"
_CSV_ROW = "1.5,0x123,0,0,0,1,AQ==\n"


def test_a_reader_that_fails_mid_file_ends_with_a_truncation(tmp_path: Path) -> None:
    path = tmp_path / "bad_row.csv"
    path.write_text(_CSV_HEAD + _CSV_ROW * 2 + "1.5,not an id,0,0,0,1,AQ==\n" + _CSV_ROW)
    *read, last = read_with_python_can(path)
    assert [(f.can_id, f.data) for f in read] == [(0x123, b"\x01")] * 2  # type: ignore[union-attr]
    assert isinstance(last, Truncation)
    assert last.reason.startswith(f"{path}: python-can stopped reading at message 3 (")
    assert last.reason.endswith("the file is damaged there; the frames before were read")


def test_a_reader_that_fails_at_the_first_message_refuses_the_file(tmp_path: Path) -> None:
    path = tmp_path / "bad_first.csv"
    path.write_text(_CSV_HEAD + "1.5,not an id,0,0,0,1,AQ==\n")
    with pytest.raises(SourceError, match=r"bad_first\.csv: not a readable CSV file \(") as error:
        list(read_with_python_can(path))
    assert error.value.__context__ is None
