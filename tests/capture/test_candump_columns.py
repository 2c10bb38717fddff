"""The column-wise candump parser against the per-frame reader, frame for frame: its fixed
layouts (`candump._fixed_lines`) and the lines it leaves to the general parser, on
generated logs with faults (bytes changed, cut or merged lines, stray carriage returns),
merged logs of several layouts, 11- and 29-bit ids, error, remote and CAN FD lines."""

from __future__ import annotations

import datetime
import tempfile
from pathlib import Path
from typing import Any

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from veronte4x.capture.columnar import candump
from veronte4x.capture.columnar.batches import read_batches
from veronte4x.capture.columnar.frames import FrameColumns, concat
from veronte4x.capture.columnar.sources import read_frames
from veronte4x.capture.frames import BadLine, Frame, micros
from veronte4x.capture.source import open_frames

INTERFACES = ["can0", "can1", "vcan10", "c", "if_of_sixteen_ch", "if_of_seventeen_c", "cän1"]
STAMPS = ["{:.6f}", "{:017.6f}", "{:.3f}", "{:.0f}", "{:.9f}", "{:010.6f}"]


def _ident(draw: st.DrawFn) -> str:
    if draw(st.booleans()):
        text = f"{draw(st.integers(0, 0xFFF)):03X}"
    else:
        text = f"{draw(st.integers(0, 0x3FFFFFFF)):08X}"  # error frames (bit 29) too
    return text.lower() if draw(st.integers(0, 5)) == 0 else text


@st.composite
def log_line(draw: st.DrawFn, stamp_form: str, interface: str) -> str:
    """A log-form line: mostly classic data frames, sometimes any other form."""
    stamp = stamp_form.format(
        draw(st.sampled_from([1.7e9, 12.5, 0.0, 1e4])) + draw(st.floats(0, 1e3))
    )
    data = draw(st.binary(max_size=8)).hex()
    if draw(st.booleans()):
        data = data.upper()
    frame = f"{_ident(draw)}#{data}"
    other = draw(st.integers(0, 9))
    if other == 1:
        frame = f"{_ident(draw)}#R{draw(st.sampled_from(['', '3', '8']))}"
    elif other == 2:
        frame = f"{_ident(draw)}##{draw(st.integers(0, 15)):X}{draw(st.binary(max_size=16)).hex()}"
    elif other == 3:
        frame += draw(st.sampled_from([" R", " T", "_E", "_9"]))
    elif other == 4:
        pairs = " ".join(data[i : i + 2] for i in range(0, len(data), 2))
        frame = f"{_ident(draw)}   [{len(data) // 2}]  {pairs}"
        return f"({stamp})  {interface}  {frame}"
    return f"({stamp}) {interface} {frame}"


@st.composite
def logs(draw: st.DrawFn) -> bytes:
    """A log of one to three layouts mixed, lines damaged here and there."""
    layouts = draw(
        st.lists(
            st.tuples(st.sampled_from(STAMPS), st.sampled_from(INTERFACES)), min_size=1, max_size=3
        )
    )
    lines = [
        draw(log_line(*draw(st.sampled_from(layouts)))) for _ in range(draw(st.integers(0, 30)))
    ]
    ending = draw(st.sampled_from(["\n", "\r\n"]))
    text = bytearray("".join(line + ending for line in lines).encode())
    for _ in range(draw(st.integers(0, 3))):  # faults
        if not text:
            break
        at = draw(st.integers(0, len(text) - 1))
        fault = draw(st.integers(0, 3))
        if fault == 0:  # any byte: control, non-ASCII, space, "#", a line break
            text[at] = draw(
                st.sampled_from([0, 9, 10, 13, 16, 25, 32, 35, 40, 41, 46, 127, 195, 255])
            )
        elif fault == 1:  # a byte dropped (a line break: two lines merged)
            del text[at]
        elif fault == 2:  # any byte added
            text.insert(at, draw(st.integers(0, 255)))
        else:  # the rest of the line cut
            end = text.find(b"\n", at)
            del text[at : end if end >= 0 else len(text)]
    if draw(st.booleans()) and text.endswith(b"\n"):
        del text[-1]  # no line break after the last line
    return bytes(text)


def _items(columns: FrameColumns) -> list[tuple[int, Any]]:
    """The frames and bad lines in capture order (the frames' order as given)."""
    assert (np.diff(columns.order) > 0).all()
    frames = columns.frames_of(np.arange(len(columns)))
    both = [*zip(columns.order.tolist(), frames, strict=True), *columns.bad_lines]
    return sorted(both, key=lambda item: item[0])


def _exact(item: Frame | BadLine) -> Any:
    """An item with its time exact (a `Seconds` equals its float)."""
    if isinstance(item, BadLine):
        return tuple(item)
    time = None if item.timestamp is None else (item.timestamp, micros(item.timestamp))
    return (time, *item[1:])


def _expected(path: Path) -> list[Any]:
    return [_exact(item) for item in open_frames(path)]


def _got(columns: FrameColumns) -> list[Any]:
    return [_exact(item) for _, item in _items(columns)]


@settings(max_examples=300, suppress_health_check=[HealthCheck.too_slow])
@given(logs(), st.integers(1, 300))
def test_logs_with_faults_agree_with_the_per_frame_reader(text: bytes, batch_bytes: int) -> None:
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "capture.log"
        path.write_bytes(text)
        expected = _expected(path)
        assert _got(read_frames(path)) == expected
        batches = [batch.frames for batch in read_batches(path, batch_bytes)]
        assert _got(concat(batches) if batches else read_frames(path)) == expected


def test_a_fixed_layout_takes_the_plain_lines() -> None:
    """The plain lines of one layout are read in the fixed layout, none by the general
    parser; a damaged line goes there."""
    text = (
        b"(1700000000.000001) can0 123#0011\n"
        b"(1700000000.000002) can0 1ABCDEF0#\r\n"
        b"(1700000000.000003) can0 1ABCDEF0#0102030405060708\n"
        b"(1700000000.000004) can0 12\x153#0011\n"
    )
    a = np.full(len(text) + 1 + candump._PAD, 10, np.uint8)
    a[: len(text)] = np.frombuffer(text, np.uint8)
    breaks = np.flatnonzero(a[: len(text)] == 10)
    starts = np.append(0, breaks[:-1] + 1)
    ends = breaks - (a[breaks - 1] == 13)
    layout = candump._layout(a, starts, ends, np.arange(4))
    assert layout == candump._Layout(17, 10, 4)
    found, others = candump._fixed_lines(a, starts, ends, layout)
    assert found.line.tolist() == [0, 1, 2]
    assert others.tolist() == [3]
    assert found.can_id.tolist() == [0x123, 0x1ABCDEF0, 0x1ABCDEF0]
    assert found.micros.tolist() == [1700000000000001, 1700000000000002, 1700000000000003]
    columns = candump.parse_text(text)
    assert columns is not None
    assert [bad.line_number for _, bad in columns.bad_lines] == [4]


def test_the_human_view_takes_dated_lines_with_their_exact_times() -> None:
    """``candump -t A`` lines (a date and a time of day) are read column-wise, with the
    microseconds since the epoch that `datetime` gives, leap days and the last second of a
    year included; a date that is no date goes to the general parser."""
    stamps = [
        "2025-11-21 15:00:00.010000",
        "2024-02-29 23:59:59.999999",
        "1999-12-31 23:59:59.000001",
        "1970-01-01 00:00:00.000000",
        "2100-03-01 12:34:56.789012",
    ]
    text = "".join(f"({s})  can0  123   [2]  00 11\n" for s in stamps)
    text += "(2023-02-29 00:00:00.000000)  can0  123   [2]  00 11\n"  # no such day
    raw = text.encode()
    a = np.full(len(raw) + 1 + candump._PAD, 10, np.uint8)
    a[: len(raw)] = np.frombuffer(raw, np.uint8)
    breaks = np.flatnonzero(a[: len(raw)] == 10)
    starts = np.append(0, breaks[:-1] + 1)
    found = candump._human_lines(a, starts, breaks, np.arange(len(starts)))
    assert found.line.tolist() == list(range(len(stamps)))
    epoch = datetime.datetime(1970, 1, 1, tzinfo=datetime.timezone.utc)
    expected = [
        (datetime.datetime.strptime(s, "%Y-%m-%d %H:%M:%S.%f").replace(tzinfo=epoch.tzinfo)
         - epoch) // datetime.timedelta(microseconds=1)
        for s in stamps
    ]  # fmt: skip
    assert found.micros.tolist() == expected
    assert found.stamp.tolist() == [m / 1e6 for m in found.micros.tolist()]


def test_a_line_with_an_empty_interface_is_a_bad_line_on_every_path(tmp_path: Path) -> None:
    """``(t)  ID#DATA`` (two spaces, no interface name) is no frame for the per-frame reader;
    the column parser's fixed layout took it as a frame on interface ''."""
    path = tmp_path / "capture.log"
    path.write_bytes(b"(1.0)  123#00\n(2.0)  00000000#\n(3.0) can0 123#00\n")
    expected = _expected(path)
    assert [type(item) for item in open_frames(path)] == [BadLine, BadLine, Frame]
    assert _got(read_frames(path)) == expected
    for batch_bytes in (1, 20, 300):
        batches = [batch.frames for batch in read_batches(path, batch_bytes)]
        assert _got(concat(batches)) == expected
