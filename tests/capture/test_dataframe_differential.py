"""`to_dataframe` of records against the plain per-record algorithm: the same frame."""

from __future__ import annotations

import enum
import re
from collections.abc import Iterable
from dataclasses import dataclass
from typing import Any

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.capture.columnar_support import BUS_MAPS, captures
from veronte4x import capture
from veronte4x.capture import BusMap, CaptureDecoder, Record
from veronte4x.capture.busmap import Role
from veronte4x.capture.dataframe import _dtype  # the dtype rule both algorithms share
from veronte4x.capture.frames import micros
from veronte4x.times import TIME_FORMS
from veronte4x.units import unit

pandas = pytest.importorskip("pandas")

HEAD = ("timestamp", "channel", "can_id", "sender", "message", "error", "detail", "data")


def reference(records: Iterable[Record], time: str = "timestamp") -> Any:
    """One record at a time: its fields appended to growing lists, then pandas' dtypes;
    times from each record's exact microseconds, one at a time."""
    units: dict[str, str] = {} if time == "timestamp" else {"timestamp": "s"}
    start: int | None = None
    head: dict[str, list[Any]] = {name: [] for name in HEAD}
    columns: dict[str, list[Any]] = {}
    kinds: dict[str, set[type]] = {}
    rows = 0
    for record in records:
        exact = None if record.timestamp is None else micros(record.timestamp)
        stamp: Any = exact
        if exact is not None and time == "timestamp":
            stamp = pandas.Timestamp(exact, unit="us", tz="UTC")
        elif exact is not None:
            start = exact if start is None else start
            stamp = (exact - (start if time == "relative" else 0)) / 1_000_000
        head["timestamp"].append(stamp)
        head["channel"].append(record.channel)
        head["can_id"].append(record.can_id)
        head["sender"].append(record.sender)
        head["message"].append(None if record.message is None else type(record.message).__name__)
        head["error"].append(record.error)
        head["detail"].append(record.detail)
        head["data"].append(record.data.hex())
        for name, value in capture.fields(record.message).items():
            if name not in columns:
                columns[name] = [None] * rows
                kinds[name] = set()
                symbol = unit(type(record.message).__name__, name)
                if symbol is not None:
                    units[name] = symbol
            columns[name] += [None] * (rows - len(columns[name])) + [value]
            if value is not None:
                kinds[name].add(type(value))
        rows += 1
    data: dict[str, Any] = dict(head)
    if time == "timestamp":
        data["timestamp"] = pandas.Series(head["timestamp"], dtype="datetime64[us, UTC]")
    for name, values in columns.items():
        values += [None] * (rows - len(values))
        data[name] = pandas.array(values, dtype=_dtype(kinds[name]))
    frame = pandas.DataFrame(data)
    frame.attrs["units"] = units
    return frame


def assert_same(records: list[Record]) -> None:
    """Both algorithms give equal frames, attrs and column order included, or one error."""
    for time in TIME_FORMS:
        try:
            expected = reference(records, time)
        except Exception as error:  # the new one must fail the same way
            with pytest.raises(type(error), match=re.escape(str(error))):
                capture.to_dataframe(iter(records), time=time)
            continue
        got = capture.to_dataframe(iter(records), time=time)
        pandas.testing.assert_frame_equal(got, expected, check_exact=True)
        assert list(got.columns) == list(expected.columns)
        assert list(got.attrs["units"].items()) == list(expected.attrs["units"].items())


@settings(max_examples=100, suppress_health_check=[HealthCheck.too_slow])
@given(st.data(), BUS_MAPS)
def test_decoded_captures(data: st.DataObject, bus_map: BusMap) -> None:
    lines = data.draw(captures(bus_map))
    text = "".join(line + "\n" for line in lines)
    assert_same(list(CaptureDecoder(bus_map).decode_chunks([text.encode()])))


class Mode(enum.Enum):
    OFF = 0
    ON = "on"


@dataclass(frozen=True, slots=True)
class Inner:
    x: Any
    mode: Any = Mode.OFF


@dataclass(frozen=True, slots=True)
class Other:
    y: Any


@dataclass(frozen=True, slots=True)
class Odd:
    """Fields of any shape: scalars, tuples, enums, nested dataclasses, lists, None."""

    a: Any
    b: Any = None
    b_1: Any = 0  # the same name as b's second item when b is a tuple


anything: st.SearchStrategy[Any] = st.deferred(
    lambda: st.one_of(
        st.none(),
        st.booleans(),
        st.integers(-(2**70), 2**70),
        st.integers(-5, 5),
        st.floats(),
        st.text(max_size=3),
        st.binary(max_size=3),
        st.sampled_from(Mode),
        st.lists(st.integers(0, 3), max_size=2),
        st.lists(st.booleans() | st.integers(0, 3), max_size=3).map(tuple),
        # Arrays of structs, of enums, of tuples (ArrayCommand's commands and the like).
        st.lists(
            st.builds(Inner, st.integers(0, 3))
            | st.sampled_from(Mode)
            | st.tuples(st.integers(0, 1)),
            max_size=3,
        ).map(tuple),
        st.builds(Inner, anything, st.sampled_from(Mode) | st.none()),
        st.builds(Other, st.integers(0, 3) | st.floats(0, 1)),
    )
)
messages = st.one_of(
    st.none(),
    st.just("not a dataclass"),
    st.builds(Inner, st.integers(0, 3), st.sampled_from(Mode)),
    st.builds(Odd, anything, anything, anything),
    st.builds(Other, st.integers(0, 3) | st.booleans() | st.none()),
)


@st.composite
def records(draw: st.DrawFn) -> Record:
    return Record(
        draw(st.none() | st.floats(0, 1e9) | st.integers(0, 10)),
        draw(st.sampled_from(["can0", "can1"])),
        draw(st.integers(0, 0x7FF)),
        draw(st.sampled_from(list(Role))),
        draw(st.none() | st.integers(0, 3)),
        draw(st.none() | st.integers(1, 127)),
        draw(messages),
        draw(st.none() | st.just("bad line")),
        "",
        draw(st.binary(max_size=8)),
    )


@settings(max_examples=300)
@given(st.lists(records(), max_size=12))
def test_messages_of_any_shape(generated: list[Record]) -> None:
    assert_same(generated)


def test_columns_in_first_seen_order_with_nullable_dtypes() -> None:
    def record(message: Any) -> Record:
        return Record(1.5, "can0", 8, Role.ARBITER, None, None, message, None, "", b"\x01")

    rows = [
        Odd(True, (1, 2)),
        Inner(2, Mode.ON),
        Odd(None, (3,), 7),
        Other(2.5),
        Odd(False, (4, 5, 6)),
    ]
    frame = capture.to_dataframe([record(message) for message in rows])
    assert list(frame.columns[8:]) == ["a", "b_0", "b_1", "x", "mode", "y", "b_2"]
    assert [str(frame[name].dtype) for name in frame.columns[8:]] == [
        "boolean", "Int64", "Int64", "Int64", "string", "float64", "Int64"
    ]  # fmt: skip
    na = pandas.NA
    assert frame["a"].tolist() == [True, na, na, na, False]
    assert frame["b_0"].tolist() == [1, na, 3, na, 4]
    assert frame["b_1"].tolist() == [0, na, 7, na, 0]  # the field b_1 wins over b's item
    assert frame["x"].tolist() == [na, 2, na, na, na]
    assert frame["mode"].tolist() == [na, "on", na, na, na]
    assert frame["y"].fillna(-1.0).tolist() == [-1.0, -1.0, -1.0, 2.5, -1.0]
    assert frame["b_2"].tolist() == [na, na, na, na, 6]
    assert frame.attrs["units"] == {}


def test_ints_beyond_int64_fail_as_pandas_fails() -> None:
    record = Record(None, "can0", 8, Role.ARBITER, None, None, Other(2**63), None, "", b"")
    with pytest.raises(TypeError, match="cannot safely cast non-equivalent uint64 to int64"):
        capture.to_dataframe([record])
    with pytest.raises(OverflowError, match="Python int too large to convert to C long"):
        capture.to_dataframe([record, record._replace(message=Other(None))])


def test_no_records_gives_the_head_columns() -> None:
    frame = capture.to_dataframe([])
    assert list(frame.columns) == list(HEAD)
    assert len(frame) == 0
    assert frame.attrs["units"] == {}


def test_nested_messages_whose_shapes_differ() -> None:
    def record(message: Any) -> Record:
        return Record(2.0, "can0", 9, Role.ARBITER, None, None, message, None, "", b"")

    nested = [Odd(Inner((1,))), Odd(Inner((True, 2))), Odd(Inner(3))]
    unions = [Odd(Inner(1)), Odd(Other(2))]
    assert_same([record(message) for message in nested])
    assert_same([record(message) for message in unions])
    frame = capture.to_dataframe([record(message) for message in nested + unions])
    assert list(frame.columns[8:]) == [
        "a.x_0", "a.mode", "b", "b_1", "a.x_1", "a.x", "a.y"
    ]  # fmt: skip
    assert frame["a.x_0"].tolist() == [1, True, None, None, None]
    assert frame["a.x"].tolist() == [pandas.NA, pandas.NA, 3, 1, pandas.NA]


def test_a_field_named_like_a_tuple_item_wins_in_place() -> None:
    def record(message: Any) -> Record:
        return Record(2.0, "can0", 9, Role.ARBITER, None, None, message, None, "", b"")

    collisions = [record(Odd(1, (2, 3), 4)), record(Odd(5, (6, 7), 8))]
    assert_same(collisions)
    frame = capture.to_dataframe(collisions)
    assert list(frame.columns[8:]) == ["a", "b_0", "b_1"]
    assert frame["b_1"].tolist() == [4, 8]


def test_messages_of_one_nested_shape_are_flattened_column_wise(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """A mutation survivor: nested dataclasses no longer taken column-wise, every message
    flattened one by one instead (same frame, slower): here no message is."""
    from veronte4x.capture import dataframe

    def record(message: Any) -> Record:
        return Record(2.0, "can0", 9, Role.ARBITER, None, None, message, None, "", b"")

    nested = [record(Odd(Inner(i), Inner(-i))) for i in range(5)]
    expected = capture.to_dataframe(nested)
    flattened: list[object] = []

    def one_by_one(message: Any) -> dict[str, Any]:
        flattened.append(message)
        return capture.fields(message)

    monkeypatch.setattr(dataframe, "fields", one_by_one)
    frame = capture.to_dataframe(nested)
    assert frame.equals(expected) and flattened == []
    assert list(frame.columns[8:]) == ["a.x", "a.mode", "b.x", "b.mode", "b_1"]
    assert frame["b.x"].tolist() == [0, -1, -2, -3, -4]
    assert frame["b.mode"].tolist() == [0] * 5  # Mode.OFF by its value
