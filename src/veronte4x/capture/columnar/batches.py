"""Read a capture as consecutive batches of `FrameColumns`, in memory that does not grow
with the file: the streaming side of `veronte4x.capture.columnar.sources`.

The batches, joined, are the frames `sources.read_frames` gives for the whole file, with the
same positions: candump text is cut at line breaks into blocks parsed column-wise (lines
numbered as the per-frame reader numbers them, lone carriage returns included), and a gzip
file that ends early is read on line by line from where the blocks stopped, as
`read_frames` reads it. Formats python-can reads go message by message; MF4 is read whole
(asammdf reads its arrays at once) and then cut.
"""

from __future__ import annotations

import contextlib
import gzip
import io
import itertools
import os
import sys
import zlib
from collections.abc import Iterable, Iterator
from concurrent.futures import ThreadPoolExecutor, wait
from dataclasses import dataclass
from typing import BinaryIO

from veronte4x.capture.columnar.candump import parse_text
from veronte4x.capture.columnar.frames import FrameColumns, from_frames
from veronte4x.capture.columnar.sources import read_frames
from veronte4x.capture.frames import BadLine, Frame
from veronte4x.capture.readers.candump import parse_candump
from veronte4x.capture.source import Format, Source, Truncated, open_lines, resolve

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
    """

    frames: FrameColumns
    position: int | None


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
    if source.format is Format.CANDUMP:
        return _candump(source, batch_bytes, batch_frames)
    if source.path.lower().endswith(".mf4"):
        return _cut(read_frames(source.path), batch_frames)
    return _python_can(source.path, batch_frames)


def _python_can(path: str, batch_frames: int) -> Iterator[Batch]:
    """Opened on the first batch, so that one thread opens, reads and closes the file
    (python-can's SQLite reader works only in the thread that opened it)."""
    from veronte4x.capture.readers.pythoncan import read_with_python_can

    yield from _items(enumerate(read_with_python_can(path), 1), batch_frames)


def _candump(source: Source, batch_bytes: int, batch_frames: int) -> Iterator[Batch]:
    line = 1
    with _open_raw(source) as raw:
        stream: BinaryIO = gzip.GzipFile(fileobj=raw) if source.gzipped else raw  # type: ignore[assignment]
        try:
            for block in _blocks(stream, batch_bytes):
                frames = parse_text(block, line)
                if frames is None:  # lone carriage returns: the per-frame reader's lines
                    frames, count = _universal_lines(block, line)
                else:
                    count = block.count(b"\n") + (not block.endswith(b"\n"))
                line += count
                yield Batch(frames, _position(raw))
            return
        except (EOFError, gzip.BadGzipFile, zlib.error):
            pass  # a truncated gzip file: its last lines are the per-frame reader's call
    yield from _lines_from(source, line, batch_frames)


def _open_raw(source: Source) -> BinaryIO:
    if source.is_stdin:
        return open(sys.stdin.buffer.fileno(), "rb", closefd=False)
    return open(source.path, "rb")


def _position(raw: BinaryIO) -> int | None:
    try:
        return raw.tell()
    except OSError:  # a pipe
        return None


def _blocks(stream: BinaryIO, size: int) -> Iterator[bytes]:
    """Blocks of about ``size`` bytes that end at a line break (the last one may not)."""
    rest = b""
    while True:
        chunk = stream.read(size)
        if not chunk:
            if rest:
                yield rest
            return
        block = rest + chunk
        cut = block.rfind(b"\n")
        if cut < 0:
            rest = block
            continue
        rest = block[cut + 1 :]
        yield block[: cut + 1]


def _universal_lines(block: bytes, first_line: int) -> tuple[FrameColumns, int]:
    """A block parsed line by line, its lines split as the per-frame reader splits them."""
    lines = io.TextIOWrapper(io.BytesIO(block), encoding="utf-8", errors="replace")
    items: list[tuple[int, Frame | BadLine]] = []
    count = 0
    for count, text in enumerate(lines, 1):
        number = first_line + count - 1
        items += [(number, item) for item in parse_candump((text,), first_line=number)]
    return from_frames(items), count


def _lines_from(source: Source, first_line: int, batch_frames: int) -> Iterator[Batch]:
    """The lines from ``first_line`` on, through the per-frame reader, to where it stops."""
    items: list[tuple[int, Frame | BadLine]] = []
    with open_lines(source) as lines:
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


def _cut(frames: FrameColumns, batch_frames: int) -> Iterator[Batch]:
    from veronte4x.capture.columnar.stream import split

    sizes = [batch_frames] * (len(frames) // max(batch_frames, 1))
    for part in split(frames, sizes):
        yield Batch(part, None)


def ahead(batches: Iterator[Batch]) -> Iterator[Batch]:
    """The batches, each read on a thread while the one before it is decoded."""
    with ThreadPoolExecutor(1) as thread:
        try:
            coming = thread.submit(next, batches, None)
            while (batch := coming.result()) is not None:
                coming = thread.submit(next, batches, None)
                yield batch
        finally:
            coming.cancel()
            wait([coming])
            with contextlib.suppress(Exception):
                coming.result()
            close = getattr(batches, "close", None)
            if close is not None:  # in the thread that read them (see _python_can)
                thread.submit(close).result()
