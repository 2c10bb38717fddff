"""A live python-can bus as a stream of `Frame`, for the decoders that read captures.

Needs the ``can`` extra (``pip install "veronte4x[can]"``). The bus is opened by the caller
(`veronte4x.canbus.open_bus`); this adapter only turns what it receives into frames.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable, Iterator
from typing import Any

from veronte4x.capture.frames import Frame
from veronte4x.capture.readers.pythoncan import frame_from_message
from veronte4x.errors import Veronte4xError


class BusFailedError(Veronte4xError, OSError):
    """The bus stopped working while it was read (python-can raised ``can.CanError``)."""


POLL = 0.1
"""Longest single wait on the bus, in seconds (how soon a duration ends on a quiet bus)."""


def read_bus(
    bus: Any,
    channel: str | None = None,
    duration: float | None = None,
    clock: Callable[[], float] = time.monotonic,
    stop: threading.Event | None = None,
) -> Iterator[Frame]:
    """Yield the frames received on ``bus`` until ``duration`` seconds pass, Ctrl-C or
    ``stop`` is set.

    Args:
        bus: An open python-can bus.
        channel: Channel name put in frames that carry none (the ``virtual`` interface's).
        duration: Seconds of ``clock`` to read, or None for no limit.
        clock: Measures ``duration``.
        stop: Set by another thread to end the stream.

    Raises:
        BusFailedError: python-can reported a bus failure.
    """
    import can

    end = None if duration is None else clock() + duration
    try:
        while stop is None or not stop.is_set():
            wait = POLL
            if end is not None:
                wait = min(wait, end - clock())
                if wait <= 0:
                    return
            try:
                message = bus.recv(timeout=wait)
            except can.CanError as error:
                raise BusFailedError(f"the CAN bus failed: {error}") from None
            if message is None:
                continue
            frame = frame_from_message(message)
            if not frame.channel and channel:
                frame = frame._replace(channel=channel)
            yield frame
    except KeyboardInterrupt:
        return
