"""Read every log format python-can knows (ASC, BLF, TRC, CSV, MF4, .gz) through can.LogReader.

Needs the ``can`` extra (``pip install "veronte4x[can]"``).
"""

from __future__ import annotations

import os
import zlib
from collections.abc import Iterator
from typing import Any

from veronte4x.capture.frames import BadLine, Frame, Truncation
from veronte4x.extras import require


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
    )


def read_with_python_can(
    path: str | os.PathLike[str], channel: str | None = None
) -> Iterator[Frame | BadLine]:
    """Stream a capture through ``can.LogReader``; a reader failure ends it with a `Truncation`.

    Raises:
        MissingExtraError: python-can is not installed (raised by the call).
    """
    can = require("can", "can", f"reading {os.fspath(path)}")
    return _read(can.LogReader(os.fspath(path)), channel)


def _read(reader: Any, channel: str | None) -> Iterator[Frame | BadLine]:
    count = 0
    try:
        for message in reader:
            count += 1
            frame = frame_from_message(message)
            if channel is None or frame.channel == channel:
                yield frame
    except (ValueError, IndexError, KeyError, OSError, EOFError, zlib.error) as error:
        # python-can's readers stop at the first line they cannot parse.
        yield Truncation(
            count + 1,
            "",
            f"python-can stopped reading at message {count + 1} ({error}): the rest of the "
            "file is not read",
        )
    finally:
        reader.stop()
