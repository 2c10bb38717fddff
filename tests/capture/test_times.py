"""Time as time (issue 19, item 5): the ``timestamp`` column is the log's time, exactly.

The expected microseconds come from the text's digits by string handling alone (no float,
no Fraction): integer seconds, the first six decimals, and a half-to-even rounding on the
rest, written out digit by digit.
"""

from __future__ import annotations

import pickle
import subprocess
import sys
from datetime import datetime, timedelta, timezone
from pathlib import Path
from typing import Any

import pyarrow as pa
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.capture.columnar_support import assert_same_tables
from veronte4x import capture
from veronte4x.capture import BusMap
from veronte4x.capture.frames import Seconds, micros, text_seconds
from veronte4x.times import END_MICROS, FIRST_MICROS

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "capture.log"
NO_DRONECAN = BusMap(dronecan=False)
"""Every frame off the bus map's Veronte IDs gives one row (unknown traffic or an error)."""
UTC = pa.timestamp("us", tz="UTC")


def expected_micros(whole: str, decimals: str) -> int | None:
    """The microseconds of ``whole.decimals`` seconds from the digits: the first six
    decimals, the rest rounded half to even; None outside the years 1 to 9999."""
    head = int(whole + decimals[:6].ljust(6, "0"))
    rest = decimals[6:]
    if rest and (rest[0] > "5" or (rest[0] == "5" and (rest[1:].strip("0") or head % 2))):
        head += 1
    return head if FIRST_MICROS <= head < END_MICROS else None


def stamp_text(whole: str, decimals: str, dot: bool) -> str:
    return whole + ("." + decimals if dot or decimals else "")


wholes = st.one_of(
    st.integers(1_700_000_000, 1_800_000_000).map(str),  # today, as candump writes it
    st.integers(0, 10**12 - 1).map(str),  # far past (1970) to beyond the year 9999
    st.integers(0, 10**10 - 1).map(lambda n: f"{n:010d}"),  # zero-padded
)
decimal_digits = st.one_of(
    st.integers(0, 999_999).map(lambda n: f"{n:06d}"),  # candump's six
    st.text("0123456789", min_size=0, max_size=12),  # none to many
    st.sampled_from(["5", "0000005", "0000015", "0000025", "00000050", "9999995", "4999995"]),
)


@st.composite
def lines(draw: st.DrawFn, index: int) -> tuple[str, int | None, bool]:
    """A candump line of any form with a generated time, its expected microseconds, and
    whether the time is in the text at all."""
    whole, decimals = draw(wholes), draw(decimal_digits)
    dot = draw(st.booleans())
    stamp = stamp_text(whole, decimals, dot)
    extended = draw(st.booleans())
    can_id = f"{0x1000 + index:08X}" if extended else f"{0x300 + index:03X}"
    form = draw(
        st.sampled_from(["log", "flag", "remote", "fd", "error", "dlc", "human", "date", "none"])
    )
    expected = expected_micros(whole, decimals)
    if form == "log":
        return f"({stamp}) can0 {can_id}#{index % 256:02X}11", expected, True
    if form == "flag":
        return (
            f"({stamp}) can1 {can_id}#{index % 256:02X} {draw(st.sampled_from('RT'))}",
            expected,
            True,
        )
    if form == "remote":
        return f"({stamp}) can0 {can_id}#R", expected, True
    if form == "fd":
        return f"({stamp}) can0 {can_id}##1{index % 256:02X}", expected, True
    if form == "error":
        return f"({stamp}) can0 20000080#0000000000000000", expected, True
    if form == "dlc":
        return f"({stamp}) can0 {can_id}#1122334455667788_E", expected, True
    if form == "human":
        return f"({stamp})  can0  {can_id}   [1]  {index % 256:02X}", expected, True
    if form == "date":
        moment = draw(st.datetimes(datetime(1, 1, 1), datetime(9999, 12, 31, 23, 59, 59, 999999)))
        text = moment.strftime("%Y-%m-%d %H:%M:%S.%f").rjust(26, "0")
        exact = (moment.replace(tzinfo=timezone.utc) - EPOCH) // timedelta(microseconds=1)
        return f"({text})  can0  {can_id}   [1]  {index % 256:02X}", exact, True
    return f"  can0  {can_id}   [1]  {index % 256:02X}", None, False


EPOCH = datetime(1970, 1, 1, tzinfo=timezone.utc)


@st.composite
def captures(draw: st.DrawFn) -> list[tuple[str, int | None, bool]]:
    count = draw(st.integers(1, 12))
    return [draw(lines(index)) for index in range(count)]


def times_in_order(path: Path, time: str = "timestamp") -> list[Any]:
    """The ``timestamp`` column of every row, in capture order."""
    frame = capture.to_dataframe(path, NO_DRONECAN, time=time)  # type: ignore[arg-type]
    import pandas

    return [None if pandas.isna(value) else value for value in frame["timestamp"]]


def as_micros(value: Any) -> int | None:
    if value is None:
        return None
    return int((value.to_pydatetime() - EPOCH) // timedelta(microseconds=1))


@settings(max_examples=150, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(captures())
def test_the_timestamp_column_is_the_text_digit_for_digit(
    tmp_path: Path, generated: list[tuple[str, int | None, bool]]
) -> None:
    path = tmp_path / "times.log"
    path.write_text("".join(line + "\n" for line, _, _ in generated))
    tables = capture.read_tables(path, NO_DRONECAN)
    assert all(table.schema.field("timestamp").type == UTC for table in tables.values())
    got = [as_micros(value) for value in times_in_order(path)]
    assert got == [expected for _, expected, _ in generated]
    # The per-frame path gives the same tables: its records carry the exact time.
    assert_same_tables(tables, capture.tables_from_records(capture.read(path, NO_DRONECAN)))


def test_candump_examples_exactly() -> None:
    text = (
        "(1763737000.123456) can0 123#11\n"
        "(1763737000.999999) can0 1FFFFFFF#22\n"  # a 29-bit id
        "(1763737001.000001)  can0  123   [1]  33\n"
        "(2025-11-21 15:00:00.010000)  can0  123   [1]  44\n"
        "(9999999999.999999) can0 123#55\n"  # past 2242: a float no longer holds the us
        "(1763737000.1234565) can0 123#66\n"  # seven decimals: half to even
        "(1763737000.1234575) can0 123#77\n"
    )
    stamps = [str(value) for value in _times_of_text(text)]
    assert stamps == [
        "2025-11-21 14:56:40.123456+00:00",
        "2025-11-21 14:56:40.999999+00:00",
        "2025-11-21 14:56:41.000001+00:00",
        "2025-11-21 15:00:00.010000+00:00",
        "2286-11-20 17:46:39.999999+00:00",
        "2025-11-21 14:56:40.123456+00:00",
        "2025-11-21 14:56:40.123458+00:00",
    ]


def _times_of_text(text: str) -> list[Any]:
    import tempfile

    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "x.log"
        path.write_text(text)
        return times_in_order(path)


@settings(max_examples=100)
@given(
    st.integers(0, 10**11).map(str),
    st.text("0123456789", min_size=1, max_size=6),
)
def test_seconds_and_relative_are_floats_of_the_exact_time(whole: str, decimals: str) -> None:
    text = f"(1700000000.5) can0 123#00\n({whole}.{decimals}) can0 124#00\n"
    seconds = _times_of_text_as(text, "seconds")
    relative = _times_of_text_as(text, "relative")
    exact = expected_micros(whole, decimals)
    assert exact is not None
    assert seconds == [1700000000.5, exact / 1_000_000]  # int / int: correctly rounded
    assert relative == [0.0, (exact - 1_700_000_000_500_000) / 1_000_000]
    if exact < 2**33 * 10**6:
        assert seconds[1] == float(f"{whole}.{decimals}")  # as logged


def _times_of_text_as(text: str, time: str) -> list[Any]:
    import tempfile

    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "x.log"
        path.write_text(text)
        tables = capture.read_tables(path, NO_DRONECAN, time=time)  # type: ignore[arg-type]
        assert tables["unknown"].schema.field("timestamp").type == pa.float64()
        return times_in_order(path, time)


def test_relative_time_starts_at_the_first_frame_of_the_channel(tmp_path: Path) -> None:
    path = tmp_path / "two.log"
    path.write_text(
        "(100.000000) can0 123#00\n(101.500000) can1 124#00\n(102.250000) can1 125#00\n"
    )
    tables = capture.read_tables(path, NO_DRONECAN, channel="can1", time="relative")
    assert tables["unknown"].column("timestamp").to_pylist() == [0.0, 0.75]


def test_a_wrong_time_form_is_one_line() -> None:
    message = "time='utc': give 'timestamp' (UTC, the default), 'relative' (seconds from the"
    for call in (
        lambda: capture.read_tables(EXAMPLE, time="utc"),  # type: ignore[arg-type]
        lambda: capture.to_dataframe(EXAMPLE, time="utc"),  # type: ignore[arg-type]
        lambda: capture.to_dataframe([], time="utc"),  # type: ignore[arg-type]
        lambda: capture.to_parquet(EXAMPLE, "/nonexistent", time="utc"),  # type: ignore[arg-type]
    ):
        with pytest.raises(ValueError, match=message.replace("(", r"\(").replace(")", r"\)")):
            call()


def test_records_carry_the_exact_time_only_where_the_float_loses_it() -> None:
    assert type(text_seconds("1763737000.123456")) is float
    assert type(text_seconds("0.5")) is float
    far = text_seconds("9999999999.999999")
    assert isinstance(far, Seconds) and far.micros == 9_999_999_999_999_999
    assert far == float("9999999999.999999")
    seven = text_seconds("0.0000025")
    assert isinstance(seven, Seconds) and seven.micros == 2 and seven == 2.5e-6
    assert pickle.loads(pickle.dumps(far)).micros == far.micros
    assert text_seconds("1e3") == 1000.0 and micros(text_seconds("1e-7")) == 0
    assert micros(float("nan")) is None and micros(1e300) is None
    assert micros(0.0078125) == 7812  # a tie of the float itself: half to even


def test_every_record_path_gives_the_exact_time(tmp_path: Path) -> None:
    path = tmp_path / "far.log"
    path.write_text("(9999999999.999999) can0 123#11\n(1.0000005) can0 1ABCDEF0#22\n")
    records = list(capture.read(path, NO_DRONECAN))
    assert [micros(r.timestamp or 0.0) for r in records] == [9_999_999_999_999_999, 1_000_000]
    assert [r.timestamp for r in records] == [9999999999.999999, 1.0000005]  # the floats


def test_datasets_read_back_as_utc_timestamps(tmp_path: Path) -> None:
    duckdb = pytest.importorskip("duckdb")
    polars = pytest.importorskip("polars")
    out = tmp_path / "dataset"
    capture.to_parquet(EXAMPLE, out)
    files = str(out / "capture=*" / "Score.parquet")
    kind = (
        duckdb.connect().sql(f"DESCRIBE SELECT timestamp FROM read_parquet('{files}')").fetchall()
    )
    assert kind[0][1] == "TIMESTAMP WITH TIME ZONE"
    first = (
        duckdb.connect()
        .sql(
            "SELECT strftime(timestamp AT TIME ZONE 'UTC', '%Y-%m-%d %H:%M:%S.%f') "
            f"FROM read_parquet('{files}') LIMIT 1"
        )
        .fetchall()
    )
    assert first == [("2025-11-21 15:00:00.260000",)]
    frame = polars.read_parquet(files)
    assert frame.schema["timestamp"] == polars.Datetime("us", "UTC")
    assert frame["timestamp"][0] == datetime(2025, 11, 21, 15, 0, 0, 260000, tzinfo=timezone.utc)
    tables = capture.read_tables(EXAMPLE)
    assert frame["timestamp"].to_list() == tables["Score"].column("timestamp").to_pylist()


@pytest.mark.parametrize("time", ["seconds", "relative"])
def test_datasets_of_seconds(tmp_path: Path, time: str) -> None:

    out = tmp_path / time
    capture.to_parquet(EXAMPLE, out, time=time)  # type: ignore[arg-type]
    read = capture.open_dataset(out, "Score").to_table()
    expected = capture.read_tables(EXAMPLE, time=time)["Score"]  # type: ignore[arg-type]
    assert read.schema.field("timestamp").type == pa.float64()
    assert read.column("timestamp").to_pylist() == expected.column("timestamp").to_pylist()


def test_convert_cli_time_option(tmp_path: Path) -> None:
    out = tmp_path / "dataset"
    done = subprocess.run(
        [sys.executable, "-m", "veronte4x", "convert", str(EXAMPLE), "--to", "parquet", str(out),
         "--time", "seconds"],
        capture_output=True, text=True, cwd=ROOT, check=False,
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    import pyarrow.parquet as pq

    table = pq.read_table(capture.dataset_files(out, "Score"))
    assert table.schema.field("timestamp").type == pa.float64()
    wrong = subprocess.run(
        [sys.executable, "-m", "veronte4x", "convert", str(EXAMPLE), "--to", "parquet", str(out),
         "--time", "utc"],
        capture_output=True, text=True, cwd=ROOT, check=False,
    )  # fmt: skip
    assert wrong.returncode == 2
    assert "invalid choice: 'utc'" in wrong.stderr and "Traceback" not in wrong.stderr


def test_csv_times_are_iso(tmp_path: Path) -> None:
    out = tmp_path / "grid.csv"
    done = subprocess.run(
        [sys.executable, "-m", "veronte4x", "convert", str(EXAMPLE), "--to", "csv", str(out),
         "--every", "100ms"],
        capture_output=True, text=True, cwd=ROOT, check=False,
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    lines = out.read_text().splitlines()
    assert lines[0].startswith('"time",') or lines[0].startswith("time,")
    assert lines[1].startswith('"2025-11-21T15:00:00.000000Z",')
    seconds = tmp_path / "seconds.csv"
    subprocess.run(
        [sys.executable, "-m", "veronte4x", "convert", str(EXAMPLE), "--to", "csv", str(seconds),
         "--every", "100ms", "--time", "seconds"],
        capture_output=True, text=True, cwd=ROOT, check=True,
    )  # fmt: skip
    assert seconds.read_text().splitlines()[1].startswith("1763737200,")
