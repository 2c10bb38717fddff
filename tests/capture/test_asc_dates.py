"""ASC captures: times from the file's date line and channel numbers as python-can's
ASCReader gives them (``relative_timestamp=False``; channels from 0), on every path: the
per-frame reader, the columnar one, ``capture.read`` and ``read_tables``."""

from __future__ import annotations

import datetime as dt
import math
import tempfile
from pathlib import Path

import can
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from veronte4x import capture
from veronte4x.capture.columnar.sources import read_frames
from veronte4x.capture.frames import Frame, micros

Seen = tuple[float, str, int, bytes, bool, bool, bool, bool, bool, bool, int]
"""A frame as compared: time, channel, ID, data, extended, remote, FD, error, BRS, ESI,
and a remote frame's DLC."""


def python_can(path: Path) -> list[Seen]:
    """The frames as python-can's ASCReader reads them with absolute times."""
    with can.ASCReader(str(path), relative_timestamp=False) as reader:
        return [
            (
                m.timestamp,
                str(m.channel),
                m.arbitration_id,
                bytes(m.data),
                m.is_extended_id,
                m.is_remote_frame,
                m.is_fd,
                m.is_error_frame,
                m.bitrate_switch,
                m.error_state_indicator,
                m.dlc if m.is_remote_frame else 0,
            )
            for m in reader
        ]


def ours(frames: list[Frame]) -> list[Seen]:
    return [
        (
            f.timestamp if f.timestamp is not None else math.nan,
            f.channel,
            f.can_id,
            f.data,
            f.extended,
            f.remote,
            f.fd,
            f.error,
            f.brs,
            f.esi,
            f.dlc,
        )
        for f in frames
    ]


def every_path_agrees(path: Path, one_record_per_frame: bool = True) -> list[Seen]:
    """The frames of every reader of ``path``, checked equal to python-can's; returned.

    The records of ``capture.read`` and the rows of ``read_tables`` have the frames' times,
    channels and IDs, one per frame where no DroneCAN transfer spans several frames.
    """
    expected = python_can(path)
    per_frame = [f for f in capture.open_frames(path) if isinstance(f, Frame)]
    assert ours(per_frame) == expected
    columns = read_frames(path)
    assert ours([columns.frame(row) for row in range(len(columns))]) == expected
    assert ours(columns.frames_of(np.arange(len(columns)))) == expected
    keys = [s[:3] for s in expected]
    records = [(r.timestamp, r.channel, r.can_id) for r in capture.read(path)]
    rows = [
        (stamp.as_py(), channel.as_py(), can_id.as_py())
        for table in capture.read_tables(path).values()
        for stamp, channel, can_id in zip(
            table["timestamp"].cast("int64"), table["channel"], table["can_id"], strict=True
        )
    ]
    table_keys = [(micros(t), c, i) for t, c, i in keys]
    if one_record_per_frame:
        assert records == keys
        assert sorted(rows) == sorted(table_keys)
    else:
        assert set(records) <= set(keys)
        assert set(rows) <= set(table_keys)
    return expected


def test_a_hand_written_file_starts_at_its_date_line(tmp_path: Path) -> None:
    path = tmp_path / "vector.asc"
    path.write_text(
        "date Wed Dec 2 05:22:01.727 pm 2026\n"
        "base hex  timestamps absolute\n"
        "internal events logged\n"
        "// version 9.0.0\n"
        "Begin Triggerblock\n"  # no date of its own: the date line's holds
        "   0.000000 Start of measurement\n"
        "   0.010000 1  123             Rx   d 2 01 02\n"
        "   0.020000 2  1ABCDEF0x       Rx   d 1 FF\n"
        "   0.030000 1  321             Rx   r 5\n"
        "   0.040000 CANFD   2 Rx        124                                   1 1 9 12"
        " 11 11 11 11 11 11 11 11 11 11 11 11        0    0     7000        0        0"
        "        0        0        0\n"
        "   0.050000 1  ErrorFrame\n"
        "End TriggerBlock\n",
        encoding="utf-8",
    )
    start = dt.datetime(2026, 12, 2, 17, 22, 1, 727000).timestamp()  # local, as python-can
    expected = every_path_agrees(path)
    assert [s[:3] for s in expected] == [
        (start + 0.01, "0", 0x123),  # the file's channel 1 is python-can's 0
        (start + 0.02, "1", 0x1ABCDEF0),
        (start + 0.03, "0", 0x321),
        (start + 0.04, "1", 0x124),
        (start + 0.05, "0", 0),
    ]
    assert [s[5:] for s in expected[2:5]] == [
        (True, False, False, False, False, 5),
        (False, True, False, True, True, 0),
        (False, False, True, False, False, 0),
    ]


def test_a_file_without_a_date_line_starts_at_zero(tmp_path: Path) -> None:
    path = tmp_path / "bare.asc"
    path.write_text(
        "base hex  timestamps absolute\nno internal events logged\n"
        "   1.500000 3  7FF             Rx   d 0\n",
        encoding="utf-8",
    )
    assert [s[:3] for s in every_path_agrees(path)] == [(1.5, "2", 0x7FF)]


_DATA_FRAME = st.builds(
    lambda ident, data, channel: can.Message(
        arbitration_id=ident[0], is_extended_id=ident[1], data=data, channel=channel
    ),
    st.one_of(
        st.tuples(st.integers(0, 0x7FF), st.just(False)),
        st.tuples(st.integers(0, 0x1FFFFFFF), st.just(True)),
    ),
    st.binary(max_size=8),
    st.integers(0, 3),
)
_REMOTE_FRAME = st.builds(
    lambda ident, dlc, channel: can.Message(
        arbitration_id=ident, is_remote_frame=True, is_extended_id=False, dlc=dlc, channel=channel
    ),
    st.integers(0, 0x7FF),
    st.integers(0, 8),
    st.integers(0, 3),
)
_FD_FRAME = st.builds(
    lambda ident, size, brs, esi, channel: can.Message(
        arbitration_id=ident,
        is_extended_id=True,
        is_fd=True,
        data=bytes(range(size)),
        bitrate_switch=brs,
        error_state_indicator=esi,
        channel=channel,
    ),
    st.integers(0, 0x1FFFFFFF),
    st.sampled_from([0, 1, 8, 12, 16, 20, 24, 32, 48, 64]),
    st.booleans(),
    st.booleans(),
    st.integers(0, 3),
)
_ERROR_FRAME = st.builds(
    lambda channel: can.Message(is_error_frame=True, channel=channel), st.integers(0, 3)
)


@settings(max_examples=40)
@given(
    st.floats(0, 4e9, allow_nan=False),
    st.lists(
        st.tuples(
            st.integers(0, 10**7), st.one_of(_DATA_FRAME, _REMOTE_FRAME, _FD_FRAME, _ERROR_FRAME)
        ),
        min_size=1,
        max_size=12,
    ),
)
def test_files_python_can_writes(start: float, items: list[tuple[int, can.Message]]) -> None:
    step = 0.0
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "written.asc"
        with can.ASCWriter(str(path)) as writer:
            for offset, message in items:
                step += offset / 1e6
                message.timestamp = start + step
                writer.on_message_received(message)
        expected = every_path_agrees(path, one_record_per_frame=False)
    assert len(expected) == len(items)
    # ASCWriter numbers channels from 1 in the file; python-can and we read them from 0.
    assert [s[1] for s in expected] == [str(m.channel) for _, m in items]


@pytest.mark.parametrize(
    ("line", "start"),
    [
        ("date Wed Dec 02 05:22:01.727 2026", dt.datetime(2026, 12, 2, 5, 22, 1, 727000)),
        ("date Wed Dec 02 05:22:01 am 2026", dt.datetime(2026, 12, 2, 5, 22, 1)),
        ("date Mi Mär 04 13:00:00 2026", dt.datetime(2026, 3, 4, 13, 0, 0)),
    ],
)
def test_every_date_form_python_can_reads(tmp_path: Path, line: str, start: dt.datetime) -> None:
    path = tmp_path / "dated.asc"
    path.write_text(
        f"{line}\nbase hex  timestamps absolute\nno internal events logged\n"
        "   0.250000 1  123             Rx   d 1 2A\n",
        encoding="utf-8",
    )
    assert [s[0] for s in every_path_agrees(path)] == [start.timestamp() + 0.25]
