"""python-can in and out: decode ``can.Message`` objects, make them, listen to a live bus.

Needs the ``can`` extra (``pip install "veronte4x[can]"``). This is the thin I/O adapter;
decoding itself stays sans-IO in `veronte4x.capture.decoder`.
"""

from __future__ import annotations

import configparser
import contextlib
import os
import socket
import sys
from collections.abc import Callable
from typing import Any

from veronte4x.errors import MissingExtraError

try:
    import can
except ModuleNotFoundError as missing:  # pragma: no cover - the can extra is installed in CI
    if missing.name != "can":
        raise
    raise MissingExtraError("can", "can", "veronte4x.canbus") from None

from veronte4x import codec, dronecan
from veronte4x.capture.busmap import BusMap
from veronte4x.capture.decoder import CaptureDecoder
from veronte4x.capture.readers.live import frame_socket
from veronte4x.capture.readers.pythoncan import frame_from_message
from veronte4x.capture.records import Record
from veronte4x.errors import Veronte4xError


class BusOpenError(Veronte4xError, OSError):
    """A CAN bus that cannot be opened; the message says which and why."""


def open_bus(
    interface: str | None = None,
    channel: str | None = None,
    bitrate: int | None = None,
    config_file: str | None = None,
    options: dict[str, Any] | None = None,
) -> can.BusABC:
    """Open a python-can bus from python-can's own settings.

    Args:
        interface: python-can interface name (``socketcan``, ``pcan``, ``udp_multicast``...);
            None lets python-can take it from its configuration.
        channel: The interface's channel.
        bitrate: Bit rate in bit/s.
        config_file: A python-can configuration file, read before the other arguments.
        options: More keyword arguments of the bus (e.g. ``{"port": 43113}``).

    Raises:
        BusOpenError: python-can could not open it (the message names interface and
            channel, and python-can's reason).
    """
    settings: dict[str, Any] = {}
    if config_file is not None:
        if not os.path.isfile(config_file):
            raise BusOpenError(f"python-can configuration file {config_file!r} not found")
        try:
            settings.update(can.util.load_file_config(config_file))
        except (configparser.Error, UnicodeDecodeError) as error:
            reason = str(error).splitlines()[0] if str(error) else type(error).__name__
            raise BusOpenError(
                f"python-can configuration file {config_file!r} is not a UTF-8 INI file "
                f"with a [default] section: {reason}"
            ) from None
    given = {"interface": interface, "channel": channel, "bitrate": bitrate}
    settings.update({k: v for k, v in given.items() if v is not None})
    settings.update(options or {})
    where = ", ".join(f"{k} {settings[k]}" for k in ("interface", "channel") if k in settings)
    try:
        bus = can.Bus(**settings)
    except Exception as error:  # an interface may raise anything: struct.error for hop_limit=x
        reason = str(error) or type(error).__name__
        raise BusOpenError(
            f"cannot open the CAN bus ({where or 'python-can defaults'}): {reason}"
        ) from None
    widen_receive_buffer(bus)
    return bus


RECEIVE_BUFFER = 16 * 1024 * 1024
"""Bytes of receive buffer `widen_receive_buffer` asks for: some 40,000 frames on
``udp_multicast`` (4.5 s of a full 1 Mbit/s bus), where the system grants it."""


SO_RCVBUFFORCE = 33
"""Linux's ``SO_RCVBUF`` past ``net.core.rmem_max``, for a process with ``CAP_NET_ADMIN``
(candump's ``-r`` uses it the same way)."""


def widen_receive_buffer(bus: can.BusABC, size: int = RECEIVE_BUFFER) -> None:
    """Raise the receive buffer of a bus that is a datagram socket (python-can's
    ``udp_multicast``) or a SocketCAN one to ``size`` bytes, as far as the system lets the
    process (Linux: ``net.core.rmem_max`` for a user, any size with ``CAP_NET_ADMIN``);
    other buses, and a buffer already as large, are left alone.

    Each CAN frame is a datagram there, which the kernel counts at about 1 kB: the default
    buffer (about 200 kB on Linux) holds some 200 frames and drops the rest, while 8 nodes
    served at once take 300 frames in one burst (38 per 256-byte file read), and each lost
    frame costs a node its request timeout; a full 1 Mbit/s bus sends 8,800 frames a
    second. `open_bus` calls it on every bus it opens.
    """
    duplicate = frame_socket(bus)
    if duplicate is None:
        return  # no socket behind it (virtual, a vendor library) or no socket to share
    with duplicate, contextlib.suppress(OSError):
        if duplicate.getsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF) >= size:
            return
        if sys.platform == "linux":
            with contextlib.suppress(OSError):  # not allowed: as far as rmem_max then
                duplicate.setsockopt(socket.SOL_SOCKET, SO_RCVBUFFORCE, size)
                return
        duplicate.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, size)


__all__ = [
    "RECEIVE_BUFFER",
    "BusOpenError",
    "DecodingListener",
    "decode_can_message",
    "frame_to_message",
    "is_dronecan_frame",
    "open_bus",
    "to_can_message",
    "to_can_messages",
    "widen_receive_buffer",
]


def decode_can_message(message: can.Message, decoder: CaptureDecoder | None = None) -> list[Record]:
    """Decode one ``can.Message`` into its records (none while a DroneCAN transfer is open).

    Pass the same `CaptureDecoder` for every message of a bus: it keeps the DroneCAN
    reassembly state between frames.
    """
    return list((decoder or CaptureDecoder()).decode((frame_from_message(message),)))


def to_can_message(
    message: codec.Message,
    can_id: int | None = None,
    *,
    autopilot: int | None = None,
    bus_map: BusMap | None = None,
    timestamp: float = 0.0,
    channel: str | None = None,
) -> can.Message:
    """Encode a Veronte message into a ``can.Message``.

    Args:
        message: The message.
        can_id: The CAN ID. By default Status and Score go on the bus map's arbiter ID and
            Ready and ArbitrationVariable on the ID of `autopilot`; other messages need it.
        autopilot: 0 = AP1 .. 3 = external, for Ready and ArbitrationVariable.
        bus_map: IDs and codec choices; Embention's template defaults if None.
        timestamp: The message's timestamp.
        channel: The message's channel.

    Raises:
        EncodeError: A field is out of range.
        ValueError: No CAN ID given and none follows from the message.
    """
    bus_map = bus_map or BusMap()
    if can_id is None:
        if isinstance(message, (codec.Status, codec.Score)):
            can_id = bus_map.arbiter_id
        elif isinstance(message, (codec.Ready, codec.ArbitrationVariable)):
            if autopilot is None or not 0 <= autopilot <= 3:
                raise ValueError(f"{type(message).__name__} needs autopilot=0..3 or can_id")
            can_id = bus_map.autopilot_ids[autopilot]
        else:
            raise ValueError(f"{type(message).__name__} needs a can_id")
    return can.Message(
        timestamp=timestamp,
        arbitration_id=can_id,
        is_extended_id=bus_map.extended,
        data=bus_map.codec().encode(message),
        channel=channel,
    )


def is_dronecan_frame(message: can.Message) -> bool:
    """Whether a bus message can be a DroneCAN frame: extended ID, data, classic CAN."""
    return (
        message.is_extended_id
        and not message.is_remote_frame
        and not message.is_error_frame
        and not message.is_fd
        and 0 < message.dlc <= 8
    )


def frame_to_message(
    frame: dronecan.TransferFrame, timestamp: float = 0.0, channel: str | None = None
) -> can.Message:
    """One DroneCAN frame as an extended ``can.Message``."""
    return can.Message(
        timestamp=timestamp,
        arbitration_id=frame.can_id,
        is_extended_id=True,
        data=frame.data,
        channel=channel,
    )


def to_can_messages(
    message: Any,
    *,
    source_node_id: int,
    transfer_id: int,
    priority: int = dronecan.DEFAULT_PRIORITY,
    destination_node_id: int | None = None,
    timestamp: float = 0.0,
    channel: str | None = None,
) -> list[can.Message]:
    """Encode a DroneCAN message, request or response into the ``can.Message`` frames of its
    transfer (see `veronte4x.dronecan.encode` for the arguments).

    Raises:
        EncodeError: A field is out of range, or an argument is.
    """
    frames = dronecan.encode(
        message,
        source_node_id=source_node_id,
        transfer_id=transfer_id,
        priority=priority,
        destination_node_id=destination_node_id,
    )
    return [frame_to_message(frame, timestamp, channel) for frame in frames]


class DecodingListener(can.Listener):
    """A ``can.Listener`` that decodes live traffic and hands each record to a callback.

    Attach it to a bus with ``can.Notifier(bus, [DecodingListener(records.append)])``. Each
    received message goes through `on_message_received`:

    Examples:
        >>> from veronte4x import dronecan
        >>> records = []
        >>> listener = DecodingListener(records.append)
        >>> status = dronecan.NodeStatus(5, dronecan.Health.OK, dronecan.Mode.OPERATIONAL, 0, 0)
        >>> for message in to_can_messages(status, source_node_id=10, transfer_id=0):
        ...     listener.on_message_received(message)
        >>> records[0].node_id, records[0].message.uptime_sec
        (10, 5)

    Args:
        callback: Called with every record, in order.
        bus_map: IDs and codec choices; Embention's template defaults if None.
    """

    def __init__(self, callback: Callable[[Record], object], bus_map: BusMap | None = None) -> None:
        self.callback = callback
        self.decoder = CaptureDecoder(bus_map)

    def on_message_received(self, msg: can.Message) -> None:
        """Decode one received message and pass its records on."""
        for record in self.decoder.decode((frame_from_message(msg),)):
            self.callback(record)
