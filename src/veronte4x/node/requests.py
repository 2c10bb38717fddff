"""Service requests as values: send, match the response, time out and retry (sans-IO).

`Requester` never reads a clock: every method takes the current time. The frames it wants
sent collect in its outbox (`Requester.take_frames`); responses are given to it as
reassembled transfers (`Requester.receive`), and `Requester.poll` reports the requests
whose time is up after their last retry. One node's requests of one type to one node go
out one at a time: a transfer id then names one pending request, so that no response is
taken for another request's (many requests at once, e.g. from an asyncio program, would
otherwise reuse the 32 transfer ids while their predecessors still wait).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Any

from veronte4x.dronecan.can_id import TransferKind
from veronte4x.dronecan.codec import BY_CLASS
from veronte4x.dronecan.frame import TransferFrame
from veronte4x.dronecan.messages import GetSetRequest, GetSetResponse
from veronte4x.dronecan.transfer import DEFAULT_PRIORITY, Transfer, encode
from veronte4x.errors import EncodeError, check_seconds
from veronte4x.node.transfer_ids import TransferIds

DEFAULT_TIMEOUT = 1.0
"""Seconds to wait for a response before retrying: the DroneCAN GUI tool's default."""

DEFAULT_RETRIES = 2
"""Times a request is sent again after a timeout before it fails."""


def answers(request: Any, response: Any) -> bool:
    """Whether ``response`` can be the answer to ``request``, as far as its data tells.

    Source, destination, data type and transfer id are matched by `Requester.receive`;
    this checks what the response says about its request. A GetSet response names the
    parameter (DSDL ``param.GetSet``): a reply naming another parameter answers another
    request, e.g. of another tool using the same node id and transfer id. An empty reply
    (no such parameter) and a reply to a request by index name nothing that can be
    checked. The other services' responses (GetNodeInfo, ExecuteOpcode, RestartNode,
    BeginFirmwareUpdate, file.GetInfo, file.Read) carry nothing of their request.
    """
    if isinstance(request, GetSetRequest) and isinstance(response, GetSetResponse):
        return not request.name or not response.name or response.name == request.name
    return True


@dataclass(frozen=True, slots=True)
class Pending:
    """A request waiting for its response.

    Attributes:
        handle: The number `Requester.request` returned.
        message: The request.
        destination: The node asked.
        data_type_id: The request's data type id.
        transfer_ids: The transfer id of each attempt so far (a late answer to any counts).
        deadline: When the current attempt times out.
        timeout: Seconds each attempt waits.
        retries_left: Attempts still allowed after this one.
    """

    handle: int
    message: Any
    destination: int
    data_type_id: int
    transfer_ids: tuple[int, ...]
    deadline: float
    timeout: float
    retries_left: int

    @property
    def request_name(self) -> str:
        """The DSDL name of the request, e.g. ``uavcan.protocol.GetNodeInfo``."""
        return BY_CLASS[type(self.message)].data_type.full_name


@dataclass(frozen=True, slots=True)
class Answered:
    """A request got its response.

    Attributes:
        request: The request as it was pending.
        transfer: The response transfer.
    """

    request: Pending
    transfer: Transfer


@dataclass(frozen=True, slots=True)
class TimedOut:
    """A request got no response, after every retry.

    Attributes:
        request: The request as it was pending (``transfer_ids`` has one id per attempt).
    """

    request: Pending

    @property
    def attempts(self) -> int:
        """How many times the request was sent."""
        return len(self.request.transfer_ids)


class Requester:
    """Service requests from node ``node_id``, matched with their responses.

    Args:
        node_id: This node's id, 1..127.
        transfer_ids: The transfer id counters to share with other senders of this node.
        priority: CAN priority of the requests.

    Examples:
        >>> from veronte4x import dronecan
        >>> requester = Requester(node_id=127)
        >>> handle = requester.request(dronecan.GetNodeInfoRequest(), 21, now=0.0)
        >>> [hex(f.can_id) for f in requester.take_frames()]
        ['0x100195ff']
        >>> requester.poll(1.5), len(requester.take_frames())  # timed out once: sent again
        ([], 1)
        >>> [t.attempts for t in requester.poll(2.5) + requester.poll(3.5)]
        [3]
    """

    def __init__(
        self,
        node_id: int,
        transfer_ids: TransferIds | None = None,
        priority: int = DEFAULT_PRIORITY,
    ) -> None:
        self.node_id = node_id
        self.priority = priority
        self.transfer_ids = transfer_ids or TransferIds()
        self._pending: dict[int, Pending] = {}
        self._queued: dict[int, Pending] = {}
        """Requests waiting for an earlier one of their node and type, in order; a queued
        request's ``deadline`` is when it was queued (sent at the first `poll` it is free)."""
        self._outbox: list[TransferFrame] = []
        self._handles = 0
        self.mismatched = 0
        """Responses that matched a request's node, type and transfer id but answered
        another request (see `answers`): discarded, the request still waits."""

    def request(
        self,
        message: Any,
        destination: int,
        now: float,
        *,
        timeout: float = DEFAULT_TIMEOUT,
        retries: int = DEFAULT_RETRIES,
    ) -> int:
        """Queue a request to ``destination``; return its handle.

        Raises:
            EncodeError: Not a request class, a field out of range, or a timeout that is
                not a finite number of seconds above 0.
            TypeError: ``now`` or ``timeout`` is not a number of seconds.
        """
        now = check_seconds("request", "now", now)
        timeout = check_seconds("request", "timeout", timeout)
        if not 0 < timeout < math.inf:  # NaN would time out at once, inf never
            raise EncodeError("request", "timeout", timeout, "a finite number of seconds above 0")
        codec = BY_CLASS.get(type(message))
        if codec is None or codec.data_type.kind is not TransferKind.REQUEST:
            raise EncodeError("request", "message", message, "a DroneCAN service request")
        self._handles += 1
        pending = Pending(
            self._handles,
            message,
            destination,
            codec.data_type.data_type_id,
            (),
            now,
            timeout,
            retries,
        )
        if self._busy(pending):
            self._queued[pending.handle] = pending
        else:
            self._pending[pending.handle] = self._send(pending, now)
        return pending.handle

    def _busy(self, request: Pending) -> bool:
        """Whether a request to the same node, of the same type, is pending."""
        return any(
            p.destination == request.destination and p.data_type_id == request.data_type_id
            for p in self._pending.values()
        )

    def _free(self) -> list[Pending]:
        """The queued requests that may go out now: the first of each node and type."""
        free: list[Pending] = []
        for queued in self._queued.values():
            if not self._busy(queued) and not any(
                q.destination == queued.destination and q.data_type_id == queued.data_type_id
                for q in free
            ):
                free.append(queued)
        return free

    def _send(self, pending: Pending, now: float) -> Pending:
        transfer_id = self.transfer_ids.next(
            TransferKind.REQUEST, pending.data_type_id, pending.destination
        )
        self._outbox += encode(
            pending.message,
            source_node_id=self.node_id,
            destination_node_id=pending.destination,
            transfer_id=transfer_id,
            priority=self.priority,
        )
        return replace(
            pending,
            transfer_ids=(*pending.transfer_ids, transfer_id),
            deadline=now + pending.timeout,
        )

    def take_frames(self) -> list[TransferFrame]:
        """The frames to send now, in order; the outbox is emptied."""
        frames, self._outbox = self._outbox, []
        return frames

    def receive(self, transfer: Transfer) -> Answered | None:
        """Match a received transfer with a pending request.

        A response matches when it comes from the node asked, to this node, with the
        request's data type and the transfer id of one of its attempts, and its data
        `answers` the request; one that fails only the last test is counted in
        `mismatched` and discarded.
        """
        if transfer.kind is not TransferKind.RESPONSE or transfer.destination_node_id != (
            self.node_id
        ):
            return None
        mismatched = False
        for handle, pending in self._pending.items():
            if (
                pending.destination == transfer.source_node_id
                and pending.data_type_id == transfer.data_type_id
                and transfer.transfer_id in pending.transfer_ids
            ):
                if answers(pending.message, transfer.message):
                    del self._pending[handle]
                    self._send_free(transfer.timestamp)
                    return Answered(pending, transfer)
                mismatched = True
        self.mismatched += mismatched
        return None

    def poll(self, now: float) -> list[TimedOut]:
        """Retry the requests whose attempt timed out at ``now``; return those out of retries."""
        now = check_seconds("poll", "now", now)
        failed = []
        for handle, pending in list(self._pending.items()):
            if now < pending.deadline:
                continue
            if pending.retries_left > 0:
                retry = replace(pending, retries_left=pending.retries_left - 1)
                self._pending[handle] = self._send(retry, now)
            else:
                del self._pending[handle]
                failed.append(TimedOut(pending))
        self._send_free(now)
        return failed

    def _send_free(self, now: float) -> None:
        """Send the queued requests whose predecessors have ended."""
        for queued in self._free():
            del self._queued[queued.handle]
            self._pending[queued.handle] = self._send(queued, now)

    def cancel(self, handle: int) -> None:
        """Forget a pending or queued request (its response, if any, is then ignored)."""
        self._pending.pop(handle, None)
        self._queued.pop(handle, None)

    def pending(self, handle: int) -> Pending | None:
        """The request of ``handle`` if it still waits (sent or queued), else None."""
        return self._pending.get(handle) or self._queued.get(handle)

    def next_deadline(self) -> float | None:
        """When `poll` next has something to do, or None with nothing pending."""
        return min((p.deadline for p in (*self._pending.values(), *self._free())), default=None)
