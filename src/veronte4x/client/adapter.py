"""What the blocking and the asyncio clients share on a python-can bus (the ``can`` extra).

`BusAdapter` holds the sans-IO node (`ClientProtocol`) and its `Runner`, stamps received
messages with its clock and feeds them in, and sends what the node has to send. The two
clients add only their way of waiting: `veronte4x.client.bus.BusClient` blocks on
``bus.recv``, `veronte4x.client.aio.AsyncBusClient` awaits python-can's asyncio reader.
"""

from __future__ import annotations

import contextlib
import threading
import time
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from contextlib import contextmanager

from veronte4x.errors import MissingExtraError

try:
    import can
except ModuleNotFoundError as missing:  # pragma: no cover - the can extra is installed in CI
    if missing.name != "can":
        raise
    raise MissingExtraError("can", "can", "veronte4x.client.adapter") from None

from veronte4x.canbus import frame_to_message, is_dronecan_frame
from veronte4x.client.commander import STOP_REPEATS, Commander
from veronte4x.client.firmware import UpdateProgress
from veronte4x.client.operations import Runner
from veronte4x.client.protocol import DEFAULT_NODE_ID, ClientProtocol, Event
from veronte4x.dronecan.frame import TransferFrame
from veronte4x.dronecan.messages import RawCommand
from veronte4x.dronecan.transfer import DEFAULT_PRIORITY
from veronte4x.node.requests import DEFAULT_RETRIES, DEFAULT_TIMEOUT
from veronte4x.progress import Bar

MAX_WAIT = 0.05
"""Longest single wait for frames, in seconds."""

Progress = Callable[[UpdateProgress], object] | bool | None
"""What a client's ``update_firmware`` takes as ``progress``: a callable given each change,
True for a progress bar, False for nothing, None for a bar only when interactive."""


@contextmanager
def progress_callback(
    progress: Progress, node_id: int, size: int
) -> Iterator[Callable[[UpdateProgress], object] | None]:
    """The callable an update of ``size`` bytes reports to: ``progress`` itself, or one that
    moves a tqdm bar (`veronte4x.progress.Bar`, in a terminal or a notebook) by the bytes
    sent; the bar is taken off when the block ends.

    Raises:
        MissingExtraError: A bar was asked for (True) and tqdm is not installed.
    """
    if callable(progress):
        yield progress
        return
    bar = Bar(progress, size, "B", f"node {node_id} firmware", extra="can")
    sent = 0

    def advance(current: UpdateProgress) -> None:
        nonlocal sent
        bar.update(current.sent - sent)
        sent = current.sent

    try:
        yield advance
    finally:
        bar.close()


class BusAdapter:
    """A `ClientProtocol` and its `Runner` on a python-can bus, with a clock.

    Args:
        bus: Any python-can bus.
        node_id: This node's id, 1..127 (127 by default, like the DroneCAN GUI tool).
        clock: Seconds from any monotonic source; stamps frames and measures timeouts.
        timeout: Seconds to wait for each response.
        retries: Times a request is sent again after a timeout.
        priority: CAN priority of what it sends.
        first_transfer_id: Where every transfer id stream starts; a tool that runs briefly
            and often should pick it at random (see `TransferIds`).
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

    @property
    def node_id(self) -> int:
        """This client's node id."""
        return self.protocol.node_id

    @property
    def timeout(self) -> float:
        """Seconds to wait for each response."""
        return self.runner.timeout

    @timeout.setter
    def timeout(self, value: float) -> None:
        self.runner.timeout = value

    @property
    def retries(self) -> int:
        """Times a request is sent again after a timeout."""
        return self.runner.retries

    @retries.setter
    def retries(self, value: int) -> None:
        self.runner.retries = value

    def send_frame(self, can_id: int, data: bytes) -> None:
        """Send one extended frame."""
        self.send_frames((TransferFrame(can_id, data),))

    def send_frames(self, frames: Iterable[TransferFrame]) -> None:
        """Send frames in order (a 256-byte file read answers with 37: one call for all)."""
        send = self.bus.send
        for frame in frames:
            send(frame_to_message(frame))

    def flush(self) -> None:
        """Send every frame the node has to send now."""
        self.send_frames(self.protocol.take_frames())

    def wait_time(self, longest: float = MAX_WAIT) -> float:
        """Seconds to wait for frames now (`Runner.wait`)."""
        return self.runner.wait(self.clock(), longest)

    def receive(self, messages: Iterable[can.Message]) -> list[Event]:
        """Feed the DroneCAN frames among ``messages`` in, each stamped with the clock; then
        settle the runner (`Runner.settle`) and send what is due. Returns the events."""
        events: list[Event] = []
        for message in messages:
            if is_dronecan_frame(message):
                events += self.protocol.receive(
                    message.arbitration_id, bytes(message.data), self.clock()
                )
        events = self.runner.settle(events, self.clock())
        self.flush()
        return events


class StreamBase:
    """What the blocking and the asyncio command streams share: the `Commander` behind a
    lock, the sending, and the failure that stopped the stream.

    Args:
        client: The client whose bus and node id it uses.
        commander: The rate and watchdog (`Commander`).
    """

    STOP_REPEATS = STOP_REPEATS
    """Zero-throttle commands sent when the stream stops."""

    def __init__(self, client: BusAdapter, commander: Commander) -> None:
        self.client = client
        self.commander = commander
        self._lock = threading.Lock()
        self.failure: Exception | None = None
        """The error that stopped the stream, or None."""
        self.sent = 0
        """Commands sent so far."""

    def set(self, throttles: Sequence[float] | Mapping[int, float]) -> None:
        """New throttle fractions in [-1, 1] by ESC index; they also feed the watchdog.

        Raises:
            Exception: The error that stopped the stream.
        """
        if self.failure is not None:
            raise self.failure
        with self._lock:
            self.commander.set(throttles, self.client.clock())

    @property
    def tripped(self) -> bool:
        """Whether the watchdog has zeroed the throttle since the last `set`."""
        return self.commander.tripped

    def _send(self, commands: list[RawCommand]) -> None:
        for command in commands:
            self.client.send_frames(self.client.protocol.message_frames(command))
            self.sent += 1

    def _send_due(self) -> float:
        """Send the command due now, if any; the seconds to wait for the next one."""
        with self._lock:
            command = self.commander.poll(self.client.clock())
            wait = self.commander.wait(self.client.clock(), MAX_WAIT)
        if command is not None:
            self._send([command])
        return wait

    def _failed(self, error: Exception) -> None:
        """Keep the error that stopped the stream; send zero throttle if the bus takes it."""
        self.failure = error
        with self._lock:
            zero = self.commander.stop_commands()
        with contextlib.suppress(Exception):
            self._send(zero)

    @staticmethod
    @contextmanager
    def _stopping_at_block_end(kind: type[BaseException] | None) -> Iterator[None]:
        """Around the stop at the end of a stream's ``with`` (or ``async with``) block: the
        stop's error is raised if the block ended normally, else the block's own goes on."""
        try:
            yield
        except Exception:
            if kind is None:
                raise

    def _stop_motors(self) -> None:
        """Send zero throttle `STOP_REPEATS` times (after the sender has stopped).

        Raises:
            Exception: The error that stopped the stream (its zero throttle was tried).
        """
        with self._lock:
            zero = self.commander.stop_commands()
        if self.failure is not None:
            raise self.failure
        self._send(zero)
