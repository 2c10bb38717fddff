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
import os
import sys
from collections.abc import Callable, Iterable, Iterator, Sequence
from typing import Any, TypeVar

from veronte4x.errors import MissingExtraError

try:
    import can
except ModuleNotFoundError as missing:  # pragma: no cover - the can extra is installed in CI
    if missing.name != "can":
        raise
    raise MissingExtraError("can", "can", "veronte4x.client.aio") from None

from veronte4x.client import allocator, indices, operations
from veronte4x.client.adapter import (
    MAX_WAIT,
    BusAdapter,
    Progress,
    StreamBase,
    progress_callback,
)
from veronte4x.client.allocator import AllocationEvent, Allocator
from veronte4x.client.commander import DEFAULT_RATE, DEFAULT_WATCHDOG, Commander
from veronte4x.client.errors import OperationCancelledError
from veronte4x.client.firmware import (
    MAX_IMAGE_SIZE,
    READ_TIMEOUT,
    RESTART_TIMEOUT,
    START_TIMEOUT,
    FirmwareOptions,
)
from veronte4x.client.nodes import NodeEntry
from veronte4x.client.operations import Operation, OperationBatch, Task
from veronte4x.client.params import ParameterInfo
from veronte4x.client.protocol import Event
from veronte4x.client.spin import (
    DEFAULT_SILENCE,
    SETTLE,
    STEP,
    AllowUnknown,
    Spin,
    SpinResult,
    spin_plan,
)
from veronte4x.dronecan.messages import GetNodeInfoResponse, Opcode, RawCommand, Value

__all__ = ["AsyncBusClient", "AsyncCommandStream"]

T = TypeVar("T")


if sys.version_info >= (3, 11):

    async def _next(queue: asyncio.Queue[can.Message], timeout: float) -> can.Message | None:
        """The next message within ``timeout`` s, else None. A cancellation is never lost:
        ``asyncio.wait_for`` drops one that comes as the message does, before Python 3.12
        (CPython gh-86296), and the operation being cancelled went on."""
        try:
            async with asyncio.timeout(timeout):
                return await queue.get()
        except TimeoutError:
            return None

else:  # pragma: no cover - Python 3.10 has no asyncio.timeout

    async def _next(queue: asyncio.Queue[can.Message], timeout: float) -> can.Message | None:
        """The next message within ``timeout`` s, else None."""
        try:
            return await asyncio.wait_for(queue.get(), timeout=timeout)
        except asyncio.TimeoutError:
            return None


class AsyncBusClient(BusAdapter):
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

    _reader: can.AsyncBufferedReader | None = None
    _notifier: can.Notifier | None = None
    _reading: asyncio.Lock
    _streams: tuple[AsyncCommandStream, ...] = ()

    async def __aenter__(self) -> AsyncBusClient:
        self.start()
        return self

    async def __aexit__(self, *exc: object) -> None:
        running = [s._task for s in self._streams if s._task is not None]
        self.stop()
        if running:
            await asyncio.wait(running)  # cancelled by stop: they end at once

    def start(self) -> None:
        """Start receiving frames on the running event loop."""
        self._reading = asyncio.Lock()
        self._reader = can.AsyncBufferedReader()
        self._notifier = can.Notifier(self.bus, [self._reader], loop=asyncio.get_running_loop())

    def stop(self) -> None:
        """Stop receiving frames, and every command stream of this client still running:
        each sends zero throttle and sends nothing more (no stream outlives its client)."""
        for stream in self._streams:
            stream.close()
        self._streams = ()
        if self._notifier is not None:
            self._notifier.stop()
            self._notifier = None
        self._reader = None

    def _started(self) -> can.AsyncBufferedReader:
        """The reader, or a RuntimeError when the client was not started."""
        if self._reader is None:
            raise RuntimeError("start the client first: async with AsyncBusClient(bus) as client")
        return self._reader

    def _waiting(self, first: can.Message | None) -> Iterator[can.Message]:
        assert self._reader is not None
        queue = self._reader.buffer
        message = first
        while message is not None:
            yield message
            message = None if queue.empty() else queue.get_nowait()

    async def spin_once(self, max_wait: float = MAX_WAIT) -> list[Event]:
        """Wait for frames (at most ``max_wait`` s), feed them in, send what is due.

        Operations awaited at once (``asyncio.gather``) take turns: one waits on the bus and
        feeds in what came, for all of them (each waiting alone could take frames in one
        order and feed them in another, which loses multi-frame responses).

        Returns:
            The events of the frames received and of the requests timed out.
        """
        reader = self._started()
        async with self._reading:  # one reader at a time: frames are fed in bus order
            message = await _next(reader.buffer, self.wait_time(max_wait))
            return self.receive(self._waiting(message))

    async def run(self, operation: Operation[T]) -> T:
        """Run one operation of `veronte4x.client.operations` to its end; return its result."""
        result: T = (await self.run_all([operation], 1))[0].result()
        return result

    async def run_all(
        self, operations: Sequence[Operation[Any]], limit: int = 8
    ) -> list[Task[Any]]:
        """Run operations concurrently, at most ``limit`` at a time (as `BusClient.run_all`);
        a cancellation forgets the requests of those still running."""
        self._started()  # before anything is sent: no answer could be read
        batch = OperationBatch(self.runner, operations, limit)
        try:
            while batch.fill(self.clock()):
                self.flush()
                await self.spin_once()
            self.flush()
        finally:
            batch.cancel()
        return batch.tasks

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
        progress: Progress = None,
        start_timeout: float = START_TIMEOUT,
        read_timeout: float = READ_TIMEOUT,
        restart_timeout: float = RESTART_TIMEOUT,
        max_image_size: int = MAX_IMAGE_SIZE,
    ) -> GetNodeInfoResponse:
        """Update a node's firmware (see `BusClient.update_firmware`, ``progress`` too)."""
        with progress_callback(progress, node_id, len(image)) as report:
            return await self.run(
                operations.update_firmware(
                    self.protocol,
                    node_id,
                    image,
                    path,
                    progress=report,
                    options=FirmwareOptions(
                        start_timeout, read_timeout, restart_timeout, max_image_size
                    ),
                )
            )

    async def serve_allocations(
        self,
        table: str | os.PathLike[str],
        *,
        duration: float | None = None,
        on_event: Callable[[AllocationEvent], object] | None = None,
    ) -> list[AllocationEvent]:
        """Serve dynamic node ID allocations for ``duration`` seconds, or until cancelled
        (see `BusClient.serve_allocations`: the same table file, events and errors)."""
        self._started()  # before the table is read: no request could be heard
        served = Allocator.from_file(
            self.protocol, table, self.clock(), info_timeout=self.timeout, info_retries=self.retries
        )
        return await self.run(allocator.serve(served, duration, on_event))

    # -- motors -----------------------------------------------------------------------------

    def command_stream(
        self, rate: float = DEFAULT_RATE, watchdog: float = DEFAULT_WATCHDOG
    ) -> AsyncCommandStream:
        """An `AsyncCommandStream` from this client (start it with ``async with``)."""
        return AsyncCommandStream(self, Commander(rate, watchdog))

    async def spin(
        self,
        nodes: Iterable[int],
        throttle: float,
        duration: float,
        *,
        rate: float = DEFAULT_RATE,
        watchdog: float = DEFAULT_WATCHDOG,
        silence: float = DEFAULT_SILENCE,
        max_temperature: float | None = None,
        max_current: float | None = None,
        allow_unknown: AllowUnknown = (),
        on_start: Callable[[Spin], object] | None = None,
    ) -> SpinResult:
        """Spin motors, watching them, then zero throttle (see `BusClient.spin`: the same
        checks, refusals, limits and errors); a cancellation sends zero throttle
        `AsyncCommandStream.STOP_REPEATS` times and nothing after, and goes on."""
        plan = spin_plan(
            nodes,
            throttle,
            duration,
            rate=rate,
            watchdog=watchdog,
            silence=silence,
            max_temperature=max_temperature,
            max_current=max_current,
            allow_unknown=allow_unknown,
        )
        found = await self.run(indices.survey(self.protocol, plan.nodes))
        spin = plan.start(found, self.clock())
        if on_start is not None:
            on_start(spin)
        async with self.command_stream(plan.rate, plan.watchdog) as stream:
            while spin.going(self.clock()):
                stream.set(spin.setpoint)
                spin.observe(await self.spin_once(STEP), self.clock())
        result = spin.result()
        settle = self.clock() + SETTLE
        while self.clock() < settle:
            await self.spin_once(STEP)
        return result


class AsyncCommandStream(StreamBase):
    """RawCommand sent from an asyncio task at a fixed rate, with a watchdog.

    The asyncio twin of `veronte4x.client.bus.CommandStream`, on the same `Commander`:
    refresh the throttles with `set` more often than the watchdog period; when refreshes
    stop, zero throttle is sent. Leaving the ``async with`` block, normally, by an exception
    or by a cancellation, stops the task and sends zero throttle `STOP_REPEATS` times
    before anything else can run on the loop. While the task that started the stream has a
    cancellation pending (``asyncio.wait_for``, ``asyncio.timeout``, ``Task.cancel``), the
    commands due go out at zero throttle: from a cancellation on, zero, then nothing once
    the block has ended (a cancellation the block catches lets the setpoints go on). The
    client's end stops its streams the same way, started with ``async with`` or not (`set`
    then raises `OperationCancelledError`). If
    sending fails in the task, it sends zero throttle if it can and stops; `set` and the
    end of the block raise that error.

    Args:
        client: The client whose bus and node id it uses.
        commander: The rate and watchdog (`Commander`).

    Examples:
        >>> import asyncio, can
        >>> async def drive(bus: can.BusABC) -> int:
        ...     async with AsyncBusClient(bus) as client:
        ...         async with client.command_stream(rate=100) as stream:
        ...             stream.set([0.5])
        ...             await asyncio.sleep(0.05)
        ...         return stream.sent
        >>> with can.Bus(interface="virtual", channel="doc-aio-stream") as bus:
        ...     asyncio.run(drive(bus)) > 3  # some at 50 %, then 3 at zero
        True
    """

    def __init__(self, client: AsyncBusClient, commander: Commander) -> None:
        super().__init__(client, commander)
        self._client = client
        self._task: asyncio.Task[None] | None = None
        self._owner: asyncio.Task[Any] | None = None
        self._closed = False

    async def _run(self) -> None:
        wait = 0.0
        try:
            while True:
                await asyncio.sleep(wait)
                wait = self._send_zero() if self._owner_cancelled() else self._send_due()
        except Exception as error:  # a failing bus
            self._failed(error)

    def _owner_cancelled(self) -> bool:
        """Whether the task that started the stream has a cancellation pending: it may be
        about to leave the block, so no throttle may go out (Python 3.10 cannot tell)."""
        cancelling = getattr(self._owner, "cancelling", None)
        return cancelling is not None and cancelling() > 0

    def _send_zero(self) -> float:
        """Send the command due now, if any, at zero throttle; the seconds to the next."""
        with self._lock:
            command = self.commander.poll(self.client.clock())
            wait = self.commander.wait(self.client.clock(), MAX_WAIT)
        if command is not None:
            self._send([RawCommand((0,) * len(command.cmd))])
        return wait

    def start(self) -> None:
        """Start sending on the running loop (nothing goes out before the first `set`),
        until `stop`, or until its client stops (`AsyncBusClient.stop`)."""
        self._owner = asyncio.current_task()
        self._task = asyncio.get_running_loop().create_task(self._run())
        self._client._streams = (*self._client._streams, self)

    def close(self) -> None:
        """Stop at once, from synchronous code (its client does this when it stops): the
        task is cancelled before it can send again, then zero throttle `STOP_REPEATS` times
        unless the stream had stopped already; `set` then raises `OperationCancelledError`."""
        self._cancel_task()
        if self.failure is None:
            self._failed(
                OperationCancelledError(
                    "the command stream stopped with its client: zero throttle was sent"
                )
            )
        self._closed = True

    async def stop(self) -> None:
        """Stop the task and send zero throttle `STOP_REPEATS` times, at once.

        Raises:
            Exception: The error that stopped the stream's task (not when its client
                stopped it: `close`).
        """
        task = self._cancel_task()
        self._client._streams = tuple(s for s in self._client._streams if s is not self)
        if not self._closed:
            self._stop_motors()
        if task is not None:
            await asyncio.wait([task])  # a cancellation of ours still ends this wait

    def _cancel_task(self) -> asyncio.Task[None] | None:
        """Cancel the sending task, if any, and forget it; the task (it sends nothing more:
        it only sends between its awaits)."""
        task, self._task = self._task, None
        if task is not None:
            task.cancel()
        return task

    async def __aenter__(self) -> AsyncCommandStream:
        self.start()
        return self

    async def __aexit__(self, kind: type[BaseException] | None, *exc: object) -> None:
        with self._stopping_at_block_end(kind):
            await self.stop()
