"""A live python-can bus as a stream of `Frame`, for the decoders that read captures.

Needs the ``can`` extra (``pip install "veronte4x[can]"``). The bus is opened by the caller
(`veronte4x.canbus.open_bus`); this adapter only turns what it receives into frames, and
counts the frames the bus layer dropped before they could be read (`BusLoss`): on Linux the
kernel counts, per socket, the frames it dropped for a full receive buffer, on the socket of
a SocketCAN bus (the count ``SO_RXQ_OVFL`` reports) as on a ``udp_multicast`` one.
python-can's interfaces keep no count of their own, and neither carries sequence numbers.
"""

from __future__ import annotations

import contextlib
import threading
import time
from collections.abc import Callable, Iterator
from typing import Any

from veronte4x.capture.frames import Frame
from veronte4x.capture.readers.pythoncan import frame_from_message
from veronte4x.errors import Veronte4xError
from veronte4x.sockets import frame_socket, kernel_drops
from veronte4x.words import counted


class BusFailedError(Veronte4xError, OSError):
    """The bus stopped working while it was read (python-can raised ``can.CanError``)."""


POLL = 0.1
"""Longest single wait on the bus, in seconds (how soon a duration ends on a quiet bus)."""
COUNT_EVERY = 1024
"""Frames read between two looks at the kernel's count of dropped frames (it is also read
whenever the bus is quiet, and when the reading ends)."""


class BusLoss:
    """The frames the bus layer dropped while `read_bus` read a bus, as far as it says.

    Attributes:
        frames: Frames the kernel dropped for a full receive buffer on the bus's socket
            since the reading began; updated as the reading goes (another thread may read
            it meanwhile).
        counted: The bus says what it drops (a SocketCAN or ``udp_multicast`` bus on
            Linux); else ``frames`` stays 0 and means nothing.
    """

    def __init__(self) -> None:
        self.frames = 0
        self.counted = False

    def text(self) -> str | None:
        """``N frames lost by the bus layer``; None when the bus does not count them."""
        return f"{counted(self.frames, 'frame')} lost by the bus layer" if self.counted else None


class _DropCount:
    """Keeps a `BusLoss` up to date from a bus's socket."""

    def __init__(self, bus: Any, loss: BusLoss | None) -> None:
        self.socket = frame_socket(bus) if loss is not None else None
        self.loss = loss
        self.start = None if self.socket is None else kernel_drops(self.socket)
        if loss is not None:
            loss.frames, loss.counted = 0, self.start is not None

    def update(self) -> None:
        if self.socket is None or self.start is None or self.loss is None:
            return
        now = kernel_drops(self.socket)
        if now is not None:
            self.loss.frames = (now - self.start) % (1 << 32)

    def close(self) -> None:
        self.update()
        if self.socket is not None:
            self.socket.close()


def read_bus(
    bus: Any,
    channel: str | None = None,
    duration: float | None = None,
    clock: Callable[[], float] = time.monotonic,
    stop: threading.Event | None = None,
    loss: BusLoss | None = None,
) -> Iterator[Frame]:
    """Yield the frames received on ``bus`` until ``duration`` seconds pass, Ctrl-C or
    ``stop`` is set.

    Args:
        bus: An open python-can bus.
        channel: Channel name put in frames that carry none (the ``virtual`` interface's).
        duration: Seconds of ``clock`` to read, or None for no limit.
        clock: Measures ``duration``.
        stop: Set by another thread to end the stream.
        loss: Kept up to date with the frames the bus layer dropped meanwhile.

    Raises:
        BusFailedError: python-can reported a bus failure.
    """
    import can

    end = None if duration is None else clock() + duration
    drops = _DropCount(bus, loss)
    read = 0
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
                drops.update()
                continue
            read += 1
            if read % COUNT_EVERY == 0:
                drops.update()
            frame = frame_from_message(message)
            if not frame.channel and channel:
                frame = frame._replace(channel=channel)
            yield frame
    except KeyboardInterrupt:
        return
    finally:
        with contextlib.suppress(OSError):
            drops.close()
