"""A small DroneCAN client on a python-can bus, for tests and examples (the ``can`` extra).

It sends messages and service requests and reassembles what comes back. Timeouts are
measured with the ``clock`` argument; a ``while_waiting`` callback (for example
`EscNode.step`) lets one thread run a simulated node and the client together.
"""

from __future__ import annotations

import time
from collections import deque
from collections.abc import Callable
from typing import Any

import can

from veronte4x.dronecan.can_id import TransferKind
from veronte4x.dronecan.reassembler import Reassembler
from veronte4x.dronecan.transfer import DEFAULT_PRIORITY, Transfer, encode
from veronte4x.simulator.can_node import to_message, wanted

__all__ = ["DroneCanClient"]

WAIT_STEP = 0.001
"""Longest single wait on the bus, in seconds, while a ``while_waiting`` callback runs."""


class DroneCanClient:
    """Send DroneCAN messages and requests from node ``node_id`` and collect transfers.

    Args:
        bus: Any python-can bus.
        node_id: This client's node id, 1..127.
        clock: Seconds from any monotonic source; stamps received frames and measures
            timeouts.
        priority: CAN priority of what it sends.

    Attributes:
        inbox: Transfers received and not yet returned (oldest first, at most 10000).
        reassembler: The reassembler of received frames.
    """

    def __init__(
        self,
        bus: can.BusABC,
        node_id: int,
        clock: Callable[[], float] = time.monotonic,
        priority: int = DEFAULT_PRIORITY,
    ) -> None:
        self.bus = bus
        self.node_id = node_id
        self.clock = clock
        self.priority = priority
        self.reassembler = Reassembler()
        self.inbox: deque[Transfer] = deque(maxlen=10_000)
        self._transfer_ids: dict[tuple[type, int | None], int] = {}

    def _send(self, message: Any, destination: int | None) -> int:
        key = (type(message), destination)
        transfer_id = self._transfer_ids.get(key, 0)
        self._transfer_ids[key] = (transfer_id + 1) & 0x1F
        for frame in encode(
            message,
            source_node_id=self.node_id,
            transfer_id=transfer_id,
            priority=self.priority,
            destination_node_id=destination,
        ):
            self.bus.send(to_message(frame))
        return transfer_id

    def send(self, message: Any) -> None:
        """Broadcast a message (e.g. a RawCommand); transfer ids count per type."""
        self._send(message, None)

    def _pump(self, wait: float) -> None:
        """Take what arrives within ``wait`` seconds and everything queued after it."""
        message = self.bus.recv(timeout=wait)
        while message is not None:
            if wanted(message):
                transfer = self.reassembler.feed(
                    message.arbitration_id, bytes(message.data), self.clock()
                )
                if transfer is not None:
                    self.inbox.append(transfer)
            message = self.bus.recv(timeout=0.0)

    def _wait(self, deadline: float, while_waiting: Callable[[], object] | None) -> bool:
        """One round of waiting; False once ``deadline`` has passed."""
        if while_waiting is not None:
            while_waiting()
        remaining = deadline - self.clock()
        if remaining <= 0:
            self._pump(0.0)
            return False
        self._pump(min(remaining, WAIT_STEP) if while_waiting is not None else remaining)
        return True

    def request(
        self,
        message: Any,
        destination: int,
        timeout: float = 1.0,
        *,
        while_waiting: Callable[[], object] | None = None,
    ) -> Transfer | None:
        """Send a service request and wait for its response.

        Args:
            message: A request (e.g. ``vertiq.get_parameter("esc_index")``).
            destination: The server's node id.
            timeout: Seconds of the clock to wait.
            while_waiting: Called before each wait, e.g. the simulated node's ``step``.

        Returns:
            The response transfer (same transfer id, from ``destination``), or None on
            timeout. Other transfers received meanwhile stay in `inbox`.
        """
        transfer_id = self._send(message, destination)
        deadline = self.clock() + timeout
        while True:
            waiting = self._wait(deadline, while_waiting)
            for transfer in self.inbox:
                if (
                    transfer.kind is TransferKind.RESPONSE
                    and transfer.source_node_id == destination
                    and transfer.destination_node_id == self.node_id
                    and transfer.transfer_id == transfer_id
                ):
                    self.inbox.remove(transfer)
                    return transfer
            if not waiting:
                return None

    def listen(
        self, duration: float, *, while_waiting: Callable[[], object] | None = None
    ) -> list[Transfer]:
        """Collect transfers for ``duration`` seconds of the clock; empties `inbox`."""
        deadline = self.clock() + duration
        while self._wait(deadline, while_waiting):
            pass
        received = list(self.inbox)
        self.inbox.clear()
        return received
