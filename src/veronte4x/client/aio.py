"""`AsyncBusClient`: the ground-station client for asyncio programs (the ``can`` extra).

The same operations as `veronte4x.client.bus.BusClient`, with the same semantics and
errors, awaited instead of blocking: both are loops over the sans-IO `Runner` of
`veronte4x.client.operations`, so nothing of a node's logic is written twice. Frames come
through python-can's asyncio support (a ``can.Notifier`` bound to the running loop feeding a
``can.AsyncBufferedReader``).

Examples:
    >>> import asyncio, can, threading
    >>> from veronte4x.simulator import SimulatedEsc
    >>> from veronte4x.simulator.can_node import EscBus
    >>> async def main(bus: can.BusABC) -> dict:
    ...     async with AsyncBusClient(bus) as client:
    ...         return (await client.get_param(21, "esc_index")).as_dict()
    >>> with can.Bus(interface="virtual", channel="doc-aio") as a, can.Bus(
    ...     interface="virtual", channel="doc-aio"
    ... ) as b:
    ...     stop = threading.Event()
    ...     escs = threading.Thread(target=EscBus(a, [SimulatedEsc(21)]).run, args=(stop,))
    ...     escs.start()
    ...     try:
    ...         print(asyncio.run(main(b))["value"])
    ...     finally:
    ...         stop.set()
    ...         escs.join()
    0
"""

from __future__ import annotations

import asyncio
import time
from collections.abc import Callable, Sequence
from typing import Any, TypeVar

import can

from veronte4x.canbus import frame_to_message, is_dronecan_frame
from veronte4x.client import operations
from veronte4x.client.firmware import (
    MAX_IMAGE_SIZE,
    READ_TIMEOUT,
    RESTART_TIMEOUT,
    START_TIMEOUT,
    UpdateProgress,
)
from veronte4x.client.nodes import NodeEntry
from veronte4x.client.operations import Operation, Runner, Task
from veronte4x.client.params import ParameterInfo
from veronte4x.client.protocol import DEFAULT_NODE_ID, ClientProtocol, Event
from veronte4x.dronecan.messages import GetNodeInfoResponse, Opcode, Value
from veronte4x.dronecan.transfer import DEFAULT_PRIORITY
from veronte4x.node.requests import DEFAULT_RETRIES, DEFAULT_TIMEOUT

__all__ = ["AsyncBusClient"]

T = TypeVar("T")

MAX_WAIT = 0.05
"""Longest single wait for a frame, in seconds."""


class AsyncBusClient:
    """A ground-station node on a python-can bus, for asyncio: use ``async with``.

    Args:
        bus: Any python-can bus.
        node_id: This node's id, 1..127 (127 by default, like the DroneCAN GUI tool).
        clock: Seconds from any monotonic source; stamps frames and measures timeouts.
        timeout: Seconds to wait for each response.
        retries: Times a request is sent again after a timeout.
        priority: CAN priority of what it sends.
        first_transfer_id: Where every transfer id stream starts (see `TransferIds`).
    """

    def __init__(
        self,
        bus: can.BusABC,
        node_id: int = DEFAULT_NODE_ID,
        *,
        clock: Callable[[], float] = time.monotonic,
        timeout: float = DEFAULT_TIMEOUT,
        retries: int = DEFAULT_RETRIES,
        priority: int = DEFAULT_PRIORITY,
        first_transfer_id: int = 0,
    ) -> None:
        self.bus = bus
        self.protocol = ClientProtocol(node_id, priority, first_transfer_id)
        self.runner = Runner(self.protocol, timeout, retries)
        self.clock = clock
        self._reader: can.AsyncBufferedReader | None = None
        self._notifier: can.Notifier | None = None

    @property
    def node_id(self) -> int:
        """This client's node id."""
        return self.protocol.node_id

    async def __aenter__(self) -> AsyncBusClient:
        self.start()
        return self

    async def __aexit__(self, *exc: object) -> None:
        self.stop()

    def start(self) -> None:
        """Start receiving frames on the running event loop."""
        self._reader = can.AsyncBufferedReader()
        self._notifier = can.Notifier(self.bus, [self._reader], loop=asyncio.get_running_loop())

    def stop(self) -> None:
        """Stop receiving frames."""
        if self._notifier is not None:
            self._notifier.stop()
            self._notifier = None

    def _flush(self) -> None:
        for frame in self.protocol.take_frames():
            self.bus.send(frame_to_message(frame))

    async def spin_once(self, max_wait: float = MAX_WAIT) -> list[Event]:
        """Wait for frames (at most ``max_wait`` s), feed them in, send what is due.

        Returns:
            The events of the frames received and of the requests timed out.
        """
        if self._reader is None:
            raise RuntimeError("start the client first: async with AsyncBusClient(bus) as client")
        now = self.clock()
        for deadline in (self.protocol.next_deadline(), self.runner.next_deadline()):
            if deadline is not None:
                max_wait = max(0.0, min(max_wait, deadline - now))
        queue = self._reader.buffer
        message: can.Message | None
        try:
            message = await asyncio.wait_for(queue.get(), timeout=max_wait)
        except asyncio.TimeoutError:
            message = None
        events: list[Event] = []
        while message is not None:
            if is_dronecan_frame(message):
                events += self.protocol.receive(
                    message.arbitration_id, bytes(message.data), self.clock()
                )
            message = None if queue.empty() else queue.get_nowait()
        now = self.clock()
        events += self.protocol.poll(now)
        self.runner.feed(events, now)
        self.runner.poll(now)
        self._flush()
        return events

    async def run(self, operation: Operation[T]) -> T:
        """Run one operation of `veronte4x.client.operations` to its end; return its result."""
        task = self.runner.start(operation, self.clock())
        self._flush()
        try:
            while not task.done:
                await self.spin_once()
        finally:
            if not task.done:  # cancelled: forget its requests
                self.runner.cancel(task)
        return task.result()

    async def run_all(
        self, operations: Sequence[Operation[Any]], limit: int = 8
    ) -> list[Task[Any]]:
        """Run operations concurrently, at most ``limit`` at a time (as `BusClient.run_all`)."""
        waiting = list(reversed(operations))
        tasks: list[Task[Any]] = []
        running: list[Task[Any]] = []
        try:
            while waiting or running:
                while waiting and len(running) < limit:
                    task = self.runner.start(waiting.pop(), self.clock())
                    tasks.append(task)
                    running.append(task)
                self._flush()
                running = [t for t in running if not t.done]
                if running:
                    await self.spin_once()
                    running = [t for t in running if not t.done]
        finally:
            for task in running:
                self.runner.cancel(task)
        return tasks

    async def discover(self, duration: float = 1.1) -> list[NodeEntry]:
        """Listen for ``duration`` seconds; return the nodes online then, by id."""
        return await self.run(operations.discover(self.protocol, duration))

    async def node_info(self, node_id: int) -> GetNodeInfoResponse:
        """GetNodeInfo: status, software and hardware version, name."""
        return await self.run(operations.node_info(node_id))

    async def get_param(
        self, node_id: int, name: str | None = None, *, index: int | None = None
    ) -> ParameterInfo:
        """Read one parameter by name, or by ``index`` (see `BusClient.get_param`)."""
        return await self.run(operations.get_param(node_id, name, index=index))

    async def list_params(self, node_id: int) -> list[ParameterInfo]:
        """Every parameter, walking the indices from 0 to the first empty answer."""
        return await self.run(operations.list_params(node_id))

    async def set_param(
        self,
        node_id: int,
        name: str | None,
        value: int | float | bool | str | Value,
        *,
        index: int | None = None,
    ) -> ParameterInfo:
        """Set a parameter, checked first (see `BusClient.set_param`)."""
        return await self.run(operations.set_param(node_id, name, value, index=index))

    async def save_params(self, node_id: int) -> None:
        """Save the parameters to non-volatile storage (ExecuteOpcode SAVE)."""
        await self.run(operations.opcode(node_id, Opcode.SAVE))

    async def erase_params(self, node_id: int) -> None:
        """Clear the stored parameters back to defaults (ExecuteOpcode ERASE)."""
        await self.run(operations.opcode(node_id, Opcode.ERASE))

    async def restart(self, node_id: int, *, bootloader: bool = False) -> None:
        """RestartNode with the magic number (Vertiq's bootloader one with ``bootloader``)."""
        await self.run(operations.restart(node_id, bootloader=bootloader))

    async def update_firmware(
        self,
        node_id: int,
        image: bytes,
        path: str = "firmware.bin",
        *,
        progress: Callable[[UpdateProgress], object] | None = None,
        start_timeout: float = START_TIMEOUT,
        read_timeout: float = READ_TIMEOUT,
        restart_timeout: float = RESTART_TIMEOUT,
        max_image_size: int = MAX_IMAGE_SIZE,
    ) -> GetNodeInfoResponse:
        """Update a node's firmware (see `BusClient.update_firmware`)."""
        return await self.run(
            operations.update_firmware(
                self.protocol,
                node_id,
                image,
                path,
                progress=progress,
                start_timeout=start_timeout,
                read_timeout=read_timeout,
                restart_timeout=restart_timeout,
                max_image_size=max_image_size,
            )
        )
