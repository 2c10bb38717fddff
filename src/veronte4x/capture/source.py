"""Where a capture comes from, decided once: candump text (plain, gzip or standard input) or a
format python-can reads.

Every reader of the package, per-frame and columnar, asks `resolve` and opens through it, so
that one rule decides how a source is read.
"""

from __future__ import annotations

import enum
import gzip
import io
import os
import sys
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from typing import IO

from veronte4x.capture.frames import BadLine, Frame

CANDUMP_SUFFIXES = (".log", ".txt", ".candump")
"""File names the native candump parser reads, gzipped (``.gz``) or not."""

STDIN = "-"
"""The path that stands for candump text on standard input."""


class Format(enum.Enum):
    """How a source is parsed."""

    CANDUMP = "candump"
    PYTHON_CAN = "python-can"


@dataclass(frozen=True, slots=True)
class Source:
    """A capture to read.

    Attributes:
        path: The file's path, or ``-`` for standard input.
        format: How it is parsed.
        gzipped: The file is gzip-compressed.
    """

    path: str
    format: Format
    gzipped: bool = False

    @property
    def is_stdin(self) -> bool:
        """The source is standard input."""
        return self.path == STDIN


def resolve(path: str | os.PathLike[str]) -> Source:
    """Decide how a capture is read from its path.

    candump text (``.log``, ``.txt``, ``.candump``, gzipped or not, or ``-`` for standard
    input) is parsed natively; every other format goes through python-can's ``LogReader``.
    """
    name = os.fspath(path)
    if name == STDIN:
        return Source(name, Format.CANDUMP)
    lower = name.lower()
    gzipped = lower.endswith(".gz")
    stem = lower[:-3] if gzipped else lower
    if stem.endswith(CANDUMP_SUFFIXES):
        return Source(name, Format.CANDUMP, gzipped)
    return Source(name, Format.PYTHON_CAN, gzipped)


@contextmanager
def open_text(source: Source) -> Iterator[IO[str]]:
    """Open candump text for reading as lines; bytes that are not UTF-8 are replaced."""
    if source.is_stdin:
        stream = io.TextIOWrapper(sys.stdin.buffer, encoding="utf-8", errors="replace")
        try:
            yield stream
        finally:
            stream.detach()
        return
    opener = gzip.open if source.gzipped else open
    with opener(source.path, "rt", encoding="utf-8", errors="replace") as lines:
        yield lines


def open_frames(
    path: str | os.PathLike[str], channel: str | None = None
) -> Iterator[Frame | BadLine]:
    """Stream the frames of a capture, whatever its format.

    Args:
        path: The capture file, or ``-`` for candump text on standard input.
        channel: Keep only frames of this interface (None keeps all).

    Raises:
        ImportError: The format needs python-can and it is not installed.
    """
    source = resolve(path)
    if source.format is Format.CANDUMP:
        return _candump_frames(source, channel)
    from veronte4x.capture.readers.pythoncan import read_with_python_can

    return read_with_python_can(source.path, channel)


def _candump_frames(source: Source, channel: str | None) -> Iterator[Frame | BadLine]:
    from veronte4x.capture.readers.candump import parse_candump

    with open_text(source) as lines:
        yield from parse_candump(lines, channel)
