"""The client refuses what could re-address a node or flash a wrong image, and takes no
other request's answer for its own (issue 20, items 1-3), on python-can's virtual bus."""

from __future__ import annotations

import itertools
from collections.abc import Callable, Iterator

import can
import pytest

from veronte4x import dronecan
from veronte4x.client import (
    MAX_IMAGE_SIZE,
    InvalidRequestError,
    NodeIdConflictError,
    ParameterError,
    Requester,
    SpinMonitor,
    answers,
)
from veronte4x.client.bus import BusClient
from veronte4x.dronecan import vertiq
from veronte4x.simulator import SimulatedEsc
from veronte4x.simulator.can_node import EscBus

from ..simulator.support import StepClock

_CHANNELS = itertools.count()


@pytest.fixture
def channel() -> str:
    return f"test-client-safety-{next(_CHANNELS)}"


@pytest.fixture
def escs(channel: str) -> Iterator[EscBus]:
    with can.Bus(interface="virtual", channel=channel) as bus:
        yield EscBus(bus, [SimulatedEsc(21, 0), SimulatedEsc(22, 1)], StepClock(0.001))


def _client(bus: can.BusABC, escs: EscBus, node_id: int = 127, first: int = 0) -> BusClient:
    return BusClient(
        bus,
        node_id,
        clock=escs.clock,
        timeout=0.2,
        retries=2,
        while_waiting=escs.step,
        first_transfer_id=first,
    )


def test_an_empty_name_is_refused_before_anything_is_sent(channel: str, escs: EscBus) -> None:
    with (
        can.Bus(interface="virtual", channel=channel) as bus,
        can.Bus(interface="virtual", channel=channel) as spy,
    ):
        client = _client(bus, escs)
        calls: list[Callable[[], object]] = [
            lambda: client.set_param(21, "", 5),
            lambda: client.get_param(21, ""),
            lambda: client.get_param(21),
            lambda: client.set_param(21, "esc_index", 5, index=2),
        ]
        for call in calls:
            with pytest.raises(InvalidRequestError) as error:
                call()
            assert "\n" not in str(error.value)
        assert spy.recv(0.0) is None  # nothing sent
        with pytest.raises(InvalidRequestError, match=r"^an empty parameter name is refused"):
            client.set_param(21, "", 5)
        with pytest.raises(TypeError, match="index="):
            client.get_param(21, 0)  # type: ignore[arg-type]
        assert escs.escs[0].state.parameters["uavcan_node_id"] == 21
        # By index only when said so.
        assert client.get_param(21, index=0).name == "uavcan_node_id"


def test_a_value_that_does_not_parse_is_refused_in_plain_words(channel: str, escs: EscBus) -> None:
    with can.Bus(interface="virtual", channel=channel) as bus:
        client = _client(bus, escs)
        with pytest.raises(
            InvalidRequestError, match=r"^node 21: esc_index takes an integer, not 'abc'$"
        ):
            client.set_param(21, "esc_index", "abc")
        with pytest.raises(ParameterError, match=r"^node 21: esc_index takes an integer, not 2.5$"):
            client.set_param(21, "esc_index", 2.5)


def test_two_clients_with_one_node_id_refuse_rather_than_take_each_others_answers(
    channel: str, escs: EscBus
) -> None:
    """Same node id, same first transfer id: a sends GetSet #0 to node 21, b reads another
    parameter with the same transfer id. Each hears the other's request from its own id and
    refuses from then on: no answer is taken for another's."""
    with (
        can.Bus(interface="virtual", channel=channel) as bus_a,
        can.Bus(interface="virtual", channel=channel) as bus_b,
    ):
        a, b = _client(bus_a, escs), _client(bus_b, escs)
        a.protocol.request(vertiq.get_parameter("esc_index"), 21, a.clock(), timeout=0.2)
        a.spin_once(0.0)  # sent
        line = (
            "another tool or node on the bus sends with this tool's node id 127 (a "
            "uavcan.protocol.param.GetSet request to node 21), so their answers cannot be "
            "told apart; give each tool on the bus a node id of its own"
        )
        with pytest.raises(NodeIdConflictError) as error:
            b.get_param(21, "bit_rate")
        assert str(error.value) == line
        with pytest.raises(NodeIdConflictError):  # refused from then on
            b.get_param(22, "bit_rate")
        with pytest.raises(NodeIdConflictError):  # a heard b's request too
            a.get_param(22, "esc_index")
        assert a.protocol.requests.mismatched == b.protocol.requests.mismatched == 0
        c = _client(bus_b, escs, node_id=100)  # another id: served as ever
        assert c.get_param(22, "esc_index").name == "esc_index"


def test_answers_checks_what_a_reply_says_of_its_request() -> None:
    esc_index = vertiq.get_parameter("esc_index")
    reply = dronecan.GetSetResponse(value=dronecan.IntegerValue(1), name=b"bit_rate")
    assert not answers(esc_index, reply)
    assert answers(vertiq.get_parameter("bit_rate"), reply)
    assert answers(vertiq.get_parameter_by_index(1), reply)  # by index: nothing to check
    assert answers(esc_index, dronecan.GetSetResponse())  # "no such parameter" names nothing
    assert answers(dronecan.ExecuteOpcodeRequest(0, 0), dronecan.ExecuteOpcodeResponse(0, True))
    requester = Requester(127)
    requester.request(esc_index, 21, 0.0)
    transfer = _transfer(requester.take_frames())
    wrong = dronecan.encode(
        reply, source_node_id=21, destination_node_id=127, transfer_id=transfer.transfer_id
    )
    assert requester.receive(_transfer(wrong)) is None
    assert requester.mismatched == 1
    assert requester.next_deadline() is not None  # still waiting for its own answer


def _transfer(frames: list[dronecan.TransferFrame]) -> dronecan.Transfer:
    reassembler = dronecan.Reassembler()
    transfers = [reassembler.feed(f.can_id, f.data, 0.0) for f in frames]
    assert transfers[-1] is not None
    return transfers[-1]


def test_empty_and_oversized_images_are_refused_before_anything_is_sent(
    channel: str, escs: EscBus
) -> None:
    with (
        can.Bus(interface="virtual", channel=channel) as bus,
        can.Bus(interface="virtual", channel=channel) as spy,
    ):
        client = _client(bus, escs)
        with pytest.raises(InvalidRequestError, match=r"^the firmware image is empty \(0 bytes\)"):
            client.update_firmware(21, b"")
        with pytest.raises(InvalidRequestError, match=r"^the firmware image has 101 bytes, more"):
            client.update_firmware(21, bytes(101), max_image_size=100)
        with pytest.raises(InvalidRequestError, match=r"^the firmware image has 1 byte, more"):
            client.update_firmware(21, bytes(1), max_image_size=0)
        with pytest.raises(InvalidRequestError, match=f"more than the limit of {MAX_IMAGE_SIZE}"):
            client.update_firmware(21, bytes(MAX_IMAGE_SIZE + 1))
        assert spy.recv(0.0) is None
        assert escs.escs[0].state.mode is dronecan.Mode.OPERATIONAL


def _status(
    node: int, at: float, temperature: float = 300.0, current: float = 1.0
) -> dronecan.Transfer:
    message = dronecan.EscStatus(0, 25.0, current, temperature, 1000, 10, 0)
    return dronecan.Transfer(message, node, None, 16, 0, at, dronecan.TransferKind.MESSAGE, 1034)


def test_spin_monitor_stops_on_silence_and_on_limits() -> None:
    monitor = SpinMonitor([21, 22], 0.0, silence=1.0)
    monitor.observe(_status(21, 0.9))
    monitor.observe(_status(22, 0.5))
    assert monitor.check(1.4) is None
    assert monitor.check(1.6) == "node 22 fell silent: no esc.Status or NodeStatus for 1 s"
    assert not monitor.over_limit
    hot = SpinMonitor([21], 0.0, max_temperature=80.0, max_current=20.0)
    hot.observe(_status(21, 0.1, temperature=273.15 + 85.0))
    assert hot.check(0.1) == "node 21 reported 85.0 °C, above the limit of 80 °C"
    assert hot.over_limit
    amps = SpinMonitor([21], 0.0, max_current=20.0)
    amps.observe(_status(99, 0.1, current=50.0))  # not a spun node
    assert amps.check(0.1) is None
    amps.observe(_status(21, 0.1, current=25.5))
    assert amps.check(0.1) == "node 21 reported 25.5 A, above the limit of 20 A"
