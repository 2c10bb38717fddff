"""The node table: who is on the bus, from the NodeStatus messages seen (sans-IO)."""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, replace

from veronte4x.display import table
from veronte4x.dronecan.messages import Health, Mode, NodeStatus
from veronte4x.dronecan.transfer import Transfer
from veronte4x.times import format_time
from veronte4x.values import shown

OFFLINE_TIMEOUT = NodeStatus.OFFLINE_TIMEOUT_MS / 1000
"""Seconds without a NodeStatus after which a node counts as gone (DSDL OFFLINE_TIMEOUT_MS)."""


@dataclass(frozen=True, slots=True)
class NodeEntry:
    """What the latest NodeStatus of a node said, and when it came.

    Attributes:
        node_id: The node.
        health: Its health.
        mode: Its mode (an int for reserved values).
        sub_mode: Its sub-mode.
        vendor_specific_status_code: Its vendor status code.
        uptime_sec: Its uptime, s.
        first_seen: Time of its first NodeStatus in this table.
        last_seen: Time of its latest NodeStatus.
        restarts: How often its uptime went backwards (a restart) while watched.
    """

    node_id: int
    health: Health
    mode: Mode | int
    sub_mode: int
    vendor_specific_status_code: int
    uptime_sec: int
    first_seen: float
    last_seen: float
    restarts: int = 0

    def online(self, now: float) -> bool:
        """Whether its latest NodeStatus is less than `OFFLINE_TIMEOUT` old at ``now``."""
        return now - self.last_seen < OFFLINE_TIMEOUT

    def _repr_html_(self) -> str:
        """Jupyter's view: a one-row node table (`nodes_html`)."""
        return nodes_html([self], f"node {self.node_id}")


class NodeTable:
    """Nodes by id, updated from NodeStatus transfers given with their timestamps.

    Examples:
        >>> from veronte4x import dronecan
        >>> table = NodeTable()
        >>> status = dronecan.NodeStatus(5, dronecan.Health.OK, dronecan.Mode.OPERATIONAL, 0, 0)
        >>> entry = table.observe_status(21, status, 10.0)
        >>> entry.node_id, entry.uptime_sec, [e.node_id for e in table.online(12.0)]
        (21, 5, [21])
        >>> table.online(13.5)
        []
    """

    def __init__(self) -> None:
        self._nodes: dict[int, NodeEntry] = {}

    def observe(self, transfer: Transfer) -> NodeEntry | None:
        """Take any transfer; a NodeStatus updates its sender's entry, which is returned."""
        if not isinstance(transfer.message, NodeStatus) or transfer.source_node_id is None:
            return None
        return self.observe_status(transfer.source_node_id, transfer.message, transfer.timestamp)

    def observe_status(self, node_id: int, status: NodeStatus, timestamp: float) -> NodeEntry:
        """Record one NodeStatus of ``node_id`` received at ``timestamp``."""
        old = self._nodes.get(node_id)
        entry = NodeEntry(
            node_id,
            status.health,
            status.mode,
            status.sub_mode,
            status.vendor_specific_status_code,
            status.uptime_sec,
            timestamp if old is None else old.first_seen,
            timestamp,
            0 if old is None else old.restarts,
        )
        if old is not None and status.uptime_sec < old.uptime_sec:
            entry = replace(entry, restarts=old.restarts + 1)
        self._nodes[node_id] = entry
        return entry

    def get(self, node_id: int) -> NodeEntry | None:
        """The entry of ``node_id``, or None if it was never seen."""
        return self._nodes.get(node_id)

    def all(self) -> list[NodeEntry]:
        """Every node ever seen, by id."""
        return [self._nodes[n] for n in sorted(self._nodes)]

    def online(self, now: float) -> list[NodeEntry]:
        """The nodes seen within `OFFLINE_TIMEOUT` of ``now``, by id."""
        return [entry for entry in self.all() if entry.online(now)]

    def _repr_html_(self) -> str:
        """Jupyter's view: every node seen, one row each (`nodes_html`)."""
        return nodes_html(self.all(), "nodes")


def nodes_html(entries: Iterable[NodeEntry], caption: str) -> str:
    """Node entries as an HTML table, one row each: status, uptime, when seen, restarts."""
    columns = (
        "node",
        "health",
        "mode",
        "sub-mode",
        "vendor code",
        "uptime (s)",
        "first seen",
        "last seen",
        "restarts",
    )
    rows = [
        (
            entry.node_id,
            shown(type(entry), "health", entry.health),
            shown(type(entry), "mode", entry.mode),
            entry.sub_mode,
            entry.vendor_specific_status_code,
            entry.uptime_sec,
            format_time(entry.first_seen),
            format_time(entry.last_seen),
            entry.restarts,
        )
        for entry in entries
    ]
    return table(caption, columns, rows)
