"""python-can bus I/O: open a bus, widen its receive buffer, DroneCAN frames to and from
``can.Message``.

Needs the ``can`` extra (``pip install "veronte4x[can]"``). This module knows DroneCAN frames
and python-can only; decoding a live bus into records is `veronte4x.capture.can_messages`.
"""

from __future__ import annotations

import configparser
import contextlib
import os
import socket
import sys
from typing import Any

from veronte4x.errors import MissingExtraError

try:
    import can
except ModuleNotFoundError as missing:  # pragma: no cover - the can extra is installed in CI
    if missing.name != "can":
        raise
    raise MissingExtraError("can", "can", "veronte4x.canbus") from None

from veronte4x.dronecan.frame import TransferFrame
from veronte4x.dronecan.transfer import DEFAULT_PRIORITY, encode
from veronte4x.errors import Veronte4xError
from veronte4x.mcastbus import INTERFACE, McastBus
from veronte4x.sockets import frame_socket, receive_buffer

__all__ = [
    "RECEIVE_BUFFER",
    "BusOpenError",
    "frame_to_message",
    "is_dronecan_frame",
    "open_bus",
    "to_can_messages",
    "widen_receive_buffer",
]


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
        interface: python-can interface name (``socketcan``, ``pcan``, ``udp_multicast``...),
            or ``mcast``, the bus of pydronecan and ArduPilot SITL (`veronte4x.mcastbus`,
            its channel the bus number); None lets python-can take it from its configuration.
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
    bus: can.BusABC
    try:
        if settings.get("interface") == INTERFACE:
            settings.pop("interface")
            bus = McastBus(**settings)
        else:
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
    second. `open_bus` calls it on every bus it opens; the live commands say so where the
    system gave less (`veronte4x.capture.readers.live.BusLoss`).
    """
    duplicate = frame_socket(bus)
    if duplicate is None:
        return  # no socket behind it (virtual, a vendor library) or no socket to share
    with duplicate, contextlib.suppress(OSError):
        if receive_buffer(duplicate) >= size:
            return
        if sys.platform == "linux":
            with contextlib.suppress(OSError):  # not allowed: as far as rmem_max then
                duplicate.setsockopt(socket.SOL_SOCKET, SO_RCVBUFFORCE, size)
                return
        duplicate.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, size)


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
    frame: TransferFrame, timestamp: float = 0.0, channel: str | None = None
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
    priority: int = DEFAULT_PRIORITY,
    destination_node_id: int | None = None,
    timestamp: float = 0.0,
    channel: str | None = None,
) -> list[can.Message]:
    """Encode a DroneCAN message, request or response into the ``can.Message`` frames of its
    transfer (see `veronte4x.dronecan.encode` for the arguments).

    Raises:
        EncodeError: A field is out of range, or an argument is.
    """
    frames = encode(
        message,
        source_node_id=source_node_id,
        transfer_id=transfer_id,
        priority=priority,
        destination_node_id=destination_node_id,
    )
    return [frame_to_message(frame, timestamp, channel) for frame in frames]
