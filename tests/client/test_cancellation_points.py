"""Cancellation at every wait of set, save, firmware update and command streams, blocking
and asyncio (issue 41, item 7): each run cancels at the next wait in turn until the
operation finishes first. After each cancellation: no request left pending, no operation
left waiting, the image no longer served, nothing sent by the client, no motor driven,
and for streams zero throttle, then nothing; no task or thread left running."""

from __future__ import annotations

import asyncio
import itertools
import threading
import time
from collections.abc import Callable, Iterator
from typing import Any

import can
import pytest

from veronte4x import dronecan
from veronte4x.client.adapter import MAX_WAIT
from veronte4x.client.aio import AsyncBusClient
from veronte4x.client.bus import BusClient
from veronte4x.client.protocol import ClientProtocol
from veronte4x.simulator import SimulatedEsc
from veronte4x.simulator.can_node import EscBus

from ..simulator.support import StepClock

_CHANNELS = itertools.count()
IMAGE = bytes((i * 11 + 1) & 0xFF for i in range(300))
MOST_WAITS = 5000
"""A guard against an operation that never ends, not a bound on its waits."""

Act = Callable[[Any], Any]
ACTIONS: dict[str, Act] = {
    "set": lambda client: client.set_param(21, "esc_index", 3),
    "save": lambda client: client.save_params(21),
    "update": lambda client: client.update_firmware(21, IMAGE, "fw.bin", progress=False),
}


def _settled(protocol: ClientProtocol, client: BusClient | AsyncBusClient) -> None:
    """Nothing pending or waiting; the image no longer served."""
    assert protocol.next_deadline() is None
    assert client.runner.next_deadline() is None
    read = dronecan.FileReadRequest(0, dronecan.Path(b"fw.bin"))
    assert protocol.files.read(read)[1].size is None


def _own_frames(spy: can.BusABC) -> int:
    """Frames from node 127 (the client) heard so far."""
    count = 0
    while (message := spy.recv(0.0)) is not None:
        count += message.arbitration_id & 0x7F == 127
    return count


class Interrupted(BaseException):
    """What the blocking client's wait raises, as Ctrl-C's KeyboardInterrupt would."""


@pytest.mark.parametrize("name", list(ACTIONS))
def test_blocking_client_interrupted_at_every_wait(name: str) -> None:
    """The simulated ESC runs in the client's waits on a step clock: every run takes the
    same waits, and each is interrupted once in turn."""
    for cancel_at in range(1, MOST_WAITS):
        if _interrupted_at(name, cancel_at):
            assert cancel_at > 1  # it was interrupted at its first wait before
            return
    pytest.fail("the operation never finished")


def _interrupted_at(name: str, cancel_at: int) -> bool:
    """Run the action, interrupted at its ``cancel_at``-th wait; whether it finished first."""
    channel = f"test-cancel-points-{next(_CHANNELS)}"
    with (
        can.Bus(interface="virtual", channel=channel) as esc_bus,
        can.Bus(interface="virtual", channel=channel) as bus,
        can.Bus(interface="virtual", channel=channel) as spy,
    ):
        esc = SimulatedEsc(21)
        clock = StepClock(0.005)
        escs = EscBus(esc_bus, [esc], clock)
        waits = 0

        def waiting() -> None:
            nonlocal waits
            waits += 1
            if waits == cancel_at:
                raise Interrupted
            escs.step()

        client = BusClient(bus, clock=clock, timeout=0.3, while_waiting=waiting)
        try:
            ACTIONS[name](client)
        except Interrupted:
            pass
        else:
            return True
        _settled(client.protocol, client)
        _own_frames(spy)
        for _ in range(150):  # the ESC goes on (1.5 s of its clock: past its file timeout)
            escs.step()
        assert _own_frames(spy) == 0  # the client sent nothing more
        assert not esc.motor.driven
        return False


class CancelledAt(AsyncBusClient):
    """An `AsyncBusClient` whose ``cancel_at``-th wait on the bus cancels its task."""

    cancel_at = 0
    waits = 0

    async def spin_once(self, max_wait: float = MAX_WAIT) -> list[Any]:
        self.waits += 1
        if self.waits == self.cancel_at:
            task = asyncio.current_task()
            assert task is not None
            task.cancel()  # takes effect at the wait below
        return await super().spin_once(max_wait)


@pytest.fixture
def served() -> Iterator[Callable[[], tuple[str, SimulatedEsc]]]:
    """``served()``: a new channel with a new ESC served from a thread on it."""
    stops: list[Callable[[], None]] = []

    def make() -> tuple[str, SimulatedEsc]:
        channel = f"test-cancel-points-{next(_CHANNELS)}"
        esc = SimulatedEsc(21)
        bus = can.Bus(interface="virtual", channel=channel)
        stop = threading.Event()
        thread = threading.Thread(target=EscBus(bus, [esc]).run, args=(stop,))
        thread.start()

        def end() -> None:
            stop.set()
            thread.join()
            bus.shutdown()

        stops.append(end)
        return channel, esc

    yield make
    for end in stops:
        end()


@pytest.mark.parametrize("name", list(ACTIONS))
def test_asyncio_client_cancelled_at_every_await(
    name: str, served: Callable[[], tuple[str, SimulatedEsc]]
) -> None:
    for cancel_at in range(1, MOST_WAITS):
        channel, esc = served()
        if asyncio.run(_cancelled_at(name, cancel_at, channel)):
            assert cancel_at > 1  # it was cancelled at its first await before
            return
        assert not esc.motor.driven
    pytest.fail("the operation never finished")


async def _cancelled_at(name: str, cancel_at: int, channel: str) -> bool:
    """Run the action, cancelled at its ``cancel_at``-th await; whether it finished first."""
    with (
        can.Bus(interface="virtual", channel=channel) as bus,
        can.Bus(interface="virtual", channel=channel) as spy,
    ):
        client = CancelledAt(bus, timeout=0.3)
        client.cancel_at = cancel_at
        async with client:
            action = asyncio.ensure_future(ACTIONS[name](client))
            await asyncio.wait([action])
            if not action.cancelled():
                action.result()
                return True
            _settled(client.protocol, client)
            _own_frames(spy)
            await asyncio.sleep(0.3)  # the ESC goes on
            assert _own_frames(spy) == 0  # the client sent nothing more
            assert asyncio.all_tasks() == {asyncio.current_task()}
        return False


def _commands(spy: can.BusABC) -> list[tuple[int, ...]]:
    reassembler = dronecan.Reassembler()
    heard = []
    while (message := spy.recv(0.0)) is not None:
        transfer = reassembler.feed(message.arbitration_id, bytes(message.data), 0.0)
        if transfer is not None and isinstance(transfer.message, dronecan.RawCommand):
            heard.append(transfer.message.cmd)
    return heard


STEPS = 6
"""Waits of the driving loop below; the stream is cancelled at each in turn."""


@pytest.mark.parametrize("cancel_at", range(STEPS + 1))
def test_blocking_stream_interrupted_at_every_step(cancel_at: int) -> None:
    channel = f"test-cancel-points-{next(_CHANNELS)}"
    with (
        can.Bus(interface="virtual", channel=channel) as bus,
        can.Bus(interface="virtual", channel=channel) as spy,
    ):
        client = BusClient(bus)
        stream = client.command_stream(rate=200, watchdog=5.0)
        sent_at = None
        with pytest.raises(Interrupted), stream:
            for step in range(STEPS + 1):
                if step == cancel_at:
                    sent_at = stream.sent
                    raise Interrupted
                stream.set([0.5])
                time.sleep(0.01)
        heard = _commands(spy)
        assert stream._thread is None
        time.sleep(0.05)
        assert _commands(spy) == []  # nothing after the stop
    assert sent_at is not None
    if cancel_at == 0:
        assert heard == []  # nothing was set: nothing to stop
        return
    driven = [c for c in heard[sent_at:] if c != (0,)]
    assert len(driven) <= 1  # one the thread had decided on before the interrupt
    assert heard[-3:] == [(0,)] * 3 and (0,) not in heard[:-3]


@pytest.mark.parametrize("cancel_at", range(STEPS + 2))
def test_asyncio_stream_cancelled_at_every_await(cancel_at: int) -> None:
    """Awaits 0..STEPS-1 are the driving loop's, STEPS is the block's end (the stop's wait
    for the stream's task)."""
    channel = f"test-cancel-points-{next(_CHANNELS)}"

    async def drive(client: AsyncBusClient, sent_at: list[int]) -> None:
        task = asyncio.current_task()
        assert task is not None
        async with client.command_stream(rate=200, watchdog=5.0) as stream:
            for step in range(STEPS):
                stream.set([0.5])
                if step == cancel_at:
                    sent_at.append(stream.sent)
                    task.cancel()
                await asyncio.sleep(0.01)
            if cancel_at == STEPS:
                sent_at.append(stream.sent)
                asyncio.get_running_loop().call_soon(task.cancel)  # during the stop

    async def run(bus: can.BusABC) -> int | None:
        async with AsyncBusClient(bus) as client:
            sent_at: list[int] = []
            driving = asyncio.ensure_future(drive(client, sent_at))
            await asyncio.wait([driving])
            assert driving.cancelled() == (cancel_at <= STEPS)
            assert client._streams == () and asyncio.all_tasks() == {asyncio.current_task()}
            return sent_at[0] if sent_at else None

    with (
        can.Bus(interface="virtual", channel=channel) as bus,
        can.Bus(interface="virtual", channel=channel) as spy,
    ):
        sent_at = asyncio.run(run(bus))
        heard = _commands(spy)
    assert heard[-3:] == [(0,)] * 3
    if sent_at is not None:
        assert set(heard[sent_at:]) == {(0,)}  # from the cancellation on: zero, then nothing
    assert (0,) not in heard[: -len([c for c in heard if c == (0,)])]
