"""`Allocator`: a dynamic node ID allocation server, the centralized one (sans-IO).

The allocator of DroneCAN dynamic node ID allocation in its non-redundant configuration
(DroneCAN specification, 6 "Application-level functions", "Dynamic node ID allocation":
"Allocatee-allocator exchanges" and "Non-redundant allocator"). An allocatee sends its
unique id in anonymous ``uavcan.protocol.dynamic_node_id.Allocation`` messages of 6, 6
and 4 bytes; the allocator answers the first two with the unique id so far and the last
with the node id allocated, following the specification's pseudocode (``handleAllocation``:
a stage out of turn is ignored, a follow-up later than ``FOLLOWUP_TIMEOUT_MS`` starts over).

The node id: the one the table has for the unique id; else the preferred one if free, else
the nearest free above it, else below (the DSDL's ``findFreeNodeID``, `free_node_id`), in
1..125 (126 and 127 are the maintenance tools'). Taken are every node id of the table and
every node id seen on the bus, the allocator's own included. As the specification's duties
of the allocator say, each node seen on the bus is asked GetNodeInfo, and its unique id
goes into the table (a *mock entry* with unique id zero after 3 unanswered attempts);
requests wait until no node is still being asked, and until the allocator has listened
`LISTEN_FIRST` seconds, in which every node on the bus has published NodeStatus.

What contradicts the table is refused, each once, with one line (`AllocationConflict`):
a node that reports a unique id the table binds to another node id, a node at a node id
the table binds to another unique id, another allocator answering requests, no free node
id. An allocatee whose unique id or node id is disputed so gets nothing.

The table grows only through ``store`` before anything is sent: the adapter writes the
file (`veronte4x.client.allocation_table.save`), then the answer goes out. Nothing here
touches a bus or reads a clock.
"""

from __future__ import annotations

import functools
import os
from collections.abc import Callable, Sequence
from dataclasses import dataclass

from veronte4x.client import allocation_table
from veronte4x.client.allocation_table import (
    MOCK,
    AllocationConflictError,
    AllocationTable,
    Entry,
)
from veronte4x.client.nodes import OFFLINE_TIMEOUT
from veronte4x.client.operations import NOW, Listen, Operation
from veronte4x.client.protocol import ClientProtocol, Event, NodeIdConflict, Received, StatusSeen
from veronte4x.dronecan import Allocation
from veronte4x.dronecan.messages import GetNodeInfoRequest, GetNodeInfoResponse
from veronte4x.dronecan.transfer import Transfer
from veronte4x.node.allocatee import STAGE_SIZE, UNIQUE_ID_SIZE
from veronte4x.node.requests import DEFAULT_RETRIES, DEFAULT_TIMEOUT, Answered, TimedOut

DYNAMIC_NODE_IDS = range(1, 126)
"""The node ids an allocator hands out: 1..125 (the DSDL of ``Allocation``: 126 and 127
are for network maintenance tools)."""

FOLLOWUP_TIMEOUT = Allocation.FOLLOWUP_TIMEOUT_MS / 1000
"""Seconds after which an allocation in progress starts over (DSDL)."""

GET_NODE_INFO_ATTEMPTS = 3
"""GetNodeInfo requests to a node before it gets a mock entry (the specification: "after at
least 3 attempts")."""

LISTEN_FIRST = OFFLINE_TIMEOUT
"""Seconds the allocator listens before it serves requests: a node silent that long is
offline (DSDL ``NodeStatus.OFFLINE_TIMEOUT_MS``), so every node on the bus has been heard,
and none of their node ids is handed out."""


def free_node_id(preferred: int, taken: set[int], node_ids: range = DYNAMIC_NODE_IDS) -> int | None:
    """The node id to allocate: ``preferred`` if free, else the nearest free above it, else
    the nearest below; the highest free one for no preference (0). The DSDL's
    ``findFreeNodeID``, within ``node_ids`` (a preference above them starts at the top).

    Examples:
        >>> free_node_id(0, set()), free_node_id(21, {21, 22}), free_node_id(124, {124, 125})
        (125, 23, 123)
    """
    low, high = node_ids[0], node_ids[-1]
    start = min(max(preferred or high, low), high)
    candidates = (*range(start, high + 1), *range(start, low - 1, -1))
    return next((c for c in candidates if c not in taken), None)


@dataclass(frozen=True, slots=True)
class Allocated:
    """A node id sent to an allocatee.

    Attributes:
        node_id: The node id.
        unique_id: The allocatee's unique id.
        preferred_node_id: The node id it asked for, 0 for any.
        again: The table had it already: its node id of before.
    """

    node_id: int
    unique_id: bytes
    preferred_node_id: int
    again: bool


@dataclass(frozen=True, slots=True)
class NodeRecorded:
    """A node seen on the bus, entered into the table.

    Attributes:
        node_id: Its node id.
        unique_id: The unique id its GetNodeInfo reports; `MOCK` if it did not answer.
    """

    node_id: int
    unique_id: bytes


@dataclass(frozen=True, slots=True)
class AllocationConflict:
    """Something the allocator refuses, in one line that says what to do.

    Attributes:
        message: The line.
        node_id: The node id concerned, if one.
        unique_id: The unique id concerned, if one.
    """

    message: str
    node_id: int | None = None
    unique_id: bytes | None = None


AllocationEvent = Allocated | NodeRecorded | AllocationConflict
"""What `Allocator.receive` reports."""


def _stage(message: Allocation) -> int | None:
    """The stage of a request (1..3), None for a malformed one (the specification's
    ``detectRequestStage``)."""
    size = len(message.unique_id)
    if size not in (STAGE_SIZE, UNIQUE_ID_SIZE - 2 * STAGE_SIZE, UNIQUE_ID_SIZE):
        return None
    if message.first_part_of_unique_id:
        return 1
    if size == STAGE_SIZE:
        return 2
    return 3 if size < STAGE_SIZE else None


def _expected(query: bytes) -> int | None:
    """The stage the unique id heard so far calls for (``getExpectedStage``)."""
    if not query:
        return 1
    if len(query) >= 2 * STAGE_SIZE:
        return 3
    return 2 if len(query) >= STAGE_SIZE else None


class Allocator:
    """A centralized dynamic node ID allocation server on a `ClientProtocol`.

    Give it every event of the protocol (`receive`); it asks GetNodeInfo and broadcasts its
    answers through the protocol, whose frames the adapter sends.

    Args:
        protocol: The node it serves from (its node id answers the allocatees).
        table: The allocation table; it grows.
        now: When it starts listening.
        store: Called with the table each time it grows, before anything is sent (the
            adapter's file write); an error from it goes out of `receive`.
        node_ids: The node ids it hands out.
        listen_first: Seconds it listens before serving requests (`LISTEN_FIRST`).
        info_timeout: Seconds each GetNodeInfo waits.
        info_retries: Times a GetNodeInfo is sent again, at least
            `GET_NODE_INFO_ATTEMPTS` - 1.

    Examples:
        >>> from veronte4x.dronecan import Reassembler
        >>> from veronte4x.node.allocatee import Allocatee
        >>> server, node = ClientProtocol(1), Allocatee(bytes(range(16)), 21)
        >>> allocator = Allocator(server, AllocationTable(), now=-5.0)
        >>> heard, time, events = Reassembler(), 0.0, []
        >>> while node.node_id is None and time < 10:
        ...     time += 0.01
        ...     for frame in node.poll(time):
        ...         events += allocator.receive(server.receive(*frame, time), time)
        ...     for frame in server.take_frames():
        ...         transfer = heard.feed(*frame, time)
        ...         if transfer is not None:
        ...             node.receive(transfer)
        >>> node.node_id, [(e.node_id, e.again) for e in events], len(allocator.table)
        (21, [(21, False)], 1)
    """

    def __init__(
        self,
        protocol: ClientProtocol,
        table: AllocationTable,
        now: float,
        *,
        store: Callable[[AllocationTable], object] | None = None,
        node_ids: range = DYNAMIC_NODE_IDS,
        listen_first: float = LISTEN_FIRST,
        info_timeout: float = DEFAULT_TIMEOUT,
        info_retries: int = DEFAULT_RETRIES,
    ) -> None:
        self.protocol = protocol
        self.table = table
        self.store = store
        self.node_ids = node_ids
        self.info_timeout = info_timeout
        self.info_retries = max(info_retries, GET_NODE_INFO_ATTEMPTS - 1)
        self.ready_at = now + listen_first
        """When it starts serving requests."""
        self._asking: dict[int, int] = {}  # GetNodeInfo handle: node id
        self._restarts: dict[int, int] = {}  # node id: its restarts when last asked
        self._disputed_ids: set[int] = set()
        self._disputed: set[bytes] = set()
        self._reported: set[str] = set()
        self._query = b""
        self._query_time = float("-inf")

    @classmethod
    def from_file(
        cls,
        protocol: ClientProtocol,
        path: str | os.PathLike[str],
        now: float,
        *,
        info_timeout: float = DEFAULT_TIMEOUT,
        info_retries: int = DEFAULT_RETRIES,
    ) -> Allocator:
        """An allocator whose table is the file at ``path`` (`allocation_table.load`; none
        yet is an empty table), written whole each time it grows (`allocation_table.save`);
        the other arguments as the constructor's.

        Raises:
            AllocationTableError: The file is not a valid allocation table.
            OSError: It cannot be read.
        """
        return cls(
            protocol,
            allocation_table.load(path),
            now,
            store=functools.partial(allocation_table.save, path),
            info_timeout=info_timeout,
            info_retries=info_retries,
        )

    def receive(self, events: Sequence[Event], now: float) -> list[AllocationEvent]:
        """Take the protocol's events at ``now``; return what the allocator did.

        Raises:
            NodeIdConflictError: Another node sends with the allocator's node id.
            Exception: What ``store`` raised (nothing of that change was sent, and the
                table is as before it).
        """
        out: list[AllocationEvent] = []
        for event in events:
            if isinstance(event, NodeIdConflict):
                raise event.error
            if isinstance(event, StatusSeen):
                self._seen(event.entry.node_id, event.entry.restarts, now, out)
            elif isinstance(event, (Answered, TimedOut)):
                node_id = self._asking.pop(event.request.handle, None)
                if node_id is not None:
                    answer = event.transfer.message if isinstance(event, Answered) else None
                    self._identified(node_id, answer, out)
            elif isinstance(event, Received) and isinstance(event.transfer.message, Allocation):
                self._allocation(event.transfer, out)
        return out

    def _report(self, out: list[AllocationEvent], conflict: AllocationConflict) -> None:
        if conflict.message not in self._reported:
            self._reported.add(conflict.message)
            out.append(conflict)

    def _grow(self, entry: Entry) -> None:
        """Add an entry: stored first, so that a failing store leaves the table as the file
        has it."""
        grown = AllocationTable((*self.table, entry))
        if self.store is not None:
            self.store(grown)
        self.table.add(entry)

    # -- the nodes on the bus ---------------------------------------------------------------

    def _seen(self, node_id: int, restarts: int, now: float, out: list[AllocationEvent]) -> None:
        """A NodeStatus: a node not asked yet, or restarted since, is asked GetNodeInfo."""
        if node_id == self.protocol.node_id:
            self._report(
                out,
                AllocationConflict(
                    f"node {node_id}, this allocation server's node id, is on the bus: give "
                    "the server another one with --node-id",
                    node_id,
                ),
            )
            return
        if self._restarts.get(node_id) == restarts or node_id in self._asking.values():
            return
        self._restarts[node_id] = restarts
        handle = self.protocol.request(
            GetNodeInfoRequest(),
            node_id,
            now,
            timeout=self.info_timeout,
            retries=self.info_retries,
        )
        self._asking[handle] = node_id

    def _identified(
        self, node_id: int, info: GetNodeInfoResponse | None, out: list[AllocationEvent]
    ) -> None:
        """A GetNodeInfo answer (None: none after every attempt) goes into the table."""
        unique_id = MOCK if info is None else info.hardware_version.unique_id
        if unique_id == MOCK and self.table.unique_id(node_id) is not None:
            return
        before = self.table.unique_id(node_id)
        try:
            self._grow(Entry(node_id, unique_id))
        except AllocationConflictError as error:
            self._disputed_ids.add(node_id)
            self._disputed.add(unique_id)
            self._report(
                out,
                AllocationConflict(
                    f"node {node_id} on the bus reports unique id {unique_id.hex()}, but {error} "
                    "in the allocation table: two nodes with one unique id, or a node replaced; "
                    "no allocation for either until its line is removed from the table or the "
                    "node from the bus",
                    node_id,
                    unique_id,
                ),
            )
            return
        if before != unique_id:
            out.append(NodeRecorded(node_id, unique_id))

    # -- allocation requests ----------------------------------------------------------------

    def _allocation(self, transfer: Transfer, out: list[AllocationEvent]) -> None:
        """One Allocation message: the specification's ``handleAllocation``."""
        if transfer.source_node_id is not None:
            self._report(
                out,
                AllocationConflict(
                    f"node {transfer.source_node_id} answers allocation requests too: a "
                    "centralized allocation server must be the only one on the bus",
                    transfer.source_node_id,
                ),
            )
            return
        now = transfer.timestamp
        if now < self.ready_at or self._asking:
            return  # every node on the bus must be known first
        message = transfer.message
        if now > self._query_time + FOLLOWUP_TIMEOUT:
            self._query = b""
        stage = _stage(message)
        if stage is None or stage != _expected(self._query):
            return
        if len(message.unique_id) > UNIQUE_ID_SIZE - len(self._query):
            return
        self._query += message.unique_id
        if len(self._query) == UNIQUE_ID_SIZE:
            query, self._query = self._query, b""
            self._grant(query, message.node_id, out)
        else:
            self.protocol.broadcast(Allocation(0, False, self._query))
        self._query_time = now

    def _grant(self, unique_id: bytes, preferred: int, out: list[AllocationEvent]) -> None:
        """A whole unique id: its node id of before, or a free one, or a refusal."""
        node_id = self.table.node_id(unique_id)
        if unique_id in self._disputed or node_id in self._disputed_ids:
            self._report(
                out,
                AllocationConflict(
                    f"no node id for unique id {unique_id.hex()}: it or its node id "
                    f"{node_id} is disputed (see above)",
                    node_id,
                    unique_id,
                ),
            )
            return
        again = node_id is not None
        if node_id is None:
            taken = {e.node_id for e in self.table} | self._disputed_ids
            taken |= {e.node_id for e in self.protocol.nodes.all()}
            taken.add(self.protocol.node_id)
            node_id = free_node_id(preferred, taken, self.node_ids)
            if node_id is None:
                self._report(
                    out,
                    AllocationConflict(
                        f"no free node id in {self.node_ids[0]}..{self.node_ids[-1]} for "
                        f"unique id {unique_id.hex()}: every one is in the table or on the bus",
                        None,
                        unique_id,
                    ),
                )
                return
            self._grow(Entry(node_id, unique_id))
        self.protocol.broadcast(Allocation(node_id, False, unique_id))
        out.append(Allocated(node_id, unique_id, preferred, again))


def serve(
    allocator: Allocator,
    duration: float | None = None,
    on_event: Callable[[AllocationEvent], object] | None = None,
) -> Operation[list[AllocationEvent]]:
    """Serve allocations for ``duration`` seconds (None: until stopped); each event goes to
    ``on_event`` as it comes. Returns every event.

    Raises:
        NodeIdConflictError: Another node sends with the allocator's node id.
    """
    now: float = yield NOW
    end = None if duration is None else now + duration
    happened: list[AllocationEvent] = []
    while end is None or now < end:
        events, now = yield Listen(end)
        for event in allocator.receive(events, now):
            happened.append(event)
            if on_event is not None:
                on_event(event)
    return happened
