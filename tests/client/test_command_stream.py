"""The RawCommand stream with its zero-throttle watchdog, through the blocking `BusClient`
and the asyncio `AsyncBusClient` alike: simulated ESCs served from a thread on python-can's
virtual bus (real clock), and a third bus node that records every RawCommand sent.

The simulated ESCs hold a setpoint for ever (``command_timeout=None``), so a motor that
stops was stopped by a zero command of the stream, never by the ESC's own timeout.
"""

from __future__ import annotations

import asyncio
import itertools
import threading
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any

import can
import pytest

from veronte4x.client.aio import AsyncBusClient
from veronte4x.client.bus import BusClient
from veronte4x.client.commander import STOP_REPEATS
from veronte4x.dronecan import RawCommand, Reassembler
from veronte4x.simulator import SimulatedEsc
from veronte4x.simulator.can_node import EscBus

_CHANNELS = itertools.count()


class Driver:
    """One kind of client, driven from the test's thread (an event loop run step by step
    for the asyncio one)."""

    def __init__(self, kind: str, bus: can.BusABC) -> None:
        self.loop: asyncio.AbstractEventLoop | None = None
        self.client: Any
        if kind == "blocking":
            self.client = BusClient(bus)
        else:
            self.loop = asyncio.new_event_loop()
            self.client = AsyncBusClient(bus)
            self.run(self._start())

    async def _start(self) -> None:
        self.client.start()

    def run(self, awaitable: Any) -> Any:
        assert self.loop is not None
        return self.loop.run_until_complete(awaitable)

    @contextmanager
    def stream(self, rate: float, watchdog: float) -> Iterator[Any]:
        """The client's command stream, entered and left as its own ``with`` would."""
        stream = self.client.command_stream(rate=rate, watchdog=watchdog)
        if self.loop is None:
            with stream:
                yield stream
            return
        self.run(stream.__aenter__())
        try:
            yield stream
        except BaseException as error:
            self.run(stream.__aexit__(type(error), error, error.__traceback__))
            raise
        self.run(stream.__aexit__(None, None, None))

    def sleep(self, seconds: float) -> None:
        if self.loop is None:
            time.sleep(seconds)
        else:
            self.run(asyncio.sleep(seconds))

    def until(self, condition: Callable[[], bool], timeout: float = 10.0) -> None:
        """Wait (letting the stream run) until ``condition`` holds; generous, not a timing."""
        end = time.monotonic() + timeout
        while not condition():
            assert time.monotonic() < end, "timed out"
            self.sleep(0.01)

    def close(self) -> None:
        if self.loop is not None:
            self.client.stop()
            self.loop.close()


class Rig:
    """Two simulated ESCs (nodes 21, 22 at indices 0, 1) and a recorder of RawCommand."""

    def __init__(self, channel: str) -> None:
        self.esc_bus = can.Bus(interface="virtual", channel=channel)
        self.spy = can.Bus(interface="virtual", channel=channel)
        self.escs = [
            SimulatedEsc(21, 0, telem_frequency=0, command_timeout=None),
            SimulatedEsc(22, 1, telem_frequency=0, command_timeout=None),
        ]
        self._stop = threading.Event()
        self._thread = threading.Thread(
            target=EscBus(self.esc_bus, self.escs).run, args=(self._stop,)
        )
        self._thread.start()
        self._reassembler = Reassembler()
        self.commands: list[tuple[int, ...]] = []

    def driven(self) -> list[bool]:
        return [esc.motor.driven for esc in self.escs]

    def record(self) -> list[tuple[int, ...]]:
        """Every RawCommand heard so far, in order (``cmd`` of each)."""
        message = self.spy.recv(0.0)
        while message is not None:
            transfer = self._reassembler.feed(
                message.arbitration_id, bytes(message.data), time.monotonic()
            )
            if transfer is not None and isinstance(transfer.message, RawCommand):
                self.commands.append(transfer.message.cmd)
            message = self.spy.recv(0.0)
        return self.commands

    def close(self) -> None:
        self._stop.set()
        self._thread.join()
        self.esc_bus.shutdown()
        self.spy.shutdown()


@pytest.fixture(params=["blocking", "asyncio"])
def kind(request: pytest.FixtureRequest) -> str:
    return str(request.param)


@pytest.fixture
def setup(kind: str) -> Iterator[tuple[Rig, Driver]]:
    channel = f"test-command-stream-{next(_CHANNELS)}"
    rig = Rig(channel)
    client_bus = can.Bus(interface="virtual", channel=channel)
    driver = Driver(kind, client_bus)
    try:
        yield rig, driver
    finally:
        driver.close()
        client_bus.shutdown()
        rig.close()


def _ends_stopped(commands: list[tuple[int, ...]], width: int = 2) -> None:
    """The stream's last words: zero throttle `STOP_REPEATS` times."""
    assert commands[-STOP_REPEATS:] == [(0,) * width] * STOP_REPEATS


def test_the_watchdog_stops_the_motors_when_the_caller_stops_feeding(
    setup: tuple[Rig, Driver],
) -> None:
    rig, driver = setup
    first, second = rig.escs
    with driver.stream(rate=100, watchdog=0.2) as stream:
        stream.set([0.5, 0.25])
        driver.until(lambda: all(rig.driven()))
        assert first.state.throttle == pytest.approx(0.5, abs=1e-3)
        assert second.state.throttle == pytest.approx(0.25, abs=1e-3)
        for _ in range(10):  # refreshed often enough: the watchdog stays quiet
            stream.set([0.5, 0.25])
            driver.sleep(0.05)
        assert not stream.tripped and all(rig.driven())
        driver.until(lambda: stream.tripped)  # the caller stops refreshing
        driver.until(lambda: not any(rig.driven()))
        assert first.state.throttle == second.state.throttle == 0.0
        assert (0, 0) in rig.record()
        stream.set([0.3])  # a new set starts again
        driver.until(lambda: first.motor.driven)
        assert first.state.throttle == pytest.approx(0.3, abs=1e-3)
    driver.until(lambda: not first.motor.driven)  # leaving the block sends zero throttle
    commands = rig.record()
    assert (4096, 2048) in commands and (2457,) in commands  # 0.5, 0.25, 0.3
    _ends_stopped(commands, 1)
    assert stream.sent == len(commands) > 20


def test_an_exception_in_the_block_stops_the_motors(setup: tuple[Rig, Driver]) -> None:
    rig, driver = setup
    with (
        pytest.raises(KeyError, match="the caller's own"),
        driver.stream(rate=100, watchdog=5.0) as stream,
    ):
        stream.set([0.5, 0.5])
        driver.until(lambda: all(rig.driven()))
        raise KeyError("the caller's own")
    driver.until(lambda: not any(rig.driven()))
    _ends_stopped(rig.record())


def test_a_bus_that_fails_is_reported_by_set_and_by_the_block(
    setup: tuple[Rig, Driver],
) -> None:
    rig, driver = setup
    with pytest.raises(can.CanError), driver.stream(rate=100, watchdog=5.0) as stream:
        stream.set([0.5, 0.5])
        driver.until(lambda: all(rig.driven()))
        driver.client.bus.shutdown()  # every send fails from now on
        driver.until(lambda: stream.failure is not None)
        stream.set([0.5, 0.5])  # raises the stream's error
    assert isinstance(stream.failure, can.CanError)
    assert all(cmd != (0, 0) for cmd in rig.record())  # no zero got through a dead bus...
    assert all(rig.driven())  # ...so the ESCs' own command timeout must stop them


def test_a_cancelled_task_stops_the_motors() -> None:
    channel = f"test-command-stream-{next(_CHANNELS)}"
    rig = Rig(channel)
    client_bus = can.Bus(interface="virtual", channel=channel)
    loop = asyncio.new_event_loop()
    entered = asyncio.Event()

    async def drive() -> None:
        async with (
            AsyncBusClient(client_bus) as client,
            client.command_stream(rate=100, watchdog=5.0) as stream,
        ):
            stream.set([0.5, -0.5])
            entered.set()
            while True:  # fed for ever: only the cancellation ends it
                stream.set([0.5, -0.5])
                await asyncio.sleep(0.01)

    async def main() -> None:
        task = asyncio.create_task(drive())
        await entered.wait()
        end = time.monotonic() + 10
        while not all(rig.driven()):
            assert time.monotonic() < end, "timed out"
            await asyncio.sleep(0.01)
        task.cancel()
        with pytest.raises(asyncio.CancelledError):
            await task

    try:
        loop.run_until_complete(main())
        commands = rig.record()
        assert (4096, -4096) in commands
        _ends_stopped(commands)
        end = time.monotonic() + 10
        while any(rig.driven()):
            assert time.monotonic() < end, "timed out"
            time.sleep(0.01)
    finally:
        loop.close()
        client_bus.shutdown()
        rig.close()
