"""What the ground station does, written once as sans-IO operations, and the runner that
drives many of them at once.

An operation is a generator that yields steps and gets their results back: `Call` sends a
service request and resumes with the response (or raises `NoResponseError` in the
operation), `Listen` resumes with the events that came, or with none when its time is up,
and `NOW` resumes with the current time. `Runner` drives any number of operations over one
`ClientProtocol`, each waiting on its own requests, so that independent nodes are served
concurrently; it never reads a clock or touches a bus. The blocking `BusClient` and the
asyncio `AsyncBusClient` are loops that feed it frames and times: every behaviour (parameter
checks, the firmware update's phases, timeouts and progress) lives here once.

Examples:
    >>> from veronte4x.client.protocol import ClientProtocol
    >>> from veronte4x.simulator import SimulatedEsc
    >>> protocol, esc = ClientProtocol(), SimulatedEsc(21)
    >>> runner = Runner(protocol)
    >>> task = runner.start(get_param(21, "esc_index"), now=0.0)
    >>> for frame in protocol.take_frames():
    ...     esc.receive(frame.can_id, frame.data, 0.0)
    >>> for frame in esc.poll(0.01):
    ...     runner.feed(protocol.receive(frame.can_id, frame.data, 0.01), 0.01)
    >>> task.result().as_dict()["value"]
    0
"""

from __future__ import annotations

from collections.abc import Callable, Generator, Sequence
from dataclasses import dataclass
from typing import Any, Generic, TypeVar

from veronte4x.client.errors import (
    FirmwareUpdateFailedError,
    InvalidRequestError,
    NodeIdConflictError,
    NoResponseError,
    OperationCancelledError,
    ParameterError,
    RejectedError,
)
from veronte4x.client.firmware import (
    DEFAULT_OPTIONS,
    FirmwareOptions,
    FirmwareUpdate,
    Phase,
    UpdateProgress,
    check_image,
    image_crc,
)
from veronte4x.client.nodes import NodeEntry
from veronte4x.client.paramfile import Change, NodeParameters
from veronte4x.client.params import ParameterInfo, parameter_request, plain
from veronte4x.client.protocol import (
    ClientProtocol,
    Event,
    FileServed,
    NodeIdConflict,
    StatusSeen,
)
from veronte4x.dronecan import vertiq
from veronte4x.dronecan.messages import (
    BeginFirmwareUpdateRequest,
    BooleanValue,
    Empty,
    ExecuteOpcodeRequest,
    GetNodeInfoRequest,
    GetNodeInfoResponse,
    GetSetRequest,
    GetSetResponse,
    IntegerValue,
    Opcode,
    Path,
    RealValue,
    SoftwareVersionFlag,
    StringValue,
    Value,
)
from veronte4x.node.requests import DEFAULT_RETRIES, DEFAULT_TIMEOUT, Answered, TimedOut

T = TypeVar("T")

MAX_PARAMETERS = 8192
"""Indices a parameter walk tries at most (GetSet ``index`` is 13 bits)."""

_VALUES = (Empty, IntegerValue, RealValue, BooleanValue, StringValue)


@dataclass(frozen=True, slots=True)
class Call:
    """Send a service request; resume with the response message.

    Attributes:
        message: The request.
        node_id: The node asked.
        timeout: Seconds each attempt waits (None: the runner's).
        retries: Attempts after the first (None: the runner's).
    """

    message: Any
    node_id: int
    timeout: float | None = None
    retries: int | None = None


@dataclass(frozen=True, slots=True)
class Listen:
    """Wait for events; resume with ``(events, now)``, events empty when ``until`` came.

    Attributes:
        until: When to resume without events (None: only on events).
    """

    until: float | None


@dataclass(frozen=True, slots=True)
class Now:
    """Resume at once with the current time."""


NOW = Now()
"""The step that resumes with the current time."""

Step = Call | Listen | Now
"""What an operation yields."""

Operation = Generator[Step, Any, T]
"""A ground-station operation: yields steps, returns its result."""


class Task(Generic[T]):
    """An operation being run: done, with its result or its error, or waiting."""

    def __init__(self, operation: Operation[T]) -> None:
        self.operation = operation
        self.done = False
        self.waiting: Step | None = None
        self._result: T | None = None
        self._error: Exception | None = None

    @property
    def error(self) -> Exception | None:
        """The error the operation ended with, or None."""
        return self._error

    def result(self) -> T:
        """The operation's result.

        Raises:
            Exception: The error the operation ended with.
            RuntimeError: It is not done.
        """
        if self._error is not None:
            raise self._error
        if not self.done:
            raise RuntimeError("the operation is still running")
        return self._result  # type: ignore[return-value]


class Runner:
    """Drives operations over one `ClientProtocol`, concurrently, from events and times.

    Feed it the events of `ClientProtocol.receive` and `ClientProtocol.poll` with `feed`,
    call `poll` with the time, and send `ClientProtocol.take_frames`; `next_deadline` says
    when `poll` next has something to do.

    Args:
        protocol: The client node the operations use.
        timeout: Seconds each request attempt waits unless the operation says otherwise.
        retries: Attempts after the first unless the operation says otherwise.
    """

    def __init__(
        self,
        protocol: ClientProtocol,
        timeout: float = DEFAULT_TIMEOUT,
        retries: int = DEFAULT_RETRIES,
    ) -> None:
        self.protocol = protocol
        self.timeout = timeout
        self.retries = retries
        self._calls: dict[int, Task[Any]] = {}
        self._listening: list[Task[Any]] = []

    def start(self, operation: Operation[T], now: float) -> Task[T]:
        """Start an operation at ``now``; it runs until it first waits."""
        task: Task[T] = Task(operation)
        self._advance(task, None, None, now)
        return task

    def _advance(self, task: Task[Any], value: Any, error: Exception | None, now: float) -> None:
        while True:
            try:
                step = task.operation.throw(error) if error else task.operation.send(value)
            except StopIteration as stop:
                task.done, task.waiting, task._result = True, None, stop.value
                return
            except Exception as failure:  # the operation's own error ends it
                task.done, task.waiting, task._error = True, None, failure
                return
            value, error = None, None
            if isinstance(step, Now):
                value = now
            elif isinstance(step, Call):
                try:
                    handle = self.protocol.request(
                        step.message,
                        step.node_id,
                        now,
                        timeout=self.timeout if step.timeout is None else step.timeout,
                        retries=self.retries if step.retries is None else step.retries,
                    )
                except Exception as failure:  # EncodeError: into the operation
                    error = failure
                    continue
                task.waiting = step
                self._calls[handle] = task
                return
            else:
                task.waiting = step
                self._listening.append(task)
                return

    def feed(self, events: Sequence[Event], now: float) -> None:
        """Give the events of received frames and of `ClientProtocol.poll` at ``now``; a
        `NodeIdConflict` fails every operation waiting for an answer with its error."""
        listening = [(task, task.waiting) for task in self._listening]
        for event in events:
            if isinstance(event, NodeIdConflict):
                for handle, caller in list(self._calls.items()):
                    del self._calls[handle]
                    self.protocol.requests.cancel(handle)
                    refused = NodeIdConflictError(event.error.node_id, event.error.heard)
                    self._advance(caller, None, refused, now)
            elif isinstance(event, (Answered, TimedOut)):
                task = self._calls.pop(event.request.handle, None)
                if task is None:
                    continue
                if isinstance(event, Answered):
                    self._advance(task, event.transfer.message, None, now)
                else:
                    pending = event.request
                    error = NoResponseError(
                        pending.destination, pending.request_name, event.attempts, pending.timeout
                    )
                    self._advance(task, None, error, now)
        if events:
            for task, step in listening:
                if task.waiting is step:
                    self._listening.remove(task)
                    self._advance(task, (list(events), now), None, now)

    def poll(self, now: float) -> None:
        """Resume the operations whose `Listen` time is up at ``now``."""
        for task in list(self._listening):
            step = task.waiting
            if isinstance(step, Listen) and step.until is not None and step.until <= now:
                self._listening.remove(task)
                self._advance(task, ([], now), None, now)

    def settle(self, events: list[Event], now: float) -> list[Event]:
        """After the frames of a wait were received: time out the requests due at ``now``,
        feed every event in and resume the operations due; return the events.

        The frames to send are then in `ClientProtocol.take_frames`.
        """
        events += self.protocol.poll(now)
        self.feed(events, now)
        self.poll(now)
        return events

    def wait(self, now: float, longest: float) -> float:
        """Seconds to wait for frames at ``now``: at most ``longest``, less when a request
        or an operation is due sooner."""
        for deadline in (self.protocol.next_deadline(), self.next_deadline()):
            if deadline is not None:
                longest = max(0.0, min(longest, deadline - now))
        return longest

    def next_deadline(self) -> float | None:
        """When `poll` next resumes an operation, or None."""
        times = [
            t.waiting.until
            for t in self._listening
            if isinstance(t.waiting, Listen) and t.waiting.until is not None
        ]
        return min(times, default=None)

    def cancel(self, task: Task[Any]) -> None:
        """Stop an operation (its pending request is forgotten); its `Task.result` then
        raises `OperationCancelledError`."""
        for handle, waiting in list(self._calls.items()):
            if waiting is task:
                del self._calls[handle]
                self.protocol.requests.cancel(handle)
        if task in self._listening:
            self._listening.remove(task)
        task.operation.close()
        task.done, task.waiting = True, None
        task._error = OperationCancelledError("the operation was cancelled before it finished")


class OperationBatch:
    """Operations run concurrently on a `Runner`, at most ``limit`` at a time, in order.
    (`veronte4x.capture.columnar.batches.Batch` is a batch of a capture's frames.)

    An adapter calls `fill` with the time, sends the frames, waits for frames and calls
    `Runner.settle`, until `fill` returns False; then every task is done. `cancel` forgets
    what still runs (on an exception or a cancellation of the adapter's loop).

    Args:
        runner: The runner.
        operations: The operations, started in this order.
        limit: How many run at once, at least 1.
    """

    def __init__(self, runner: Runner, operations: Sequence[Operation[Any]], limit: int) -> None:
        self.runner = runner
        self.limit = max(1, limit)
        self.tasks: list[Task[Any]] = []
        """The tasks started so far, in the order of the operations."""
        self._waiting = list(reversed(operations))
        self._running: list[Task[Any]] = []

    def fill(self, now: float) -> bool:
        """Start operations while fewer than ``limit`` run; whether any is still running."""
        while True:
            self._running = [t for t in self._running if not t.done]
            if not self._waiting or len(self._running) >= self.limit:
                return bool(self._running)
            task = self.runner.start(self._waiting.pop(), now)
            self.tasks.append(task)
            self._running.append(task)

    def cancel(self) -> None:
        """Stop the operations still running (`Runner.cancel`)."""
        for task in self._running:
            if not task.done:
                self.runner.cancel(task)
        self._running = []


# -- operations --------------------------------------------------------------------------------


def call(
    message: Any, node_id: int, timeout: float | None = None, retries: int | None = None
) -> Operation[Any]:
    """Send one request; return the response message."""
    response = yield Call(message, node_id, timeout, retries)
    return response


def node_info(node_id: int) -> Operation[GetNodeInfoResponse]:
    """GetNodeInfo: status, software and hardware version, name."""
    response: GetNodeInfoResponse = yield Call(GetNodeInfoRequest(), node_id)
    return response


def discover(protocol: ClientProtocol, duration: float) -> Operation[list[NodeEntry]]:
    """Listen for ``duration`` seconds; the nodes online then, by id."""
    now: float = yield NOW
    end = now + duration
    while now < end:
        _, now = yield Listen(end)
    return protocol.nodes.online(now)


def _parameter(
    node_id: int, name: str | None, index: int | None, response: GetSetResponse
) -> ParameterInfo:
    if vertiq.is_end_of_parameters(response):
        where = f"at index {index}" if name is None else repr(name)
        raise ParameterError(f"node {node_id} has no parameter {where}")
    return ParameterInfo.from_response(response, index)


def get_param(
    node_id: int, name: str | None = None, *, index: int | None = None
) -> Operation[ParameterInfo]:
    """Read one parameter by name, or by ``index`` when asked for explicitly (see
    `veronte4x.client.params.parameter_request`)."""
    request = parameter_request(name, index)
    response = yield Call(request, node_id)
    return _parameter(node_id, name, index, response)


def list_params(node_id: int) -> Operation[list[ParameterInfo]]:
    """Every parameter, walking the indices from 0 to the first empty answer."""
    found = []
    for index in range(MAX_PARAMETERS):
        response = yield Call(vertiq.get_parameter_by_index(index), node_id)
        if vertiq.is_end_of_parameters(response):
            break
        found.append(ParameterInfo.from_response(response, index))
    return found


def wanted_value(
    node_id: int, current: ParameterInfo, value: int | float | bool | str | Value
) -> Value:
    """The value to set ``current`` to, checked against its type and range.

    A ``str`` is parsed as a value of the parameter's type.

    Raises:
        InvalidRequestError: Text that does not parse as the parameter's type.
        ParameterError: No such parameter (an Empty value), a value of another type or out
            of range.
    """
    if not current.exists:
        raise ParameterError(f"node {node_id} has no parameter {current.name!r}")
    if isinstance(value, _VALUES):
        wanted: Value = value
    elif isinstance(value, str) and not isinstance(current.value, StringValue):
        try:
            wanted = current.parse(value)
        except ValueError as error:
            raise InvalidRequestError(f"node {node_id}: {error}") from None
    else:
        wanted = vertiq.set_parameter(current.name, value).value
    problem = current.check(wanted)
    if problem is not None:
        raise ParameterError(f"node {node_id}: {problem}")
    return wanted


def set_param(
    node_id: int,
    name: str | None,
    value: int | float | bool | str | Value,
    *,
    index: int | None = None,
) -> Operation[ParameterInfo]:
    """Read the parameter, check ``value`` (`wanted_value`), set it, and return what the node
    reports after the set.

    Raises:
        RejectedError: The node kept another value.
    """
    parameter_request(name, index)  # refuse an ambiguous parameter before any request
    current = yield from get_param(node_id, name, index=index)
    wanted = wanted_value(node_id, current, value)
    if name is None:
        request = GetSetRequest(index=index or 0, value=wanted)
    else:
        request = GetSetRequest(value=wanted, name=name.encode("utf-8"))
    response = yield Call(request, node_id)
    after = _parameter(node_id, name, index, response)
    if plain(after.value) != plain(wanted):
        raise RejectedError(
            f"node {node_id} kept {after.name} at {plain(after.value)!r} "
            f"instead of {plain(wanted)!r}"
        )
    return after


def opcode(node_id: int, code: Opcode) -> Operation[None]:
    """ExecuteOpcode SAVE or ERASE.

    Raises:
        RejectedError: The node answered not ok.
    """
    response = yield Call(ExecuteOpcodeRequest(code, 0), node_id)
    if not response.ok:
        raise RejectedError(
            f"node {node_id} refused to {code.name.lower()} its parameters "
            f"(error {response.argument})"
        )


def restart(node_id: int, *, bootloader: bool = False) -> Operation[None]:
    """RestartNode with the magic number (Vertiq's bootloader one with ``bootloader``).

    Raises:
        RejectedError: The node answered that it does not restart.
    """
    response = yield Call(vertiq.restart(bootloader), node_id)
    if not response.ok:
        raise RejectedError(f"node {node_id} refused to restart")


def update_firmware(
    protocol: ClientProtocol,
    node_id: int,
    image: bytes,
    path: str = "firmware.bin",
    *,
    progress: Callable[[UpdateProgress], object] | None = None,
    options: FirmwareOptions = DEFAULT_OPTIONS,
) -> Operation[GetNodeInfoResponse]:
    """Update a node's firmware: BeginFirmwareUpdate, serve its reads, wait for it to run
    again, then check the image CRC it reports (`FirmwareUpdate` follows the phases).

    Several updates of one image may run at once: the file is served until the last ends.

    Raises:
        InvalidRequestError: An empty image or one above ``options.max_image_size``.
        FirmwareUpdateFailedError: Refused, stalled, or the node reports another image CRC.
        NoResponseError: GetNodeInfo after the update got no answer.
    """
    check_image(image, options.max_image_size)
    name = path.encode("utf-8")
    now: float = yield NOW
    update = FirmwareUpdate(
        node_id,
        name,
        len(image),
        now,
        start_timeout=options.start_timeout,
        read_timeout=options.read_timeout,
        restart_timeout=options.restart_timeout,
    )
    protocol.files.add(name, image)
    last = update.progress
    try:
        try:
            response = yield Call(BeginFirmwareUpdateRequest(protocol.node_id, Path(name)), node_id)
        except NoResponseError as error:
            update.no_answer(str(error))
        else:
            update.accepted(response, (yield NOW))
        while True:
            current = update.poll((yield NOW))
            if current != last and progress is not None:
                progress(current)
            last = current
            if last.finished:
                break
            events, now = yield Listen(update.next_deadline())
            for event in events:
                if isinstance(event, FileServed):
                    update.served(event.node_id, event.read, now)
                elif isinstance(event, StatusSeen):
                    update.status(event.entry, now)
    finally:
        protocol.files.remove(name)
    if last.phase is not Phase.DONE:
        raise FirmwareUpdateFailedError(
            last.error or f"node {node_id}: update failed", timed_out=last.timed_out
        )
    info = yield from node_info(node_id)
    version = info.software_version
    expected = image_crc(image)
    if version.optional_field_flags & SoftwareVersionFlag.IMAGE_CRC and (
        version.image_crc != expected
    ):
        raise FirmwareUpdateFailedError(
            f"node {node_id} reports image CRC {version.image_crc:#018x}, but the "
            f"image's CRC-64-WE is {expected:#018x}"
        )
    return info


# -- fleet operations --------------------------------------------------------------------------


def read_node(node_id: int) -> Operation[NodeParameters]:
    """GetNodeInfo and every parameter of a node: what a parameter file keeps of it."""
    info = yield from node_info(node_id)
    found = yield from list_params(node_id)
    version = info.software_version
    crc = (
        f"{version.image_crc:#018x}"
        if version.optional_field_flags & SoftwareVersionFlag.IMAGE_CRC
        else None
    )
    return NodeParameters(
        node_id,
        info.name.decode("utf-8", "replace"),
        info.hardware_version.unique_id.hex(),
        f"{version.major}.{version.minor}",
        crc,
        tuple(found),
    )


def apply_changes(
    node_id: int, changes: Sequence[Change], applied: list[str] | None = None
) -> Operation[list[ParameterInfo]]:
    """Set each change, read it back, then save (ExecuteOpcode SAVE) only when every set
    succeeded; ``applied`` collects the names set so far, so that a failure can say how far
    it got.

    Raises:
        RejectedError: A value read back differs from the one set.
    """
    done = []
    for change in changes:
        yield from set_param(node_id, change.name, change.wanted)
        back = yield from get_param(node_id, change.name)
        if plain(back.value) != plain(change.wanted):
            raise RejectedError(
                f"node {node_id} reads {change.name} back as {plain(back.value)!r}, "
                f"not {plain(change.wanted)!r}"
            )
        done.append(back)
        if applied is not None:
            applied.append(change.name)
    if changes:
        yield from opcode(node_id, Opcode.SAVE)
    return done


def update_unless_current(
    protocol: ClientProtocol,
    node_id: int,
    image: bytes,
    path: str = "firmware.bin",
    *,
    force: bool = False,
    progress: Callable[[UpdateProgress], object] | None = None,
    options: FirmwareOptions = DEFAULT_OPTIONS,
) -> Operation[tuple[bool, GetNodeInfoResponse]]:
    """`update_firmware`, unless the node reports the image's CRC already (``force`` updates
    anyway); returns whether it updated, and the node's GetNodeInfo."""
    check_image(image, options.max_image_size)
    info = yield from node_info(node_id)
    version = info.software_version
    if (
        not force
        and version.optional_field_flags & SoftwareVersionFlag.IMAGE_CRC
        and version.image_crc == image_crc(image)
    ):
        return False, info
    info = yield from update_firmware(
        protocol, node_id, image, path, progress=progress, options=options
    )
    return True, info
