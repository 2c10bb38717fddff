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
import functools
import math
import select
import socket
import struct
import sys
import threading
import time
from collections.abc import Callable, Generator
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
        self.short_buffer: tuple[int, int] | None = None
        """Bytes of receive buffer the system gave the bus's socket and bytes asked for,
        where it gave less (set by the command that opened the bus); else None."""

    def text(self) -> str | None:
        """``N frames lost by the bus layer``, and the receive buffer where the system
        gave less than asked for; None when the bus does not count its losses."""
        if not self.counted:
            return None
        text = f"{counted(self.frames, 'frame')} lost by the bus layer"
        if self.short_buffer is not None:
            given, asked = self.short_buffer
            text += (
                f" (a receive buffer of {_size_text(given)}, not the {_size_text(asked)} "
                "asked for: the system's limit, net.core.rmem_max on Linux)"
            )
        return text


def _size_text(size: int) -> str:
    """Bytes in KiB or MiB, to 3 significant digits: ``208 KiB``, ``16 MiB``."""
    return f"{size / 2**20:.3g} MiB" if size >= 2**20 else f"{size / 2**10:.3g} KiB"


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
    idle: Callable[[], object] | None = None,
) -> Generator[Frame, None, None]:
    """Yield the frames received on ``bus`` until ``duration`` seconds pass, Ctrl-C or
    ``stop`` is set.

    A python-can ``udp_multicast`` bus on Linux is read straight from its socket
    (`DatagramReader`: python-can's own wire format and checks, no ``can.Message`` built);
    any other bus through ``bus.recv``. A wrapper of a bus names the bus as
    ``__wrapped__``. Either way a frame is taken from the bus only when it is asked for.

    Args:
        bus: An open python-can bus.
        channel: Channel name put in frames that carry none (the ``virtual`` interface's).
        duration: Seconds of ``clock`` to read, or None for no limit.
        clock: Measures ``duration``.
        stop: Set by another thread to end the stream.
        loss: Kept up to date with the frames the bus layer dropped meanwhile.
        idle: Called whenever no frame is waiting, before the wait for the next one: by
            then the caller has handled every frame yielded (``decode`` writes its output
            out there, once a burst rather than once a record).

    Raises:
        BusFailedError: python-can reported a bus failure.
    """
    end = None if duration is None else clock() + duration
    drops = _DropCount(bus, loss)
    reader = DatagramReader.of(bus, channel or "")
    receive = _MessageReader(bus, channel or "").receive if reader is None else reader.receive
    read = 0
    try:
        while stop is None or not stop.is_set():
            wait = POLL
            if end is not None:
                wait = min(wait, end - clock())
                if wait <= 0:
                    return
            frame = receive(wait, idle)
            if frame is None:
                drops.update()
                continue
            read += 1
            if read % COUNT_EVERY == 0:
                drops.update()
            yield frame
    except KeyboardInterrupt:
        return
    finally:
        with contextlib.suppress(OSError):
            drops.close()
        if reader is not None:
            with contextlib.suppress(OSError):
                reader.close()


class _MessageReader:
    """Frames through python-can's ``recv``."""

    def __init__(self, bus: Any, unnamed: str) -> None:
        self.bus = bus
        self.unnamed = unnamed

    def receive(self, wait: float, idle: Callable[[], object] | None = None) -> Frame | None:
        """The next frame, or None when none came within ``wait`` seconds; ``idle`` is
        called first if none is waiting.

        Raises:
            BusFailedError: python-can raised ``can.CanError``.
        """
        import can

        try:
            message = None if idle is None else self.bus.recv(timeout=0.0)
            if message is None:
                if idle is not None:
                    idle()
                message = self.bus.recv(timeout=wait)
        except can.CanError as error:
            raise BusFailedError(f"the CAN bus failed: {error}") from None
        if message is None:
            return None
        frame = frame_from_message(message)
        return frame if frame.channel or not self.unnamed else frame._replace(channel=self.unnamed)


GATHER = 0.01
"""Seconds `DatagramReader` lets datagrams gather after a wait for one ends, before it
reads them: on a full 1 Mbit/s bus some 88 frames are read a wake-up, not one, for 10 ms
more latency (2 ms: 17 a wake-up)."""
MAX_DATAGRAM = 4096
"""Bytes of a datagram read, as python-can's ``udp_multicast`` reads (its ``max_buffer``,
``can/interfaces/udp_multicast/bus.py``); a longer one is cut, and fails to unpack there too."""
SO_TIMESTAMPNS = 35
"""Linux's option for the receive time of each datagram in nanoseconds, which python-can's
``udp_multicast`` bus sets on its socket and reads (``include/uapi/asm-generic/socket.h``)."""
_TIMESPEC = struct.Struct("@ll")
PACKED_FIELDS = frozenset(
    (
        "timestamp",
        "arbitration_id",
        "is_extended_id",
        "is_remote_frame",
        "is_error_frame",
        "channel",
        "dlc",
        "data",
        "is_fd",
        "bitrate_switch",
        "error_state_indicator",
    )
)
"""The keys python-can's ``udp_multicast`` packs each ``can.Message`` into (a msgpack map,
``can/interfaces/udp_multicast/utils.py::pack_message``)."""


class DatagramReader:
    """A python-can ``udp_multicast`` bus read from its socket, each datagram turned into a
    `Frame` as python-can's ``recv`` and `frame_from_message` would (`datagram_frame`).

    python-can waits with ``select`` before every datagram and builds a checked
    ``can.Message`` of each; here a datagram already waiting is read at once, the wait
    comes only when none is, and a classic data frame goes straight from its msgpack map to
    a `Frame`. The socket is a duplicate of the bus's (the same datagrams, each read once,
    by either).
    """

    def __init__(self, frames: socket.socket, fd: bool, unnamed: str = "") -> None:
        self.socket = frames
        self.fd = fd
        self.unnamed = unnamed
        self.ancillary = socket.CMSG_SPACE(_TIMESPEC.size)

    @classmethod
    def of(cls, bus: Any, unnamed: str = "") -> DatagramReader | None:
        """The reader of ``bus``: None unless it is python-can's ``udp_multicast`` on Linux,
        with no filters of python-can's own and receive times on its socket. ``unnamed``:
        the channel of frames whose message names none."""
        if sys.platform != "linux":
            return None
        try:
            from can import CanProtocol
            from can.interfaces.udp_multicast import UdpMulticastBus
        except ImportError:
            return None
        inner = getattr(bus, "__wrapped__", bus)
        if not isinstance(inner, UdpMulticastBus) or inner.filters:
            return None
        frames = frame_socket(bus)
        if frames is None:
            return None
        try:
            stamped = frames.getsockopt(socket.SOL_SOCKET, SO_TIMESTAMPNS)
        except OSError:
            stamped = 0
        if not stamped:
            frames.close()
            return None
        return cls(frames, inner.protocol is CanProtocol.CAN_FD, unnamed)

    def receive(self, wait: float, idle: Callable[[], object] | None = None) -> Frame | None:
        """The next frame: at once if a datagram is waiting, else (after calling ``idle``)
        after waiting up to ``wait`` seconds for one; None when none came.

        Raises:
            BusFailedError: The socket failed, or a datagram is not a python-can message
                (python-can's ``recv`` fails the same way).
        """
        waited = False
        while True:
            try:
                data, ancillary, _, _ = self.socket.recvmsg(
                    MAX_DATAGRAM, self.ancillary, socket.MSG_DONTWAIT
                )
            except (BlockingIOError, InterruptedError):
                if waited:
                    return None
                if idle is not None:
                    idle()
                if not self._wait(wait):
                    return None
                waited = True
                time.sleep(GATHER)
                continue
            except OSError as error:
                raise BusFailedError(f"the CAN bus failed: {error}") from None
            frame = datagram_frame(data, receive_time(ancillary), self.fd, self.unnamed)
            if frame is not None:
                return frame

    def _wait(self, wait: float) -> bool:
        """Wait up to ``wait`` seconds for a datagram; whether one came."""
        try:
            return bool(select.select([self.socket], [], [], wait)[0])
        except OSError as error:
            raise BusFailedError(
                f"the CAN bus failed: Failed to wait for IP/UDP socket: {error}"
            ) from None

    def close(self) -> None:
        """Close the duplicate socket (the bus keeps its own)."""
        self.socket.close()


def receive_time(ancillary: list[tuple[int, int, bytes]]) -> float:
    """A datagram's receive time from its ``SO_TIMESTAMPNS`` control message, as python-can
    reads it (``GeneralPurposeUdpMulticastBus.recv``).

    Raises:
        BusFailedError: Not exactly that one control message, or nanoseconds past 1e9
            (python-can's messages).
    """
    try:
        ((level, kind, data),) = ancillary
    except ValueError:
        raise BusFailedError(
            "the CAN bus failed: Only requested a single extra field but got a different amount"
        ) from None
    if level != socket.SOL_SOCKET or kind != SO_TIMESTAMPNS:
        raise BusFailedError(
            "the CAN bus failed: received control message type that was not requested"
        )
    seconds, nanoseconds = _TIMESPEC.unpack(data)
    if nanoseconds >= 1e9:
        raise BusFailedError(
            f"the CAN bus failed: Timestamp nanoseconds field was out of range: "
            f"{nanoseconds} not less than 1e9"
        )
    return float(seconds + nanoseconds * 1.0e-9)


def datagram_frame(data: bytes, timestamp: float, fd: bool, unnamed: str = "") -> Frame | None:
    """The frame of one ``udp_multicast`` datagram received at ``timestamp``: what
    python-can's ``recv`` and `frame_from_message` make of it, named ``unnamed`` where its
    message names no channel (`read_bus`'s ``channel``). A classic data frame as python-can
    packs it is read directly; anything else goes through python-can's own
    ``unpack_message`` and checks. None for a CAN FD frame on a bus without CAN FD
    (python-can skips those).

    Raises:
        BusFailedError: The datagram is not a valid python-can message (python-can's
            ``recv`` raises "could not unpack received message").
    """
    try:
        fields = _unpack()(data, raw=False)
    except Exception:
        fields = None
    if type(fields) is dict and fields.keys() == PACKED_FIELDS and 0.0 <= timestamp < math.inf:
        can_id, extended, payload = (
            fields["arbitration_id"],
            fields["is_extended_id"],
            fields["data"],
        )
        if (
            type(can_id) is int
            and type(payload) is bytes
            and (extended is True or extended is False)
            and type(fields["dlc"]) is int
            and fields["dlc"] == len(payload) <= 8
            and fields["is_remote_frame"] is False
            and fields["is_error_frame"] is False
            and fields["is_fd"] is False
            and fields["bitrate_switch"] is False
            and fields["error_state_indicator"] is False
            and 0 <= can_id < (0x20000000 if extended else 0x800)
        ):
            channel = fields["channel"]
            name = "" if channel is None else str(channel)
            return Frame(timestamp, name or unnamed, can_id, payload, extended)
    return _checked_frame(data, timestamp, fd, unnamed)


@functools.cache
def _unpack() -> Callable[..., Any]:
    """msgpack's ``unpackb``, imported when a datagram first comes."""
    import msgpack  # type: ignore[import-untyped]

    return msgpack.unpackb  # type: ignore[no-any-return]


def _checked_frame(data: bytes, timestamp: float, fd: bool, unnamed: str) -> Frame | None:
    """`datagram_frame` through python-can's ``unpack_message`` and ``can.Message``'s
    checks."""
    from can.interfaces.udp_multicast.utils import unpack_message

    try:
        message = unpack_message(data, replace={"timestamp": timestamp}, check=True)
    except Exception:
        raise BusFailedError("the CAN bus failed: could not unpack received message") from None
    if message.is_fd and not fd:
        return None
    frame = frame_from_message(message)
    return frame if frame.channel or not unnamed else frame._replace(channel=unnamed)
