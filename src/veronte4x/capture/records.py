"""The decoded record: one per frame, per DroneCAN transfer, or per problem."""

from __future__ import annotations

from typing import Any, NamedTuple

from veronte4x.capture.busmap import AUTOPILOT_NAMES, Role


class Record(NamedTuple):
    """One decoded frame or transfer, or the error that stopped it.

    A named tuple rather than a dataclass: a capture makes one per frame, and a tuple is
    the cheapest immutable record Python builds.

    Attributes:
        timestamp: The frame's timestamp (for a transfer, its last frame's), or None.
        channel: Interface name.
        can_id: CAN ID of the frame (for a transfer, of its frames).
        role: Arbiter, autopilot, DroneCAN or unknown, from the bus map.
        autopilot: 0 = AP1, 1 = AP2, 2 = AP3, 3 = external, for an autopilot's frame.
        node_id: DroneCAN source node id.
        message: The decoded message, or None when `error` is set.
        error: What stopped decoding, in a few words (``decode error``, ``unknown command``,
            ``unknown id``, ``bad line``, ``error frame``, ``remote frame``, or a DroneCAN
            reassembly problem such as ``CRC mismatch``), or None.
        detail: The error's full text, or "".
        data: The raw bytes: the frame's data, or the transfer's payload.
        destination_node_id: DroneCAN destination node id of a service transfer.
    """

    timestamp: float | None
    channel: str
    can_id: int
    role: Role
    autopilot: int | None
    node_id: int | None
    message: Any
    error: str | None
    detail: str
    data: bytes
    destination_node_id: int | None = None

    @property
    def sender(self) -> str:
        """Who sent it: ``arbiter``, ``AP1`` .. ``external``, ``node N`` or ``unknown``."""
        if self.role is Role.AUTOPILOT and self.autopilot is not None:
            return AUTOPILOT_NAMES[self.autopilot]
        if self.role is Role.DRONECAN and self.node_id is not None:
            return f"node {self.node_id}"
        return self.role.value

    @property
    def kind(self) -> str:
        """The message class name, or ``error: <error>``."""
        if self.error is not None:
            return f"error: {self.error}"
        return type(self.message).__name__
