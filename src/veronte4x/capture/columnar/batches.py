"""Read a capture as consecutive batches of `FrameColumns`, in memory that does not grow
with the file: the streaming side of `veronte4x.capture.columnar.sources`.

The batches, joined, are the frames `sources.read_frames` gives for the whole file, with the
same positions. Each format is read by the ``batches`` of its reader in
`veronte4x.capture.readers.registry`, or its frames cut into batches: candump text is cut
at line breaks into blocks parsed column-wise here (lines numbered as the per-frame reader
numbers them, lone carriage returns included), and a gzip file that ends early is read on
line by line from where the blocks stopped, as `read_frames` reads it (gzip on standard
input or a pipe, which cannot be read twice, is kept compressed in memory for that); MF4 is
read in chunks of records (`veronte4x.capture.columnar.mf4`); other formats go frame by
frame.
"""

from __future__ import annotations

import contextlib
import gzip
import io
import itertools
import os
import sys
import zlib
from collections.abc import Callable, Iterable, Iterator
from concurrent.futures import ThreadPoolExecutor, wait
from dataclasses import dataclass
from typing import Any, BinaryIO, cast

from veronte4x.capture.columnar.candump import parse_block, read_blocks
from veronte4x.capture.columnar.frames import FrameColumns, from_frames
from veronte4x.capture.frames import BadLine, Frame
from veronte4x.capture.readers.candump import parse_candump
from veronte4x.capture.readers.registry import load
from veronte4x.capture.source import (
    STDIN,
    Source,
    Truncated,
    open_lines,
    resolve,
    until_truncated,
)

BATCH_BYTES = 1 << 22
"""Bytes of candump text decoded at once."""
BATCH_FRAMES = 1 << 18
"""Frames of other formats decoded at once."""


@dataclass
class Batch:
    """Frames of a capture, and how far into the file they reach.

    Attributes:
        frames: The frames and bad lines of the batch.
        position: Bytes of the file read so far (compressed bytes for gzip), or None where
            the reader does not tell.
        prepared: What `ahead`'s ``prepare`` made of the frames, if given one.
    """

    frames: FrameColumns
    position: int | None
    prepared: Any = None


Reread = Callable[[], Iterator[Batch]]
"""Reads a capture's batches from its start (see `rereadable`)."""


def read_batches(
    path: str | os.PathLike[str],
    batch_bytes: int = BATCH_BYTES,
    batch_frames: int = BATCH_FRAMES,
) -> Iterator[Batch]:
    """The frames of one capture file, batch by batch.

    Raises:
        ImportError: The format needs python-can (or asammdf) and it is not installed.
    """
    source = resolve(path)
    if source.reader.batches is not None:
        batches: Iterator[Batch] = load(source.reader.batches)(source, batch_bytes, batch_frames)
        return batches
    return _frames(source, batch_frames)


def rereadable(path: str | os.PathLike[str], batch_bytes: int = BATCH_BYTES) -> Reread:
    """What reads a capture's batches from its start each time it is called: `read_batches`
    of a file; of standard input or a pipe, which can be read once, the batches read so far
    (kept, so memory holds the whole capture) and then the rest.

    Raises:
        ImportError: The format needs python-can (or asammdf) and it is not installed.
    """
    name = os.fspath(path)
    if name != STDIN and os.path.isfile(name):
        return lambda: read_batches(name, batch_bytes)
    kept: list[Batch] = []
    rest = read_batches(name, batch_bytes)

    def again() -> Iterator[Batch]:
        yield from kept
        for batch in rest:
            kept.append(batch)  # before it is handed out: a pass stopped there reads it again
            yield batch

    return again


def _frames(source: Source, batch_frames: int) -> Iterator[Batch]:
    """The reader's frames, cut into batches. Opened on the first batch, so that one thread
    opens, reads and closes the file (python-can's SQLite reader works only in the thread
    that opened it)."""
    yield from _items(enumerate(source.reader.open_frames(source), 1), batch_frames)


def candump_batches(source: Source, batch_bytes: int, batch_frames: int) -> Iterator[Batch]:
    """candump text in blocks parsed column-wise, the reader registry's ``batches``."""
    line = 1
    with _open_raw(source) as opened:
        raw = opened
        if source.gzipped and (source.is_stdin or not os.path.isfile(source.path)):
            raw = io.BytesIO(opened.read())  # read once: where it ends early, read again below
        stream: BinaryIO = gzip.GzipFile(fileobj=raw) if source.gzipped else raw  # type: ignore[assignment]
        try:
            for block, size in read_blocks(stream, batch_bytes):
                frames, count = parse_block(block, size, line)
                if frames is None:  # lone carriage returns: the per-frame reader's lines
                    frames, count = _universal_lines(block[:size].tobytes(), line)
                line += count
                yield Batch(frames, _position(opened))
            return
        except (EOFError, gzip.BadGzipFile, zlib.error):
            pass  # a truncated gzip file: its last lines are the per-frame reader's call
    if isinstance(raw, io.BytesIO):
        raw.seek(0)
        unpacked = io.TextIOWrapper(gzip.GzipFile(fileobj=raw), encoding="utf-8", errors="replace")
        lines = contextlib.nullcontext(until_truncated(unpacked, source.path))
        yield from _lines_from(lines, line, batch_frames)
    else:
        yield from _lines_from(open_lines(source), line, batch_frames)


def _open_raw(source: Source) -> contextlib.AbstractContextManager[BinaryIO]:
    if source.is_stdin:  # its buffer, which holds the bytes `resolve` peeked at; not closed
        return contextlib.nullcontext(cast(BinaryIO, sys.stdin.buffer))
    return open(source.path, "rb")


def _position(raw: BinaryIO) -> int | None:
    try:
        return raw.tell()
    except OSError:  # a pipe
        return None


def _universal_lines(block: bytes, first_line: int) -> tuple[FrameColumns, int]:
    """A block parsed line by line, its lines split as the per-frame reader splits them."""
    lines = io.TextIOWrapper(io.BytesIO(block), encoding="utf-8", errors="replace")
    items: list[tuple[int, Frame | BadLine]] = []
    count = 0
    for count, text in enumerate(lines, 1):
        number = first_line + count - 1
        items += [(number, item) for item in parse_candump((text,), first_line=number)]
    return from_frames(items), count


def _lines_from(
    opened: contextlib.AbstractContextManager[Iterator[str]], first_line: int, batch_frames: int
) -> Iterator[Batch]:
    """The lines from ``first_line`` on, through the per-frame reader, to where it stops."""
    items: list[tuple[int, Frame | BadLine]] = []
    with opened as lines:
        try:
            for number, text in enumerate(lines, 1):
                if number < first_line:
                    continue
                items += [(number, item) for item in parse_candump((text,), first_line=number)]
                if len(items) >= batch_frames:
                    yield Batch(from_frames(items), None)
                    items = []
        except Truncated as cut:
            items.append((cut.line_number, cut.bad_line()))
    yield Batch(from_frames(items), None)


def _items(items: Iterable[tuple[int, Frame | BadLine]], batch_frames: int) -> Iterator[Batch]:
    iterator = iter(items)
    while chunk := list(itertools.islice(iterator, batch_frames)):
        yield Batch(from_frames(chunk), None)


def ahead(
    batches: Iterator[Batch], prepare: Callable[[FrameColumns], Any] | None = None
) -> Iterator[Batch]:
    """The batches, each read on a thread while the one before it is decoded (and, with
    ``prepare``, its ``prepared`` made there too: the second processor's share of the
    decoding, such as `StreamDecoder.prepare`)."""

    def read() -> Batch | None:
        batch = next(batches, None)
        if batch is not None and prepare is not None:
            batch.prepared = prepare(batch.frames)
        return batch

    with ThreadPoolExecutor(1) as thread:
        coming = thread.submit(read)  # before the try: a Ctrl-C here has nothing to cancel
        try:
            while (batch := coming.result()) is not None:
                coming = thread.submit(read)
                yield batch
        finally:
            coming.cancel()
            wait([coming])
            with contextlib.suppress(Exception):
                coming.result()
            close = getattr(batches, "close", None)
            if close is not None:  # in the thread that read them (see _frames)
                thread.submit(close).result()
