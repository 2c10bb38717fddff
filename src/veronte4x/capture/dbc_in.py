"""Frames outside the bus map, decoded through DBC files with cantools (the ``dbc`` extra).

On a Veronte bus, the frames of a BMS, a payload or a gimbal are ``unknown`` to veronte4x,
although their owners usually have a DBC for them. Given DBC files, a frame on a CAN ID
outside the bus map that a DBC knows is decoded by cantools (strictly: a frame shorter than
its message is an error, as ``cantools decode`` says) into a message of its own class, one
per DBC message, a frozen dataclass with a field per signal (None for a multiplexed signal
the frame does not carry); a signal with a value table has two fields, its number (as
cantools' ``decode_choices=False`` gives it) and ``<signal>_name``, the table's name for that
number (None for a number the table does not name). Its table has a column per field, with
the signal's unit and DBC name in the field metadata.

Only frames that the bus map leaves unknown are looked up: a DBC message on a CAN ID the bus
map gives to Veronte, or on a 29-bit ID while DroneCAN is decoded, is reported once (a
`DbcWarning`) and its frames stay the bus map's, unless the bus map says ``dbc_first``.

DBC names become Python identifiers by one rule (`field_names`, `class_names`), the DBC
name kept in the class (``DBC_NAME``, ``SIGNALS``) and in the table's metadata:

1. every character that cannot be in a Python identifier becomes ``_``; an empty name or
   one that starts with a digit gets a leading ``_``, one that starts with ``__`` the
   prefix ``dbc``;
2. a Python keyword, an attribute of `DbcMessage` (``DBC_NAME``, ``SIGNALS``, ``UNITS``,
   ``CHOICES``, ``RANGES``), and, ignoring case, a record column (``timestamp``,
   ``can_id``, ...) or, for a message, one of veronte4x's tables (``Status``, ``errors``)
   takes a trailing ``_``;
3. a name equal, ignoring case, to one taken before it takes ``_2``, ``_3``, ...: in a
   message, the signals in DBC order, then the ``_name`` fields; messages across every
   DBC file, in the order given.

The columnar engine decodes these frames in its column-wise pass
(`veronte4x.capture.columnar.dbc`), to the same rows.
"""

from __future__ import annotations

import dataclasses
import functools
import keyword
import os
import re
import unicodedata
import warnings
from collections.abc import Callable, Iterable, Iterator, Sequence
from typing import Any

from veronte4x.capture.busmap import RECORD_COLUMNS, BusMap, Role, reserved_names
from veronte4x.capture.records import Record, dbc_record
from veronte4x.codegen import compile_source, slot_builder
from veronte4x.errors import SourceError
from veronte4x.extras import require


class DbcMessage:
    """Base class of the message classes made from DBC messages (frozen dataclasses).

    Attributes:
        DBC_NAME: The message's name in its DBC.
        SIGNALS: The DBC name of the signal of each field, in the order of the fields (a
            signal with a value table has two fields: its number and its name).
        UNITS: Field name to unit, for the fields that have one.
        CHOICES: The field of a value table's name, by the field of its signal's number.
        RANGES: Field name to the lowest and highest value, for the integer fields.
    """

    __slots__ = ()
    DBC_NAME = ""
    SIGNALS: tuple[str, ...] = ()
    UNITS: dict[str, str] = {}  # noqa: RUF012 - set once per generated class
    CHOICES: dict[str, str] = {}  # noqa: RUF012 - set once per generated class
    RANGES: dict[str, tuple[int, int]] = {}  # noqa: RUF012 - set once per generated class


class DbcWarning(UserWarning):
    """A DBC file read as asked, with something to know: a message the bus map shadows, or
    a file read as cantools does with ``strict=False``."""


@dataclasses.dataclass(frozen=True)
class DbcEntry:
    """One DBC message a decoder knows.

    Attributes:
        message: The cantools message.
        cls: Its message class (a `DbcMessage` dataclass).
        build: Decodes a frame's data into an instance of ``cls``; raises what cantools
            raises for a frame it refuses.
        path: The DBC file it comes from.
    """

    message: Any
    cls: type[Any]
    build: Callable[[bytes], Any]
    path: str


class DbcDecoder:
    """Decode the frames whose CAN ID a DBC knows.

    Args:
        paths: DBC files; when two know the same CAN ID, the first one given wins.
        lax: Read a file cantools refuses strictly (overlapping signals, a signal past its
            message) as cantools does with ``strict=False``, with a `DbcWarning` saying
            what the strict reading found.

    Raises:
        SourceError: A file that cannot be read as a DBC (the message names it).
        MissingExtraError: cantools is not installed (the ``dbc`` extra).
    """

    def __init__(self, paths: Iterable[str | os.PathLike[str]], lax: bool = False) -> None:
        cantools = require("cantools", "dbc", "decoding frames with a DBC")
        self._entries: dict[tuple[int, bool], DbcEntry] = {}
        self.notes: list[str] = []
        """What the reading found that a user should know (each also a `DbcWarning`)."""
        taken: set[str] = set()
        for given in paths:
            path = os.fspath(given)
            database = _load(cantools, path, lax, self.notes)
            for message in database.messages:
                key = (message.frame_id, bool(message.is_extended_frame))
                if key not in self._entries:
                    try:
                        cls = _message_class(message, class_name(message.name, taken))
                    except ValueError as error:
                        raise SourceError(f"{path}: {error}") from None
                    self._entries[key] = DbcEntry(message, cls, _builder(message, cls), path)
        for note in self.notes:
            warnings.warn(note, DbcWarning, stacklevel=2)

    def knows(self, can_id: int, extended: bool) -> bool:
        """Whether a DBC describes this CAN ID."""
        return (can_id, extended) in self._entries

    def decode(self, can_id: int, extended: bool, data: bytes) -> Any:
        """The message of a frame whose CAN ID a DBC knows.

        Raises:
            KeyError: No DBC knows the CAN ID.
            ValueError: cantools cannot decode the frame (wrong length, bad multiplexer
                value); the message says why.
        """
        entry = self._entries[(can_id, extended)]
        try:
            return entry.build(data)
        except Exception as error:  # cantools' DecodeError and the struct errors it lets out
            raise ValueError(failure(entry.message, error)) from None

    def entries(self) -> dict[tuple[int, bool], DbcEntry]:
        """(CAN ID, extended) to its message, for every ID known."""
        return dict(self._entries)

    def record(self, record: Record) -> Record:
        """``record`` decoded if it is unknown traffic on a CAN ID a DBC knows, else as is."""
        if record.role is not _UNKNOWN or record.error is not None or record.message is not None:
            return record
        extended = record.extended
        if (record.can_id, extended) not in self._entries:
            return record
        try:
            message = self.decode(record.can_id, extended, record.data)
        except ValueError as error:
            return record._replace(error="decode error", detail=str(error))
        return dbc_record(record.timestamp, record.channel, record.can_id, message, record.data,
                          extended)  # fmt: skip

    def records(self, records: Iterable[Record]) -> Iterator[Record]:
        """`record` applied to each record."""
        decode = self.record
        for record in records:
            yield decode(record)


_UNKNOWN = Role.UNKNOWN


def _load(cantools: Any, path: str, lax: bool, notes: list[str]) -> Any:
    """The cantools database of one DBC file, strictly, or as ``strict=False`` reads it
    when ``lax`` (with a note of what the strict reading said)."""
    try:
        return cantools.database.load_file(path, database_format="dbc")
    except OSError as error:
        raise SourceError(f"{path}: {error.strerror or error}") from None
    except Exception as error:  # cantools raises its parser's errors as they come
        strict = _one_line(error)
    try:
        database = cantools.database.load_file(path, database_format="dbc", strict=False)
    except Exception:
        raise SourceError(f"{path}: not a DBC file cantools reads: {strict}") from None
    if not lax:
        raise SourceError(
            f"{path}: not a DBC file cantools reads strictly: {strict}; give --dbc-lax "
            "(BusMap(dbc_lax=True), [dbc] lax = true) to read it as cantools does with "
            "strict=False"
        )
    notes.append(f"{path}: read as cantools does with strict=False: {strict}")
    return database


def _one_line(error: Exception) -> str:
    return " ".join(str(error).split())


def failure(message: Any, error: Exception) -> str:
    """The detail of a frame cantools cannot decode."""
    return f"{message.name}: {error}"


def decoder_of(paths: Iterable[str | os.PathLike[str]], lax: bool = False) -> DbcDecoder:
    """The decoder of these DBC files, loaded once while the files stay as they are.

    Raises:
        SourceError: As `DbcDecoder` does.
    """
    key = []
    for path in paths:
        try:
            status = os.stat(path)
        except OSError:
            return DbcDecoder([path], lax)  # raises SourceError
        key.append((os.fspath(path), status.st_mtime_ns, status.st_size))
    return _cached(tuple(key), lax)


@functools.lru_cache(maxsize=16)
def _cached(key: tuple[tuple[str, int, int], ...], lax: bool) -> DbcDecoder:
    return DbcDecoder([path for path, _, _ in key], lax)


def shadowed(bus_map: BusMap) -> list[str]:
    """One line per DBC file of ``bus_map`` with messages the bus map decodes otherwise
    (a Veronte ID, or a 29-bit ID while DroneCAN is decoded): which IDs, which messages,
    and how to let the DBC win. Empty with ``dbc_first``.

    Raises:
        SourceError: As `DbcDecoder` does.
    """
    if not bus_map.dbc or bus_map.dbc_first:
        return []
    by_path: dict[str, list[str]] = {}
    for (can_id, extended), entry in decoder_of(bus_map.dbc, bus_map.dbc_lax).entries().items():
        role, _ = bus_map.role(can_id, extended)
        if role is not Role.UNKNOWN:
            owner = "DroneCAN" if role is Role.DRONECAN else f"the Veronte {role.value}"
            ident = f"{can_id:08X}" if extended else f"{can_id:03X}"
            by_path.setdefault(entry.path, []).append(f"{entry.message.name} ({ident}: {owner})")
    lines = []
    for path, found in by_path.items():
        listed = ", ".join(found[:_LISTED]) + (
            f" and {len(found) - _LISTED} more" if len(found) > _LISTED else ""
        )
        dronecan = "; or [dronecan] enabled = false" if "DroneCAN)" in " ".join(found) else ""
        lines.append(
            f"{path}: {len(found)} DBC message(s) on CAN IDs the bus map decodes otherwise, "
            f"not decoded by the DBC: {listed}; give --dbc-first (BusMap(dbc_first=True), "
            f"[dbc] first = true) to let the DBC decode them{dronecan}"
        )
    return lines


_LISTED = 5
"""Shadowed messages named in a report line; the rest are counted."""


def claimed(bus_map: BusMap) -> frozenset[tuple[int, bool]]:
    """(CAN ID, extended) of every message of the bus map's DBC files.

    Raises:
        SourceError: As `DbcDecoder` does.
    """
    return frozenset(decoder_of(bus_map.dbc, bus_map.dbc_lax).entries())


def identifier(name: str) -> str:
    """Step 1 of the naming rule: ``name`` as a Python identifier."""
    text = "".join(c if _keeps(c) else "_" for c in name)
    if unicodedata.normalize("NFKC", text) != text:  # characters that compose: ASCII only
        text = re.sub(r"[^A-Za-z0-9_]", "_", text)
    if not text[:1].isidentifier():
        text = "_" + text
    return _undunder(text)


def _undunder(text: str) -> str:
    """``text``, prefixed ``dbc`` if it starts with ``__`` (names Python treats apart in
    a class: mangled, or special)."""
    return "dbc" + text if text.startswith("__") else text


def _keeps(character: str) -> bool:
    return ("_" + character).isidentifier() and (
        unicodedata.normalize("NFKC", character) == character
    )


_CLASS_ATTRIBUTES = frozenset(name for name in vars(DbcMessage) if not name.startswith("__"))


def field_names(signals: Sequence[str], choices: Sequence[bool]) -> tuple[list[str], list[str]]:
    """The field names of a message's signals (by DBC name), and of the names of those with
    a value table (``choices``), by the naming rule.

    Returns:
        The field of each signal's number, and of each choice signal's name, in order.
    """
    taken: set[str] = set()
    numbers = [_unique(_reserved(identifier(s), RECORD_COLUMNS), taken) for s in signals]
    names = [
        _unique(identifier(signal + "_name"), taken)
        for signal, choice in zip(signals, choices, strict=True)
        if choice
    ]
    return numbers, names


def class_name(name: str, taken: set[str]) -> str:
    """The class (and table) name of a DBC message by the naming rule, against the
    casefolded names already ``taken`` (updated)."""
    return _unique(_reserved(identifier(name), reserved_names()), taken)


def _reserved(text: str, reserved: frozenset[str]) -> str:
    """Step 2: a trailing ``_`` for a keyword, a class attribute, or (ignoring case) one of
    ``reserved``."""
    folded = {name.casefold() for name in reserved}
    if keyword.iskeyword(text) or text in _CLASS_ATTRIBUTES or text.casefold() in folded:
        return text + "_"
    return text


def _unique(text: str, taken: set[str]) -> str:
    """Step 3: ``text``, or the first of ``text_2``, ``text_3``, ... not yet ``taken``
    (casefolded; updated)."""
    name, number = text, 1
    while name.casefold() in taken:
        number += 1
        name = _undunder(f"{text}_{number}")
    taken.add(name.casefold())
    return name


def _message_class(message: Any, name: str) -> type[Any]:
    """The dataclass of a DBC message, named ``name``."""
    signals = list(message.signals)
    numbers, names = field_names([s.name for s in signals], [bool(s.choices) for s in signals])
    name_of = iter(names)
    fields: list[tuple[str, Any]] = []
    dbc_names: list[str] = []
    units: dict[str, str] = {}
    ranges: dict[str, tuple[int, int]] = {}
    choices: dict[str, str] = {}
    for signal, attr in zip(signals, numbers, strict=True):
        if not integer_signal(signal):
            kind: Any = float
        else:
            kind = int
            ranges[attr] = _integer_range(signal, message.name)
        fields.append((attr, kind | None))
        dbc_names.append(signal.name)
        if signal.unit:
            units[attr] = signal.unit
        if signal.choices:
            choices[attr] = next(name_of)
            fields.append((choices[attr], str | None))
            dbc_names.append(signal.name)
    cls = dataclasses.make_dataclass(
        name,
        [(attr, kind, dataclasses.field(default=None)) for attr, kind in fields],
        bases=(DbcMessage,),
        namespace={
            "DBC_NAME": message.name,
            "SIGNALS": tuple(dbc_names),
            "UNITS": units,
            "CHOICES": choices,
            "RANGES": ranges,
            "__module__": __name__,
        },
        frozen=True,
        slots=True,
    )
    return cls


def _builder(message: Any, cls: type[Any]) -> Callable[[bytes], Any]:
    """The generated decoder of ``message`` into ``cls`` (a `_message_class`): a field per
    signal (None where the frame has no value for it, as for a multiplexed signal it does
    not carry), filled by slot stores (`veronte4x.codegen.slot_builder`).

    cantools decodes the raw values once (``scaling=False``), and each signal's own
    conversion gives its number and, for a value table, its name. A message whose
    multiplexer is scaled (cantools then picks the branch by the scaled value) is decoded
    scaled, its names by a second decode with ``decode_choices=True``. Names reach the
    source only as literals (``repr``) or checked identifiers.
    """
    from cantools.database.conversion import IdentityConversion
    from cantools.database.namedsignalvalue import NamedSignalValue

    raw = all(
        isinstance(s.conversion, IdentityConversion) or (s.scale == 1 and s.offset == 0)
        for s in message.signals
        if s.is_multiplexer
    )
    namespace: dict[str, Any] = {
        "_decode": message.decode,
        "_new": object.__new__,
        "_B": slot_builder(cls),
        "_cls": cls,
        "_str": str,
        "_Named": NamedSignalValue,
        "_named": functools.partial(_names, message.decode),
    }
    lines = ["def build(data):"]
    if raw:
        lines.append("    get = _decode(data, False, False).get")
    else:
        lines += ["    get = _decode(data, False, True).get", "    names = _named(data)"]
    lines.append("    made = _new(_B)")
    named = set(cls.CHOICES.values())
    numbers = [f.name for f in dataclasses.fields(cls) if f.name not in named]
    for position, (signal, number) in enumerate(zip(message.signals, numbers, strict=True)):
        name = cls.CHOICES.get(_safe(number))
        convert = f"_c{position}"
        namespace[convert] = signal.conversion.raw_to_scaled
        identity = isinstance(signal.conversion, IdentityConversion) or not raw
        lines.append(f"    v = get({signal.name!r})")
        if name is None:
            lines.append(
                f"    made.{number} = v"
                if identity
                else (f"    made.{number} = None if v is None else {convert}(v, False)")
            )
            continue
        _safe(name)
        lines += [
            "    if v is None:",
            f"        made.{number} = None",
            f"        made.{name} = None",
        ]
        lines.append("    else:")
        if raw:
            lines.append(f"        made.{number} = {convert}(v, False)")
            lines.append(f"        v = {convert}(v, True)")
        else:
            lines.append(f"        made.{number} = v")
            lines.append(f"        v = names.get({signal.name!r})")
        lines.append(f"        made.{name} = _str(v) if v.__class__ is _Named else None")
    lines += ["    made.__class__ = _cls", "    return made"]
    build: Callable[[bytes], Any] = compile_source(
        "\n".join(lines), namespace, f"DBC build {cls.__name__}"
    )["build"]
    return build


def _safe(name: str) -> str:
    """``name``, checked to be a plain identifier: the only DBC text that reaches generated
    source unquoted (a field name, made by the naming rule)."""
    if not name.isidentifier() or keyword.iskeyword(name):
        raise ValueError(f"{name!r} is not a field name")
    return name


def _names(decode: Callable[..., dict[str, Any]], data: bytes) -> dict[str, Any]:
    """The values cantools decodes with ``decode_choices=True``, or none if it refuses."""
    try:
        return decode(data, True, True)
    except Exception:  # the scaled decode already succeeded: its numbers stand
        return {}


def integer_signal(signal: Any) -> bool:
    """Whether cantools decodes the cantools ``signal`` to ints (its conversion keeps a raw
    int an int: integer scale and offset, or none), as its values' type says."""
    return not signal.is_float and isinstance(signal.conversion.raw_to_scaled(0, False), int)


def _integer_range(signal: Any, message: str) -> tuple[int, int]:
    """The lowest and highest value of an `integer_signal` of the message named
    ``message``.

    Raises:
        ValueError: Values of more than `MAX_DIGITS` digits.
    """
    half = 1 << (signal.length - 1)
    raw = (-half, half - 1) if signal.is_signed else (0, 2 * half - 1)
    ends = [signal.conversion.raw_to_scaled(value, False) for value in raw]
    if max(len(str(abs(end))) for end in ends) > MAX_DIGITS:
        raise ValueError(
            f"signal {signal.name} of {message}: its values have more than "
            f"{MAX_DIGITS} digits, more than a table column holds"
        )
    return min(ends), max(ends)


MAX_DIGITS = 76
"""The most decimal digits of an integer signal's values (Arrow's ``decimal256``)."""
