"""The ``mcast:`` bus of pydronecan and ArduPilot SITL as a python-can bus: `McastBus`.

Needs the ``can`` extra. The datagram is `veronte4x.dronecan.mcast`'s; this adapter only
opens the sockets as pydronecan's driver (``dronecan/driver/mcast.py``, 1.0.27) and
ArduPilot's SITL (``libraries/AP_HAL_SITL/CAN_Multicast.cpp``) do: a receiving socket bound
to the bus's group and port 57732 (``SO_REUSEADDR``, so that every program on the machine
hears the bus) that joins the group, and a sending socket connected to it. A datagram from
the bus's own sending socket is dropped, as ArduPilot drops it (by address and port), so
the bus does not hear itself; a datagram that is no frame is dropped, as both drop it.

python-can's ``udp_multicast`` is another wire format (msgpack): the two do not hear each
other.
"""

from __future__ import annotations

import select
import socket
import struct
import time
from typing import Any

from veronte4x.errors import MissingExtraError

try:
    import can
except ModuleNotFoundError as missing:  # pragma: no cover - the can extra is installed in CI
    if missing.name != "can":
        raise
    raise MissingExtraError("can", "can", "veronte4x.mcastbus") from None

from veronte4x.dronecan.mcast import PORT, DatagramError, McastFrame, decode, encode, group

__all__ = ["McastBus", "bus_number"]

INTERFACE = "mcast"
"""The name of the bus on the command line (``--interface mcast``)."""
_RECEIVE_BYTES = 128
"""More than the longest datagram (74 bytes), so that a longer one is seen, and refused."""


def bus_number(channel: object) -> int:
    """The bus number of a channel (``0``, ``"1"``): pydronecan's ``mcast:1`` is channel 1;
    ``None`` and ``""`` are bus 0, as pydronecan's ``mcast:``.

    Raises:
        ValueError: No bus number 0 to 255.
    """
    text = "" if channel is None else str(channel).strip()
    if text == "":
        return 0
    if not text.isdigit() or int(text) > 255:
        raise ValueError(f"mcast channel {channel!r} is no bus number 0 to 255")
    return int(text)


class McastBus(can.BusABC):
    """A python-can bus on the ``mcast:`` bus ``channel`` (0 for pydronecan's ``mcast:0``
    and ArduPilot SITL's first CAN interface).

    Args:
        channel: The bus number (see `bus_number`).
        port: The UDP port; pydronecan and ArduPilot use 57732 only.
        kwargs: python-can's own (``can_filters``...).

    Raises:
        can.CanInitializationError: The sockets cannot be opened, or the channel is no bus.
    """

    def __init__(self, channel: object = 0, port: int = PORT, **kwargs: Any) -> None:
        try:
            self.bus = bus_number(channel)
        except ValueError as error:
            raise can.CanInitializationError(str(error)) from None
        address = group(self.bus)
        self.channel_info = f"{INTERFACE}:{self.bus}"
        receiver = sender = None
        try:
            receiver = socket.socket(socket.AF_INET, socket.SOCK_DGRAM, socket.IPPROTO_UDP)
            receiver.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
            receiver.bind((address, port))
            membership = struct.pack("=4s4s", socket.inet_aton(address), bytes(4))
            receiver.setsockopt(socket.IPPROTO_IP, socket.IP_ADD_MEMBERSHIP, membership)
            receiver.setblocking(False)
            sender = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
            sender.connect((address, port))
        except OSError as error:
            for opened in (receiver, sender):
                if opened is not None:
                    opened.close()
            raise can.CanInitializationError(
                f"cannot join {address} port {port}: {error.strerror or error}"
            ) from None
        self._receiver, self._sender = receiver, sender
        self._own = sender.getsockname()
        super().__init__(channel=self.channel_info, **kwargs)

    def fileno(self) -> int:
        """The receiving socket's descriptor (for its buffer size and drop count)."""
        return self._receiver.fileno()

    def _recv_internal(self, timeout: float | None) -> tuple[can.Message | None, bool]:
        readable, _, _ = select.select([self._receiver], [], [], timeout)
        if not readable:
            return None, False
        try:
            datagram, sender = self._receiver.recvfrom(_RECEIVE_BYTES)
        except BlockingIOError:
            return None, False
        except OSError as error:
            raise can.CanOperationError(error.strerror or str(error)) from None
        if sender == self._own:
            return None, False
        try:
            frame = decode(datagram)
        except DatagramError:
            return None, False
        message = can.Message(
            timestamp=time.time(),
            arbitration_id=frame.can_id,
            is_extended_id=frame.extended,
            is_remote_frame=frame.remote,
            is_error_frame=frame.error,
            is_fd=frame.fd,
            dlc=len(frame.data),
            data=frame.data,
            channel=self.channel_info,
        )
        return message, False

    def send(self, msg: can.Message, timeout: float | None = None) -> None:
        """Send one frame as one datagram.

        Raises:
            can.CanOperationError: It is no frame the datagram holds, or the socket failed.
        """
        data = b"" if msg.is_remote_frame else bytes(msg.data or b"")
        frame = McastFrame(
            msg.arbitration_id,
            data,
            msg.is_extended_id,
            msg.is_fd,
            msg.is_remote_frame,
            msg.is_error_frame,
        )
        try:
            self._sender.send(encode(frame))
        except (ValueError, OSError) as error:
            reason = getattr(error, "strerror", None) or str(error)
            raise can.CanOperationError(f"cannot send on {self.channel_info}: {reason}") from None

    def shutdown(self) -> None:
        """Close both sockets."""
        super().shutdown()
        self._receiver.close()
        self._sender.close()
