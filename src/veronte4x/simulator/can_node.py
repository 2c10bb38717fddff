"""Run a `SimulatedEsc` on a python-can bus (the ``can`` extra).

This adapter is the I/O side: it takes messages from the bus, stamps them with its clock,
feeds them to the sans-IO core and sends what the core polls as extended ``can.Message``
objects. Frames are stamped with the adapter's clock when taken from the bus rather than
with ``can.Message.timestamp``, because interfaces stamp with different clocks (the
``virtual`` interface uses ``time.time``) while the core needs one time base for its
schedules, its motor model and its reassembler.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable, Sequence

from veronte4x.errors import MissingExtraError

try:
    import can
except ModuleNotFoundError as missing:  # pragma: no cover - the can extra is installed in CI
    if missing.name != "can":
        raise
    raise MissingExtraError("can", "can", "veronte4x.simulator.can_node") from None

from veronte4x.canbus import frame_to_message, is_dronecan_frame
from veronte4x.dronecan.can_id import service_destination
from veronte4x.simulator.esc import SimulatedEsc

__all__ = ["EscBus", "EscNode"]


class EscNode:
    """A `SimulatedEsc` attached to a python-can bus.

    Args:
        bus: Any python-can bus, e.g. ``can.Bus(interface="virtual", channel="x")``.
        esc: The simulated ESC.
        clock: Seconds from any monotonic source; the only clock the simulator sees.

    Examples:
        >>> import can
        >>> from veronte4x.simulator import SimulatedEsc
        >>> with can.Bus(interface="virtual", channel="doc-esc") as bus, can.Bus(
        ...     interface="virtual", channel="doc-esc"
        ... ) as listener:
        ...     node = EscNode(bus, SimulatedEsc(20), clock=lambda: 0.0)
        ...     sent = node.step()
        ...     ids = [hex(listener.recv(0).arbitration_id) for _ in range(sent)]
        >>> ids  # NodeStatus, esc.Status in three frames, device.Temperature
        ['0x10015514', '0x10040a14', '0x10040a14', '0x10040a14', '0x10045614']
    """

    def __init__(
        self,
        bus: can.BusABC,
        esc: SimulatedEsc,
        clock: Callable[[], float] = time.monotonic,
    ) -> None:
        self.bus = bus
        self.esc = esc
        self.clock = clock

    def feed(self, message: can.Message) -> None:
        """Give one bus message to the ESC, stamped with the clock (others are skipped)."""
        if is_dronecan_frame(message):
            self.esc.receive(message.arbitration_id, bytes(message.data), self.clock())

    def step(self) -> int:
        """Feed every message waiting on the bus, then send what the ESC has to send now.

        Returns:
            The number of frames sent.
        """
        message = self.bus.recv(timeout=0.0)
        while message is not None:
            self.feed(message)
            message = self.bus.recv(timeout=0.0)
        frames = self.esc.poll(self.clock())
        for frame in frames:
            self.bus.send(frame_to_message(frame))
        return len(frames)

    def run(self, duration: float, max_wait: float = 0.05) -> None:
        """Serve the bus for ``duration`` seconds of the clock, blocking on the bus between
        sends (at most ``max_wait`` seconds at a time) rather than sleeping."""
        end = self.clock() + duration
        while True:
            now = self.clock()
            if now >= end:
                return
            due = self.esc.next_time()
            wait = min(end - now, max_wait, max(0.0, due - now) if due is not None else max_wait)
            message = self.bus.recv(timeout=wait)
            if message is not None:
                self.feed(message)
            self.step()


class EscBus:
    """Several `SimulatedEsc` on one python-can bus: each sees every frame, all send.

    Args:
        bus: Any python-can bus.
        escs: The simulated ESCs (distinct node ids).
        clock: Seconds from any monotonic source; the only clock the simulators see.

    Examples:
        >>> import can
        >>> from veronte4x.simulator import SimulatedEsc
        >>> with can.Bus(interface="virtual", channel="doc-escs") as bus:
        ...     escs = EscBus(bus, [SimulatedEsc(21), SimulatedEsc(22, esc_index=1)])
        ...     escs.step()  # NodeStatus, esc.Status (3 frames), Temperature, twice
        10
    """

    def __init__(
        self,
        bus: can.BusABC,
        escs: Sequence[SimulatedEsc],
        clock: Callable[[], float] = time.monotonic,
    ) -> None:
        self.bus = bus
        self.escs = list(escs)
        self.clock = clock

    def feed(self, message: can.Message) -> None:
        """Give one bus message to every ESC it may concern, stamped with the clock: a
        message to each, a service frame only to the ESC it is addressed to (the others
        would drop it, as `SimulatedEsc.receive` does; 8 ESCs take a 256-byte file read in
        38 frames, for one of them)."""
        if is_dronecan_frame(message):
            now = self.clock()
            can_id = message.arbitration_id
            data = bytes(message.data)
            destination = service_destination(can_id)
            for esc in self.escs:
                if destination is None or esc.node_id == destination:
                    esc.receive(can_id, data, now)

    def step(self) -> int:
        """Feed every message waiting on the bus, then send what each ESC has to send now.

        Returns:
            The number of frames sent.
        """
        message = self.bus.recv(timeout=0.0)
        while message is not None:
            self.feed(message)
            message = self.bus.recv(timeout=0.0)
        sent = 0
        now = self.clock()
        for esc in self.escs:
            for frame in esc.poll(now):
                self.bus.send(frame_to_message(frame))
                sent += 1
        return sent

    def run(self, stop: threading.Event, max_wait: float = 0.01) -> None:
        """Serve the bus until ``stop`` is set, blocking on the bus between sends."""
        while not stop.is_set():
            now = self.clock()
            times = [t for t in (esc.next_time() for esc in self.escs) if t is not None]
            wait = min([max_wait, *(max(0.0, t - now) for t in times)])
            message = self.bus.recv(timeout=wait)
            if message is not None:
                self.feed(message)
            self.step()
