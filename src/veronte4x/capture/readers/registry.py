"""The reader registry: one map from a log format to the functions that read it.

As python-can's ``MESSAGE_READERS``, `READERS` maps a format's name to its `Reader`: the
file suffixes it claims, how its content is recognised, and how it is read, frame by frame
(required) and column-wise (optional; the columnar engine falls back on the frames).
`veronte4x.capture.source.resolve` picks the reader of a path with `pick`, and every entry
point reads through the reader it picks: `veronte4x.capture.read`,
`veronte4x.capture.open_frames`, `veronte4x.capture.read_tables`,
`veronte4x.capture.to_parquet` and the command line.

Several formats may claim one suffix (``.csv`` is python-can's CSV and SavvyCAN's GVRET
CSV): the content settles it. Each claimant offers a ``sniff`` of a file's first bytes and
the first that recognises them reads the file; at most one claimant of a suffix has no
sniff, and it reads the files that no other claimant recognises.

Adding a format is one module and one entry: a module with a ``frames(source)`` function
(and, for speed, column-wise ones), and a `register` call (the built-in formats are
registered at the end of this module), or, from another package, a `Reader` named in the
entry point group ``veronte4x.readers`` (`ENTRY_POINT_GROUP`), as python-can's
``can.io.message_reader``. The functions are given as ``"module:name"`` so that a format's
dependencies (NumPy for the column-wise readers, python-can, asammdf) are imported only when
a file of it is read.
"""

from __future__ import annotations

import importlib
import warnings
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from veronte4x.capture.decoder import CaptureDecoder
    from veronte4x.capture.frames import BadLine, Frame
    from veronte4x.capture.records import Record
    from veronte4x.capture.source import Source

Function = Callable[..., Any] | str
"""A reader's function, or its ``"module:name"`` (imported on first use)."""


@dataclass(frozen=True)
class Reader:
    """How one log format is read.

    Attributes:
        name: The format's name, its key in `READERS` (``candump``, ``mf4``, ...).
        suffixes: The lower-case file suffixes it claims (``.log``), each also with ``.gz``.
        frames: ``frames(source) -> Iterator[Frame | BadLine]``, the frames of a
            `veronte4x.capture.source.Source` in capture order (a `Truncation` last where
            the file ends early). Every entry point can read the format through it alone.
        records: ``records(source, decoder, channel) -> Iterator[Record]``: a faster path
            to the records of `veronte4x.capture.read`, or None to decode ``frames``.
        columns: ``columns(source) -> FrameColumns``: the whole file's frames as columns,
            or None to buffer ``frames`` into columns.
        batches: ``batches(source, batch_bytes, batch_frames) -> Iterator[Batch]``: the
            file's frames as consecutive batches of columns, in bounded memory, or None to
            cut ``frames`` into batches.
        sniff: ``sniff(head) -> bool``: whether the first `SNIFF_BYTES` of a file (gunzipped)
            are this format: asked for a file whose suffix it shares with other formats, or
            that no format's suffix settles. Cheap: it looks at the bytes given, no more.
            None to claim files by suffix only (one such claimant per suffix).
        streams: Reads standard input (``-``) and pipes (one reader does: candump text).
    """

    name: str
    suffixes: tuple[str, ...]
    frames: Function
    records: Function | None = None
    columns: Function | None = None
    batches: Function | None = None
    sniff: Function | None = None
    streams: bool = False

    def open_frames(self, source: Source, channel: str | None = None) -> Iterator[Frame | BadLine]:
        """The frames of ``source`` (only ``channel``'s if given) and its bad lines."""
        frames: Iterator[Frame | BadLine] = load(self.frames)(source)
        return frames if channel is None else _only(frames, channel)

    def read_records(
        self, source: Source, decoder: CaptureDecoder, channel: str | None = None
    ) -> Iterator[Record]:
        """The records of ``source`` through ``decoder``: those of `open_frames`, decoded."""
        if self.records is not None:
            records: Iterator[Record] = load(self.records)(source, decoder, channel)
            return records
        return decoder.decode(self.open_frames(source, channel))

    def recognises(self, head: bytes) -> bool:
        """Whether ``head``, the first bytes of a file, are in this format."""
        return self.sniff is not None and bool(load(self.sniff)(head))


def _only(frames: Iterator[Frame | BadLine], channel: str) -> Iterator[Frame | BadLine]:
    from veronte4x.capture.frames import Frame

    for item in frames:
        if type(item) is not Frame or item.channel == channel:  # bad lines are kept
            yield item


def load(function: Function) -> Callable[..., Any]:
    """A reader's function, imported if given as ``"module:name"``."""
    if not isinstance(function, str):
        return function
    module, _, name = function.partition(":")
    loaded: Callable[..., Any] = getattr(importlib.import_module(module), name)
    return loaded


SNIFF_BYTES = 4096
"""Bytes of a file's start a ``sniff`` function is given (fewer if the file is shorter)."""

READERS: dict[str, Reader] = {}
"""Every format veronte4x reads, by name, in the order suffixes and contents are tried (the
built-in formats first, then those registered, then those of the entry point group)."""

ENTRY_POINT_GROUP = "veronte4x.readers"
"""The entry point group of readers from other packages: each entry point names a `Reader`
(``module:attribute``), the entry point's name being the format's."""


def register(reader: Reader) -> Reader:
    """Add a format (or replace the one of the same name); returns it.

    Raises:
        ValueError: It shares a suffix with a format and neither has a ``sniff`` (nothing
            would tell their files apart), or a second reader streams.
    """
    for other in READERS.values():
        if other.name == reader.name:
            continue
        taken = set(other.suffixes) & set(reader.suffixes)
        if taken and other.sniff is None and reader.sniff is None:
            raise ValueError(
                f"{', '.join(sorted(taken))} already read as {other.name}: a second format of "
                "a suffix needs a sniff, to tell its files by content"
            )
        if other.streams and reader.streams:
            raise ValueError(f"standard input is already read as {other.name}")
    READERS[reader.name] = reader
    return reader


def unregister(name: str) -> None:
    """Remove a format (a test's toy format, say)."""
    READERS.pop(name, None)


def claimants(name: str) -> list[Reader]:
    """The readers claiming a file name's suffix (``.gz`` aside), in the order they are tried."""
    _load_entry_points()
    return _registered_claimants(name)


def _registered_claimants(name: str) -> list[Reader]:
    """`claimants` among the formats registered so far (the entry points not scanned)."""
    stem = name.lower().removesuffix(".gz")
    return [r for r in READERS.values() if r.suffixes and stem.endswith(r.suffixes)]


def pick(name: str, head: bytes | None) -> Reader | None:
    """The reader of a file from its name and first bytes (gunzipped), or None.

    The claimants of its suffix that sniff are asked first, in order; then the claimant
    that does not sniff reads it. Where every claimant sniffs and none recognises it, or no
    format claims the suffix, the first format that recognises its content reads it (a
    candump file saved as ``flight.bin``); failing that, the suffix's first claimant, whose
    reader says what is wrong with the file.

    Args:
        name: The file's name.
        head: Its first `SNIFF_BYTES` (fewer if it is shorter), or None where the content
            cannot be looked at ahead of reading (a pipe, a missing file): then the
            suffix alone decides.
    """
    if head is not None:
        # The entry points' formats come after those registered (the built-in ones): where
        # one of these claims the suffix and recognises the content, it is the answer, and
        # the installed packages are not scanned (importlib.metadata costs a command ~20 ms).
        known = next((r for r in _registered_claimants(name) if r.recognises(head)), None)
        if known is not None:
            return known
    claiming = claimants(name)
    fallback = next((r for r in claiming if r.sniff is None), None)
    if head is None:
        return fallback or next(iter(claiming), None)
    sniffed = next((r for r in claiming if r.recognises(head)), None)
    return sniffed or fallback or by_content(head) or next(iter(claiming), None)


def by_content(head: bytes) -> Reader | None:
    """The first reader that recognises a file's first bytes, or None."""
    _load_entry_points()
    return next((r for r in READERS.values() if r.recognises(head)), None)


def sniffing() -> list[str]:
    """The names of the formats recognised by content, in the order they are tried."""
    _load_entry_points()
    return [r.name for r in READERS.values() if r.sniff is not None]


def streaming() -> Reader:
    """The reader of standard input and pipes."""
    _load_entry_points()
    return next(r for r in READERS.values() if r.streams)


def known_suffixes() -> str:
    """The suffixes of every format, for an error message: those of standard input's
    format first, then the others in alphabetical order, each once."""
    first = streaming().suffixes
    rest = sorted({s for r in READERS.values() for s in r.suffixes if s not in first})
    return ", ".join((*first, *rest))


_entry_points_loaded = False


def _load_entry_points() -> None:
    """Register the readers of the entry point group, once, on the first question asked of
    the registry (so that importing veronte4x scans no installed package).

    A format of the same name as one already registered keeps the registered one (as
    python-can keeps its own readers); an entry point that cannot be loaded, or that names
    no `Reader`, is left out with a warning that names it, so that one broken package does
    not stop every other format being read.
    """
    global _entry_points_loaded
    if _entry_points_loaded:
        return
    _entry_points_loaded = True
    from importlib.metadata import entry_points

    for point in entry_points(group=ENTRY_POINT_GROUP):
        if point.name in READERS:
            continue
        try:
            reader = point.load()
            if not isinstance(reader, Reader) or reader.name != point.name:
                raise TypeError(f"{point.value} is no Reader named {point.name!r}")
            register(reader)
        except Exception as error:  # any failure of another package's code
            warnings.warn(
                f"veronte4x: the reader {point.name!r} of the entry point group "
                f"{ENTRY_POINT_GROUP} is left out: {error}; fix or uninstall its package",
                RuntimeWarning,
                stacklevel=2,
            )


_CANDUMP = "veronte4x.capture.readers.candump"
_COLUMNS = "veronte4x.capture.columnar.sources"
_BATCHES = "veronte4x.capture.columnar.batches"
_PYTHON_CAN = "veronte4x.capture.readers.pythoncan"
_MF4 = "veronte4x.capture.columnar.mf4"
_GVRET = "veronte4x.capture.readers.gvret"
_DATAFLASH = "veronte4x.capture.readers.dataflash"
_PYDRONECAN = "veronte4x.capture.readers.pydronecan"

register(
    Reader(
        "candump",
        (".log", ".txt", ".candump"),
        frames=f"{_CANDUMP}:frames",
        records=f"{_CANDUMP}:records",
        columns=f"{_COLUMNS}:candump_columns",
        batches=f"{_BATCHES}:candump_batches",
        sniff=f"{_CANDUMP}:sniff",
        streams=True,
    )
)
register(Reader("python-can", (".asc", ".blf", ".csv", ".db", ".trc"), f"{_PYTHON_CAN}:frames"))
register(
    Reader(
        "mf4",
        (".mf4",),
        frames=f"{_PYTHON_CAN}:frames",
        columns=f"{_MF4}:columns",
        batches=f"{_MF4}:batches",
    )
)
register(Reader("gvret", (".csv",), f"{_GVRET}:frames", sniff=f"{_GVRET}:sniff"))
register(Reader("dataflash", (".bin",), f"{_DATAFLASH}:frames", sniff=f"{_DATAFLASH}:sniff"))
register(Reader("pydronecan", (), f"{_PYDRONECAN}:frames", sniff=f"{_PYDRONECAN}:sniff"))
