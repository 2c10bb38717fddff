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

Names become Python identifiers (other characters as ``_``); a name that is a Python
keyword, a message name that is one of veronte4x's tables (``Status``, ``errors``) or a
signal name that is a record column (``timestamp``, ``can_id``) takes a trailing ``_``.
The columnar engine decodes these frames in its column-wise pass
(`veronte4x.capture.columnar.dbc`), to the same rows.
"""

from __future__ import annotations

import dataclasses
import functools
import keyword
import os
import re
from collections.abc import Callable, Iterable, Iterator
from typing import Any

from veronte4x.capture.busmap import RECORD_COLUMNS, Role, reserved_names
from veronte4x.capture.records import Record, dbc_record
from veronte4x.codegen import compile_source, slot_builder
from veronte4x.errors import SourceError
from veronte4x.extras import require


class DbcMessage:
    """Base class of the message classes made from DBC messages (frozen dataclasses).

    Attributes:
        DBC_NAME: The message's name in its DBC.
        UNITS: Field name to unit, for the fields that have one.
        SIGNALS: The DBC names of the signals, in the order of the fields.
        CHOICES: Positions of the signals that have a value table.
        RANGES: Field name to the lowest and highest value, for the integer fields.
    """

    __slots__ = ()
    DBC_NAME = ""
    UNITS: dict[str, str] = {}  # noqa: RUF012 - set once per generated class
    SIGNALS: tuple[str, ...] = ()
    CHOICES: tuple[int, ...] = ()
    RANGES: dict[str, tuple[int, int]] = {}  # noqa: RUF012 - set once per generated class


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
        self._builders: dict[tuple[int, bool], tuple[Callable[..., Any], Build]] = {}
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
                    try:
                        cls = _message_class(message)
                    except ValueError as error:
                        raise SourceError(f"{os.fspath(path)}: {error}") from None
                    self._messages[key] = (message, cls)
                    self._builders[key] = (message.decode, _builder(cls))

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
        decode, build = self._builders[(can_id, extended)]
        try:
            values = decode(data, True, True)  # decode_choices, scaling
        except Exception as error:  # cantools' DecodeError and the struct errors it lets out
            raise ValueError(failure(self._messages[(can_id, extended)][0], error)) from None
        return build(values)

    def entries(self) -> dict[tuple[int, bool], tuple[Any, type[Any]]]:
        """(CAN ID, extended) to the cantools message and its class, for every ID known."""
        return dict(self._messages)

    def record(self, record: Record) -> Record:
        """``record`` decoded if it is unknown traffic on a CAN ID a DBC knows, else as is."""
        if record.role is not _UNKNOWN or record.error is not None or record.message is not None:
            return record
        extended = _EXTENDED.get(record.detail[:_PREFIX])
        if extended is None or (record.can_id, extended) not in self._builders:
            return record
        try:
            message = self.decode(record.can_id, extended, record.data)
        except ValueError as error:
            return record._replace(error="decode error", detail=str(error))
        return dbc_record(record.timestamp, record.channel, record.can_id, message, record.data)

    def records(self, records: Iterable[Record]) -> Iterator[Record]:
        """`record` applied to each record."""
        decode = self.record
        for record in records:
            yield decode(record)


_UNKNOWN = Role.UNKNOWN
_EXTENDED = {"11-bit CAN ID ": False, "29-bit CAN ID ": True}
"""Whether an unknown record's frame is extended, by the start of its detail."""
_PREFIX = len("11-bit CAN ID ")

Build = Callable[[dict[str, Any]], Any]
"""Builds a DBC message from the values cantools decoded, by signal name."""


def _builder(cls: type[Any]) -> Build:
    """The generated builder of ``cls`` (a `_message_class`): a field per signal (None
    where the frame has no value for it, as for a multiplexed signal it does not carry), a
    value table's name as text; filled by slot stores (`veronte4x.codegen.slot_builder`)."""
    names = [f.name for f in dataclasses.fields(cls)]
    lines = [f"def build_{cls.__name__}(values):", "    get = values.get"]
    for position, signal in enumerate(cls.SIGNALS):
        lines.append(f"    v{position} = get({signal!r})")
        if position in cls.CHOICES:
            lines.append(f"    if v{position} is not None:")
            lines.append(f"        v{position} = _str(v{position})")
    lines.append("    made = _new(_B)")
    lines += [f"    made.{attr} = v{i}" for i, attr in enumerate(names)]
    lines += ["    made.__class__ = _cls", "    return made"]
    namespace = {"_new": object.__new__, "_B": slot_builder(cls), "_cls": cls, "_str": str}
    title = f"DBC build {cls.DBC_NAME}"
    build: Build = compile_source("\n".join(lines), namespace, title)[f"build_{cls.__name__}"]
    return build


def failure(message: Any, error: Exception) -> str:
    """The detail of a frame cantools cannot decode."""
    return f"{message.name}: {error}"


def decoder_of(paths: Iterable[str | os.PathLike[str]]) -> DbcDecoder:
    """The decoder of these DBC files, loaded once while the files stay as they are.

    Raises:
        SourceError: As `DbcDecoder` does.
    """
    key = []
    for path in paths:
        try:
            status = os.stat(path)
        except OSError:
            return DbcDecoder([path])  # raises SourceError
        key.append((os.fspath(path), status.st_mtime_ns, status.st_size))
    return _cached(tuple(key))


@functools.lru_cache(maxsize=16)
def _cached(key: tuple[tuple[str, int, int], ...]) -> DbcDecoder:
    return DbcDecoder([path for path, _, _ in key])


def _identifier(name: str, taken: frozenset[str] = frozenset()) -> str:
    text = re.sub(r"\W", "_", name)
    if not text or text[0].isdigit():
        text = "_" + text
    return text + "_" if keyword.iskeyword(text) or text in taken else text


def _message_class(message: Any) -> type[Any]:
    fields: list[tuple[str, Any]] = []
    units: dict[str, str] = {}
    ranges: dict[str, tuple[int, int]] = {}
    for signal in message.signals:
        attr = _identifier(signal.name, RECORD_COLUMNS)
        if signal.choices:
            kind: Any = str
        elif (
            signal.is_float
            or not isinstance(signal.scale, int)
            or not isinstance(signal.offset, int)
        ):
            kind = float
        else:
            kind = int
            ranges[attr] = _integer_range(signal, message.name)
        fields.append((attr, kind | None))
        if signal.unit:
            units[attr] = signal.unit
    cls = dataclasses.make_dataclass(
        _identifier(message.name, reserved_names()),
        [(attr, kind, dataclasses.field(default=None)) for attr, kind in fields],
        bases=(DbcMessage,),
        namespace={
            "DBC_NAME": message.name,
            "UNITS": units,
            "RANGES": ranges,
            "SIGNALS": tuple(signal.name for signal in message.signals),
            "CHOICES": tuple(i for i, signal in enumerate(message.signals) if signal.choices),
            "__module__": __name__,
        },
        frozen=True,
        slots=True,
    )
    return cls


def _integer_range(signal: Any, message: str) -> tuple[int, int]:
    """The lowest and highest value of an integer signal (integer scale and offset) of the
    message named ``message``.

    Raises:
        ValueError: Values of more than `MAX_DIGITS` digits.
    """
    half = 1 << (signal.length - 1)
    raw = (-half, half - 1) if signal.is_signed else (0, 2 * half - 1)
    ends = [value * signal.scale + signal.offset for value in raw]
    if max(len(str(abs(end))) for end in ends) > MAX_DIGITS:
        raise ValueError(
            f"signal {signal.name} of {message}: its values have more than "
            f"{MAX_DIGITS} digits, more than a table column holds"
        )
    return min(ends), max(ends)


MAX_DIGITS = 76
"""The most decimal digits of an integer signal's values (Arrow's ``decimal256``)."""
