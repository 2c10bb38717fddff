"""Open any capture as `FrameColumns`: the columnar side of `veronte4x.capture.source`.

Each format is read by its reader in `veronte4x.capture.readers.registry`: candump text
(files, gzip, standard input, gzip on standard input) is parsed column-wise here; MF4 bus
logging is read in chunks through asammdf (`veronte4x.capture.columnar.mf4`); every other
format (BLF, ASC, TRC, CSV, SQLite, and any format registered) is read frame by frame and
buffered into columns. Each gives the frames the per-frame readers give, in the same order.
"""

from __future__ import annotations

import gzip
import io
import os
import sys
import zlib
from collections.abc import Callable, Iterable
from typing import BinaryIO, cast

from veronte4x.capture.columnar.candump import parse_stream, parse_text
from veronte4x.capture.columnar.frames import FrameColumns, from_frames
from veronte4x.capture.frames import BadLine, Frame
from veronte4x.capture.readers.candump import parse_candump
from veronte4x.capture.readers.registry import load
from veronte4x.capture.source import Source, Truncated, resolve, until_truncated


def read_frames(path: str | os.PathLike[str]) -> FrameColumns:
    """The frames of one capture, as columns: its reader's ``columns``, or its frames
    buffered into columns (see `veronte4x.capture.readers.registry`).

    Raises:
        ImportError: The format needs python-can (or asammdf) and it is not installed.
    """
    source = resolve(path)
    reader = source.reader
    if reader.columns is not None:
        columns: FrameColumns = load(reader.columns)(source)
        return columns
    return from_frames(list(enumerate(reader.open_frames(source), 1)))


def candump_columns(source: Source) -> FrameColumns:
    """candump text parsed column-wise, the reader registry's ``columns`` for candump."""
    if source.is_stdin:
        text = sys.stdin.buffer.read()  # standard input cannot be read twice: held whole
        if source.gzipped:
            return _candump(source, lambda: io.BytesIO(text))
        columns = parse_text(text)
        if columns is not None:
            return columns
        return _line_by_line(io.TextIOWrapper(io.BytesIO(text), "utf-8", "replace"), "-")
    return _candump(source, lambda: open(source.path, "rb"))


def _candump(source: Source, raw: Callable[[], BinaryIO]) -> FrameColumns:
    """Gzip-compressed or plain candump text from the file ``raw`` opens."""
    try:
        with raw() as file:
            stream = cast(BinaryIO, gzip.GzipFile(fileobj=file)) if source.gzipped else file
            columns = parse_stream(stream)
    except (EOFError, gzip.BadGzipFile, zlib.error):
        columns = None  # a truncated gzip file: where it ends is the per-frame reader's call
    if columns is not None:
        return columns
    with raw() as file:
        if source.gzipped:
            file = cast(BinaryIO, gzip.GzipFile(fileobj=file))
        text = io.TextIOWrapper(file, "utf-8", "replace")
        lines = until_truncated(text, source.path) if source.gzipped else text
        return _line_by_line(lines, source.path)


def _line_by_line(lines: Iterable[str], path: str) -> FrameColumns:
    """Text the column parser does not read as the per-frame reader does (lone carriage
    returns, a truncated gzip file): parse it line by line, with that reader's lines."""
    items: list[tuple[int, Frame | BadLine]] = []
    try:
        for number, line in enumerate(lines, 1):
            items += [(number, item) for item in parse_candump((line,), first_line=number)]
    except Truncated as cut:
        items.append((cut.line_number, cut.bad_line()))
    return from_frames(items)
