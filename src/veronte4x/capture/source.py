"""Where a capture comes from, decided once: which format's reader reads it (see
`veronte4x.capture.readers.registry`), and how candump text is opened (plain, gzip or
standard input).

Every entry point of the package, per-frame and columnar, asks `resolve` and reads through
the reader it picks, so that one rule decides how a source is read: by suffix where the
suffix says it, by content otherwise (a candump file saved as ``flight`` or ``flight.bin``
is still candump), and with a `SourceError` naming the path for a directory or a file in no
format veronte4x knows.
"""

from __future__ import annotations

import gzip
import io
import os
import sys
import zlib
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from typing import IO, BinaryIO, cast

from veronte4x.capture.frames import BadLine, Frame, Truncation
from veronte4x.capture.readers import registry
from veronte4x.capture.readers.registry import Reader
from veronte4x.errors import SourceError

_GZIP_MAGIC = b"\x1f\x8b"

STDIN = "-"
"""The path that stands for candump text on standard input."""


@dataclass(frozen=True, slots=True)
class Source:
    """A capture to read.

    Attributes:
        path: The file's path, or ``-`` for standard input.
        reader: The format's reader, from `veronte4x.capture.readers.registry.READERS`.
        gzipped: The file is gzip-compressed.
    """

    path: str
    reader: Reader
    gzipped: bool = False

    @property
    def format(self) -> str:
        """The format's name (``candump``, ``python-can``, ``mf4``, ...)."""
        return self.reader.name

    @property
    def is_stdin(self) -> bool:
        """The source is standard input."""
        return self.path == STDIN


def resolve(path: str | os.PathLike[str]) -> Source:
    """Decide how a capture is read from its path and its content.

    The format whose reader claims the suffix (``.gz`` aside) reads it: candump text
    (``.log``, ``.txt``, ``.candump``) natively; ``.asc``, ``.blf``, ``.csv``, ``.db``,
    ``.mf4`` and ``.trc`` through python-can (MF4 column-wise through asammdf); see
    `veronte4x.capture.readers.registry`. Where several formats claim the suffix
    (``.csv``: python-can's CSV and SavvyCAN's GVRET CSV), the first bytes of the file
    (gunzipped if they are gzip's) settle it, as `registry.pick` says. A file with any other
    suffix, or none, is read by the first format that recognises its first bytes; standard
    input (``-``) and a pipe are read as candump text, the one format that streams. Gzip is
    recognised by the file's first bytes, whatever its name.

    Raises:
        SourceError: The path is a directory, or a file in no format veronte4x knows.
        FileNotFoundError: The file does not exist.
    """
    name = os.fspath(path)
    if name == STDIN:
        return Source(name, registry.streaming(), _stdin_is_gzip())
    if os.path.isdir(name):
        raise SourceError(f"{name} is a directory: give a capture file")
    if not os.path.isfile(name):
        # A pipe (/dev/stdin, <(candump -L can0)) cannot be read twice: it is read by its
        # suffix's format, or the format that streams. A missing file fails when opened.
        gzipped = name.lower().endswith(".gz")
        return Source(name, registry.pick(name, None) or registry.streaming(), gzipped)
    with open(name, "rb") as file:
        head = file.read(registry.SNIFF_BYTES)
    gzipped = head.startswith(_GZIP_MAGIC) or (not head and name.lower().endswith(".gz"))
    reader = registry.pick(name, _gunzip_head(name) if gzipped else head)
    if reader is not None:
        return Source(name, reader, gzipped)
    raise SourceError(_unknown(name, gzipped, empty=not head))


def _unknown(name: str, gzipped: bool, empty: bool) -> str:
    """The error of a file no reader claims: what was tried and what to do, in one line."""
    if empty:
        return f"{name} is empty: give a capture file"
    tried = " or ".join(registry.sniffing()) or "any format (none is recognised by content)"
    content = "its gunzipped content" if gzipped else "its content"
    return (
        f"{name}: in no format veronte4x knows: {content} is not {tried}, and its suffix is "
        f"none of {registry.known_suffixes()}; rename it to the suffix of its format, or "
        "convert it to candump text"
    )


def _stdin_is_gzip() -> bool:
    """Whether standard input starts with gzip's magic bytes, looked at without reading
    them (waits for the first bytes of a pipe)."""
    peek = getattr(sys.stdin.buffer, "peek", None) if sys.stdin is not None else None
    return peek is not None and peek(len(_GZIP_MAGIC))[: len(_GZIP_MAGIC)] == _GZIP_MAGIC


def _gunzip_head(name: str) -> bytes:
    """The first bytes of a gzip file's content, as many as a truncated file has."""
    out = b""
    try:
        with gzip.open(name, "rb") as file:
            while len(out) < registry.SNIFF_BYTES:
                chunk = file.read1(registry.SNIFF_BYTES - len(out))
                if not chunk:
                    break
                out += chunk
    except (EOFError, OSError, zlib.error):
        pass
    return out


class Truncated(SourceError):
    """Compressed input that ends early: the frames before the cut were read.

    Attributes:
        line_number: The line at which the input ends.
    """

    def __init__(self, path: str, line_number: int) -> None:
        self.path = path
        self.line_number = line_number
        where = "standard input" if path == STDIN else path
        super().__init__(
            f"{where}: the gzip data ends early, at line {line_number}: the file is truncated"
        )

    def bad_line(self) -> Truncation:
        """The `Truncation` that stands for the cut, so that a reader counts it and stops."""
        return Truncation(self.line_number, "", str(self))


@contextmanager
def open_text(source: Source) -> Iterator[IO[str]]:
    """Open candump text for reading; bytes that are not UTF-8 are replaced.

    Reading gzip text that ends early raises ``EOFError`` (or ``gzip.BadGzipFile``);
    `open_lines` turns that into `Truncated`.
    """
    if source.is_stdin:
        binary: IO[bytes] = sys.stdin.buffer
        if source.gzipped:
            binary = cast(IO[bytes], gzip.GzipFile(fileobj=binary, mode="rb"))
        stream = io.TextIOWrapper(binary, encoding="utf-8", errors="replace")
        try:
            yield stream
        finally:
            stream.detach()
        return
    opener = gzip.open if source.gzipped else open
    with opener(source.path, "rt", encoding="utf-8", errors="replace") as text:
        yield text


@contextmanager
def open_binary(source: Source) -> Iterator[BinaryIO]:
    """Open candump text as bytes (gzip decompressed); standard input is not closed."""
    if source.is_stdin and source.gzipped:
        yield cast(BinaryIO, gzip.GzipFile(fileobj=sys.stdin.buffer, mode="rb"))
    elif source.is_stdin:
        yield sys.stdin.buffer
    elif source.gzipped:
        with gzip.open(source.path, "rb") as stream:
            yield cast(BinaryIO, stream)
    else:
        with open(source.path, "rb") as stream:
            yield stream


def read_chunks(source: Source, size: int = 1 << 16) -> Iterator[bytes]:
    """The bytes of candump text as they come, at most ``size`` at a time.

    A read returns what is there without waiting for ``size`` bytes, so that the lines of a
    live pipe come through as they are written. Gzip data that ends early raises
    `Truncated` after the last bytes it held (its line number counts line feeds).
    """
    line_feeds = 0
    with open_binary(source) as stream:
        try:
            read = cast(io.BufferedIOBase, stream).read1
            while chunk := read(size):
                line_feeds += chunk.count(b"\n")
                yield chunk
        except (EOFError, gzip.BadGzipFile, zlib.error):
            raise Truncated(source.path, line_feeds + 1) from None


@contextmanager
def open_lines(source: Source) -> Iterator[Iterator[str]]:
    """Open candump text as lines; gzip text that ends early raises `Truncated` after its
    last whole line."""
    with open_text(source) as text:
        yield until_truncated(text, source.path) if source.gzipped else text


def until_truncated(lines: IO[str], path: str) -> Iterator[str]:
    """The lines of gzip text; `Truncated` after the last whole one where the data ends early."""
    number = 0
    try:
        for number, line in enumerate(lines, 1):  # noqa: B007 - the count is read after
            yield line
    except (EOFError, gzip.BadGzipFile, zlib.error):
        raise Truncated(path, number + 1) from None


def open_frames(
    path: str | os.PathLike[str], channel: str | None = None
) -> Iterator[Frame | BadLine]:
    """Stream the frames of a capture, whatever its format.

    Args:
        path: The capture file, or ``-`` for candump text on standard input.
        channel: Keep only frames of this interface (None keeps all).

    Raises:
        SourceError: The path is a directory or a file in no format veronte4x knows.
        MissingExtraError: The format needs python-can and it is not installed.
    """
    source = resolve(path)
    return source.reader.open_frames(source, channel)
