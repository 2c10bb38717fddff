"""The python-can adapter and the client on the virtual bus, with clocks the tests drive."""

from __future__ import annotations

import itertools
import subprocess
import sys
from collections.abc import Iterator

import can
import pytest
from hypothesis import given
from hypothesis import strategies as st

from veronte4x import dronecan
from veronte4x.canbus import frame_to_message, is_dronecan_frame
from veronte4x.client import NoResponseError
from veronte4x.client.bus import BusClient
from veronte4x.dronecan import vertiq
from veronte4x.simulator import SimulatedEsc
from veronte4x.simulator.can_node import EscBus, EscNode

from .support import ESC, StepClock

_CHANNELS = itertools.count()


@pytest.fixture
def buses() -> Iterator[tuple[can.BusABC, can.BusABC]]:
    channel = f"test-can-node-{next(_CHANNELS)}"
    with (
        can.Bus(interface="virtual", channel=channel) as esc_bus,
        can.Bus(interface="virtual", channel=channel) as client_bus,
    ):
        yield esc_bus, client_bus


def _drain(bus: can.BusABC) -> list[can.Message]:
    messages = []
    message = bus.recv(timeout=0.0)
    while message is not None:
        messages.append(message)
        message = bus.recv(timeout=0.0)
    return messages


def test_step_sends_what_the_core_polls(buses: tuple[can.BusABC, can.BusABC]) -> None:
    esc_bus, other = buses
    node = EscNode(esc_bus, SimulatedEsc(ESC, 1), clock=lambda: 0.0)
    assert node.step() == 5
    received = _drain(other)
    twin = SimulatedEsc(ESC, 1).poll(0.0)
    assert [(m.arbitration_id, bytes(m.data)) for m in received] == twin
    assert all(m.is_extended_id for m in received)
    assert node.step() == 0


def test_only_dronecan_shaped_messages_reach_the_core(
    buses: tuple[can.BusABC, can.BusABC],
) -> None:
    esc_bus, other = buses
    esc = SimulatedEsc(ESC)
    node = EscNode(esc_bus, esc, clock=lambda: 0.0)
    for message in (
        can.Message(arbitration_id=0x123, data=b"\x01\xc0", is_extended_id=False),
        can.Message(arbitration_id=0x10015501, is_remote_frame=True, dlc=2),
        can.Message(arbitration_id=0x10015501, data=bytes(12), is_fd=True),
        can.Message(arbitration_id=0x10015501, data=b""),
    ):
        assert not is_dronecan_frame(message)
        other.send(message)
    node.step()
    assert sum(esc._reassembler.counts.values()) == 0
    frame = dronecan.TransferFrame(0x10015501, bytes(7) + b"\xc0")
    assert is_dronecan_frame(frame_to_message(frame))
    assert frame_to_message(frame, 1.5).timestamp == 1.5


def test_client_requests_and_the_node_answers(buses: tuple[can.BusABC, can.BusABC]) -> None:
    esc_bus, client_bus = buses
    clock = StepClock(0.001)
    esc = SimulatedEsc(ESC, telem_frequency=0)
    node = EscNode(esc_bus, esc, clock=clock)
    client = BusClient(
        client_bus, 10, clock=clock, priority=24, timeout=0.1, while_waiting=node.step
    )
    reply = client.call(vertiq.set_parameter("esc_index", 2), ESC)
    assert reply.value == dronecan.IntegerValue(2)
    again = client.call(vertiq.get_parameter("esc_index"), ESC)
    assert again.value == dronecan.IntegerValue(2)
    info = client.call(dronecan.GetNodeInfoRequest(), ESC)
    assert info.name == b"iq_motion.esc"
    ids = client.protocol.transfer_ids
    # counted per (kind, data type, destination): GetSet twice, GetNodeInfo once
    assert ids.next(dronecan.TransferKind.REQUEST, 11, ESC) == 2
    assert ids.next(dronecan.TransferKind.REQUEST, 1, ESC) == 1
    assert esc.esc_index == 2
    client.broadcast(vertiq.raw_command([0.0, 0.0, 0.5]))
    node.step()
    assert esc.state.throttle == vertiq.raw_to_throttle(4096)
    heard = client.listen(1.0)
    assert [type(t.message).__name__ for t in heard] == ["NodeStatus"]  # 1 Hz, no telemetry


def test_request_times_out_by_the_clock(buses: tuple[can.BusABC, can.BusABC]) -> None:
    _, client_bus = buses
    clock = StepClock(0.004)
    client = BusClient(client_bus, 10, clock=clock, timeout=0.01, retries=1)
    with pytest.raises(NoResponseError) as error:
        client.call(dronecan.GetNodeInfoRequest(), ESC)
    assert str(error.value) == (
        f"node {ESC} did not answer uavcan.protocol.GetNodeInfo (sent 2 times, 0.01 s each); "
        "check the node id, the bus and the bit rate"
    )
    assert client.listen(0.01) == []


def test_run_serves_for_a_duration_of_the_clock(buses: tuple[can.BusABC, can.BusABC]) -> None:
    esc_bus, client_bus = buses
    clock = StepClock(0.01)
    node = EscNode(
        esc_bus, SimulatedEsc(ESC, telem_frequency=10, command_timeout=None), clock=clock
    )
    other = BusClient(client_bus, 10, clock=clock)
    other.broadcast(vertiq.raw_command([0.2]))
    node.run(1.5, max_wait=0.001)  # real seconds blocked per wait on the empty bus
    assert node.esc.state.throttle == vertiq.raw_to_throttle(1638)
    heard = [type(t.message).__name__ for t in other.listen(0.0)]
    assert heard.count("NodeStatus") == 2
    assert heard.count("EscStatus") == heard.count("Temperature") > 10


class _NoBus:
    """`EscBus.feed` never touches its bus."""


_REQUESTS = [
    dronecan.GetNodeInfoRequest(),
    vertiq.get_parameter("esc_index"),
    vertiq.set_parameter("esc_index", 3),
    vertiq.set_parameter("uavcan_node_id", 30),
    dronecan.RestartNodeRequest(dronecan.RestartNodeRequest.MAGIC_NUMBER),
    vertiq.raw_command([0.2, 0.4, 0.6]),
]


@st.composite
def _traffic(draw: st.DrawFn) -> list[tuple[int, bytes]]:
    """Requests to nodes 21-23 and 30 (a node id an ESC may take after a restart), RawCommands,
    and frames cut short, torn or made up: what one bus carries for several ESCs."""
    frames: list[tuple[int, bytes]] = []
    renumbered = draw(st.sampled_from([None, 21, 22, 23]))  # becomes node 30 at once
    first = [] if renumbered is None else [(_REQUESTS[3], renumbered), (_REQUESTS[4], renumbered)]
    for transfer_id in range(draw(st.integers(0, 12)) + len(first)):
        request, destination = (
            first[transfer_id]
            if transfer_id < len(first)
            else (draw(st.sampled_from(_REQUESTS)), draw(st.sampled_from([21, 22, 23, 30])))
        )
        encoded = dronecan.encode(
            request,
            source_node_id=draw(st.sampled_from([10, 127])),
            destination_node_id=None if isinstance(request, dronecan.RawCommand) else destination,
            transfer_id=transfer_id % 32,
            priority=24,
        )
        frames += [(f.can_id, f.data) for f in encoded]
        if draw(st.booleans()):
            frames.pop(draw(st.integers(0, len(frames) - 1)))  # a frame lost
        if draw(st.booleans()):
            frames.append((draw(st.integers(0, 0x1FFFFFFF)), draw(st.binary(max_size=8))))
    return frames


@given(_traffic())
def test_esc_bus_gives_each_esc_what_feeding_it_everything_does(
    frames: list[tuple[int, bytes]],
) -> None:
    routed = EscBus(_NoBus(), [SimulatedEsc(n, n - 21) for n in (21, 22, 23)])  # type: ignore[arg-type]
    twins = [SimulatedEsc(n, n - 21) for n in (21, 22, 23)]
    for step, (can_id, data) in enumerate(frames):
        now = step * 0.01
        routed.clock = lambda now=now: now  # type: ignore[misc]
        message = can.Message(arbitration_id=can_id, data=data, is_extended_id=True)
        routed.feed(message)
        for twin in twins if is_dronecan_frame(message) else []:
            twin.receive(can_id, data, now)
        if step % 5 == 4:  # restarts take effect, node ids change, responses go out
            for esc, twin in zip(routed.escs, twins, strict=True):
                assert esc.poll(now) == twin.poll(now)
    end = len(frames) * 0.01
    for esc, twin in zip(routed.escs, twins, strict=True):
        assert esc.poll(end) == twin.poll(end)
        assert (esc.node_id, esc.esc_index, esc.state) == (twin.node_id, twin.esc_index, twin.state)


def test_the_simulator_does_not_import_the_ground_client() -> None:
    code = (
        "import sys, veronte4x.simulator, veronte4x.simulator.can_node; "
        "print(sorted(m for m in sys.modules if m.startswith('veronte4x.client')))"
    )
    result = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True, timeout=60
    )
    assert result.stdout == "[]\n"
