"""The socket behind a python-can bus: a duplicate of it, and the kernel's count of the
frames it dropped there.

Plain sockets, no python-can: `veronte4x.canbus` widens a bus's receive buffer through it,
and `veronte4x.capture.readers.live` counts a live bus's losses through it.
"""

from __future__ import annotations

import os
import socket
import struct
import sys
from typing import Any

__all__ = ["SO_MEMINFO", "frame_socket", "kernel_drops", "receive_buffer"]


def frame_socket(bus: Any) -> socket.socket | None:
    """A duplicate of the socket ``bus`` receives frames on, for its options and counters
    (the caller closes it): a datagram socket (``udp_multicast``) or a SocketCAN one;
    None for a bus with no socket behind it (``virtual``, a vendor library's) or another
    kind of socket."""
    try:
        descriptor = bus.fileno()
        duplicate = socket.socket(fileno=os.dup(descriptor))
    except (NotImplementedError, AttributeError, OSError, ValueError, TypeError):
        return None
    if duplicate.type == socket.SOCK_DGRAM or duplicate.family == getattr(socket, "AF_CAN", -1):
        return duplicate
    duplicate.close()
    return None


SO_MEMINFO = 55
"""Linux's socket option giving a socket's memory counters (``include/uapi/asm-generic/
socket.h``); the ninth, ``SK_MEMINFO_DROPS``, counts the frames dropped on it."""
_MEMINFO = struct.Struct("9I")


def kernel_drops(frames: socket.socket) -> int | None:
    """The frames the kernel dropped on a socket since it was opened (a full receive
    buffer), modulo 2**32; None where the system does not say (not Linux, before 4.6)."""
    if sys.platform != "linux":
        return None
    try:
        raw = frames.getsockopt(socket.SOL_SOCKET, SO_MEMINFO, _MEMINFO.size)
    except OSError:
        return None
    return _MEMINFO.unpack_from(raw)[8] if len(raw) >= _MEMINFO.size else None


def receive_buffer(frames: socket.socket) -> int:
    """Bytes of receive buffer a socket has: ``SO_RCVBUF``, halved on Linux, which reports
    twice the size set, its bookkeeping included (``man 7 socket``)."""
    size: int = frames.getsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF)
    return size // 2 if sys.platform == "linux" else size
