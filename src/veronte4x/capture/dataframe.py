"""Tables of decoded records: message fields as flat columns, and pandas DataFrames."""

from __future__ import annotations

import contextlib
import dataclasses
import enum
import os
from collections.abc import Iterable, Iterator
from operator import attrgetter, itemgetter
from typing import TYPE_CHECKING, Any

from veronte4x.capture.busmap import BusMap
from veronte4x.capture.flat import field_names, flatten
from veronte4x.capture.records import Record
from veronte4x.extras import require
from veronte4x.times import TimeForm, check_time_form
from veronte4x.units import unit

if TYPE_CHECKING:
    import numpy
    import pandas


def fields(message: Any) -> dict[str, Any]:
    """A message's fields as a flat dict: tuples become ``name_0``, ``name_1``, enums values.

    Nested dataclasses (DroneCAN) flatten with dots: ``status.uptime_sec``; a union as its
    member's value, ``value.value``; an array of structs or unions item by item,
    ``choices_0.value``.
    """
    return flatten(message, _value)


def _value(owner: type, attr: str, value: Any) -> Any:
    """A leaf of `fields`: its value, an enum's as its int."""
    return value.value if isinstance(value, enum.Enum) else value


_SCALARS = frozenset({int, float, bool, str, bytes, type(None)})


def to_dataframe(
    source: Iterable[Record] | str | os.PathLike[str],
    bus_map: BusMap | None = None,
    channel: str | None = None,
    time: TimeForm = "timestamp",
) -> pandas.DataFrame:
    """One row per record, the record's columns then every message field as a column.

    Given records (from `veronte4x.capture.read` or a live bus), columns are
    ``timestamp``, ``channel``, ``can_id``, ``sender``, ``message`` (class name),
    ``error``, ``detail``, ``data`` (hex), then the fields of `fields`. A field column holds
    missing values where a row's message has no such field, with a nullable dtype that keeps
    its kind: ``Int64`` for integers, ``boolean`` for flags, ``float64`` for floats. Needs the
    ``pandas`` extra.

    Given a path, the capture is decoded by the columnar engine (`read_tables`, the
    ``arrow`` extra too) and the frame joins its tables in capture order: the same rows, with
    the tables' column names and Arrow-backed dtypes (enums as categories of names,
    RawCommand's ``cmd`` as a list, DroneCAN text fields as strings unless the bus map's
    ``dronecan_text`` is ``binary``); ``data`` is kept for errors only.

    Either way, ``timestamp`` is the capture's time in UTC to the microsecond (the log's,
    exactly), and ``frame.attrs["units"]`` maps each column with a physical unit to its
    symbol (``voltage``: ``V``, ... see `veronte4x.units`; ``timestamp``: ``s`` when given
    as seconds).

    Args:
        source: Records, or a capture file (``bus_map`` and ``channel`` apply to a file).
        bus_map: CAN IDs and codec choices; defaults to Embention's template IDs.
        channel: Keep only this interface's frames.
        time: ``timestamp`` (the default): times in UTC, a pandas datetime column;
            ``relative``: float seconds from the first timestamped record, as
            ``candump -t z`` and ``veronte4x decode --time relative`` show them;
            ``seconds``: float seconds as logged (Unix time for candump).

    Raises:
        ValueError: ``time`` is none of those.
        MissingExtraError: pandas is not installed (the ``pandas`` extra), or pyarrow for a
            file (the ``arrow`` extra).
    """
    require("pandas", "pandas", "capture.to_dataframe")  # fails first, either way

    check_time_form(time)
    if isinstance(source, (str, os.PathLike)):
        return _tables_frame(source, bus_map, channel, time)
    return _records_frame(source, time)


def _tables_frame(
    path: str | os.PathLike[str], bus_map: BusMap | None, channel: str | None, time: TimeForm
) -> pandas.DataFrame:
    """`to_dataframe` of a capture file: every table of `read_tables` in one frame, its rows
    in capture order."""
    import numpy as np
    import pandas

    from veronte4x.capture import _columnar

    parts = []
    keys = []
    units: dict[str, str] = {}
    for kind, (table, key) in _columnar().keyed_tables(path, bus_map, channel, time).items():
        for field in table.schema:
            if field.metadata and b"unit" in field.metadata:
                units[field.name] = field.metadata[b"unit"].decode()
        part = table.to_pandas(types_mapper=pandas.ArrowDtype)
        if kind in ("errors", "unknown"):
            part.insert(4, "message", None)
            part["data"] = [value.hex() for value in table.column("data").to_pylist()]
        else:
            part.insert(4, "message", kind)
        parts.append(part)
        keys.append(key)
    if not parts:
        return pandas.DataFrame(columns=["timestamp", "channel", "can_id", "sender", "message"])
    joined = pandas.concat(parts, ignore_index=True, sort=False)
    order = np.argsort(np.concatenate(keys), kind="stable")
    frame = joined.iloc[order].reset_index(drop=True)
    frame.attrs["units"] = units
    return frame


_Classes = dict[type, tuple[list[int], list[Any]]]
"""Messages grouped by class: their rows and themselves."""


def _records_frame(records: Iterable[Record], time: TimeForm) -> pandas.DataFrame:
    """`to_dataframe` of records: the messages grouped by class, each field a column."""
    import pandas

    data, classes = _gather(records)
    data["timestamp"] = _times(data["timestamp"], time)
    units: dict[str, str] = {} if time == "timestamp" else {"timestamp": "s"}
    pieces: dict[str, list[tuple[numpy.ndarray, list[Any]]]] = {}
    for class_name, rows, columns in sorted(_parts(classes), key=lambda part: part[1][0]):
        for name, values in columns:
            if name not in pieces:  # first seen: the column's place and unit
                pieces[name] = []
                symbol = unit(class_name, name)
                if symbol is not None:
                    units[name] = symbol
            pieces[name].append((rows, values))
    length = len(data["timestamp"])
    for name, column in pieces.items():
        data[name] = _column(column, length)
    frame = pandas.DataFrame(data)
    frame.attrs["units"] = units
    return frame


def _gather(records: Iterable[Record]) -> tuple[dict[str, list[Any]], _Classes]:
    """The records' own columns, and their messages by class. Records are not kept: the
    garbage collector would walk every one of them again and again."""
    head: dict[str, list[Any]] = {name: [] for name in _HEAD}
    stamps, channels, can_ids, senders, names, errors, details, data = head.values()
    classes: _Classes = {}
    for row, record in enumerate(records):
        message = record.message
        stamps.append(record.timestamp)
        channels.append(record.channel)
        can_ids.append(record.can_id)
        senders.append(record.sender)
        names.append(None if message is None else type(message).__name__)
        errors.append(record.error)
        details.append(record.detail)
        data.append(record.data.hex())
        group = classes.get(type(message))
        if group is None:
            group = classes[type(message)] = ([], [])
        group[0].append(row)
        group[1].append(message)
    return head, classes


def _times(stamps: list[float | None], time: TimeForm) -> Any:
    """The ``timestamp`` column of records' timestamps, in the form ``time`` names (the
    records' microseconds as the tables have them)."""
    import numpy
    import pandas

    from veronte4x.capture.columnar.frames import NO_TIME, micros_of

    micros = micros_of(stamps)
    missing = (micros == NO_TIME) | numpy.array([s is None for s in stamps], numpy.bool_)
    if time == "timestamp":
        values = numpy.where(missing, numpy.datetime64("NaT"), micros.astype("datetime64[us]"))
        return pandas.Series(values, dtype="datetime64[us]").dt.tz_localize("UTC")
    start = 0
    if time == "relative" and not missing.all():
        start = int(micros[numpy.flatnonzero(~missing)[0]])
    seconds = (micros - start) / 1e6
    big = numpy.flatnonzero(~missing & (numpy.abs(micros - start) >= 1 << 53))
    for row in big.tolist():
        seconds[row] = (int(micros[row]) - start) / 1_000_000
    return [None if gone else value for gone, value in zip(missing, seconds.tolist(), strict=True)]


_HEAD = ("timestamp", "channel", "can_id", "sender", "message", "error", "detail", "data")


_Part = tuple[str, "numpy.ndarray", list[tuple[str, list[Any]]]]
"""A message class name, the rows of its messages, and their columns: name and values."""


def _parts(classes: _Classes) -> Iterator[_Part]:
    """The field columns of each message class, or of each shape of a class's messages
    when the class has no single shape (tuples of several lengths, a union of classes)."""
    import numpy

    for cls, (rows, instances) in classes.items():
        if not dataclasses.is_dataclass(cls):
            continue
        columns = _class_columns("", cls, instances)
        if columns is not None:
            yield cls.__name__, numpy.array(rows), columns
            continue
        shapes: dict[tuple[str, ...], tuple[list[int], list[tuple[Any, ...]]]] = {}
        for row, message in zip(rows, instances, strict=True):
            flat = fields(message)
            shape = shapes.setdefault(tuple(flat), ([], []))
            shape[0].append(row)
            shape[1].append(tuple(flat.values()))
        for names, (shape_rows, shape_values) in shapes.items():
            transposed = zip(*shape_values, strict=True)
            columns = [(name, list(v)) for name, v in zip(names, transposed, strict=True)]
            yield cls.__name__, numpy.array(shape_rows), columns


def _class_columns(
    prefix: str, cls: type, instances: list[Any]
) -> list[tuple[str, list[Any]]] | None:
    """The columns `fields` gives every instance of one class, field by field; None when
    the instances differ in shape or two columns share a name."""
    columns: list[tuple[str, list[Any]]] = []
    for field in field_names(cls):
        found = _columns(prefix + field, list(map(attrgetter(field), instances)))
        if found is None:
            return None
        columns += found
    if len({name for name, _ in columns}) < len(columns):
        return None
    return columns


def _columns(name: str, values: list[Any], item: bool = False) -> _Columns | None:
    """The columns `fields` gives one field's ``values`` (of an array's items if ``item``:
    a tuple there is a value); None when they differ in shape."""
    kinds = set(map(type, values))
    shapes = set(map(_shape, kinds))
    if item:
        shapes = {"value" if shape == "tuple" else shape for shape in shapes}
    if shapes == {"value"}:
        return [(name, values)]
    if shapes <= {"value", "enum"}:
        return [(name, [v.value if isinstance(v, enum.Enum) else v for v in values])]
    if shapes == {"dataclass"} and len(kinds) == 1:
        return _class_columns(name + ".", kinds.pop(), values)
    if shapes == {"tuple"} and len(lengths := set(map(len, values))) == 1:
        columns: _Columns = []
        for i in range(lengths.pop()):  # by itemgetter: zip(*values) makes a tracked iterator
            found = _columns(f"{name}_{i}", list(map(itemgetter(i), values)), item=True)
            if found is None:
                return None
            columns += found
        return columns
    return None


_Columns = list[tuple[str, list[Any]]]
"""Columns by name, each a list of values."""


def _shape(kind: type) -> str:
    """How `fields` flattens a value of this type (`veronte4x.capture.flat`)."""
    if kind in _SCALARS:
        return "value"
    if kind is tuple:
        return "tuple"
    if issubclass(kind, enum.Enum):
        return "enum"
    if dataclasses.is_dataclass(kind):
        return "dataclass"
    return "value"


def _column(pieces: list[tuple[numpy.ndarray, list[Any]]], length: int) -> Any:
    """A full-length column from its values at some rows, missing elsewhere: NumPy builds
    flag, integer and float columns, pandas infers the others from the Python values."""
    import pandas

    kinds: set[type] = set().union(*(map(type, values) for _, values in pieces))
    dtype = _dtype(kinds - {type(None)})
    if dtype == "float64" or (dtype is not None and type(None) not in kinds):
        with contextlib.suppress(OverflowError):  # beyond int64 or float64: as pandas has it
            return _numpy_column(dtype, pieces, length)
    full: list[Any] = [None] * length
    for rows, values in pieces:
        for row, value in zip(rows.tolist(), values, strict=True):
            full[row] = value
    return pandas.array(full, dtype=dtype)


def _numpy_column(
    dtype: str, pieces: list[tuple[numpy.ndarray, list[Any]]], length: int
) -> numpy.ndarray | pandas.api.extensions.ExtensionArray:
    """`_column` of values that NumPy holds as they are: no None, unless floats."""
    import numpy
    import pandas

    rows = numpy.concatenate([rows for rows, _ in pieces])
    dense = numpy.concatenate([numpy.array(values, dtype=_NUMPY[dtype]) for _, values in pieces])
    if dtype == "float64":
        column = numpy.full(length, numpy.nan)
        column[rows] = dense
        return column
    data = numpy.zeros(length, dtype=dense.dtype)
    data[rows] = dense
    mask = numpy.ones(length, dtype=bool)
    mask[rows] = False
    if dtype == "boolean":
        return pandas.arrays.BooleanArray(data, mask)
    return pandas.arrays.IntegerArray(data, mask)


_NUMPY = {"boolean": "bool", "Int64": "int64", "float64": "float64"}


def _dtype(kinds: set[type]) -> str | None:
    """The nullable pandas dtype of a field column from the Python types it holds."""
    if kinds == {bool}:
        return "boolean"
    if kinds and all(issubclass(k, int) and not issubclass(k, bool) for k in kinds):
        return "Int64"
    if kinds and all(issubclass(k, (int, float)) and not issubclass(k, bool) for k in kinds):
        return "float64"
    return None
