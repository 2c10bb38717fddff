"""Tables of decoded records: message fields as flat columns, and pandas DataFrames."""

from __future__ import annotations

import dataclasses
import enum
import os
from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

from veronte4x.capture.busmap import BusMap
from veronte4x.capture.records import Record
from veronte4x.units import unit

if TYPE_CHECKING:
    import pandas


def fields(message: Any) -> dict[str, Any]:
    """A message's fields as a flat dict: tuples become ``name_0``, ``name_1``, enums values.

    Nested dataclasses (DroneCAN) flatten with dots: ``status.uptime_sec``.
    """
    out: dict[str, Any] = {}
    if dataclasses.is_dataclass(message) and not isinstance(message, type):
        _flatten(message, "", out)
    return out


_SCALARS = frozenset({int, float, bool, str, bytes, type(None)})
_FIELD_NAMES: dict[type, tuple[str, ...]] = {}


def _flatten(message: Any, prefix: str, out: dict[str, Any]) -> None:
    cls = type(message)
    names = _FIELD_NAMES.get(cls)
    if names is None:  # dataclasses.fields() is slow: once per class
        names = _FIELD_NAMES[cls] = tuple(f.name for f in dataclasses.fields(message))
    for field in names:
        value = getattr(message, field)
        name = prefix + field
        if type(value) in _SCALARS:
            out[name] = value
        elif isinstance(value, tuple):
            for index, item in enumerate(value):
                out[f"{name}_{index}"] = item
        elif isinstance(value, enum.Enum):
            out[name] = value.value
        elif dataclasses.is_dataclass(value) and not isinstance(value, type):
            _flatten(value, name + ".", out)
        else:
            out[name] = value


def to_dataframe(
    source: Iterable[Record] | str | os.PathLike[str],
    bus_map: BusMap | None = None,
    channel: str | None = None,
    relative_time: bool = False,
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
    RawCommand's ``cmd`` as a list); ``data`` is kept for errors only.

    Either way, ``frame.attrs["units"]`` maps each column with a physical unit to its
    symbol (``timestamp``: ``s``, ``voltage``: ``V``, ... see `veronte4x.units`).

    Args:
        source: Records, or a capture file (``bus_map`` and ``channel`` apply to a file).
        bus_map: CAN IDs and codec choices; defaults to Embention's template IDs.
        channel: Keep only this interface's frames.
        relative_time: Timestamps in seconds from the first timestamped record, as
            ``candump -t z`` and ``veronte4x decode --relative-time`` show them.
    """
    import pandas

    if isinstance(source, (str, os.PathLike)):
        from veronte4x.capture import _columnar

        frame: pandas.DataFrame = _columnar().frame.dataframe(
            source, bus_map, channel, relative_time
        )
        return frame
    records = source
    units: dict[str, str] = {"timestamp": "s"}
    start: float | None = None

    head: dict[str, list[Any]] = {name: [] for name in _HEAD_COLUMNS}
    columns: dict[str, list[Any]] = {}
    kinds: dict[str, set[type]] = {}
    rows = 0
    for record in records:
        stamp = record.timestamp
        if relative_time and stamp is not None:
            start = stamp if start is None else start
            stamp -= start
        head["timestamp"].append(stamp)
        head["channel"].append(record.channel)
        head["can_id"].append(record.can_id)
        head["sender"].append(record.sender)
        head["message"].append(None if record.message is None else type(record.message).__name__)
        head["error"].append(record.error)
        head["detail"].append(record.detail)
        head["data"].append(record.data.hex())
        for name, value in fields(record.message).items():
            column = columns.get(name)
            if column is None:
                column = columns[name] = []
                kinds[name] = set()
                symbol = unit(type(record.message).__name__, name)
                if symbol is not None:
                    units[name] = symbol
            if len(column) < rows:  # rows whose message had no such field
                column.extend([None] * (rows - len(column)))
            column.append(value)
            if value is not None:
                kinds[name].add(type(value))
        rows += 1
    data: dict[str, Any] = dict(head)
    for name, values in columns.items():
        values.extend([None] * (rows - len(values)))
        data[name] = pandas.array(values, dtype=_dtype(kinds[name]))
    frame = pandas.DataFrame(data)
    frame.attrs["units"] = units
    return frame


_HEAD_COLUMNS = ("timestamp", "channel", "can_id", "sender", "message", "error", "detail", "data")


def _dtype(kinds: set[type]) -> str | None:
    """The nullable pandas dtype of a field column from the Python types it holds."""
    if kinds == {bool}:
        return "boolean"
    if kinds and all(issubclass(k, int) and not issubclass(k, bool) for k in kinds):
        return "Int64"
    if kinds and all(issubclass(k, (int, float)) and not issubclass(k, bool) for k in kinds):
        return "float64"
    return None
