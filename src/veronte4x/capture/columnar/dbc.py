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
from veronte4x.capture.dbc_in import MAX_DIGITS, decoder_of, failure
from veronte4x.capture.records import Record, error_record
from veronte4x.errors import SourceError

_UNKNOWN = SENDER_INDEX["unknown"]
_CHOICE = pa.dictionary(pa.int16(), pa.string())


def decode_dbc_frames(
    frames: FrameColumns, bus_map: BusMap, done: npt.NDArray[np.bool_], tables: Tables
) -> None:
    """Decode the frames not ``done`` that a DBC of the bus map knows into ``tables``, and
    mark them done."""
    if not bus_map.dbc:
        return
    entries = decoder_of(bus_map.dbc).entries()
    keys = frames.can_id.astype(np.int64) | (frames.extended.astype(np.int64) << 32)
    known = np.array([can_id | (int(ext) << 32) for can_id, ext in entries], np.int64)
    rows = np.flatnonzero(~done & np.isin(keys, known) & ~(frames.error | frames.remote))
    veronte = frames.extended[rows] == bus_map.extended
    veronte &= np.isin(frames.can_id[rows], list(bus_map.veronte_roles))
    dronecan = frames.extended[rows] & bus_map.dronecan
    rows = rows[~(veronte | dronecan)]
    if not len(rows):
        return
    errors: list[tuple[int, Record]] = []
    for key in np.unique(keys[rows]).tolist():
        group = rows[keys[rows] == key]
        message, cls = entries[(key & 0xFFFFFFFF, bool(key >> 32))]
        errors += _decode_group(frames, group, message, cls, tables)
    done[rows] = True
    tables.add_records(errors)


decode_frames = decode_dbc_frames  # old name, kept as an alias
"""`decode_dbc_frames` under its earlier name, kept for code that imports it from here."""


def _decode_group(
    frames: FrameColumns,
    rows: npt.NDArray[np.int64],
    message: Any,
    cls: type[Any],
    tables: Tables,
) -> list[tuple[int, Record]]:
    """Decode one CAN ID's frames; return the records of those cantools refuses."""
    spec = table_spec(cls)
    if tables.specs.setdefault(spec.kind, spec) is not spec:
        raise SourceError(
            f"a DBC message and a declared layout are both named {spec.kind}: rename one"
        )
    if _simple(message):
        whole = (frames.length[rows] >= message.length) & (frames.length[rows] <= MAX_DATA)
        fields = _vectorised(message, spec, frames.data[rows[whole]])
        _add(frames, rows[whole], spec, fields, tables)
        rows = rows[~whole]
    decode = message.decode
    blob = frames.data[rows].tobytes()
    long_data = frames.long_data
    values: list[dict[str, Any]] = []
    good: list[int] = []
    bad: list[tuple[int, str]] = []
    for at, (row, size) in enumerate(zip(rows.tolist(), frames.length[rows].tolist(), strict=True)):
        data = long_data.get(row) if long_data else None
        if data is None:
            data = blob[at * MAX_DATA : at * MAX_DATA + size]
        try:
            values.append(decode(data, True, True))  # decode_choices, scaling
        except Exception as error:  # as `DbcDecoder.decode` takes them
            bad.append((row, failure(message, error)))
        else:
            good.append(at)
    found: dict[str, list[Any]] = {}
    for column, name, choice in zip(spec.columns, cls.SIGNALS, _choices(cls), strict=True):
        got = [value.get(name) for value in values]
        found[column.name] = [None if v is None else str(v) for v in got] if choice else got
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
    multiplexing, integers of up to 62 bits within 8 bytes, integer results that fit int64."""
    if message.is_multiplexed() or message.length > MAX_DATA:
        return False
    for signal in message.signals:
        if signal.is_float or signal.length > 62:
            return False
        scale, offset = signal.conversion.scale, signal.conversion.offset
        if not isinstance(scale, (int, float)) or not isinstance(offset, (int, float)):
            return False
        if isinstance(scale, int) and abs(scale) * (1 << signal.length) >= _LIMIT:
            return False
        if isinstance(offset, int) and abs(offset) >= _LIMIT:
            return False
    return True


def _vectorised(message: Any, spec: TableSpec, data: npt.NDArray[np.uint8]) -> dict[str, Any]:
    """The signal columns of whole frames (``data``: a row of 8 bytes each) of a `_simple`
    message, as cantools' ``decode`` (choices and scaling) gives them."""
    little = np.ascontiguousarray(data).view("<u8")[:, 0]
    big = np.ascontiguousarray(data).view(">u8")[:, 0]
    out: dict[str, Any] = {}
    for signal, column in zip(message.signals, [c.name for c in spec.columns], strict=True):
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
            names = [str(conversion.raw_to_scaled(value, True)) for value in unique.tolist()]
            out[column] = np.array(names, object)[where.reshape(-1)]
        elif isinstance(scale, int) and isinstance(offset, int):
            out[column] = raw * scale + offset
        elif isinstance(scale, int):  # Python: the exact product, then the float sum
            out[column] = (raw * scale).astype(np.float64) + offset
        else:
            out[column] = raw.astype(np.float64) * scale + offset
    return out


def _error(frames: FrameColumns, row: int, detail: str) -> Record:
    (frame,) = frames.frames_of(np.array([row], np.int64))
    return error_record(frame.timestamp, frame.channel, frame.can_id, Role.UNKNOWN, None, None,
                        "decode error", detail, frame.data)  # fmt: skip


def _choices(cls: type[Any]) -> list[bool]:
    return [i in cls.CHOICES for i in range(len(cls.SIGNALS))]


@dataclasses.dataclass(frozen=True)
class DbcTableSpec(TableSpec):
    """A DBC message's table, its units taken from the DBC.

    Attributes:
        units: Column name to unit, for the signals that have one.
    """

    units: tuple[tuple[str, str], ...] = ()

    @property
    def schema(self) -> pa.Schema:
        """The record columns, then the signals', a unit in the metadata of each that has one."""
        units = dict(self.units)
        fields = [
            pa.field(c.name, c.type, metadata={"unit": units[c.name]} if c.name in units else None)
            for c in self.columns
        ]
        return pa.schema([*self.head, *fields])


def table_spec(cls: type[Any]) -> TableSpec:
    """The table of a DBC message class: the record columns, then a column per signal
    (int64, float64, or the value table's names; an integer signal past int64 uint64 or a
    decimal), its unit in the field's metadata."""
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
    return DbcTableSpec(cls.__name__, HEAD, tuple(columns), tuple(cls.UNITS.items()))


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
