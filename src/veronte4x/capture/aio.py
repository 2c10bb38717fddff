"""Live decoding for asyncio programs: ``async for record in capture.stream(bus)``.

Frames come through python-can's asyncio support (a ``can.Notifier`` bound to the running
loop feeding a ``can.AsyncBufferedReader``) and go through the same `CaptureDecoder` as
`veronte4x.capture.read` gives the frames of a python-can log: the records are those
`read` would give for a log of the same messages. Needs the ``can`` extra. asyncio is
imported by the calls, so that importing `veronte4x.capture` does not import it.
"""

from __future__ import annotations

import os
import time
from collections.abc import AsyncIterator, Callable, Iterable
from typing import Any

from veronte4x.capture.busmap import BusMap
from veronte4x.capture.dbc_in import DbcDecoder
from veronte4x.capture.decoder import CaptureDecoder
from veronte4x.capture.frames import Frame
from veronte4x.capture.readers.live import BusFailedError
from veronte4x.capture.readers.pythoncan import frame_from_message
from veronte4x.capture.records import Record
from veronte4x.extras import require

__all__ = ["stream"]


def stream(
    bus: Any,
    bus_map: BusMap | None = None,
    channel: str | None = None,
    dbc: Iterable[str | os.PathLike[str]] = (),
    *,
    duration: float | None = None,
    clock: Callable[[], float] = time.monotonic,
) -> AsyncIterator[Record]:
    """The decoded records of the frames a python-can bus receives, as they come.

    Use it with ``async for`` on a running event loop; leaving the loop (``break``, an
    exception, a cancellation) or `duration` ending stops receiving and closes the stream.

    Args:
        bus: An open python-can bus (the caller opens and shuts it).
        bus_map: CAN IDs and codec choices; defaults to Embention's template IDs.
        channel: Keep only this interface's frames (as `veronte4x.capture.read`).
        dbc: DBC files for the frames outside the bus map (see `veronte4x.capture.read`).
        duration: Seconds of ``clock`` to receive, or None for no limit.
        clock: Measures ``duration``.

    Raises:
        SourceError: A DBC file cantools cannot read (raised by the call).
        MissingExtraError: python-can (or cantools for ``dbc``) is not installed.
        BusFailedError: python-can reported a bus failure (raised by the iteration).

    Examples:
        >>> import asyncio, can
        >>> from veronte4x import capture
        >>> async def first(bus: can.BusABC) -> list[str]:
        ...     return [type(r.message).__name__ async for r in capture.stream(bus, duration=0.2)]
        >>> with can.Bus(interface="virtual", channel="doc-stream") as bus, can.Bus(
        ...     interface="virtual", channel="doc-stream"
        ... ) as other:
        ...     other.send(can.Message(arbitration_id=0x008, data=b"\\x01\\x09\\x06\\x0c",
        ...                            is_extended_id=False))
        ...     asyncio.run(first(bus))
        ['VersionResponse']
    """
    require("can", "can", "live decoding")
    decoder = CaptureDecoder(bus_map)
    by_dbc = DbcDecoder(list(dbc)) if dbc else None
    return _records(bus, decoder, by_dbc, channel, duration, clock)


class _Inbox:
    """The notifier's listener: messages, or the bus's failure, queued on the loop."""

    def __init__(self) -> None:
        import asyncio

        self.queue: asyncio.Queue[Any] = asyncio.Queue()

    def __call__(self, message: Any) -> None:
        self.queue.put_nowait(message)

    def on_error(self, error: Exception) -> None:
        self.queue.put_nowait(error)


async def _records(
    bus: Any,
    decoder: CaptureDecoder,
    by_dbc: DbcDecoder | None,
    channel: str | None,
    duration: float | None,
    clock: Callable[[], float],
) -> AsyncIterator[Record]:
    import asyncio

    import can

    inbox = _Inbox()
    notifier = can.Notifier(bus, [inbox], loop=asyncio.get_running_loop())
    end = None if duration is None else clock() + duration
    try:
        while True:
            wait = None if end is None else end - clock()
            if wait is not None and wait <= 0:
                return
            try:
                item = await asyncio.wait_for(inbox.queue.get(), wait)
            except asyncio.TimeoutError:
                return
            frames: list[Frame] = []
            while not isinstance(item, Exception):
                frame = frame_from_message(item)
                if channel is None or frame.channel == channel:
                    frames.append(frame)
                if inbox.queue.empty():
                    break
                item = inbox.queue.get_nowait()
            for record in decoder.decode(frames):  # the frames before a failure first
                yield record if by_dbc is None else by_dbc.record(record)
            if isinstance(item, Exception):
                raise BusFailedError(f"the CAN bus failed: {item}") from None
    finally:
        notifier.stop()
