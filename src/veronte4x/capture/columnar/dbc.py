"""The frames a DBC knows, decoded in the column-wise pass (see `veronte4x.capture.dbc_in`).

The frames that the bus map leaves unknown and whose CAN ID one of the bus map's DBC files
(`veronte4x.capture.BusMap.dbc`) knows are grouped by CAN ID; each group goes through its
cantools message in one tight loop, and its signals become the columns of the message's
table. A frame cantools refuses becomes the ``decode error`` record the per-frame path
gives. Without DBC files this costs one test.
"""

from __future__ import annotations

import dataclasses
import weakref
from typing import Any

import numpy as np
import numpy.typing as npt
import pyarrow as pa

from veronte4x.capture.busmap import BusMap, Role
from veronte4x.capture.columnar.frames import MAX_DATA, FrameColumns
from veronte4x.capture.columnar.schema import HEAD, SENDER_INDEX, Column, TableSpec
from veronte4x.capture.columnar.tables import SUB, Tables
from veronte4x.capture.dbc_in import MAX_DIGITS, DbcEntry, decoder_of, failure, integer_signal
from veronte4x.capture.records import Record, error_record
from veronte4x.errors import SourceError

_UNKNOWN = SENDER_INDEX["unknown"]
_CHOICE = pa.dictionary(pa.int32(), pa.string())
"""A value table's names: int32 indexes, more than any value table holds."""


def decode_dbc_frames(
    frames: FrameColumns, bus_map: BusMap, done: npt.NDArray[np.bool_], tables: Tables
) -> None:
    """Decode the frames not ``done`` that a DBC of the bus map knows into ``tables``, and
    mark them done."""
    if not bus_map.dbc:
        return
    entries = decoder_of(bus_map.dbc, bus_map.dbc_lax).entries()
    keys = frames.can_id.astype(np.int64) | (frames.extended.astype(np.int64) << 32)
    known = np.array([can_id | (int(ext) << 32) for can_id, ext in entries], np.int64)
    rows = np.flatnonzero(~done & np.isin(keys, known) & ~(frames.error | frames.remote))
    veronte = frames.extended[rows] == bus_map.extended
    veronte &= np.isin(frames.can_id[rows], list(bus_map.veronte_roles))
    dronecan = frames.extended[rows] & bus_map.dronecan
    if bus_map.dbc_ids:
        dronecan &= ~np.isin(frames.can_id[rows], list(bus_map.dbc_ids))
    rows = rows[~(veronte | dronecan)]
    if not len(rows):
        return
    errors: list[tuple[int, Record]] = []
    for key in np.unique(keys[rows]).tolist():
        group = rows[keys[rows] == key]
        errors += _decode_group(frames, group, entries[(key & 0xFFFFFFFF, bool(key >> 32))], tables)
    done[rows] = True
    tables.add_records(errors)


def _decode_group(
    frames: FrameColumns, rows: npt.NDArray[np.int64], entry: DbcEntry, tables: Tables
) -> list[tuple[int, Record]]:
    """Decode one CAN ID's frames; return the records of those cantools refuses."""
    message, cls = entry.message, entry.cls
    spec = table_spec(cls)
    if tables.specs.setdefault(spec.kind, spec) is not spec:
        raise SourceError(
            f"a DBC message and a declared layout are both named {spec.kind}: rename one"
        )
    if _simple(message):
        whole = (frames.length[rows] >= message.length) & (frames.length[rows] <= MAX_DATA)
        fields = _vectorised(message, cls, frames.data[rows[whole]])
        _add(frames, rows[whole], spec, fields, tables)
        rows = rows[~whole]
    build = entry.build
    blob = frames.data[rows].tobytes()
    long_data = frames.long_data
    values: list[Any] = []
    good: list[int] = []
    bad: list[tuple[int, str]] = []
    for at, (row, size) in enumerate(zip(rows.tolist(), frames.length[rows].tolist(), strict=True)):
        data = long_data.get(row) if long_data else None
        if data is None:
            data = blob[at * MAX_DATA : at * MAX_DATA + size]
        try:
            values.append(build(data))
        except Exception as error:  # as `DbcDecoder.decode` takes them
            bad.append((row, failure(message, error)))
        else:
            good.append(at)
    found = {c.name: [getattr(value, c.name) for value in values] for c in spec.columns}
    _add(frames, rows[good], spec, found, tables)
    return [(int(frames.order[row]) * SUB, _error(frames, row, detail)) for row, detail in bad]


def _add(
    frames: FrameColumns,
    taken: npt.NDArray[np.int64],
    spec: TableSpec,
    fields: dict[str, Any],
    tables: Tables,
) -> None:
    if not len(taken):
        return
    head = {
        "time": frames.time[taken],
        "has_time": frames.has_time[taken],
        "channel": frames.channel[taken],
        "can_id": frames.can_id[taken],
        "sender": np.full(len(taken), _UNKNOWN, np.int16),
    }
    tables.add_columns(spec.kind, frames.order[taken] * SUB, head, fields)


_LIMIT = 1 << 62
"""Scaled integers past this could overflow int64: such signals go through cantools."""


def _simple(message: Any) -> bool:
    """Whether NumPy decodes every signal of ``message`` exactly as cantools does: no
    multiplexing, integers of up to 62 bits within 8 bytes, integer results that fit int64,
    and a layout cantools decodes (a file read with ``strict=False`` may hold overlapping
    signals, which cantools refuses to unpack whatever the data)."""
    if message.is_multiplexed() or message.length > MAX_DATA:
        return False
    try:
        message.decode(bytes(message.length))
    except Exception:  # as `DbcDecoder.decode` takes them
        return False
    for signal in message.signals:
        if signal.is_float or signal.length > 62 or signal.multiplexer_ids:
            return False  # (a multiplexed signal without a multiplexer: cantools skips it)
        scale, offset = signal.conversion.scale, signal.conversion.offset
        if not isinstance(scale, (int, float)) or not isinstance(offset, (int, float)):
            return False
        if isinstance(scale, int) and abs(scale) * (1 << signal.length) >= _LIMIT:
            return False
        if isinstance(offset, int) and abs(offset) >= _LIMIT:
            return False
    return True


def _vectorised(message: Any, cls: type[Any], data: npt.NDArray[np.uint8]) -> dict[str, Any]:
    """The columns of whole frames (``data``: a row of 8 bytes each) of a `_simple`
    message, as cantools' ``decode`` gives them: the numbers scaled (``decode_choices=False``),
    a value table's names as ``decode_choices=True`` gives them (None where it gives a
    number)."""
    little = np.ascontiguousarray(data).view("<u8")[:, 0]
    big = np.ascontiguousarray(data).view(">u8")[:, 0]
    named = set(cls.CHOICES.values())
    numbers = [f.name for f in dataclasses.fields(cls) if f.name not in named]
    out: dict[str, Any] = {}
    for signal, column in zip(message.signals, numbers, strict=True):
        length = signal.length
        if signal.byte_order == "little_endian":
            word, shift = little, signal.start
        else:  # the start bit is the most significant, numbered as in the DBC
            word, shift = big, 64 - (8 * (signal.start // 8) + 7 - signal.start % 8) - length
        raw = ((word >> np.uint64(shift)) & np.uint64((1 << length) - 1)).astype(np.int64)
        if signal.is_signed:
            raw = np.where(raw >= 1 << (length - 1), raw - (1 << length), raw)
        conversion = signal.conversion
        scale, offset = conversion.scale, conversion.offset
        if conversion.choices:
            unique, where = np.unique(raw, return_inverse=True)
            names = [_name(conversion.raw_to_scaled(value, True)) for value in unique.tolist()]
            out[cls.CHOICES[column]] = np.array(names, object)[where.reshape(-1)]
        if integer_signal(signal):  # integral scale and offset, as cantools keeps ints
            out[column] = raw * int(scale) + int(offset)
        elif isinstance(scale, int):  # Python: the exact product, then the float sum
            out[column] = (raw * scale).astype(np.float64) + offset
        else:
            out[column] = raw.astype(np.float64) * scale + offset
    return out


def _error(frames: FrameColumns, row: int, detail: str) -> Record:
    (frame,) = frames.frames_of(np.array([row], np.int64))
    return error_record(frame.timestamp, frame.channel, frame.can_id, Role.UNKNOWN, None, None,
                        "decode error", detail, frame.data, frame.extended)  # fmt: skip


def _name(value: Any) -> str | None:
    """A value table's name, None for a number (``raw_to_scaled`` with choices)."""
    return None if isinstance(value, (int, float)) else str(value)


@dataclasses.dataclass(frozen=True)
class DbcTableSpec(TableSpec):
    """A DBC message's table, its units and names taken from the DBC.

    Attributes:
        units: Column name to unit, for the signals that have one.
        signals: The DBC name of each column's signal, in column order.
        message: The message's DBC name.
    """

    units: tuple[tuple[str, str], ...] = ()
    signals: tuple[str, ...] = ()
    message: str = ""

    @property
    def schema(self) -> pa.Schema:
        """The record columns, then the signals', each with its signal's DBC name
        (``dbc_signal``) and unit (``unit``, where it has one) in its metadata; the
        message's DBC name in the schema's (``dbc_message``)."""
        units = dict(self.units)
        fields = [
            pa.field(c.name, c.type, metadata=_metadata(signal, units.get(c.name)))
            for c, signal in zip(self.columns, self.signals, strict=True)
        ]
        return pa.schema([*self.head, *fields], metadata={"dbc_message": self.message})


def _metadata(signal: str, unit: str | None) -> dict[str, str]:
    return {"dbc_signal": signal} if unit is None else {"unit": unit, "dbc_signal": signal}


def table_spec(cls: type[Any]) -> TableSpec:
    """The table of a DBC message class: the record columns, then a column per field
    (int64, float64, or a value table's names; an integer signal past int64 uint64 or a
    decimal), its signal's DBC name and unit in the field's metadata."""
    spec = _SPECS.get(cls)
    if spec is None:
        spec = _SPECS[cls] = _spec(cls)
    return spec


_SPECS: weakref.WeakKeyDictionary[type[Any], TableSpec] = weakref.WeakKeyDictionary()


def _spec(cls: type[Any]) -> TableSpec:
    columns = []
    for item in dataclasses.fields(cls):
        kind = {str: _CHOICE, float: pa.float64()}.get(_base(item.type))
        if kind is None:
            kind = _integer_type(*cls.RANGES.get(item.name, (0, 0)))
        columns.append(Column(item.name, kind, _getter(item.name)))
    return DbcTableSpec(
        cls.__name__, HEAD, tuple(columns), tuple(cls.UNITS.items()), cls.SIGNALS, cls.DBC_NAME
    )


def _integer_type(low: int, high: int) -> pa.DataType:
    """The column of an integer signal: int64, else uint64, else an integer decimal (a
    64-bit signal scaled by a large integer factor)."""
    if low >= -(1 << 63) and high < 1 << 63:
        return pa.int64()
    if low >= 0 and high < 1 << 64:
        return pa.uint64()
    digits = len(str(max(-low, high)))
    return pa.decimal128(38, 0) if digits <= 38 else pa.decimal256(MAX_DIGITS, 0)


def _getter(name: str) -> Any:
    def get(message: Any) -> Any:
        return getattr(message, name)

    return get


def _base(annotation: Any) -> Any:
    """``int`` of ``int | None``."""
    for kind in (str, float, int):
        if annotation == kind | None or annotation is kind:
            return kind
    return int
