"""`BusClient`: the ground-station client on a python-can bus (the ``can`` extra).

The thin I/O side of `ClientProtocol`: it takes frames from the bus and stamps them with
its clock, sends what the protocol has to send, and blocks until a request is answered or
has timed out. Failures raise the errors of `veronte4x.client.errors`, each one line that
names the node and what it did not do.
"""

from __future__ import annotations

import os
import threading
import time
from collections.abc import Callable, Iterable, Iterator, Sequence
from typing import Any, TypeVar

from veronte4x.errors import MissingExtraError

try:
    import can
except ModuleNotFoundError as missing:  # pragma: no cover - the can extra is installed in CI
    if missing.name != "can":
        raise
    raise MissingExtraError("can", "can", "veronte4x.client.bus") from None

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
from veronte4x.client.protocol import DEFAULT_NODE_ID, Event, Received
from veronte4x.client.spin import (
    DEFAULT_SILENCE,
    SETTLE,
    STEP,
    AllowUnknown,
    Spin,
    SpinResult,
    spin_plan,
)
from veronte4x.dronecan.frame import TransferFrame
from veronte4x.dronecan.messages import GetNodeInfoResponse, Opcode, Value
from veronte4x.dronecan.transfer import DEFAULT_PRIORITY, Transfer
from veronte4x.node.requests import DEFAULT_RETRIES, DEFAULT_TIMEOUT

__all__ = ["BusClient", "CommandStream"]

T = TypeVar("T")

WAIT_STEP = 0.001
"""Longest single wait while a ``while_waiting`` callback runs."""


class BusClient(BusAdapter):
    """A ground-station node on a python-can bus: discovery, services, firmware update.

    Args:
        bus: Any python-can bus.
        node_id: This node's id, 1..127 (127 by default, like the DroneCAN GUI tool).
        clock: Seconds from any monotonic source; stamps frames and measures timeouts.
        timeout: Seconds to wait for each response.
        retries: Times a request is sent again after a timeout.
        while_waiting: Called before each short wait on the bus (e.g. a simulated node's
            ``step``, to run it in the same thread).
        priority: CAN priority of what it sends.
        first_transfer_id: Where every transfer id stream starts; a tool that runs briefly
            and often should pick it at random (see `TransferIds`).

    Examples:
        >>> import can
        >>> from veronte4x.simulator import SimulatedEsc
        >>> from veronte4x.simulator.can_node import EscBus
        >>> with can.Bus(interface="virtual", channel="doc-client") as a, can.Bus(
        ...     interface="virtual", channel="doc-client"
        ... ) as b:
        ...     escs = EscBus(a, [SimulatedEsc(21)], clock=time.monotonic)
        ...     client = BusClient(b, while_waiting=escs.step)
        ...     client.get_param(21, "esc_index").as_dict()
        {'name': 'esc_index', 'value': 0, 'default': 0, 'min': 0, 'max': 19, 'index': None}
    """

    def __init__(
        self,
        bus: can.BusABC,
        node_id: int = DEFAULT_NODE_ID,
        *,
        clock: Callable[[], float] = time.monotonic,
        timeout: float = DEFAULT_TIMEOUT,
        retries: int = DEFAULT_RETRIES,
        while_waiting: Callable[[], object] | None = None,
        priority: int = DEFAULT_PRIORITY,
        first_transfer_id: int = 0,
    ) -> None:
        super().__init__(
            bus,
            node_id,
            clock=clock,
            timeout=timeout,
            retries=retries,
            priority=priority,
            first_transfer_id=first_transfer_id,
        )
        self.while_waiting = while_waiting
        self._lock = threading.Lock()

    # -- I/O ----------------------------------------------------------------------------

    def send_frames(self, frames: Iterable[TransferFrame]) -> None:
        """Send frames in order (thread-safe with `CommandStream`)."""
        with self._lock:
            super().send_frames(frames)

    def _messages(self, wait: float) -> Iterator[can.Message]:
        message = self.bus.recv(timeout=wait)
        while message is not None:
            yield message
            message = self.bus.recv(timeout=0.0)

    def spin_once(self, max_wait: float = MAX_WAIT) -> list[Event]:
        """Wait for frames (at most ``max_wait`` s), feed them in, send what is due.

        Returns:
            The events of the frames received and of the requests timed out.
        """
        if self.while_waiting is not None:
            self.while_waiting()
            max_wait = min(max_wait, WAIT_STEP)
        return self.receive(self._messages(self.wait_time(max_wait)))

    # -- operations -------------------------------------------------------------------------

    def run(self, operation: Operation[T]) -> T:
        """Run one operation of `veronte4x.client.operations` to its end; return its result.

        Raises:
            Exception: The operation's error (`NoResponseError`, `ParameterError`, ...).
        """
        result: T = self.run_all([operation], 1)[0].result()
        return result

    def run_all(self, operations: Sequence[Operation[Any]], limit: int = 8) -> list[Task[Any]]:
        """Run operations concurrently, at most ``limit`` at a time; return their tasks, done,
        in the order given (each holds its result or its error).

        Operations on different nodes proceed side by side: each waits only for its own
        answers, as the bus carries every node's traffic interleaved. An exception (e.g.
        KeyboardInterrupt) forgets the requests of those still running.
        """
        batch = OperationBatch(self.runner, operations, limit)
        try:
            while batch.fill(self.clock()):
                self.flush()
                self.spin_once()
            self.flush()
        finally:
            batch.cancel()
        return batch.tasks

    def call(
        self,
        request: Any,
        node_id: int,
        *,
        timeout: float | None = None,
        retries: int | None = None,
    ) -> Any:
        """Send a service request and return the response message.

        Raises:
            NoResponseError: No response after every retry.
            EncodeError: The request cannot be encoded.
        """
        return self.run(operations.call(request, node_id, timeout, retries))

    def broadcast(self, message: Any) -> None:
        """Send a message now (e.g. one RawCommand); transfer ids count per data type."""
        self.protocol.broadcast(message)
        self.flush()

    def listen(self, duration: float) -> list[Transfer]:
        """Every transfer received within ``duration`` seconds of the clock, in order."""
        end = self.clock() + duration
        heard = []
        while True:
            remaining = end - self.clock()
            events = self.spin_once(min(MAX_WAIT, max(0.0, remaining)))
            heard += [e.transfer for e in events if isinstance(e, Received)]
            if remaining <= 0:
                return heard

    def discover(self, duration: float = 1.1) -> list[NodeEntry]:
        """Listen for ``duration`` seconds; return the nodes online then, by id.

        Nodes publish NodeStatus at least once a second (DSDL MAX_BROADCASTING_PERIOD_MS),
        so the default hears every node once.
        """
        return self.run(operations.discover(self.protocol, duration))

    def node_info(self, node_id: int) -> GetNodeInfoResponse:
        """GetNodeInfo: status, software and hardware version, name."""
        return self.run(operations.node_info(node_id))

    def get_param(
        self, node_id: int, name: str | None = None, *, index: int | None = None
    ) -> ParameterInfo:
        """Read one parameter by name, or by ``index`` when asked for explicitly.

        Vertiq's modules are best read by name: their indices may change between firmware
        versions and serve for discovery only. An empty name is refused: GetSet reads by
        index when the name is empty, and index 0 is ``uavcan_node_id``.

        Raises:
            InvalidRequestError: An empty name, or both or neither of name and index.
            ParameterError: The node has no such parameter.
        """
        return self.run(operations.get_param(node_id, name, index=index))

    def list_params(self, node_id: int) -> list[ParameterInfo]:
        """Every parameter, walking the indices from 0 to the first empty answer."""
        return self.run(operations.list_params(node_id))

    def set_param(
        self,
        node_id: int,
        name: str | None,
        value: int | float | bool | str | Value,
        *,
        index: int | None = None,
    ) -> ParameterInfo:
        """Set a parameter by name (or by ``index``, given with ``name=None``); return what
        the node reports after the set.

        The parameter is read first: a ``str`` is parsed as a value of its type, and a value
        of another type or outside the node's range is refused before anything is set.

        Raises:
            InvalidRequestError: An empty name, both or neither of name and index, or a
                text value that does not parse as the parameter's type.
            ParameterError: No such parameter, a wrong type or a value out of range.
            RejectedError: The node kept another value.
        """
        return self.run(operations.set_param(node_id, name, value, index=index))

    def save_params(self, node_id: int) -> None:
        """Save the parameters to non-volatile storage (ExecuteOpcode SAVE)."""
        self.run(operations.opcode(node_id, Opcode.SAVE))

    def erase_params(self, node_id: int) -> None:
        """Clear the stored parameters back to defaults (ExecuteOpcode ERASE)."""
        self.run(operations.opcode(node_id, Opcode.ERASE))

    def restart(self, node_id: int, *, bootloader: bool = False) -> None:
        """RestartNode with the magic number (Vertiq's bootloader one with ``bootloader``).

        Raises:
            RejectedError: The node answered that it does not restart.
        """
        self.run(operations.restart(node_id, bootloader=bootloader))

    def update_firmware(
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
        """Update a node's firmware: BeginFirmwareUpdate, serve its reads, wait for it.

        Args:
            node_id: The node.
            image: The firmware image.
            path: The name the node is told to read (at most 200 bytes).
            progress: A callable given each change of phase or of bytes sent (an
                `UpdateProgress`); True shows a progress bar (tqdm's, in a terminal or a
                notebook), False nothing; None shows a bar when standard error is a
                terminal or in a notebook, and nothing otherwise.
            start_timeout: Seconds from accepting to the first read.
            read_timeout: Seconds without a read that count as a stall.
            restart_timeout: Seconds after the last read for the node to run again.
            max_image_size: Bytes above which an image is refused (`MAX_IMAGE_SIZE`).

        Returns:
            The node's GetNodeInfo after the update.

        Raises:
            InvalidRequestError: An empty image or one above ``max_image_size``, refused
                before anything is sent.
            FirmwareUpdateFailedError: Refused, stalled, or the node reports another image CRC.
            NoResponseError: GetNodeInfo after the update got no answer.
        """
        with progress_callback(progress, node_id, len(image)) as report:
            return self.run(
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

    def serve_allocations(
        self,
        table: str | os.PathLike[str],
        *,
        duration: float | None = None,
        on_event: Callable[[AllocationEvent], object] | None = None,
    ) -> list[AllocationEvent]:
        """Serve dynamic node ID allocations from this node (a centralized allocator,
        `veronte4x.client.allocator`) for ``duration`` seconds, or until interrupted.

        Args:
            table: The allocation table's file (`veronte4x.client.allocation_table`),
                created when it first grows, written whole at every change before the
                answer goes out.
            duration: Seconds to serve (None: until KeyboardInterrupt).
            on_event: Called with each `Allocated`, `NodeRecorded` or
                `AllocationConflict` as it comes.

        Returns:
            Every event, in order.

        Raises:
            AllocationTableError: The file is not a valid allocation table.
            NodeIdConflictError: Another node sends with this client's node id.
            OSError: The file cannot be read or written.
        """
        served = Allocator.from_file(
            self.protocol, table, self.clock(), info_timeout=self.timeout, info_retries=self.retries
        )
        return self.run(allocator.serve(served, duration, on_event))

    # -- motors -----------------------------------------------------------------------------

    def command_stream(
        self, rate: float = DEFAULT_RATE, watchdog: float = DEFAULT_WATCHDOG
    ) -> CommandStream:
        """A `CommandStream` from this client (start it with ``with``)."""
        return CommandStream(self, Commander(rate, watchdog))

    def spin(
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
        """Spin the motors of ``nodes`` at ``throttle`` for ``duration`` seconds, watching
        them, then zero throttle.

        The arguments are checked before anything is sent (`spin_plan`); then every node's
        ``esc_index`` is read (`veronte4x.client.indices.survey`) and a spin that would turn
        a motor not named is refused (`spin_indices`). RawCommand goes out at ``rate`` from a
        `CommandStream`; every motor gets zero throttle `CommandStream.STOP_REPEATS` times
        however the spin ends: at its end, when a node falls silent for ``silence`` seconds
        or reports over ``max_temperature`` (°C) or ``max_current`` (A), or on an exception
        (KeyboardInterrupt included, which goes on). A spin that ran its course reads the bus
        `SETTLE` seconds more.

        Args:
            nodes: The nodes to spin (each once).
            throttle: The fraction, -1..1.
            duration: Seconds, finite and above 0.
            rate: RawCommand per second.
            watchdog: Seconds after which an unrefreshed setpoint drops to zero.
            silence: Seconds without esc.Status or NodeStatus from a node that stop it.
            max_temperature: Stop above this temperature, °C (None: no limit).
            max_current: Stop above this current, A (None: no limit).
            allow_unknown: Nodes known to drive no motor whose ``esc_index`` may be
                unreadable (``"all"``: any such node).
            on_start: Called with the `Spin` once the indices are known, before the first
                command (e.g. to route SIGTERM to KeyboardInterrupt).

        Returns:
            What each node did (its index, peak rpm and esc.Status count).

        Raises:
            SpinArgumentError: An argument out of range; nothing was sent.
            EscIndexError: Another motor would turn; no command was sent.
            NoResponseError: A node to spin did not answer for its ``esc_index``.
            SpinStoppedError: A node fell silent or reported over a limit; every motor
                got zero throttle.
        """
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
        spin = plan.start(self.run(indices.survey(self.protocol, plan.nodes)), self.clock())
        if on_start is not None:
            on_start(spin)
        with self.command_stream(plan.rate, plan.watchdog) as stream:
            while spin.going(self.clock()):
                stream.set(spin.setpoint)
                spin.observe(self.spin_once(STEP), self.clock())
        result = spin.result()
        settle = self.clock() + SETTLE
        while self.clock() < settle:
            self.spin_once(STEP)
        return result


class CommandStream(StreamBase):
    """RawCommand sent from a background thread at a fixed rate, with a watchdog.

    Use it as a context manager and refresh the throttles with `set` more often than the
    watchdog period; when refreshes stop, zero throttle is sent. Leaving the ``with``
    block, normally or by an exception, stops the thread after sending zero throttle
    (`STOP_REPEATS` times). If sending fails in the thread, it sends zero throttle if it
    can and stops; `set` and the end of the ``with`` block raise that error.

    Args:
        client: The client whose bus and node id it uses.
        commander: The rate and watchdog (`Commander`).
    """

    def __init__(self, client: BusClient, commander: Commander) -> None:
        super().__init__(client, commander)
        self._stopped = threading.Event()
        self._thread: threading.Thread | None = None

    def _run(self) -> None:
        try:
            while not self._stopped.is_set():
                self._stopped.wait(self._send_due())
        except Exception as error:  # a failing bus
            self._failed(error)

    def start(self) -> None:
        """Start sending (nothing goes out before the first `set`)."""
        self._stopped.clear()
        self._thread = threading.Thread(target=self._run, name="veronte4x-raw-command")
        self._thread.daemon = True
        self._thread.start()

    def stop(self) -> None:
        """Stop the thread, then send zero throttle `STOP_REPEATS` times.

        Raises:
            Exception: The error that stopped the stream's thread.
        """
        self._stopped.set()
        if self._thread is not None:
            self._thread.join()
            self._thread = None
        self._stop_motors()

    def __enter__(self) -> CommandStream:
        self.start()
        return self

    def __exit__(self, kind: type[BaseException] | None, *exc: object) -> None:
        with self._stopping_at_block_end(kind):
            self.stop()
