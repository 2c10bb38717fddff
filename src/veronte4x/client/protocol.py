"""`ClientProtocol`: the ground station's DroneCAN node, frames in and frames out (sans-IO).

It reassembles what it is given, keeps the node table, matches responses with requests,
retries and times them out, and answers the file requests of nodes pulling a served file.
Nothing here touches a bus or reads a clock: an adapter (`veronte4x.client.bus`) feeds it
frames with their timestamps, calls `ClientProtocol.poll` with the time, and sends what
`ClientProtocol.take_frames` returns.
"""

from __future__ import annotations

from collections import Counter, deque
from dataclasses import dataclass
from typing import Any

from veronte4x.client.errors import NodeIdConflictError
from veronte4x.client.files import FileRead, FileServer
from veronte4x.client.nodes import NodeEntry, NodeTable
from veronte4x.dronecan.can_id import TransferKind, parse_can_id
from veronte4x.dronecan.codec import BY_CLASS, BY_ID
from veronte4x.dronecan.compiled import can_id_base
from veronte4x.dronecan.frame import TransferFrame
from veronte4x.dronecan.messages import FileGetInfoRequest, FileReadRequest, NodeStatus
from veronte4x.dronecan.reassembler import Reassembler
from veronte4x.dronecan.transfer import DEFAULT_PRIORITY, Transfer, encode
from veronte4x.errors import EncodeError, check_seconds
from veronte4x.node.requests import (
    DEFAULT_RETRIES,
    DEFAULT_TIMEOUT,
    Answered,
    Requester,
    TimedOut,
)
from veronte4x.node.transfer_ids import TransferIds

_TYPE_BITS = 0xFFFF80
"""The CAN ID bits of a message's data type id and the service bit (spec 4.1)."""

_NODE_STATUS = can_id_base(BY_CLASS[NodeStatus].data_type)
"""Those bits in a NodeStatus frame."""

_SERVICE = 0x80
"""The CAN ID bit of a service frame (spec 4.1)."""

SENT_RECORD = 4096
"""Service frames a client remembers having sent (`SentFrames`): far more than it sends
between sending a frame and hearing its echo."""

DEFAULT_NODE_ID = 127
"""The client's node id unless told otherwise: the DroneCAN GUI tool's default."""


@dataclass(frozen=True, slots=True)
class Received:
    """A complete transfer from the bus (any kind, any destination)."""

    transfer: Transfer


@dataclass(frozen=True, slots=True)
class StatusSeen:
    """A NodeStatus updated the node table."""

    entry: NodeEntry


@dataclass(frozen=True, slots=True)
class FileServed:
    """The client answered a file request of ``node_id``."""

    node_id: int
    read: FileRead


@dataclass(frozen=True, slots=True)
class NodeIdConflict:
    """A service frame from this node's own id that it did not send: another tool (or
    node) uses the id, and from now on the client takes no answer (`NodeIdConflictError`)."""

    error: NodeIdConflictError


Event = Received | StatusSeen | Answered | TimedOut | FileServed | NodeIdConflict
"""What `ClientProtocol.receive` and `ClientProtocol.poll` report."""


class SentFrames:
    """The service frames a node sent lately, to tell their echoes from another sender's.

    A bus that loops frames back to their sender (python-can's ``udp_multicast``) gives
    each frame back once: a frame from this node's id is an echo while fewer copies of it
    came back than were sent; any other is another sender's. The oldest are forgotten past
    ``size``, their echoes taken first (a bus keeps the order of one sender's frames).

    Examples:
        >>> sent = SentFrames()
        >>> sent.add(0x1E0B95FF, b"\\xc0")
        >>> sent.echo(0x1E0B95FF, b"\\xc0"), sent.echo(0x1E0B95FF, b"\\xc0")
        (True, False)
    """

    def __init__(self, size: int = SENT_RECORD) -> None:
        self.size = size
        self._order: deque[tuple[int, bytes]] = deque()
        self._sent: Counter[tuple[int, bytes]] = Counter()
        self._echoed: Counter[tuple[int, bytes]] = Counter()

    def add(self, can_id: int, data: bytes) -> None:
        """Remember a frame sent."""
        key = (can_id, data)
        self._order.append(key)
        self._sent[key] += 1
        if len(self._order) > self.size:
            old = self._order.popleft()
            self._sent[old] -= 1
            if self._echoed[old]:
                self._echoed[old] -= 1
            if not self._sent[old]:
                del self._sent[old]
                self._echoed.pop(old, None)

    def echo(self, can_id: int, data: bytes) -> bool:
        """Whether a frame heard is the echo of one sent (then counted as come back)."""
        key = (can_id, data)
        if self._echoed[key] >= self._sent[key]:
            return False
        self._echoed[key] += 1
        return True


def heard(can_id: int) -> str:
    """A service frame's CAN ID in words: ``a uavcan.protocol.param.GetSet request to node
    21``."""
    fields = parse_can_id(can_id)
    codec = BY_ID.get((fields.kind, fields.data_type_id))
    name = f"data type {fields.data_type_id}" if codec is None else codec.data_type.full_name
    return f"a {name} {fields.kind.name.lower()} to node {fields.destination_node_id}"


class ClientProtocol:
    """A ground-station node on a DroneCAN bus, as a state machine.

    Args:
        node_id: This node's id, 1..127.
        priority: CAN priority of what it sends.
        first_transfer_id: Where every transfer id stream starts (see `TransferIds`).

    Examples:
        >>> from veronte4x import dronecan
        >>> from veronte4x.simulator import SimulatedEsc
        >>> client, esc = ClientProtocol(), SimulatedEsc(node_id=21)
        >>> handle = client.request(dronecan.GetNodeInfoRequest(), 21, now=0.0)
        >>> for frame in client.take_frames():
        ...     esc.receive(frame.can_id, frame.data, 0.0)
        >>> events = [e for f in esc.poll(0.01) for e in client.receive(f.can_id, f.data, 0.01)]
        >>> [type(e).__name__ for e in events]
        ['Received', 'Answered', 'Received', 'StatusSeen', 'Received', 'Received']
        >>> events[1].transfer.message.name
        b'iq_motion.esc'
    """

    def __init__(
        self,
        node_id: int = DEFAULT_NODE_ID,
        priority: int = DEFAULT_PRIORITY,
        first_transfer_id: int = 0,
    ) -> None:
        if isinstance(node_id, bool) or not isinstance(node_id, int) or not 1 <= node_id <= 127:
            raise EncodeError("ClientProtocol", "node_id", node_id, "a node id in 1..127")
        self.node_id = node_id
        self.priority = priority
        self.transfer_ids = TransferIds(first_transfer_id)
        self.requests = Requester(node_id, self.transfer_ids, priority)
        self.nodes = NodeTable()
        self.files = FileServer()
        self.reassembler = Reassembler()
        self.sent = SentFrames()
        self.conflict: NodeIdConflictError | None = None
        """Set by the first service frame from this node's id that it did not send."""
        self._outbox: list[TransferFrame] = []

    def receive(self, can_id: int, data: bytes, timestamp: float) -> list[Event]:
        """Take one frame (29-bit ``can_id``, data with its tail byte) seen at ``timestamp``.

        A frame whose source node id (CAN ID bits 0-6, DroneCAN specification, "CAN bus
        transport layer") is this node's own is its own frame echoed back, as buses that
        loop frames back to the sender do (python-can's ``udp_multicast``): it is dropped
        unread, as a CAN controller does not receive what it sends. But this node sends no
        NodeStatus, so one from its own id is another node's: it goes into the node table,
        where the conflict shows. A service frame from its own id that it did not send
        (`SentFrames`) is another tool's: the first gives a `NodeIdConflict`, and from then
        on no response is taken and every request refused, as nothing tells which tool an
        answer is for (a GetSet read by index, say). On a bus that gives each frame to
        every node in one order (CAN does), such a frame comes before any answer to it.
        """
        timestamp = check_seconds("receive", "timestamp", timestamp)
        if can_id & 0x7F == self.node_id and can_id & _TYPE_BITS != _NODE_STATUS:
            if can_id & _SERVICE and not self.sent.echo(can_id, data) and self.conflict is None:
                self.conflict = NodeIdConflictError(self.node_id, heard(can_id))
                return [NodeIdConflict(self.conflict)]
            return []
        transfer = self.reassembler.feed(can_id, data, timestamp)
        if transfer is None:
            return []
        events: list[Event] = [Received(transfer)]
        entry = self.nodes.observe(transfer)
        if entry is not None:
            events.append(StatusSeen(entry))
        if transfer.destination_node_id != self.node_id:
            return events
        if transfer.kind is TransferKind.RESPONSE:
            if self.conflict is not None:
                return events
            answered = self.requests.receive(transfer)
            if answered is not None:
                events.append(answered)
        elif isinstance(transfer.message, FileReadRequest):
            response, read = self.files.read(transfer.message)
            self._respond(transfer, response)
            assert transfer.source_node_id is not None  # a request is never anonymous
            events.append(FileServed(transfer.source_node_id, read))
        elif isinstance(transfer.message, FileGetInfoRequest):
            self._respond(transfer, self.files.get_info(transfer.message))
        return events

    def _respond(self, request: Transfer, response: Any) -> None:
        """Answer a request: same transfer id and priority (spec 4.1)."""
        self._outbox += encode(
            response,
            source_node_id=self.node_id,
            destination_node_id=request.source_node_id,
            transfer_id=request.transfer_id,
            priority=request.priority,
        )

    def request(
        self,
        message: Any,
        destination: int,
        now: float,
        *,
        timeout: float = DEFAULT_TIMEOUT,
        retries: int = DEFAULT_RETRIES,
    ) -> int:
        """Send a service request; its `Answered` or `TimedOut` event carries the handle.

        Raises:
            EncodeError: Not a request, or a field out of range.
            NodeIdConflictError: Another tool was heard sending with this node's id.
        """
        if self.conflict is not None:
            raise NodeIdConflictError(self.node_id, self.conflict.heard)
        return self.requests.request(message, destination, now, timeout=timeout, retries=retries)

    def broadcast(self, message: Any) -> None:
        """Send a message (e.g. RawCommand); transfer ids count per data type.

        Raises:
            EncodeError: Not a message, or a field out of range.
        """
        self._outbox += self.message_frames(message)

    def message_frames(self, message: Any) -> list[TransferFrame]:
        """The frames of a message with its next transfer id, for the caller to send at once
        (a command stream sends them from its own loop, past the outbox).

        Raises:
            EncodeError: Not a message, or a field out of range.
        """
        codec = BY_CLASS.get(type(message))
        if codec is None or codec.data_type.kind is not TransferKind.MESSAGE:
            raise EncodeError("broadcast", "message", message, "a DroneCAN message")
        transfer_id = self.transfer_ids.next(
            TransferKind.MESSAGE, codec.data_type.data_type_id, None
        )
        return encode(
            message, source_node_id=self.node_id, transfer_id=transfer_id, priority=self.priority
        )

    def poll(self, now: float) -> list[TimedOut]:
        """Retry or time out pending requests at ``now``."""
        return self.requests.poll(now)

    def take_frames(self) -> list[TransferFrame]:
        """Every frame to send now, in order: responses, messages, then requests."""
        frames = self._outbox + self.requests.take_frames()
        self._outbox = []
        for frame in frames:
            if frame.can_id & _SERVICE:
                self.sent.add(frame.can_id, frame.data)
        return frames

    def next_deadline(self) -> float | None:
        """When `poll` next has something to do."""
        return self.requests.next_deadline()
