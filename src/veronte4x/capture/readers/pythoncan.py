"""Read every log format python-can knows (ASC, BLF, TRC, CSV, MF4, .gz) through can.LogReader.

Needs the ``can`` extra (``pip install "veronte4x[can]"``).

A damaged file makes python-can's readers (and sqlite3 and asammdf under them) raise
whatever their parsers meet. Here that becomes a `SourceError` when the file gives no frame
at all, and a `Truncation` after the frames read before the damage otherwise.
"""

from __future__ import annotations

import gc
import logging
import os
import sys
from collections.abc import Iterator
from contextlib import contextmanager
from typing import TYPE_CHECKING, Any

from veronte4x.capture.frames import BadLine, Frame, Truncation
from veronte4x.errors import SourceError
from veronte4x.extras import require

if TYPE_CHECKING:
    from veronte4x.capture.source import Source

_NOT_DAMAGE = (ImportError, FileNotFoundError, PermissionError, IsADirectoryError)
"""Errors that say something other than a damaged file: passed on as they are."""


def frame_from_message(message: Any) -> Frame:
    """Turn a ``can.Message`` into a `Frame`."""
    channel = "" if message.channel is None else str(message.channel)
    return Frame(
        message.timestamp,
        channel,
        message.arbitration_id,
        bytes(message.data or b""),
        message.is_extended_id,
        message.is_remote_frame,
        message.is_fd,
        message.is_error_frame,
        message.bitrate_switch,
        message.error_state_indicator,
        message.dlc if message.is_remote_frame else 0,
    )


def frames(source: Source) -> Iterator[Frame | BadLine]:
    """The frames of a file python-can reads: the reader registry's ``frames``."""
    return read_with_python_can(source.path)


def read_with_python_can(
    path: str | os.PathLike[str], channel: str | None = None
) -> Iterator[Frame | BadLine]:
    """Stream a capture through ``can.LogReader``.

    The file is opened by the call. A reader failure after some frames ends the stream
    with a `Truncation`, as does a BLF file shorter than its header says.

    Raises:
        MissingExtraError: python-can is not installed, or for an MF4 file asammdf (the
            ``mf4`` extra brings both; raised by the call).
        SourceError: The file is damaged or not in the format of its suffix (raised by the
            call, or by the stream before its first frame).
        FileNotFoundError: The file does not exist.
    """
    name = os.fspath(path)
    if os.path.splitext(name.lower())[1] == ".mf4":  # python-can reads MF4 with asammdf
        can = require("can", "mf4", f"reading {name}")
        require("asammdf", "mf4", f"reading {name}")
    else:
        can = require("can", "can", f"reading {name}")
    with quiet_parsers():
        try:
            # ASC: times from the file's date (and triggerblock) line, as ASCReader gives
            # them with relative_timestamp=False; the other readers ignore the option.
            reader = can.LogReader(name, relative_timestamp=False)
            return _read(reader, name, channel)
        except _NOT_DAMAGE:
            raise
        except Exception as error:
            problem = damaged(name, error)
    collect_quietly()  # out here the parser's error, and what its traceback held, are gone
    raise problem


_KINDS = {".db": "SQLite (.db)"}


def damaged(path: str, error: BaseException) -> SourceError:
    """The `SourceError` of a file whose reader failed before its first frame."""
    suffix = os.path.splitext(path.lower().removesuffix(".gz"))[1]
    kind = _KINDS.get(suffix, suffix.lstrip(".").upper() or "capture")
    return SourceError(
        f"{path}: not a readable {kind} file ({_reason(error)}): the file is damaged or not "
        f"{kind}; export or copy it again"
    )


def _reason(error: BaseException) -> str:
    """The first line of an error's message, or its type's name when it has none."""
    text = str(error)
    return text.splitlines()[0] if text else type(error).__name__


def _read(reader: Any, path: str, channel: str | None) -> Iterator[Frame | BadLine]:
    count = 0
    try:
        try:
            for message in reader:
                count += 1
                frame = frame_from_message(message)
                if channel is None or frame.channel == channel:
                    yield frame
        except _NOT_DAMAGE:
            raise
        except Exception as error:
            reason: str | None = _reason(error)
            fatal = damaged(path, error) if count == 0 else None
        else:
            reason, fatal = None, None
        if fatal is not None:  # raised out here, without the parser's error as its context
            raise fatal
        size, declared = os.path.getsize(path), getattr(reader, "file_size", None)
        if reason is not None:
            yield Truncation(
                count + 1,
                "",
                f"{path}: python-can stopped reading at message {count + 1} "
                f"({reason}): the file is damaged there; the frames before were read",
            )
        elif isinstance(declared, int) and 0 < size < declared:  # BLF: its header's size
            yield Truncation(
                count + 1,
                "",
                f"{path}: the BLF file ends early, after message {count} ({size} of the "
                f"{declared} bytes its header gives): the file is truncated",
            )
    finally:
        reader.stop()


@contextmanager
def quiet_parsers() -> Iterator[None]:
    """Keep asammdf from logging the damage it meets meanwhile: the error raised says it."""
    logger = logging.getLogger("asammdf")
    disabled, logger.disabled = logger.disabled, True
    try:
        yield
    finally:
        logger.disabled = disabled


def collect_quietly() -> None:
    """Collect the half-built readers a parser left on a damaged file, silencing the errors
    they raise in ``__del__`` (asammdf's do, and sit in reference cycles), which Python
    would print as tracebacks."""
    hook = sys.unraisablehook
    sys.unraisablehook = _ignore
    try:
        gc.collect()
    finally:
        sys.unraisablehook = hook


def _ignore(_: Any) -> None:
    pass
