"""`Allocatee`: a node without a node id asking an allocation server for one (sans-IO).

The allocatee's side of DroneCAN dynamic node ID allocation (DroneCAN specification, 6
"Application-level functions", "Dynamic node ID allocation"; the rules A to E in the DSDL
comments of ``uavcan.protocol.dynamic_node_id.Allocation``). It sends its 16-byte unique id
in anonymous single-frame requests of 6, 6 and 4 bytes, each after the server has answered
the one before with the unique id so far, and takes the node id of the answer that carries
its whole unique id. Intervals are drawn from the DSDL's ranges with the ``rng`` given (by
default a `random.Random` started from the unique id), so a run is reproducible.

Nothing here reads a clock: every time is an argument.
"""

from __future__ import annotations

import random
from dataclasses import dataclass

from veronte4x.dronecan import Allocation
from veronte4x.dronecan.can_id import anonymous_can_id
from veronte4x.dronecan.codec import BY_CLASS
from veronte4x.dronecan.crc import crc16
from veronte4x.dronecan.frame import TransferFrame
from veronte4x.dronecan.tail import SINGLE_FRAME
from veronte4x.dronecan.transfer import Transfer
from veronte4x.errors import EncodeError, check_seconds
from veronte4x.node.transfer_ids import TRANSFER_ID_MODULO

UNIQUE_ID_SIZE = 16
"""Bytes of a node's unique id (``uavcan.protocol.HardwareVersion.unique_id``)."""

STAGE_SIZE = Allocation.MAX_LENGTH_OF_UNIQUE_ID_IN_REQUEST
"""Bytes of unique id an anonymous request carries at most (one CAN frame)."""

REQUEST_PERIOD = (
    Allocation.MIN_REQUEST_PERIOD_MS / 1000,
    Allocation.MAX_REQUEST_PERIOD_MS / 1000,
)
"""The range of the random request period Trequest, in seconds (DSDL)."""

FOLLOWUP_DELAY = (
    Allocation.MIN_FOLLOWUP_DELAY_MS / 1000,
    Allocation.MAX_FOLLOWUP_DELAY_MS / 1000,
)
"""The range of the random follow-up delay Tfollowup, in seconds (DSDL)."""

REQUEST_PRIORITY = 30
"""CAN priority of the requests: low, as the specification's example log and kocherga send
them (allocation is not urgent; the DSDL advises giving way to other traffic)."""

_ALLOCATION = BY_CLASS[Allocation]


def anonymous_frame(message: Allocation, transfer_id: int, priority: int) -> TransferFrame:
    """The single frame of an anonymous Allocation (spec 4.1, anonymous message frames).

    The discriminator is the low 14 bits of the CRC-16-CCITT-FALSE of the frame's data, as
    in the specification's example log and kocherga's allocatee: random enough to tell two
    allocatees' frames apart, the same for the same frame.

    Raises:
        EncodeError: More unique id than one frame holds, or a field out of range.
    """
    payload = _ALLOCATION.encode(message)
    if len(payload) > 7:
        raise EncodeError(
            "anonymous_frame", "unique_id", message.unique_id, f"at most {STAGE_SIZE} bytes"
        )
    data = payload + bytes((SINGLE_FRAME | transfer_id,))
    can_id = anonymous_can_id(priority, _ALLOCATION.data_type.data_type_id, crc16(data) & 0x3FFF)
    return TransferFrame(can_id, data)


@dataclass(frozen=True, slots=True)
class _Followup:
    """A request due at ``time`` unless another Allocation comes first (rule D)."""

    time: float
    message: Allocation


class Allocatee:
    """A node asking for a node id: feed it the Allocation transfers heard, poll it for
    the frames to send, read `node_id` once granted.

    Args:
        unique_id: The node's 16-byte unique id (the one its GetNodeInfo reports).
        preferred_node_id: The node id it asks for, 1..125, or 0 for any.
        start_time: When it starts (rule A: the first request comes a random period later).
        rng: The source of its random intervals; None: ``random.Random(unique_id)``.
        priority: CAN priority of its requests.

    Raises:
        EncodeError: A unique id that is not 16 bytes, or a node id out of range.

    Examples:
        >>> allocatee = Allocatee(bytes(range(16)), 21)
        >>> allocatee.poll(0.0), allocatee.next_time() < 1.0
        ([], True)
        >>> [f.data.hex() for f in allocatee.poll(1.0)]  # stage 1: 6 bytes, preferring 21
        ['2b000102030405c0']
    """

    def __init__(
        self,
        unique_id: bytes,
        preferred_node_id: int = Allocation.ANY_NODE_ID,
        *,
        start_time: float = 0.0,
        rng: random.Random | None = None,
        priority: int = REQUEST_PRIORITY,
    ) -> None:
        if not isinstance(unique_id, bytes) or len(unique_id) != UNIQUE_ID_SIZE:
            raise EncodeError("Allocatee", "unique_id", unique_id, "16 bytes")
        if (
            isinstance(preferred_node_id, bool)
            or not isinstance(preferred_node_id, int)
            or not 0 <= preferred_node_id <= 125
        ):
            raise EncodeError(
                "Allocatee", "preferred_node_id", preferred_node_id, "0 (any) or 1..125"
            )
        self.unique_id = unique_id
        self.preferred_node_id = preferred_node_id
        self.priority = priority
        self.node_id: int | None = None
        """The node id granted, None until then."""
        self._rng = random.Random(unique_id) if rng is None else rng
        self._transfer_id = 0
        self._sent: Allocation | None = None
        self._followup: _Followup | None = None
        self._request_at = check_seconds("Allocatee", "start_time", start_time)
        self._restart_timer(self._request_at)

    def _restart_timer(self, now: float) -> None:
        self._request_at = now + self._rng.uniform(*REQUEST_PERIOD)

    def receive(self, transfer: Transfer) -> None:
        """Take one transfer heard on the bus; only Allocation messages count.

        Any Allocation restarts the request timer and cancels a follow-up not yet sent
        (rules C, D.1); the echo of this node's own last request (a bus that loops frames
        back) is not another node's and is ignored. An answer from a server whose unique id
        starts this node's sends the next part after a random delay (rule D); one with the
        whole unique id and a node id grants it (rule E).
        """
        message = transfer.message
        if self.node_id is not None or not isinstance(message, Allocation):
            return
        if transfer.source_node_id is None and message == self._sent:
            return
        now = transfer.timestamp
        self._restart_timer(now)
        self._followup = None
        if transfer.source_node_id is None:
            return
        known = message.unique_id
        if known == self.unique_id:
            if message.node_id:
                self.node_id = message.node_id
            return
        if known and len(known) < UNIQUE_ID_SIZE and self.unique_id.startswith(known):
            part = self.unique_id[len(known) : len(known) + STAGE_SIZE]
            self._followup = _Followup(
                now + self._rng.uniform(*FOLLOWUP_DELAY),
                Allocation(self.preferred_node_id, False, part),
            )

    def poll(self, now: float) -> list[TransferFrame]:
        """The frames to send at ``now``: a follow-up due (rule D.2), or a first-stage
        request when the request timer has expired (rule B)."""
        now = check_seconds("poll", "now", now)
        if self.node_id is not None:
            return []
        if self._followup is not None and self._followup.time <= now:
            message = self._followup.message
            self._followup = None
        elif now >= self._request_at:
            self._restart_timer(now)
            message = Allocation(self.preferred_node_id, True, self.unique_id[:STAGE_SIZE])
        else:
            return []
        self._sent = message
        frame = anonymous_frame(message, self._transfer_id, self.priority)
        self._transfer_id = (self._transfer_id + 1) % TRANSFER_ID_MODULO
        return [frame]

    def next_time(self) -> float | None:
        """When `poll` next has a frame to send; None once a node id is granted."""
        if self.node_id is not None:
            return None
        if self._followup is not None:
            return min(self._followup.time, self._request_at)
        return self._request_at
