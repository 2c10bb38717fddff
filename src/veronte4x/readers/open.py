"""Open any capture as a stream of frames: candump text natively, the rest through python-can."""

from __future__ import annotations

from collections.abc import Iterator

from veronte4x.frames import BadLine, Frame
from veronte4x.readers.candump import read_candump

CANDUMP_SUFFIXES = (".log", ".txt", ".candump", ".log.gz", ".txt.gz", ".candump.gz")
"""File names the native candump parser reads; ``-`` (standard input) is candump too."""


def open_frames(path: str, channel: str | None = None) -> Iterator[Frame | BadLine]:
    """Stream the frames of a capture file.

    candump text (``.log``, ``.txt``, ``.candump``, gzipped or not, or ``-`` for standard
    input) goes through the native parser. Every other format python-can reads (ASC, BLF,
    TRC, CSV, MF4, ...) goes through ``can.LogReader``, which needs the ``can`` extra.

    Args:
        path: The capture file, or ``-`` for candump text on standard input.
        channel: Keep only frames of this interface (None keeps all).

    Raises:
        ImportError: The format needs python-can and it is not installed.
    """
    if path == "-" or path.lower().endswith(CANDUMP_SUFFIXES):
        return read_candump(path, channel)
    from veronte4x.readers.pythoncan import read_with_python_can

    return read_with_python_can(path, channel)
