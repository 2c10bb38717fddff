"""`Peer`: simulated nodes on the far side of a `ClientProtocol`, some answers replaced.

Every frame goes through the real encoder and reassembler; time is an argument. The tests
use it for nodes that say something else than `SimulatedEsc` would: a node that keeps an
old value, refuses to save or to restart, or reports another image CRC.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

from veronte4x import dronecan
from veronte4x.client import operations as ops
from veronte4x.client.protocol import ClientProtocol
from veronte4x.simulator import SimulatedEsc


class Peer:
    """Simulated ESCs answering a client's frames, with some answers replaced.

    Args:
        escs: The simulated nodes.
        answer: Given each request the client sends, the response to send instead (from
            the node it was sent to), or None to let the simulated node answer.
    """

    def __init__(
        self, escs: Sequence[SimulatedEsc], answer: Callable[[Any], Any] | None = None
    ) -> None:
        self.escs = list(escs)
        self.answer = answer or (lambda request: None)
        self.requests: list[Any] = []
        """Every request the client sent, in order."""
        self._reassembler = dronecan.Reassembler()

    def exchange(self, protocol: ClientProtocol, runner: ops.Runner, now: float) -> None:
        """The client's frames to the nodes, theirs back at ``now``, the runner settled."""
        replies: list[dronecan.TransferFrame] = []
        pending: list[dronecan.TransferFrame] = []
        for frame in protocol.take_frames():
            pending.append(frame)
            transfer = self._reassembler.feed(frame.can_id, frame.data, now)
            if transfer is None:
                continue
            frames, pending = pending, []
            override = None
            if transfer.kind is dronecan.TransferKind.REQUEST:
                self.requests.append(transfer.message)
                override = self.answer(transfer.message)
            if override is None:
                for esc in self.escs:
                    for each in frames:
                        esc.receive(each.can_id, each.data, now)
            else:
                assert transfer.destination_node_id is not None
                replies += dronecan.encode(
                    override,
                    source_node_id=transfer.destination_node_id,
                    destination_node_id=transfer.source_node_id,
                    transfer_id=transfer.transfer_id,
                    priority=transfer.priority,
                )
        for esc in self.escs:
            replies += esc.poll(now)
        events = []
        for frame in replies:
            events += protocol.receive(frame.can_id, frame.data, now)
        runner.settle(events, now)

    def run(
        self,
        protocol: ClientProtocol,
        runner: ops.Runner,
        task: ops.Task[Any],
        step: float,
        start: float = 0.0,
    ) -> float:
        """Exchange every ``step`` seconds from ``start`` until ``task`` is done (within 60 s);
        return the time."""
        now = start
        while not task.done:
            now += step
            self.exchange(protocol, runner, now)
            assert now < start + 60, "the operation never ended"
        return now
