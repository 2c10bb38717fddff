"""The blocking and the asyncio clients on python-can's virtual bus, at the edges of their
life: stopped before they start or twice, a bus that dies inside a command stream's block,
an interrupted batch, frames that are not DroneCAN; and the calls the scenario tests leave
out (``call``, ``broadcast``, ``listen``, the asyncio ``erase_params`` and ``restart``).

The blocking tests run the ESCs in the client's thread on a clock that moves 1 ms at every
reading, so they are deterministic; the asyncio ones serve the ESCs from a thread.
"""

from __future__ import annotations

import asyncio
import itertools
import threading
from collections.abc import Iterator

import can
import pytest

from veronte4x import dronecan
from veronte4x.client import NoResponseError, plain
from veronte4x.client import operations as ops
from veronte4x.client.aio import AsyncBusClient
from veronte4x.client.bus import BusClient
from veronte4x.client.commander import STOP_REPEATS
from veronte4x.dronecan import vertiq
from veronte4x.simulator import SimulatedEsc
from veronte4x.simulator.can_node import EscBus

from ..simulator.support import StepClock

_CHANNELS = itertools.count()


@pytest.fixture
def channel() -> str:
    return f"test-client-adapters-{next(_CHANNELS)}"


@pytest.fixture
def client_bus(channel: str) -> Iterator[can.BusABC]:
    with can.Bus(interface="virtual", channel=channel) as bus:
        yield bus


@pytest.fixture
def spy(channel: str) -> Iterator[can.BusABC]:
    """A third node on the bus that hears what the client sends."""
    with can.Bus(interface="virtual", channel=channel) as bus:
        yield bus


def _heard(spy: can.BusABC) -> list[dronecan.Transfer]:
    """Every transfer the spy has heard so far, in order."""
    reassembler = dronecan.Reassembler()
    heard = []
    message = spy.recv(0.0)
    while message is not None:
        transfer = reassembler.feed(message.arbitration_id, bytes(message.data), 0.0)
        if transfer is not None:
            heard.append(transfer)
        message = spy.recv(0.0)
    return heard


def _commands(spy: can.BusABC) -> list[tuple[int, ...]]:
    return [t.message.cmd for t in _heard(spy) if isinstance(t.message, dronecan.RawCommand)]


ZEROS = [(0, 0)] * STOP_REPEATS


# -- the blocking client ---------------------------------------------------------------------


@pytest.fixture
def escs(channel: str) -> Iterator[EscBus]:
    with can.Bus(interface="virtual", channel=channel) as bus:
        yield EscBus(bus, [SimulatedEsc(21, 0), SimulatedEsc(22, 1)], StepClock(0.001))


def _client(bus: can.BusABC, escs: EscBus) -> BusClient:
    return BusClient(bus, clock=escs.clock, timeout=0.2, retries=1, while_waiting=escs.step)


def test_a_stream_stopped_without_its_thread_still_sends_zero_throttle(
    client_bus: can.BusABC, spy: can.BusABC
) -> None:
    """`stop` is safe to call at any time, and again: each call sends the zeros."""
    stream = BusClient(client_bus).command_stream(rate=100)
    stream.set([0.5, -0.25])  # never started: nothing goes out...
    assert _commands(spy) == []
    stream.stop()  # ...but stopping still zeroes every motor it was told of
    assert _commands(spy) == ZEROS
    stream.stop()
    assert _commands(spy) == ZEROS
    assert stream.sent == 2 * STOP_REPEATS
    # What `esc spin` reports ("zero throttle sent ... (3 times)"), as the docs say.
    assert stream.STOP_REPEATS == STOP_REPEATS == 3


def test_a_bus_that_dies_in_a_quiet_block_is_raised_at_its_end(
    client_bus: can.BusABC, spy: can.BusABC
) -> None:
    """The block itself raises nothing: leaving it raises the bus's error, so that a dead
    bus (no zero throttle got through) never passes for a clean stop."""
    with (
        pytest.raises(can.CanError),
        BusClient(client_bus).command_stream(rate=100, watchdog=5.0) as stream,
    ):
        stream.set([0.5, 0.5])
        client_bus.shutdown()  # every send fails from now on
    assert (0, 0) not in _commands(spy)


def test_call_takes_its_own_timeout_and_retries(client_bus: can.BusABC, escs: EscBus) -> None:
    client = _client(client_bus, escs)
    info = client.call(dronecan.GetNodeInfoRequest(), 21)
    assert isinstance(info, dronecan.GetNodeInfoResponse) and info.name == b"iq_motion.esc"
    with pytest.raises(NoResponseError) as error:
        client.call(dronecan.GetNodeInfoRequest(), 99, timeout=0.05, retries=0)
    assert str(error.value) == (
        "node 99 did not answer uavcan.protocol.GetNodeInfo (sent once, 0.05 s each); "
        "check the node id, the bus and the bit rate"
    )


def test_broadcast_sends_at_once_and_counts_transfer_ids_per_type(
    client_bus: can.BusABC, spy: can.BusABC, escs: EscBus
) -> None:
    client = _client(client_bus, escs)
    client.broadcast(vertiq.raw_command([0.5, -0.25]))
    client.broadcast(vertiq.raw_command([0.0, 0.0]))
    heard = _heard(spy)
    assert [(t.message.cmd, t.transfer_id, t.source_node_id) for t in heard] == [
        ((4096, -2048), 0, 127),
        ((0, 0), 1, 127),
    ]
    escs.step()
    assert [esc.state.throttle for esc in escs.escs] == [0.0, 0.0]


def test_listen_hears_every_transfer_within_its_time_and_skips_what_is_not_dronecan(
    client_bus: can.BusABC, spy: can.BusABC, escs: EscBus
) -> None:
    client = _client(client_bus, escs)
    for other in (
        can.Message(arbitration_id=0x123, data=b"\x01", is_extended_id=False),  # 11-bit id
        can.Message(arbitration_id=0x1001557F, is_remote_frame=True, dlc=1),
        can.Message(arbitration_id=0x1001557F, data=b""),  # no tail byte
    ):
        spy.send(other)
    clock = escs.clock
    assert isinstance(clock, StepClock)
    start = clock.now
    heard = client.listen(1.0)
    end = clock.now
    assert heard and all(start < t.timestamp <= end for t in heard)
    kinds = {(t.source_node_id, type(t.message).__name__) for t in heard}
    assert kinds == {
        (node, kind) for node in (21, 22) for kind in ("NodeStatus", "EscStatus", "Temperature")
    }
    assert end - start >= 1.0


def test_an_interrupted_batch_forgets_its_requests_and_the_client_goes_on(
    client_bus: can.BusABC, escs: EscBus
) -> None:
    """Ctrl-C in the middle of a fleet read: nothing stays pending, the next call works."""
    waits = 0

    def interrupted() -> None:
        nonlocal waits
        waits += 1
        if waits == 2:
            raise KeyboardInterrupt

    client = _client(client_bus, escs)
    client.while_waiting = interrupted  # the ESCs never see the requests
    with pytest.raises(KeyboardInterrupt):
        client.run_all([ops.node_info(21), ops.node_info(22)])
    assert client.protocol.next_deadline() is None and client.runner.next_deadline() is None
    client.while_waiting = escs.step
    assert client.node_info(22).name == b"iq_motion.esc"


# -- the asyncio client ----------------------------------------------------------------------


def test_an_async_client_used_before_it_starts_says_so_and_sends_nothing(
    client_bus: can.BusABC, spy: can.BusABC
) -> None:
    """Before the fix a BeginFirmwareUpdate or a RestartNode went out before this error:
    the node restarted, or waited in its bootloader for reads nobody would serve."""
    client = AsyncBusClient(client_bus)
    client.stop()  # stopping what never started does nothing
    start_first = r"^start the client first: async with AsyncBusClient\(bus\) as client$"
    with pytest.raises(RuntimeError, match=start_first):
        asyncio.run(client.spin_once())
    with pytest.raises(RuntimeError, match=start_first):
        asyncio.run(client.update_firmware(21, b"image", progress=False))
    with pytest.raises(RuntimeError, match=start_first):
        asyncio.run(client.restart(21))
    assert _heard(spy) == []
    assert (
        client.protocol.next_deadline() is None
        and client.protocol.files.read(dronecan.FileReadRequest(0, dronecan.Path(b"firmware.bin")))[
            1
        ].size
        is None
    )


def test_an_async_client_stopped_twice(client_bus: can.BusABC) -> None:
    async def twice() -> None:
        async with AsyncBusClient(client_bus) as client:
            assert await client.spin_once(0.0) == []
        client.stop()

    asyncio.run(twice())


def test_an_async_stream_stopped_without_its_task_still_sends_zero_throttle(
    client_bus: can.BusABC, spy: can.BusABC
) -> None:
    async def stop_twice() -> None:
        stream = AsyncBusClient(client_bus).command_stream(rate=100)
        stream.set([0.5, -0.25])
        await stream.stop()
        assert _commands(spy) == ZEROS
        await stream.stop()
        assert _commands(spy) == ZEROS

    asyncio.run(stop_twice())


def test_an_async_bus_that_dies_in_a_quiet_block_is_raised_at_its_end(
    client_bus: can.BusABC, spy: can.BusABC
) -> None:
    async def quiet() -> None:
        async with AsyncBusClient(client_bus).command_stream(rate=100, watchdog=5.0) as stream:
            stream.set([0.5, 0.5])
            client_bus.shutdown()

    with pytest.raises(can.CanError):
        asyncio.run(quiet())
    assert (0, 0) not in _commands(spy)


@pytest.fixture
def served_escs(channel: str) -> Iterator[list[SimulatedEsc]]:
    """Two ESCs served from a thread on the real clock, as on a bench."""
    escs = [SimulatedEsc(21, 0), SimulatedEsc(22, 1)]
    stop = threading.Event()
    with can.Bus(interface="virtual", channel=channel) as bus:
        thread = threading.Thread(target=EscBus(bus, escs).run, args=(stop,))
        thread.start()
        try:
            yield escs
        finally:
            stop.set()
            thread.join()


def test_async_erase_restores_the_defaults_and_restart_reaches_the_bootloader(
    client_bus: can.BusABC, served_escs: list[SimulatedEsc]
) -> None:
    async def bench() -> list[object]:
        async with AsyncBusClient(client_bus, timeout=1.0) as client:
            await client.set_param(21, "esc_index", 5)
            await client.save_params(21)
            after_save = (await client.get_param(21, "esc_index")).value
            await client.erase_params(21)
            after_erase = (await client.get_param(21, "esc_index")).value
            await client.restart(22, bootloader=True)
            return [plain(after_save), plain(after_erase)]

    assert asyncio.run(bench()) == [5, 0]
    assert served_escs[0].state.parameters["esc_index"] == 0
    assert served_escs[1].state.in_bootloader and not served_escs[0].state.in_bootloader


def test_timeout_and_retries_set_on_a_client_apply_to_its_next_request(
    client_bus: can.BusABC, escs: EscBus
) -> None:
    client = _client(client_bus, escs)
    assert (client.node_id, client.timeout, client.retries) == (127, 0.2, 1)
    client.timeout, client.retries = 0.05, 0
    assert (client.runner.timeout, client.runner.retries) == (0.05, 0)
    with pytest.raises(NoResponseError) as error:
        client.node_info(99)
    assert (error.value.attempts, error.value.timeout) == (1, 0.05)
