"""The asyncio client as safe as the blocking one (issue 41, item 7): many reads awaited at
once get their own answers, and two clients with one node id refuse rather than take each
other's; a command stream lets no throttle out once its task is cancelled (zero, then
nothing), and none outlives its client. Simulated ESCs served from a thread on python-can's
virtual bus (real clock)."""

from __future__ import annotations

import asyncio
import contextlib
import itertools
import sys
import threading
from collections.abc import Iterator

import can
import pytest

from veronte4x import dronecan
from veronte4x.client import NodeIdConflictError, OperationCancelledError, ParameterInfo, plain
from veronte4x.client.aio import AsyncBusClient, AsyncCommandStream
from veronte4x.simulator import SimulatedEsc
from veronte4x.simulator.can_node import EscBus

_CHANNELS = itertools.count()
ORDER = ("uavcan_node_id", "bit_rate", "esc_index", "zero_behavior", "telem_frequency")
VALUES = {
    21: {
        "uavcan_node_id": 21,
        "bit_rate": 1000000,
        "esc_index": 0,
        "zero_behavior": 0,
        "telem_frequency": 10,
    },
    22: {
        "uavcan_node_id": 22,
        "bit_rate": 250000,
        "esc_index": 1,
        "zero_behavior": 1,
        "telem_frequency": 5,
    },
}


@pytest.fixture
def channel() -> str:
    return f"test-aio-safety-{next(_CHANNELS)}"


@contextlib.contextmanager
def _serve(channel: str) -> Iterator[None]:
    """Nodes 21 and 22, with other values for each parameter, served from a thread."""
    escs = [
        SimulatedEsc(21, 0, bit_rate=1000000),
        SimulatedEsc(22, 1, bit_rate=250000, telem_frequency=5, zero_behavior=1),
    ]
    stop = threading.Event()
    with can.Bus(interface="virtual", channel=channel) as bus:
        thread = threading.Thread(target=EscBus(bus, escs).run, args=(stop,))
        thread.start()
        try:
            yield
        finally:
            stop.set()
            thread.join()


@pytest.fixture
def served(channel: str) -> Iterator[None]:
    with _serve(channel):
        yield


def _commands(spy: can.BusABC) -> list[tuple[int, ...]]:
    """The RawCommand setpoints heard so far, in order."""
    reassembler = dronecan.Reassembler()
    heard = []
    while (message := spy.recv(0.0)) is not None:
        transfer = reassembler.feed(message.arbitration_id, bytes(message.data), 0.0)
        if transfer is not None and isinstance(transfer.message, dronecan.RawCommand):
            heard.append(transfer.message.cmd)
    return heard


def test_150_reads_by_index_awaited_at_once_get_their_own_answers(
    channel: str, served: None
) -> None:
    """Before: 81 of 150 answers named another parameter (the 32 transfer ids reused while
    earlier requests still waited, and frames fed in another order than they came)."""

    async def read() -> list[str]:
        with can.Bus(interface="virtual", channel=channel) as bus:
            async with AsyncBusClient(bus) as client:
                found = await asyncio.gather(
                    *(client.get_param(21, index=i % 5) for i in range(150))
                )
        return [p.name for p in found]

    assert asyncio.run(read()) == [ORDER[i % 5] for i in range(150)]


def test_two_clients_with_one_node_id_150_reads_by_index_each_at_once(channel: str) -> None:
    """Same node id, same transfer ids, other indices: each client hears the other's
    requests from its own id and refuses from then on, so every answer it took is its own
    (before: 3 of 150 named another parameter). The clients' buses come first on the
    virtual channel, which copies a frame to each bus in turn: the ESCs' answer to a
    request then never reaches a client before the request itself, as on CAN."""
    asked = [[(21 + i % 2, (i + shift) % 5) for i in range(150)] for shift in (0, 2)]

    async def read(bus: can.BusABC, mine: list[tuple[int, int]]) -> list[object]:
        async with AsyncBusClient(bus) as client:
            return list(
                await asyncio.gather(
                    *(client.get_param(n, index=i) for n, i in mine), return_exceptions=True
                )
            )

    async def both(a: can.BusABC, b: can.BusABC) -> list[list[object]]:
        return list(await asyncio.gather(read(a, asked[0]), read(b, asked[1])))

    with (
        can.Bus(interface="virtual", channel=channel) as a,
        can.Bus(interface="virtual", channel=channel) as b,
        _serve(channel),
    ):
        results = asyncio.run(both(a, b))
    for mine, found in zip(asked, results, strict=True):
        refused = [f for f in found if isinstance(f, NodeIdConflictError)]
        assert refused, "the other client's requests went unheard"
        for (node, index), got in zip(mine, found, strict=True):
            if not isinstance(got, NodeIdConflictError):
                assert isinstance(got, ParameterInfo), got
                assert (got.name, plain(got.value)) == (ORDER[index], VALUES[node][ORDER[index]])


def _stream_of(client: AsyncBusClient) -> AsyncCommandStream:
    [stream] = client._streams
    return stream


@pytest.mark.parametrize("delay", [i * 0.00025 for i in range(20)])
def test_no_throttle_after_a_cancellation(channel: str, delay: float) -> None:
    """The stream sends every millisecond; its task is cancelled from a timer at moments
    that fall in every phase of its period. From the cancellation on: zero (a command due
    before the block ends, then the three of the stop), then nothing (before, a send due
    in the same loop turn went out at 50 %)."""

    async def drive(client: AsyncBusClient) -> None:
        async with client.command_stream(rate=1000, watchdog=5.0) as stream:
            stream.set([0.5])
            await asyncio.sleep(60)

    async def run(bus: can.BusABC) -> int:
        async with AsyncBusClient(bus) as client:
            task = asyncio.create_task(drive(client))
            await asyncio.sleep(0.005)
            stream = _stream_of(client)
            sent_at_cancel: list[int] = []

            def cancel() -> None:
                sent_at_cancel.append(stream.sent)
                task.cancel()

            asyncio.get_running_loop().call_later(delay, cancel)
            with pytest.raises(asyncio.CancelledError):
                await task
            assert client._streams == ()
            return sent_at_cancel[0]

    with (
        can.Bus(interface="virtual", channel=channel) as bus,
        can.Bus(interface="virtual", channel=channel) as spy,
    ):
        at = asyncio.run(run(bus))
        heard = _commands(spy)
    assert at >= 1 and set(heard[:at]) == {(4096,)}
    assert set(heard[at:]) == {(0,)} and 3 <= len(heard[at:]) <= 4


def test_a_stream_under_wait_for_stops_for_good(channel: str) -> None:
    async def drive(client: AsyncBusClient) -> None:
        async with client.command_stream(rate=500, watchdog=5.0) as stream:
            while True:
                stream.set([0.5])
                await asyncio.sleep(0.001)

    async def run(bus: can.BusABC) -> None:
        async with AsyncBusClient(bus) as client:
            for _ in range(20):
                with pytest.raises(asyncio.TimeoutError):
                    await asyncio.wait_for(drive(client), 0.02)
                assert client._streams == ()

    with (
        can.Bus(interface="virtual", channel=channel) as bus,
        can.Bus(interface="virtual", channel=channel) as spy,
    ):
        asyncio.run(run(bus))
        heard = _commands(spy)
    # 20 runs, each: setpoints, then zeros (three or more), nothing driven after a zero.
    text = "".join("z" if c == (0,) else "d" for c in heard)
    runs = [run for run in text.split("d") if run]
    assert len(runs) == 20 and all(len(run) >= 3 for run in runs), text
    assert text.endswith("zzz")


def test_a_stream_goes_on_after_a_cancellation_its_block_catches(channel: str) -> None:
    """``asyncio.timeout`` inside the block cancels the block's task and catches it: the
    setpoints then go on, and the block's end stops them (zero, then nothing)."""
    if sys.version_info < (3, 11):
        pytest.skip("asyncio.timeout is Python 3.11's")

    async def run(bus: can.BusABC) -> tuple[int, int]:
        async with AsyncBusClient(bus) as client:
            async with client.command_stream(rate=500, watchdog=5.0) as stream:
                stream.set([0.5])
                with contextlib.suppress(TimeoutError):
                    async with asyncio.timeout(0.02):
                        await asyncio.sleep(60)
                before = stream.sent
                while stream.sent < before + 5:  # it goes on
                    stream.set([0.5])
                    await asyncio.sleep(0.002)
            return before, stream.sent

    with (
        can.Bus(interface="virtual", channel=channel) as bus,
        can.Bus(interface="virtual", channel=channel) as spy,
    ):
        before, sent = asyncio.run(run(bus))
        heard = _commands(spy)
    assert sent == len(heard) and sent >= before + 5 + 3
    assert heard[-3:] == [(0,)] * 3 and heard[-4] == (4096,)


def test_a_stream_started_without_async_with_ends_with_its_client(channel: str) -> None:
    """Before: 49 more RawCommands after the client's block had ended."""

    async def run(bus: can.BusABC) -> tuple[AsyncCommandStream, asyncio.Task[None] | None]:
        async with AsyncBusClient(bus) as client:
            stream = client.command_stream(rate=100, watchdog=0.5)
            stream.start()
            stream.set([0.5])
            await asyncio.sleep(0.05)
            task = stream._task
        assert task is not None
        await asyncio.sleep(0)  # the cancelled task ends
        assert task.done()
        await asyncio.sleep(0.3)  # where it went on sending
        with pytest.raises(OperationCancelledError, match="stopped with its client"):
            stream.set([0.5])
        await stream.stop()  # stopping it again is quiet
        return stream, stream._task

    with (
        can.Bus(interface="virtual", channel=channel) as bus,
        can.Bus(interface="virtual", channel=channel) as spy,
    ):
        stream, task = asyncio.run(run(bus))
        heard = _commands(spy)
    assert task is None
    assert heard[-3:] == [(0,)] * 3 and set(heard[:-3]) == {(4096,)}
    assert stream.sent == len(heard)
