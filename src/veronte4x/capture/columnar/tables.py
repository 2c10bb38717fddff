"""Collect rows into one Arrow table per message type, in capture order.

Rows come in two forms: whole columns from the column-wise decoders, and `Record` objects
from the per-frame decoder for everything else. Each row carries a sort key (its position
in the capture, then its place among the records of that position), so that each table's
rows come out in capture order whatever path decoded them.
"""

from __future__ import annotations

import functools
import threading
from collections.abc import Iterable, Mapping
from typing import Any

import numpy as np
import numpy.typing as npt
import pyarrow as pa

from veronte4x.capture.columnar import text
from veronte4x.capture.columnar.frames import NO_TIME, FrameColumns, micros_of
from veronte4x.capture.columnar.schema import (
    ERRORS,
    SECONDS,
    SENDER_INDEX,
    SENDERS,
    TIME,
    UNDECODED,
    TableSpec,
)
from veronte4x.capture.records import Record
from veronte4x.times import check_time_form

SUB = 16
"""Sort keys are ``position * SUB + index among the records of that position``."""


@functools.cache
def _sender_names() -> pa.Array:
    """The sender names as Arrow strings: made on first use, since pyarrow imports pandas
    (when installed) on building its first array, which importing this module must not."""
    return pa.array(SENDERS, pa.string())


class Tables:
    """The tables being built, by kind.

    Args:
        specs: The schema of every message table, by kind.
        channels: Interface names; column-wise rows give channels as indices into it.
    """

    def __init__(self, specs: Mapping[str, TableSpec], channels: list[str]) -> None:
        self.specs = {**specs, "errors": ERRORS, "unknown": UNDECODED}
        self.channels = channels
        self._channel_codes = {name: index for index, name in enumerate(channels)}
        self._parts: dict[str, list[tuple[npt.NDArray[np.int64], dict[str, pa.Array]]]] = {}
        self._lock = threading.Lock()  # decoders of different protocols add rows side by side

    def add_columns(
        self,
        kind: str,
        keys: npt.NDArray[np.int64],
        head: Mapping[str, Any],
        fields: Mapping[str, Any],
    ) -> None:
        """Add rows given as columns (NumPy or Arrow), head columns included.

        ``head`` holds ``time`` (`FrameColumns.time`), ``has_time``, ``channel`` (codes),
        ``can_id``, ``sender`` (codes into `SENDERS`), and for DroneCAN ``node_id`` and
        ``destination_node_id``. Text columns (`Column.text`) take bytes: a value that
        is not UTF-8 adds a row to ``errors`` (`veronte4x.capture.columnar.text`).
        """
        if not len(keys):
            return
        arrays: dict[str, pa.Array] = {}
        for name, type_, where, key, names in self.specs[kind].plan:
            if where == "text":
                arrays[name], bad = text.strings(fields[name])
                if bad.any():
                    rows = text.bad_text_rows(kind, name, head, fields[name], bad)
                    self.add_columns("errors", keys[bad], rows, {})
            elif where == "field":
                arrays[name] = _arrow(fields[key], type_, len(keys), names)
            elif name == "timestamp":
                time = np.asarray(head["time"], np.int64)
                missing = ~np.asarray(head["has_time"], np.bool_) | (time == NO_TIME)
                arrays["timestamp"] = pa.array(time, TIME, mask=missing)
            elif name == "channel":
                arrays["channel"] = np.asarray(head["channel"], np.int32)
            elif name == "sender":
                arrays["sender"] = np.asarray(head["sender"], np.int16)
            else:
                arrays[name] = _arrow(head[name], type_, len(keys))
        with self._lock:
            self._parts.setdefault(kind, []).append((keys, arrays))

    def add_records(self, records: Iterable[tuple[int, Record]]) -> None:
        """Add records of the per-frame decoder with their sort keys."""
        by_kind: dict[str, list[tuple[int, Record]]] = {}
        for key, record in records:
            if record.error is not None:
                kind = "errors"
            elif record.message is None:
                kind = "unknown"
            else:
                kind = type(record.message).__name__
            by_kind.setdefault(kind, []).append((key, record))
        for kind, rows in by_kind.items():
            self._add_record_rows(kind, rows)

    def _add_record_rows(self, kind: str, rows: list[tuple[int, Record]]) -> None:
        spec = self.specs.get(kind)
        if spec is None:  # a DBC message's (`veronte4x.capture.dbc_in`)
            from veronte4x.capture.columnar.dbc import table_spec

            spec = self.specs[kind] = table_spec(type(rows[0][1].message))
        records = [record for _, record in rows]
        stamps = [r.timestamp for r in records]
        head: dict[str, Any] = {
            "time": micros_of(stamps),
            "has_time": np.array([s is not None for s in stamps], np.bool_),
            "channel": [self._channel(r.channel) for r in records],
            "can_id": [r.can_id for r in records],
            "sender": [SENDER_INDEX[r.sender] for r in records],
            "node_id": [r.node_id for r in records],
            "destination_node_id": [r.destination_node_id for r in records],
            "error": [r.error for r in records],
            "detail": [r.detail for r in records],
            "data": [r.data for r in records],
        }
        messages = [r.message for r in records]
        fields = {c.name: c.values(messages) for c in spec.columns}
        self.add_columns(kind, np.array([key for key, _ in rows], np.int64), head, fields)

    def _channel(self, name: str) -> int:
        with self._lock:
            code = self._channel_codes.get(name)
            if code is None:
                code = self._channel_codes[name] = len(self.channels)
                self.channels.append(name)
            return code

    def finish(self) -> dict[str, pa.Table]:
        """The tables, each sorted into capture order; kinds without rows are left out."""
        return {kind: table for kind, (table, _) in self.finish_with_keys().items()}

    def finish_with_keys(self) -> dict[str, tuple[pa.Table, npt.NDArray[np.int64]]]:
        """The tables, each with the sort keys of its rows (increasing)."""
        channel_names = pa.array(self.channels, pa.string())
        out: dict[str, tuple[pa.Table, npt.NDArray[np.int64]]] = {}
        for kind, parts in self._parts.items():
            spec = self.specs[kind]
            keys = np.concatenate([k for k, _ in parts])
            order = np.argsort(keys, kind="stable")
            ordered = bool((order == np.arange(len(order))).all())
            columns = []
            for field in spec.schema:
                pieces = [arrays[field.name] for _, arrays in parts]
                if field.name == "channel":
                    column = _dictionary(np.concatenate(pieces)[order], field.type, channel_names)
                elif field.name == "sender":
                    column = _dictionary(np.concatenate(pieces)[order], field.type, _sender_names())
                else:
                    joined = pa.concat_arrays(pieces) if len(pieces) > 1 else pieces[0]
                    column = joined if ordered else joined.take(pa.array(order))
                    if pa.types.is_dictionary(field.type) and pa.types.is_string(column.type):
                        column = column.dictionary_encode().cast(field.type)
                columns.append(column)
            out[kind] = pa.Table.from_arrays(columns, schema=spec.schema), keys[order]
        return out


Keyed = dict[str, tuple[pa.Table, npt.NDArray[np.int64]]]
"""Tables by kind, each with the capture-order keys of its rows."""


class Clock:
    """Gives the ``timestamp`` column of a capture's tables in the form asked for
    (`veronte4x.times.TimeForm`), batch after batch in capture order.

    ``timestamp`` keeps the column; ``seconds`` makes it float seconds (the microseconds
    divided by a million, correctly rounded); ``relative`` float seconds from the capture's
    first timestamped frame (of ``channel``, when given), which `see` finds.
    """

    def __init__(self, time: str, channel: str | None = None) -> None:
        self.time = check_time_form(time)
        self.channel = channel
        self.start: int | None = None

    def see(self, frames: FrameColumns) -> None:
        """Look at the capture's next frames, before their rows are retimed."""
        if self.time != "relative" or self.start is not None:
            return
        timed = frames.has_time & (frames.time != NO_TIME)
        if self.channel is not None:
            if self.channel not in frames.channels:
                return
            timed &= frames.channel == frames.channels.index(self.channel)
        found = np.flatnonzero(timed)
        if len(found):
            self.start = int(frames.time[found[0]])

    def __call__(self, tables: Keyed) -> Keyed:
        """The tables of the frames seen so far, retimed."""
        if self.time == "timestamp":
            return tables
        offset = self.start if self.time == "relative" and self.start is not None else 0
        return {kind: (_in_seconds(table, offset), keys) for kind, (table, keys) in tables.items()}


def _in_seconds(table: pa.Table, offset: int) -> pa.Table:
    """A table with its ``timestamp`` column as float seconds since ``offset`` us."""
    index = table.schema.get_field_index("timestamp")
    column = table.column(index).combine_chunks().cast(pa.int64())
    missing = np.asarray(column.is_null())
    micros = np.asarray(column.fill_null(0)) - offset
    seconds = micros / 1e6  # exact micros, one correctly rounded division ...
    for row in np.flatnonzero(np.abs(micros) >= _EXACT).tolist():  # ... or Python's
        seconds[row] = int(micros[row]) / 1_000_000
    return table.set_column(index, SECONDS, pa.array(seconds, pa.float64(), mask=missing))


_EXACT = 1 << 53
"""Integers below this convert to float64 exactly."""


def _dictionary(codes: np.ndarray, type_: pa.DataType, names: pa.Array) -> pa.Array:
    indices = pa.array(codes, type_.index_type)
    return pa.DictionaryArray.from_arrays(indices, names)


def _arrow(
    values: Any, type_: pa.DataType, size: int, names: tuple[str, ...] | None = None
) -> pa.Array:
    """One column as an Arrow array of its schema type (``names``: an enum's dictionary,
    ``values`` then being indices)."""
    if isinstance(values, pa.Array):
        if values.type == pa.null():
            return pa.nulls(size, type_)
        return values if values.type == type_ else values.cast(type_)
    if pa.types.is_dictionary(type_):
        if names is None:  # names found in the data: encoded once the table is whole
            return pa.array(list(values), pa.string())
        indices = pa.array(
            values if isinstance(values, np.ndarray) else list(values), type_.index_type
        )
        return pa.DictionaryArray.from_arrays(indices, pa.array(names, pa.string()))
    if isinstance(values, np.ndarray) and values.dtype != object:
        return pa.array(values, type_)
    return pa.array(list(values), type_)
