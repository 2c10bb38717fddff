"""The reader registry: one map from a log format to the functions that read it.

As python-can's ``MESSAGE_READERS``, `READERS` maps a format's name to its `Reader`: the
file suffixes it claims, how its content is recognised, and how it is read, frame by frame
(required) and column-wise (optional; the columnar engine falls back on the frames).
`veronte4x.capture.source.resolve` picks the reader of a path from it, and every entry point
reads through the reader it picks: `veronte4x.capture.read`,
`veronte4x.capture.open_frames`, `veronte4x.capture.read_tables`,
`veronte4x.capture.to_parquet` and the command line.

Adding a format is one module and one entry: a module with a ``frames(source)`` function
(and, for speed, column-wise ones), and a `register` call (the built-in formats are
registered at the end of this module). The functions are given as ``"module:name"`` so that
a format's dependencies (NumPy for the column-wise readers, python-can, asammdf) are
imported only when a file of it is read.
"""

from __future__ import annotations

import importlib
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
        sniff: ``sniff(head) -> bool``: whether the first `SNIFF_BYTES` of a file (gunzipped) are
            this format, for a file whose suffix no reader claims; None to claim files by
            suffix only.
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
"""Every format veronte4x reads, by name, in the order suffixes and contents are tried."""


def register(reader: Reader) -> Reader:
    """Add a format (or replace the one of the same name); returns it.

    Raises:
        ValueError: Another format claims one of its suffixes, or a second reader streams.
    """
    for other in READERS.values():
        if other.name == reader.name:
            continue
        taken = set(other.suffixes) & set(reader.suffixes)
        if taken:
            raise ValueError(f"{', '.join(sorted(taken))} already read as {other.name}")
        if other.streams and reader.streams:
            raise ValueError(f"standard input is already read as {other.name}")
    READERS[reader.name] = reader
    return reader


def unregister(name: str) -> None:
    """Remove a format (a test's toy format, say)."""
    READERS.pop(name, None)


def by_suffix(name: str) -> Reader | None:
    """The reader claiming a file name's suffix (``.gz`` aside), or None."""
    stem = name.lower().removesuffix(".gz")
    return next((r for r in READERS.values() if stem.endswith(r.suffixes)), None)


def by_content(head: bytes) -> Reader | None:
    """The first reader that recognises a file's first bytes, or None."""
    return next((r for r in READERS.values() if r.recognises(head)), None)


def sniffing() -> list[str]:
    """The names of the formats recognised by content, in the order they are tried."""
    return [r.name for r in READERS.values() if r.sniff is not None]


def streaming() -> Reader:
    """The reader of standard input and pipes."""
    return next(r for r in READERS.values() if r.streams)


def known_suffixes() -> str:
    """The suffixes of every format, for an error message: those of standard input's
    format first, then the others in alphabetical order."""
    first = streaming().suffixes
    rest = sorted(s for r in READERS.values() for s in r.suffixes if s not in first)
    return ", ".join((*first, *rest))


_CANDUMP = "veronte4x.capture.readers.candump"
_COLUMNS = "veronte4x.capture.columnar.sources"
_BATCHES = "veronte4x.capture.columnar.batches"
_PYTHON_CAN = "veronte4x.capture.readers.pythoncan"
_MF4 = "veronte4x.capture.columnar.mf4"

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
