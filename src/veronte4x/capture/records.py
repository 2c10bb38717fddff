"""The decoded record: one per frame, per DroneCAN transfer, per undecoded frame, or per
problem."""

from __future__ import annotations

from typing import Any, NamedTuple

from veronte4x.capture.busmap import AUTOPILOT_NAMES, Role


class Record(NamedTuple):
    """One decoded frame or transfer, an undecoded one, or the error that stopped it.

    Three cases: decoded (`message` set), undecoded foreign traffic (`message` and `error`
    None: a CAN ID outside the bus map, a DroneCAN data type with no codec; normal on a
    shared bus, not an error) and errors (`error` set).

    A named tuple rather than a dataclass: a capture makes one per frame, and a tuple is
    the cheapest immutable record Python builds.

    Attributes:
        timestamp: The frame's timestamp (for a transfer, its last frame's), or None.
        channel: Interface name.
        can_id: CAN ID of the frame (for a transfer, of its frames).
        role: Arbiter, autopilot, DroneCAN or unknown, from the bus map.
        autopilot: 0 = AP1, 1 = AP2, 2 = AP3, 3 = external, for an autopilot's frame.
        node_id: DroneCAN source node id.
        message: The decoded message, or None when undecoded or `error` is set.
        error: What stopped decoding, in a few words (``decode error``, ``unknown command``,
            ``bad line``, ``error frame``, ``remote frame``, or a DroneCAN reassembly problem
            such as ``crc mismatch``), or None.
        detail: The error's full text; for undecoded traffic, what it was
            (``11-bit CAN ID 0x123``, ``DroneCAN data type 1234``); or "".
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
        """The message class name, ``unknown`` for undecoded traffic, or ``error: <error>``."""
        if self.error is not None:
            return f"error: {self.error}"
        if self.message is None:
            return "unknown"
        return type(self.message).__name__

    def _repr_html_(self) -> str:
        """Jupyter's view: the record and its message as tables (`veronte4x.display`)."""
        from veronte4x.display import to_html

        return to_html(self)
