"""The columnar engine against the per-frame decoder: the same records, table for table."""

from __future__ import annotations

import tempfile
from pathlib import Path
from unittest import mock

from hypothesis import HealthCheck, given
from hypothesis import strategies as st

from tests.capture.columnar_support import (
    BUS_MAPS,
    LINE_ENDINGS,
    VENDOR_BUS_MAPS,
    assert_same_tables,
    captures,
    write,
)
from tests.soak import differential
from veronte4x import capture
from veronte4x.capture import BusMap
from veronte4x.capture.columnar import batches
from veronte4x.capture.columnar.candump import parse_text
from veronte4x.capture.frames import Frame, micros
from veronte4x.capture.readers.candump import parse_line


@differential(150, suppress_health_check=[HealthCheck.too_slow])
@given(st.data(), BUS_MAPS, st.sampled_from([None, "can0", "can1"]), LINE_ENDINGS)
def test_generated_captures_agree(
    data: st.DataObject, bus_map: BusMap, channel: str | None, ending: str
) -> None:
    lines = data.draw(captures(bus_map))
    with tempfile.TemporaryDirectory() as folder:
        path = write(Path(folder) / "capture.log", lines, ending)
        expected = capture.tables_from_records(capture.read(path, bus_map, channel), bus_map)
        got = capture.read_tables(path, bus_map, channel)
    assert_same_tables(got, expected)


@differential(100, suppress_health_check=[HealthCheck.too_slow])
@given(st.data(), VENDOR_BUS_MAPS, st.sampled_from([None, "can0"]), st.integers(1, 400))
def test_generated_captures_with_vendor_types_agree(
    data: st.DataObject, bus_map: BusMap, channel: str | None, batch_bytes: int
) -> None:
    """Vendor types (any payload, faults included) beside standard ones, in batches."""
    lines = data.draw(captures(bus_map))
    with tempfile.TemporaryDirectory() as folder:
        path = write(Path(folder) / "capture.log", lines)
        expected = capture.tables_from_records(capture.read(path, bus_map, channel), bus_map)
        with mock.patch.object(batches, "BATCH_BYTES", batch_bytes):
            got = capture.read_tables(path, bus_map, channel)
    assert_same_tables(got, expected)


@differential(150)
@given(st.lists(st.text(max_size=60), max_size=20))
def test_arbitrary_text_agrees(lines: list[str]) -> None:
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "capture.log"
        path.write_text("\n".join(lines), encoding="utf-8", errors="surrogatepass")
        expected = capture.tables_from_records(capture.read(path))
        got = capture.read_tables(path)
    assert_same_tables(got, expected)


stamps = st.one_of(
    st.from_regex(r"\A[0-9]{1,19}(\.[0-9]{0,12})?\Z"),
    st.from_regex(r"\A\.?[0-9]{0,4}[.e+-]?[0-9]{0,3}\Z"),
)


@differential(200)
@given(
    st.lists(
        st.tuples(stamps, st.sampled_from(["0FF#00FF01", "1004060A#00000000000000C0"])),
        min_size=1,
        max_size=12,
    )
)
def test_timestamps_of_any_shape_agree(lines: list[tuple[str, str]]) -> None:
    text = "".join(f"({stamp}) can0 {frame}\n" for stamp, frame in lines)
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "capture.log"
        path.write_text(text)
        expected = capture.tables_from_records(capture.read(path))
        got = capture.read_tables(path)
    assert_same_tables(got, expected)


human_stamps = st.one_of(
    st.datetimes().map(lambda moment: moment.strftime("%Y-%m-%d %H:%M:%S.%f")),
    st.from_regex(r"\A[0-9]{4}-[0-9]{2}-[0-9]{2} [0-9]{2}:[0-9]{2}:[0-9]{2}\.[0-9]{6}\Z"),
    stamps,
)


@differential(200)
@given(st.lists(st.tuples(human_stamps, st.booleans()), min_size=1, max_size=12))
def test_human_view_times_agree(lines: list[tuple[str, bool]]) -> None:
    frame = ["0FF   [3]  00 FF 01", "1004060A   [8]  00 00 00 00 00 00 00 C0"]
    text = "".join(f"({stamp})  can0  {frame[long]}\n" for stamp, long in lines)
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "capture.log"
        path.write_text(text)
        expected = capture.tables_from_records(capture.read(path))
        got = capture.read_tables(path)
    assert_same_tables(got, expected)


def test_an_odd_channel_does_not_name_the_next_line_crlf(tmp_path: Path) -> None:
    """Issue 20 item 14: ``can1\\x00`` then ``can1`` in a CRLF file: two channels."""
    path = tmp_path / "capture.log"
    path.write_bytes(b"(1.000000) can1\x00 123#11\r\n(2.000000) can1 123#22\r\n")
    got = capture.read_tables(path, channel="can1")
    assert sum(table.num_rows for table in got.values()) == 1
    assert_same_tables(got, capture.tables_from_records(capture.read(path, channel="can1")))
    assert_same_tables(capture.read_tables(path), capture.tables_from_records(capture.read(path)))


@differential(60, suppress_health_check=[HealthCheck.too_slow])
@given(st.data(), BUS_MAPS, st.integers(1, 400), LINE_ENDINGS)
def test_batch_boundaries_anywhere_agree(
    data: st.DataObject, bus_map: BusMap, batch_bytes: int, ending: str
) -> None:
    """read_tables decodes a file in batches (bounded memory): wherever they are cut, the
    tables are those of the per-frame decoder."""
    lines = data.draw(captures(bus_map))
    with tempfile.TemporaryDirectory() as folder:
        path = write(Path(folder) / "capture.log", lines, ending)
        expected = capture.tables_from_records(capture.read(path, bus_map), bus_map)
        with mock.patch.object(batches, "BATCH_BYTES", batch_bytes):
            got = capture.read_tables(path, bus_map)
    assert_same_tables(got, expected)


extreme_stamps = st.one_of(
    stamps,
    st.sampled_from(["253402300799.999999", "253402300800.5", "99999999999999.25", "-62135596801"]),
    st.floats(allow_nan=False, allow_infinity=False).map(repr),
)


@differential(200)
@given(st.lists(extreme_stamps, min_size=1, max_size=6))
def test_the_column_path_gives_each_frame_the_readers_time(texts: list[str]) -> None:
    """Per frame, as the per-frame fallback rows and multi-frame transfers are fed: the
    reader's timestamp, a plain float where the reader's is one (a `Seconds` only where the
    float cannot give the microseconds back), and the same microseconds, past the year 9999
    and before the year 1 included."""
    lines = [f"({text}) can0 0FF#00FF01" for text in texts]
    columns = parse_text("".join(f"{line}\n" for line in lines).encode())
    expected = [f for n, line in enumerate(lines, 1) if isinstance(f := parse_line(line, n), Frame)]
    got = [] if columns is None else [columns.frame(row) for row in range(len(columns.length))]
    assert got == expected
    for mine, theirs in zip(got, expected, strict=True):
        assert mine.timestamp is not None and theirs.timestamp is not None
        assert micros(mine.timestamp) == micros(theirs.timestamp)
        if type(theirs.timestamp) is float:
            assert type(mine.timestamp) is float
