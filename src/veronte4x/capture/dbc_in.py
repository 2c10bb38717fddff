"""Frames outside the bus map, decoded through DBC files with cantools (the ``dbc`` extra).

On a Veronte bus, the frames of a BMS, a payload or a gimbal are ``unknown`` to veronte4x,
although their owners usually have a DBC for them. Given DBC files, a frame on a CAN ID
outside the bus map that a DBC knows is decoded by cantools (strictly: a frame shorter than
its message is an error, as ``cantools decode`` says) into a message of its own class, one
per DBC message, a frozen dataclass with a field per signal (None for a multiplexed signal
the frame does not carry, a value table's name for an enum); its table has a column per
signal with the signal's unit in the field metadata. Only frames that the bus map leaves
unknown are looked up: on a bus where DroneCAN is enabled (the default), every 29-bit
frame is DroneCAN's, so a DBC of 29-bit frames needs ``[dronecan] enabled = false``.
"""

from __future__ import annotations

import dataclasses
import keyword
import os
import re
from collections.abc import Iterable, Iterator
from typing import TYPE_CHECKING, Any

from veronte4x.capture.busmap import Role
from veronte4x.capture.records import Record
from veronte4x.errors import SourceError
from veronte4x.extras import require

if TYPE_CHECKING:
    import pyarrow


class DbcMessage:
    """Base class of the message classes made from DBC messages (frozen dataclasses).

    Attributes:
        DBC_NAME: The message's name in its DBC.
        UNITS: Field name to unit, for the fields that have one.
        SIGNALS: The DBC names of the signals, in the order of the fields.
        CHOICES: Positions of the signals that have a value table.
    """

    __slots__ = ()
    DBC_NAME = ""
    UNITS: dict[str, str] = {}  # noqa: RUF012 - set once per generated class
    SIGNALS: tuple[str, ...] = ()
    CHOICES: tuple[int, ...] = ()


class DbcDecoder:
    """Decode the frames whose CAN ID a DBC knows.

    Args:
        paths: DBC files; when two know the same CAN ID, the first one given wins.

    Raises:
        SourceError: A file that cannot be read as a DBC (the message names it).
        MissingExtraError: cantools is not installed (the ``dbc`` extra).
    """

    def __init__(self, paths: Iterable[str | os.PathLike[str]]) -> None:
        cantools = require("cantools", "dbc", "decoding frames with a DBC")
        self._messages: dict[tuple[int, bool], tuple[Any, type[Any]]] = {}
        for path in paths:
            try:
                database = cantools.database.load_file(os.fspath(path), database_format="dbc")
            except OSError as error:
                raise SourceError(f"{os.fspath(path)}: {error.strerror or error}") from None
            except Exception as error:  # cantools raises its parser's errors as they come
                raise SourceError(
                    f"{os.fspath(path)}: not a DBC file cantools reads: {error}"
                ) from None
            for message in database.messages:
                key = (message.frame_id, bool(message.is_extended_frame))
                if key not in self._messages:
                    self._messages[key] = (message, _message_class(message))

    def knows(self, can_id: int, extended: bool) -> bool:
        """Whether a DBC describes this CAN ID."""
        return (can_id, extended) in self._messages

    def decode(self, can_id: int, extended: bool, data: bytes) -> Any:
        """The message of a frame whose CAN ID a DBC knows.

        Raises:
            KeyError: No DBC knows the CAN ID.
            ValueError: cantools cannot decode the frame (wrong length, bad multiplexer
                value); the message says why.
        """
        message, cls = self._messages[(can_id, extended)]
        try:
            values = message.decode(data, decode_choices=True, scaling=True)
        except Exception as error:  # cantools' DecodeError and the struct errors it lets out
            raise ValueError(f"{message.name}: {error}") from None
        get = values.get
        arguments = [get(name) for name in cls.SIGNALS]
        for position in cls.CHOICES:
            if arguments[position] is not None:
                arguments[position] = str(arguments[position])
        return cls(*arguments)

    def record(self, record: Record) -> Record:
        """``record`` decoded if it is unknown traffic on a CAN ID a DBC knows, else as is."""
        if record.role is not Role.UNKNOWN or record.error is not None or record.message:
            return record
        detail = record.detail
        if detail.startswith("11-bit CAN ID "):
            extended = False
        elif detail.startswith("29-bit CAN ID "):
            extended = True
        else:
            return record
        if (record.can_id, extended) not in self._messages:
            return record
        try:
            message = self.decode(record.can_id, extended, record.data)
        except ValueError as error:
            return record._replace(error="decode error", detail=str(error))
        return record._replace(message=message, detail="")

    def records(self, records: Iterable[Record]) -> Iterator[Record]:
        """`record` applied to each record."""
        for record in records:
            yield self.record(record)

    def tables(self, tables: dict[str, pyarrow.Table]) -> dict[str, pyarrow.Table]:
        """`read_tables`' tables with the known rows of ``unknown`` moved to tables of their
        own, one per DBC message (and the frames cantools cannot decode, to ``errors``)."""
        import pyarrow as pa

        unknown = tables.get("unknown")
        if unknown is None:
            return tables
        keep: list[int] = []
        found: dict[type[Any], tuple[Any, list[int], list[dict[str, Any]]]] = {}
        failed: list[tuple[int, str]] = []
        columns = (unknown.column(n).to_pylist() for n in ("can_id", "detail", "data"))
        for index, (can_id, detail, data) in enumerate(zip(*columns, strict=True)):
            entry = None
            if detail.startswith("11-bit CAN ID "):
                entry = self._messages.get((can_id, False))
            elif detail.startswith("29-bit CAN ID "):
                entry = self._messages.get((can_id, True))
            if entry is None:
                keep.append(index)
                continue
            message, cls = entry
            try:
                values = message.decode(data, decode_choices=True, scaling=True)
            except Exception as error:  # as in `decode`
                failed.append((index, f"{message.name}: {error}"))
                continue
            rows = found.setdefault(cls, (message, [], []))
            rows[1].append(index)
            rows[2].append(values)
        out = {name: table for name, table in tables.items() if name != "unknown"}
        for cls, (message, indices, values) in found.items():
            routing = unknown.select(["timestamp", "channel", "can_id", "sender"])
            out[cls.__name__] = _table(
                routing.take(pa.array(indices, pa.int64())), cls, message, values
            )
        if keep:
            out["unknown"] = unknown.take(pa.array(keep, pa.int64()))
        if failed:
            rows = unknown.take(pa.array([i for i, _ in failed], pa.int64())).to_pylist()
            for row, (_, detail) in zip(rows, failed, strict=True):
                row.update(error="decode error", detail=detail)
            errors = pa.Table.from_pylist(rows, schema=_errors_schema(unknown.schema, tables))
            out["errors"] = pa.concat_tables([t for t in (tables.get("errors"), errors) if t])
        return out


def _plain(signal: Any, value: Any) -> Any:
    """A value table's entry as its name (a number it does not name as text); numbers as
    they are."""
    if value is None or not (signal.choices or isinstance(value, str)):
        return value
    return str(value)


def _identifier(name: str) -> str:
    text = re.sub(r"\W", "_", name)
    if not text or text[0].isdigit():
        text = "_" + text
    return text + "_" if keyword.iskeyword(text) else text


def _message_class(message: Any) -> type[Any]:
    fields: list[tuple[str, Any]] = []
    units: dict[str, str] = {}
    for signal in message.signals:
        attr = _identifier(signal.name)
        if signal.choices:
            kind: Any = str
        elif signal.is_float or not float(signal.scale).is_integer() or signal.offset % 1:
            kind = float
        else:
            kind = int
        fields.append((attr, kind | None))
        if signal.unit:
            units[attr] = signal.unit
    cls = dataclasses.make_dataclass(
        _identifier(message.name),
        [(attr, kind, dataclasses.field(default=None)) for attr, kind in fields],
        bases=(DbcMessage,),
        namespace={
            "DBC_NAME": message.name,
            "UNITS": units,
            "SIGNALS": tuple(signal.name for signal in message.signals),
            "CHOICES": tuple(i for i, signal in enumerate(message.signals) if signal.choices),
            "__module__": __name__,
        },
        frozen=True,
        slots=True,
    )
    return cls


def _table(
    routing: pyarrow.Table, cls: type[Any], message: Any, rows: list[dict[str, Any]]
) -> pyarrow.Table:
    """The routing columns, then a column per signal of ``message`` (``cls``'s fields)."""
    import pyarrow as pa

    for item, signal in zip(dataclasses.fields(cls), message.signals, strict=True):
        kind = {str: pa.string(), float: pa.float64()}.get(_base(item.type), pa.int64())
        unit = cls.UNITS.get(item.name)
        values = [_plain(signal, row.get(signal.name)) for row in rows]
        if kind == pa.float64():
            values = [None if v is None else float(v) for v in values]
        field = pa.field(item.name, kind, metadata={"unit": unit} if unit else None)
        routing = routing.append_column(field, pa.array(values, kind))
    return routing


def _base(annotation: Any) -> Any:
    """``int`` of ``int | None``."""
    for kind in (str, float, int):
        if annotation == kind | None or annotation is kind:
            return kind
    return int


def _errors_schema(unknown: pyarrow.Schema, tables: dict[str, pyarrow.Table]) -> pyarrow.Schema:
    import pyarrow as pa

    if "errors" in tables:
        return tables["errors"].schema
    fields = [unknown.field(n) for n in ("timestamp", "channel", "can_id", "sender")]
    fields.append(pa.field("error", pa.dictionary(pa.int16(), pa.string())))
    return pa.schema([*fields, unknown.field("detail"), unknown.field("data")])
