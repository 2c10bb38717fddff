"""Every node's ``esc_index`` before a motor moves or an index is given (issue 41, item 4):
the survey as a sans-IO operation against simulated ESCs in simulated time, the checks of a
spin and of a change as pure functions, and a spin on python-can's virtual bus that turns
only the motor asked for."""

from __future__ import annotations

import asyncio
import threading
import time
from collections.abc import Iterator
from typing import Any

import can
import pytest

from veronte4x import dronecan
from veronte4x.client import indices
from veronte4x.client import operations as ops
from veronte4x.client.aio import AsyncBusClient
from veronte4x.client.bus import BusClient
from veronte4x.client.errors import InvalidRequestError, NoResponseError, ParameterError
from veronte4x.client.indices import (
    EscIndexError,
    IndexSurvey,
    OwnNodeIdError,
    check_changes,
    survey,
)
from veronte4x.client.protocol import ClientProtocol, Received
from veronte4x.client.spin import spin_indices
from veronte4x.dronecan import EscStatus
from veronte4x.simulator import SimulatedEsc
from veronte4x.simulator.can_node import EscBus

from .peer import Peer


def _survey(
    escs: list[SimulatedEsc], also: tuple[int, ...] = (), answer: Any = None
) -> tuple[IndexSurvey, Peer]:
    """`survey` run against ``escs`` in simulated time, by a client at node 127."""
    protocol = ClientProtocol()
    runner = ops.Runner(protocol, timeout=0.5, retries=0)
    task = runner.start(survey(protocol, also), 0.0)
    peer = Peer(escs, answer)
    peer.run(protocol, runner, task, 0.01)
    return task.result(), peer


def _reads(peer: Peer) -> int:
    return sum(isinstance(r, dronecan.GetSetRequest) for r in peer.requests)


def test_the_survey_reads_every_node_heard() -> None:
    found, peer = _survey([SimulatedEsc(21, 0), SimulatedEsc(22, 1), SimulatedEsc(23, 0)])
    assert found == IndexSurvey({21: 0, 22: 1, 23: 0}, {})
    assert found.nodes() == [21, 22, 23]
    assert _reads(peer) == 3


def test_a_node_that_does_not_answer_is_unread_with_its_error() -> None:
    slow = SimulatedEsc(22, 1, response_delay=5.0)  # answers after the 0.5 s timeout
    found, _ = _survey([SimulatedEsc(21, 0), slow], also=(40,))
    assert found.indices == {21: 0}
    assert sorted(found.unread) == [22, 40]  # 40 was asked although never heard
    for node in (22, 40):
        error = found.unread[node]
        assert isinstance(error, NoResponseError)
        assert str(error) == (
            f"node {node} did not answer uavcan.protocol.param.GetSet (sent once, 0.5 s "
            "each); check the node id, the bus and the bit rate"
        )


def test_a_node_without_an_integer_esc_index_is_unread() -> None:
    real = dronecan.GetSetResponse(value=dronecan.RealValue(1.5), name=b"esc_index")
    found, _ = _survey([SimulatedEsc(21, 0)], answer=lambda request: real)
    assert found.indices == {}
    assert isinstance(found.unread[21], InvalidRequestError)
    assert str(found.unread[21]) == "node 21 reports esc_index 1.5, not a number"
    found, _ = _survey([SimulatedEsc(21, 0)], answer=lambda request: dronecan.GetSetResponse())
    assert isinstance(found.unread[21], ParameterError)
    assert str(found.unread[21]) == "node 21 has no parameter 'esc_index'"


def test_a_node_with_the_tools_own_id_is_heard_but_not_asked() -> None:
    found, peer = _survey([SimulatedEsc(21, 0), SimulatedEsc(127, 1)])
    assert found.indices == {21: 0}
    assert isinstance(found.unread[127], OwnNodeIdError)
    assert str(found.unread[127]) == (
        "node 127 uses this tool's own node id, so nothing it sends can be told from this "
        "tool's own frames"
    )
    assert _reads(peer) == 1  # node 21 only


def test_the_node_table_keeps_a_node_status_from_the_own_id_and_drops_echoes() -> None:
    protocol = ClientProtocol()
    echo = dronecan.encode(dronecan.RawCommand((0,)), source_node_id=127, transfer_id=0)
    status = dronecan.encode(dronecan.NodeStatus(uptime_sec=7), source_node_id=127, transfer_id=0)
    assert protocol.receive(echo[0].can_id, echo[0].data, 1.0) == []
    events = protocol.receive(status[0].can_id, status[0].data, 1.0)
    assert [type(e).__name__ for e in events] == ["Received", "StatusSeen"]
    entry = protocol.nodes.get(127)
    assert entry is not None and entry.uptime_sec == 7


# -- spin ----------------------------------------------------------------------------------


def test_a_spin_of_nodes_with_indices_of_their_own() -> None:
    assert spin_indices([21], IndexSurvey({21: 0, 22: 1}, {})) == {21: 0}
    assert spin_indices([21, 22], IndexSurvey({21: 0, 22: 0, 23: 1}, {})) == {21: 0, 22: 0}


def test_a_spin_that_would_turn_a_node_not_named_is_refused() -> None:
    with pytest.raises(EscIndexError) as refused:
        spin_indices([21], IndexSurvey({21: 0, 22: 0, 23: 1}, {}))
    assert str(refused.value) == (
        "node 22 has esc_index 0 too: RawCommand would turn it with node 21; name it as "
        "well to spin both, or give it an esc_index of its own; nothing was sent"
    )
    assert (refused.value.shared, refused.value.unread) == (True, ())
    with pytest.raises(EscIndexError) as refused:
        spin_indices([21, 23], IndexSurvey({21: 0, 22: 0, 23: 0, 24: 1}, {}))
    assert str(refused.value) == (
        "node 22 has esc_index 0 too: RawCommand would turn it with nodes 21 and 23; name it "
        "as well to spin both, or give it an esc_index of its own; nothing was sent"
    )


def test_a_spin_with_a_node_whose_index_cannot_be_read() -> None:
    silent = NoResponseError(40, "uavcan.protocol.param.GetSet", 3, 1.0)
    found = IndexSurvey({21: 0, 22: 0}, {40: silent})
    with pytest.raises(EscIndexError) as refused:
        spin_indices([21], found)
    assert str(refused.value) == (
        "node 22 has esc_index 0 too: RawCommand would turn it with node 21; name it as "
        "well to spin both, or give it an esc_index of its own; node 40's esc_index cannot "
        "be read, so it may turn too (did not answer uavcan.protocol.param.GetSet (sent 3 "
        "times, 1 s each); check the node id, the bus and the bit rate); nothing was sent"
    )
    assert refused.value.unread == (40,)
    assert refused.value.line("add X") == str(refused.value).replace(
        "; nothing was sent", "; add X; nothing was sent"
    )
    assert spin_indices([21, 22], found, allow_unknown=[40]) == {21: 0, 22: 0}
    with pytest.raises(NoResponseError) as own:  # a node to spin must be read: its error
        spin_indices([21, 40], found, allow_unknown=[40])
    assert own.value is silent


# -- changes -------------------------------------------------------------------------------


def test_an_index_another_node_has_is_refused() -> None:
    found = IndexSurvey({21: 0, 22: 1, 23: 2}, {})
    with pytest.raises(EscIndexError) as refused:
        check_changes({21: 1}, found)
    assert str(refused.value) == (
        "node 22 has esc_index 1 already: giving it to node 21 too would make RawCommand "
        "turn both; nothing was sent"
    )
    with pytest.raises(EscIndexError) as refused:
        check_changes({21: 5, 22: 5, 24: 2}, found)
    assert str(refused.value) == (
        "node 23 has esc_index 2 already: giving it to node 24 too would make RawCommand "
        "turn both; "
        "giving esc_index 5 to nodes 21 and 22 would make RawCommand turn both; "
        "nothing was sent"
    )
    with pytest.raises(EscIndexError) as refused:
        check_changes({21: 1, 23: 1}, found)
    assert str(refused.value) == (
        "node 22 has esc_index 1 already: giving it to nodes 21 and 23 too would make "
        "RawCommand turn them all; nothing was sent"
    )
    check_changes({21: 1}, found, allow_shared=True)


def test_changes_that_leave_every_index_to_one_node_pass() -> None:
    check_changes({21: 1, 22: 0}, IndexSurvey({21: 0, 22: 1}, {}))  # a swap
    check_changes({21: 3}, IndexSurvey({21: 0, 22: 1, 23: 1}, {}))  # 22 and 23: not ours


def test_a_change_beside_a_node_whose_index_cannot_be_read() -> None:
    found = IndexSurvey(
        {21: 0}, {30: InvalidRequestError("node 30 reports esc_index 1.5, not a number")}
    )
    with pytest.raises(EscIndexError) as refused:
        check_changes({21: 4}, found, allow_shared=True)
    assert str(refused.value) == (
        "node 30's esc_index cannot be read, so it may hold the same one (reports esc_index "
        "1.5, not a number); nothing was sent"
    )
    assert (refused.value.shared, refused.value.unread) == (False, (30,))
    check_changes({21: 4}, found, allow_unknown=[30])
    check_changes({30: 4}, found)  # the node set is read by the set itself


# -- on python-can's virtual bus -----------------------------------------------------------


class Rig:
    """Simulated ESCs served from a thread on a virtual bus, and a client on it."""

    def __init__(self, channel: str, escs: list[SimulatedEsc]) -> None:
        self.escs = escs
        self.esc_bus = can.Bus(interface="virtual", channel=channel)
        self.client_bus = can.Bus(interface="virtual", channel=channel)
        self._stop = threading.Event()
        self._thread = threading.Thread(
            target=EscBus(self.esc_bus, escs).run, args=(self._stop,), daemon=True
        )
        self._thread.start()
        self.client = BusClient(self.client_bus, timeout=2.0)

    def close(self) -> None:
        self._stop.set()
        self._thread.join()
        self.esc_bus.shutdown()
        self.client_bus.shutdown()


@pytest.fixture
def shared() -> Iterator[Rig]:
    rig = Rig("test-esc-index-shared", [SimulatedEsc(21, 0), SimulatedEsc(22, 0)])
    yield rig
    rig.close()


@pytest.fixture
def apart() -> Iterator[Rig]:
    rig = Rig("test-esc-index-apart", [SimulatedEsc(21, 0), SimulatedEsc(22, 1)])
    yield rig
    rig.close()


def test_a_library_spin_refused_sends_nothing(shared: Rig) -> None:
    found = shared.client.run(survey(shared.client.protocol, [21]))
    assert found == IndexSurvey({21: 0, 22: 0}, {})
    with pytest.raises(EscIndexError):
        spin_indices([21], found)
    assert [esc.state.rpm for esc in shared.escs] == [0, 0]
    assert not any(esc.motor.driven for esc in shared.escs)


def test_the_asyncio_client_runs_the_same_survey(shared: Rig) -> None:
    async def main() -> IndexSurvey:
        async with AsyncBusClient(shared.client_bus, timeout=2.0) as client:
            found: IndexSurvey = await client.run(survey(client.protocol, [21]))
            return found

    found = asyncio.run(main())
    assert found == IndexSurvey({21: 0, 22: 0}, {})
    with pytest.raises(EscIndexError):
        spin_indices([21], found)


def test_a_library_spin_turns_only_the_motor_asked_for(apart: Rig) -> None:
    client = apart.client
    found = client.run(survey(client.protocol, [21]))
    escs = spin_indices([21], found)
    assert escs == {21: 0}
    rpm: dict[int, list[int]] = {21: [], 22: []}
    with client.command_stream(rate=50, watchdog=2.0) as stream:
        end = time.monotonic() + 60  # a guard: the loop ends on node 21's telemetry
        while not any(r > 500 for r in rpm[21]) or len(rpm[22]) < 3:
            assert time.monotonic() < end, "node 21 never reported turning"
            stream.set({index: 0.3 for index in escs.values()})
            for event in client.spin_once(0.02):
                if isinstance(event, Received) and isinstance(event.transfer.message, EscStatus):
                    node = event.transfer.source_node_id
                    assert node is not None
                    rpm[node].append(event.transfer.message.rpm)
    assert rpm[22] and set(rpm[22]) == {0}
    assert apart.escs[1].state.rpm == 0


def test_indices_module_facts() -> None:
    assert indices.ESC_INDEX == "esc_index"
    assert indices.SURVEY >= 2.0  # two NodeStatus periods
