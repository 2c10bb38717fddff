"""Dynamic node ID allocation in one process: the allocator (`veronte4x.client.allocator`)
against the DroneCAN specification's example log, simulated ESCs that ask for a node id
(`SimulatedEsc(dynamic_node_id=True)`), hand-made frames of nodes that misbehave, and the
``dronecan`` package's ``CentralizedServer``; its table file; both clients on the virtual
bus. The sans-IO runs step a clock of their own, so they are deterministic; each waits for
the allocation it expects, within a generous bound of simulated time.
"""

from __future__ import annotations

import asyncio
import itertools
import threading
import time
from collections.abc import Callable, Iterator
from pathlib import Path

import can
import pytest
from dronecan.driver.common import AbstractDriver, CANFrame
from hypothesis import assume, given
from hypothesis import strategies as st

import dronecan as pydronecan
from veronte4x import dronecan
from veronte4x.client import allocation_table
from veronte4x.client.aio import AsyncBusClient
from veronte4x.client.allocation_table import (
    MOCK,
    AllocationConflictError,
    AllocationTable,
    AllocationTableError,
    Entry,
)
from veronte4x.client.allocator import (
    LISTEN_FIRST,
    Allocated,
    AllocationConflict,
    AllocationEvent,
    Allocator,
    NodeRecorded,
    free_node_id,
)
from veronte4x.client.bus import BusClient
from veronte4x.client.protocol import ClientProtocol
from veronte4x.dronecan import Allocation
from veronte4x.dronecan.can_id import parse_can_id
from veronte4x.node.allocatee import Allocatee, anonymous_frame
from veronte4x.simulator import SimulatedEsc
from veronte4x.simulator.can_node import EscBus
from veronte4x.simulator.esc import UNIQUE_ID_PREFIX

from ..simulator.support import StepClock

BOUND = 60.0
"""Simulated seconds a run may take to reach what it waits for: a guard, far beyond the
few seconds an allocation takes (the DSDL's request period is 0.6-1 s)."""

STEP = 0.005
"""Simulated seconds between two polls of the sans-IO runs."""


def uid(node: int) -> bytes:
    """The unique id of ``SimulatedEsc(node)``."""
    return UNIQUE_ID_PREFIX + bytes((node,))


class Bench:
    """An allocator and simulated ESCs on one bus of their own, as a loop of frames: every
    frame reaches every other node (and the allocator its own, as udp_multicast echoes)."""

    def __init__(self, table: AllocationTable, escs: list[SimulatedEsc], node_id: int = 127):
        self.protocol = ClientProtocol(node_id)
        self.allocator = Allocator(self.protocol, table, now=0.0)
        self.escs = escs
        self.time = 0.0
        self.events: list[AllocationEvent] = []
        self.frames: list[tuple[int, bytes]] = []
        for esc in escs:
            esc.power_cycle(0.0)

    def send(self, frames: list[tuple[int, bytes]]) -> None:
        """Put frames on the bus now, as another node would."""
        for can_id, data in frames:
            self.frames.append((can_id, data))
            for esc in self.escs:
                esc.receive(can_id, data, self.time)
            received = self.protocol.receive(can_id, data, self.time)
            self.events += self.allocator.receive(received, self.time)

    def step(self) -> None:
        self.time += STEP
        self.events += self.allocator.receive(self.protocol.poll(self.time), self.time)
        frames = [f for esc in self.escs for f in esc.poll(self.time)]
        self.send([*frames, *self.protocol.take_frames()])
        self.send(list(self.protocol.take_frames()))

    def until(self, done: Callable[[], bool]) -> None:
        """Step until ``done()`` holds; fail after `BOUND` simulated seconds."""
        end = self.time + BOUND
        while not done():
            assert self.time < end, self.events
            self.step()

    def granted(self) -> dict[int, int]:
        return {e.unique_id[-1]: e.node_id for e in self.events if isinstance(e, Allocated)}


# -- the rule and the exchange, exactly -----------------------------------------------------

SPEC_EXAMPLE = (
    (1.117, 0x1EEE8100, "01 44 C0 8B 63 5E 05 C0"),
    (1.117, 0x1E000101, "00 44 C0 8B 63 5E 05 C0"),
    (1.406, 0x1EEBE500, "00 F4 BC 10 96 DF 11 C1"),
    (1.406, 0x1E000101, "05 B0 00 44 C0 8B 63 81"),
    (1.406, 0x1E000101, "5E 05 F4 BC 10 96 DF 21"),
    (1.406, 0x1E000101, "11 41"),
    (1.485, 0x1E41E100, "00 A8 BA 54 47 C2"),
    (1.485, 0x1E000101, "29 BA FA 44 C0 8B 63 82"),
    (1.485, 0x1E000101, "5E 05 F4 BC 10 96 DF 22"),
    (1.485, 0x1E000101, "11 A8 BA 54 47 42"),
)
"""The real-world log of the DroneCAN specification, 6 "Application-level functions",
"Dynamic node ID allocation", "Example" (dronecan.github.io, commit dff2f58): an allocatee
with no preference and unique id 44 C0 ... 47 gets node id 125 from the allocator at node
1, at priority 30."""


def test_the_allocator_answers_the_specification_example_frame_for_frame() -> None:
    protocol = ClientProtocol(1, priority=30)
    allocator = Allocator(protocol, AllocationTable(), now=1.117 - LISTEN_FIRST)
    answers, events = [], []
    for time_, can_id, data in SPEC_EXAMPLE:
        if can_id & 0x7F == 0:  # the allocatee's anonymous frames
            events += allocator.receive(protocol.receive(can_id, bytes.fromhex(data), time_), time_)
            answers += [(time_, f.can_id, f.data.hex(" ").upper()) for f in protocol.take_frames()]
    assert answers == [line for line in SPEC_EXAMPLE if line[1] & 0x7F]
    unique_id = bytes.fromhex("44C08B635E05F4BC1096DF11A8BA5447")
    assert events == [Allocated(125, unique_id, 0, False)]
    assert list(allocator.table) == [Entry(125, unique_id)]


def test_nothing_is_sent_for_an_allocation_the_table_could_not_store() -> None:
    """The table is stored before the answer: a store that fails (a full disk) ends the
    serving with its error, and the allocatee hears nothing it could take."""

    def full_disk(table: AllocationTable) -> None:
        raise OSError(28, "No space left on device", "table.jsonl")

    protocol = ClientProtocol(1, priority=30)
    allocator = Allocator(protocol, AllocationTable(), now=0.0, store=full_disk)
    requests = [(t, c, bytes.fromhex(d)) for t, c, d in SPEC_EXAMPLE if not c & 0x7F]
    for time_, can_id, data in requests[:2]:
        allocator.receive(
            protocol.receive(can_id, data, time_ + LISTEN_FIRST), time_ + LISTEN_FIRST
        )
    assert len(protocol.take_frames()) == 4  # the answers to the first two stages
    time_, can_id, data = requests[2]
    with pytest.raises(OSError, match="No space left"):
        allocator.receive(
            protocol.receive(can_id, data, time_ + LISTEN_FIRST), time_ + LISTEN_FIRST
        )
    assert protocol.take_frames() == []
    assert len(allocator.table) == 0  # as the file has it


def test_the_allocatee_sends_the_specification_example_requests() -> None:
    unique_id = bytes.fromhex("44C08B635E05F4BC1096DF11A8BA5447")
    requests = [(c, bytes.fromhex(d)) for _, c, d in SPEC_EXAMPLE if not c & 0x7F]
    stages = [Allocation(0, True, unique_id[:6]), Allocation(0, False, unique_id[6:12])]
    stages.append(Allocation(0, False, unique_id[12:]))
    assert [anonymous_frame(m, tid, 30) for tid, m in enumerate(stages)] == requests
    allocatee, heard = Allocatee(unique_id), dronecan.Reassembler()
    sent = allocatee.poll(1.117)  # its request period (0.6-1 s) is over: the first stage
    for time_, can_id, data in SPEC_EXAMPLE:
        if not can_id & 0x7F:
            continue
        transfer = heard.feed(can_id, bytes.fromhex(data), time_)
        if transfer is not None:
            allocatee.receive(transfer)
            sent += allocatee.poll(time_ + 0.4)  # the longest follow-up delay
    assert sent == requests
    assert allocatee.node_id == 125


@given(st.integers(0, 127), st.sets(st.integers(1, 125)))
def test_free_node_id_is_the_preferred_or_the_nearest_free_above_then_below(
    preferred: int, taken: set[int]
) -> None:
    """The DSDL's findFreeNodeID, stated as its comment says it."""
    chosen = free_node_id(preferred, taken)
    free = [n for n in range(1, 126) if n not in taken]
    start = min(preferred, 125) or 125
    above = [n for n in free if n >= start]
    below = [n for n in free if n < start]
    expected = above[0] if above else below[-1] if below else None
    assert chosen == expected


# -- the table file --------------------------------------------------------------------------


@given(
    st.dictionaries(
        st.integers(1, 127), st.binary(min_size=16, max_size=16) | st.just(MOCK), max_size=20
    )
)
def test_a_table_round_trips_through_its_text(entries: dict[int, bytes]) -> None:
    real = [u for u in entries.values() if u != MOCK]
    assume(len(set(real)) == len(real))
    table = AllocationTable(tuple(Entry(n, u) for n, u in entries.items()))
    text = allocation_table.dumps(table)
    assert list(allocation_table.loads(text)) == sorted(table, key=lambda e: e.node_id)
    assert text.splitlines()[0] == '{"format": "veronte4x-node-id-allocations/1"}'


HEADER = '{"format": "veronte4x-node-id-allocations/1"}\n'
A = "7665726f6e746534782e73696d000015"


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("", 'table.jsonl line 1: not an allocation table (expected {"format": '),
        ('{"format": "other/1"}\n', "table.jsonl line 1: not an allocation table"),
        (HEADER + "node 21\n", "table.jsonl line 2: not a JSON object"),
        (HEADER + '{"node_id": 21}\n', 'table.jsonl line 2: expected {"node_id": 1..127'),
        (HEADER + f'{{"node_id": 0, "unique_id": "{A}"}}\n', "line 2: node_id 0 is not a node"),
        (HEADER + '{"node_id": 21, "unique_id": "15"}\n', "line 2: unique_id '15' is not 16"),
        (
            HEADER
            + f'{{"node_id": 21, "unique_id": "{A}"}}\n{{"node_id": 22, "unique_id": "{A}"}}\n',
            f"table.jsonl line 3: unique id {A} is bound to node 21 already, not to node 22; "
            "remove one of the two lines",
        ),
        (
            HEADER
            + f'{{"node_id": 21, "unique_id": "{A}"}}\n'
            + f'{{"node_id": 21, "unique_id": "{"0" * 31}1"}}\n',
            f"table.jsonl line 3: node 21 is bound to unique id {A} already",
        ),
    ],
)
def test_a_table_it_cannot_hold_is_refused_in_one_line(text: str, message: str) -> None:
    with pytest.raises(AllocationTableError) as refused:
        allocation_table.loads(text, "table.jsonl")
    assert message in str(refused.value)
    assert "\n" not in str(refused.value)


def test_save_puts_the_whole_table_in_place_and_load_reads_it(tmp_path: Path) -> None:
    path = tmp_path / "table.jsonl"
    assert len(allocation_table.load(path)) == 0  # none yet: an empty table
    table = AllocationTable((Entry(21, uid(21)), Entry(60, MOCK)))
    allocation_table.save(path, table)
    table.add(Entry(22, uid(22)))
    allocation_table.save(path, table)
    assert [p.name for p in tmp_path.iterdir()] == ["table.jsonl"]  # no temporary file left
    assert list(allocation_table.load(path)) == [
        Entry(21, uid(21)),
        Entry(22, uid(22)),
        Entry(60, MOCK),
    ]
    assert path.read_text().count("\n") == 4


def test_a_mock_entry_takes_the_node_id_its_node_reports_later() -> None:
    table = AllocationTable((Entry(60, MOCK), Entry(61, MOCK)))
    table.add(Entry(60, uid(60)))
    assert (table.node_id(uid(60)), table.unique_id(61)) == (60, MOCK)
    with pytest.raises(AllocationConflictError):
        table.add(Entry(60, uid(61)))


# -- the allocator with simulated ESCs -------------------------------------------------------


def test_the_preferred_node_id_when_free_else_the_nearest_above_and_never_one_on_the_bus() -> None:
    """Node 22 is on the bus with a static id: the ESC preferring 22 gets 23, the one
    preferring 21 gets 21, and the one without a preference the highest free (125 is on
    the bus too, so 124)."""
    escs = [
        SimulatedEsc(22),
        SimulatedEsc(125),
        SimulatedEsc(21, dynamic_node_id=True),
        SimulatedEsc(40, dynamic_node_id=True, preferred_node_id=22),
        SimulatedEsc(41, dynamic_node_id=True, preferred_node_id=0),
    ]
    bench = Bench(AllocationTable(), escs)
    bench.until(lambda: all(e.node_id is not None for e in escs))
    assert bench.granted() == {21: 21, 40: 23, 41: 124}
    assert [e.node_id for e in escs] == [22, 125, 21, 23, 124]
    recorded = [e for e in bench.events if isinstance(e, NodeRecorded)]
    assert sorted((e.node_id, e.unique_id) for e in recorded) == [(22, uid(22)), (125, uid(125))]
    assert not [e for e in bench.events if isinstance(e, AllocationConflict)]
    assert {e.node_id: e.unique_id[-1] for e in bench.allocator.table} == {
        21: 21, 22: 22, 23: 40, 124: 41, 125: 125,
    }  # fmt: skip


def test_a_node_allocated_before_gets_its_node_id_back_after_a_restart() -> None:
    table = AllocationTable((Entry(90, uid(21)),))
    esc = SimulatedEsc(21, dynamic_node_id=True)
    bench = Bench(table, [esc])
    bench.until(lambda: esc.node_id is not None)
    esc.power_cycle(bench.time)  # a dynamic node id is asked for at every start
    assert esc.node_id is None
    bench.until(lambda: esc.node_id is not None)
    allocated = [e for e in bench.events if isinstance(e, Allocated)]
    assert allocated == [Allocated(90, uid(21), 21, True)] * 2
    assert list(table) == [Entry(90, uid(21))]


def test_a_unique_id_the_table_binds_to_another_node_id_is_refused_in_one_line() -> None:
    """A static node at 21 reports the unique id the table gives node 50: the server says
    so once and allocates neither that unique id nor node 50 (an allocatee with it asks
    in vain)."""
    table = AllocationTable((Entry(50, uid(21)),))
    static, dynamic = SimulatedEsc(21), SimulatedEsc(21, dynamic_node_id=True)
    bench = Bench(table, [static, dynamic])
    bench.until(lambda: any(isinstance(e, AllocationConflict) for e in bench.events))
    bench.until(lambda: len([e for e in bench.events if isinstance(e, AllocationConflict)]) == 2)
    conflicts = [e.message for e in bench.events if isinstance(e, AllocationConflict)]
    assert conflicts[0] == (
        f"node 21 on the bus reports unique id {uid(21).hex()}, but unique id {uid(21).hex()} is "
        "bound to node 50 already, not to node 21 in the allocation table: two nodes with one "
        "unique id, or a node replaced; no allocation for either until its line is removed from "
        "the table or the node from the bus"
    )
    assert (
        conflicts[1]
        == f"no node id for unique id {uid(21).hex()}: it or its node id 50 is disputed (see above)"
    )
    bench.until(lambda: bench.time > 20.0)  # it keeps asking: refused, and said only once
    assert len([e for e in bench.events if isinstance(e, AllocationConflict)]) == 2
    assert dynamic.node_id is None
    assert list(table) == [Entry(50, uid(21))]


def _node_status(node_id: int, transfer_id: int) -> list[tuple[int, bytes]]:
    status = dronecan.NodeStatus(1, dronecan.Health.OK, dronecan.Mode.OPERATIONAL, 0, 0)
    return list(dronecan.encode(status, source_node_id=node_id, transfer_id=transfer_id))


def test_a_node_that_never_answers_getnodeinfo_gets_a_mock_entry_first() -> None:
    """NodeStatus from node 125, which does not answer: after 3 GetNodeInfo requests it is
    entered with unique id zero, and only then is the allocatee served (with 124)."""
    esc = SimulatedEsc(30, dynamic_node_id=True, preferred_node_id=0)
    bench = Bench(AllocationTable(), [esc])
    tid = itertools.count()
    next_status = 0.0
    while esc.node_id is None:
        assert bench.time < BOUND
        if bench.time >= next_status:
            bench.send(_node_status(125, next(tid) % 32))
            next_status += 1.0
        bench.step()
    asked = [parse_can_id(c) for c, _ in bench.frames if c & 0x80]
    assert [(a.kind, a.data_type_id, a.destination_node_id) for a in asked] == [
        (dronecan.TransferKind.REQUEST, 1, 125)  # GetNodeInfo
    ] * 3
    assert [e for e in bench.events if not isinstance(e, Allocated)] == [NodeRecorded(125, MOCK)]
    assert bench.granted() == {30: 124}


def test_another_allocator_and_requests_out_of_turn() -> None:
    """A follow-up with no first stage, and one later than FOLLOWUP_TIMEOUT, get no answer;
    an Allocation from another node id is another allocator, refused once."""
    bench = Bench(AllocationTable(), [])
    bench.until(lambda: bench.time > LISTEN_FIRST)
    unique_id = uid(77)
    stage2 = anonymous_frame(Allocation(0, False, unique_id[6:12]), 0, 30)
    bench.send([stage2])
    assert not bench.protocol.take_frames()
    bench.send([anonymous_frame(Allocation(0, True, unique_id[:6]), 1, 30)])
    assert len(bench.protocol.take_frames()) == 1  # the answer to the first stage
    bench.time += 0.6
    bench.send([anonymous_frame(Allocation(0, False, unique_id[6:12]), 2, 30)])
    assert not bench.protocol.take_frames()  # too late: it starts over
    for transfer_id in range(2):
        other = Allocation(5, False, unique_id)
        bench.send(list(dronecan.encode(other, source_node_id=9, transfer_id=transfer_id)))
    conflicts = [e for e in bench.events if isinstance(e, AllocationConflict)]
    assert [c.message for c in conflicts] == [
        "node 9 answers allocation requests too: a centralized allocation server must be the "
        "only one on the bus"
    ]


# -- against the dronecan package's allocator -------------------------------------------------


class _VirtualDriver(AbstractDriver):  # type: ignore[misc]
    """The dronecan package's driver interface on a python-can virtual bus (its own
    python-can driver needs ``flush_tx_buffer``, which the virtual interface lacks)."""

    def __init__(self, channel: str) -> None:
        super().__init__()
        self.bus = can.Bus(interface="virtual", channel=channel)

    def send_frame(self, frame: CANFrame) -> None:
        self.bus.send(can.Message(arbitration_id=frame.id, data=frame.data, is_extended_id=True))

    def receive(self, timeout: float | None = None) -> CANFrame | None:
        m = self.bus.recv(timeout)
        if m is None:
            return None
        now = time.monotonic()
        return CANFrame(m.arbitration_id, bytes(m.data), m.is_extended_id, now, time.time())

    def close(self) -> None:
        self.bus.shutdown()


_CHANNELS = itertools.count()


def test_the_simulated_allocatee_gets_its_node_id_from_the_dronecan_package_server() -> None:
    channel = f"test-allocation-pydronecan-{next(_CHANNELS)}"
    node = pydronecan.node.Node(_VirtualDriver(channel), node_id=127)
    monitor = pydronecan.app.node_monitor.NodeMonitor(node)
    server = pydronecan.app.dynamic_node_id.CentralizedServer(node, monitor)
    escs = [SimulatedEsc(30), SimulatedEsc(21, dynamic_node_id=True)]
    escs.append(SimulatedEsc(22, dynamic_node_id=True, preferred_node_id=0))
    try:
        with can.Bus(interface="virtual", channel=channel) as bus:
            bench = EscBus(bus, escs)
            for esc in escs:
                esc.power_cycle(bench.clock())
            end = time.monotonic() + BOUND
            while any(e.node_id is None for e in escs):
                assert time.monotonic() < end, server.get_allocation_table()
                node.spin(0.005)
                bench.step()
    finally:
        server.close()
        node.close()
    assert [e.node_id for e in escs] == [30, 21, 125]
    twins = [SimulatedEsc(30), SimulatedEsc(21, dynamic_node_id=True)]
    twins.append(SimulatedEsc(22, dynamic_node_id=True, preferred_node_id=0))
    ours = Bench(AllocationTable(), twins)
    ours.until(lambda: all(e.node_id is not None for e in twins))
    assert [e.node_id for e in twins] == [30, 21, 125]  # the same from veronte4x's server


# -- the two clients on the virtual bus --------------------------------------------------------


@pytest.fixture
def buses() -> Iterator[tuple[can.BusABC, can.BusABC]]:
    channel = f"test-allocation-{next(_CHANNELS)}"
    with (
        can.Bus(interface="virtual", channel=channel) as esc_bus,
        can.Bus(interface="virtual", channel=channel) as client_bus,
    ):
        yield esc_bus, client_bus


def test_busclient_serves_and_keeps_the_table_in_its_file(
    buses: tuple[can.BusABC, can.BusABC], tmp_path: Path
) -> None:
    esc_bus, client_bus = buses
    path = tmp_path / "allocations.jsonl"
    clock = StepClock(0.01)  # 10 ms at every reading: 15 s go by in a few thousand readings
    escs = EscBus(esc_bus, [SimulatedEsc(21, dynamic_node_id=True)], clock=clock)
    client = BusClient(client_bus, clock=clock, while_waiting=escs.step)
    seen: list[AllocationEvent] = []
    events = client.serve_allocations(path, duration=BOUND / 4, on_event=seen.append)
    assert events == seen == [Allocated(21, uid(21), 21, False)]
    assert escs.escs[0].node_id == 21
    assert path.read_text() == HEADER + f'{{"node_id": 21, "unique_id": "{uid(21).hex()}"}}\n'
    escs.escs[0].power_cycle(clock())
    again = BusClient(client_bus, clock=clock, while_waiting=escs.step)  # the file, read anew
    assert again.serve_allocations(path, duration=BOUND / 4) == [Allocated(21, uid(21), 21, True)]


def test_asyncbusclient_serves(buses: tuple[can.BusABC, can.BusABC], tmp_path: Path) -> None:
    esc_bus, client_bus = buses
    escs = EscBus(esc_bus, [SimulatedEsc(22, dynamic_node_id=True, preferred_node_id=0)])
    stop = threading.Event()

    async def serve() -> list[AllocationEvent]:
        async with AsyncBusClient(client_bus) as client:
            events: list[AllocationEvent] = []
            task = asyncio.ensure_future(
                client.serve_allocations(tmp_path / "t.jsonl", on_event=events.append)
            )
            end = time.monotonic() + BOUND
            while not events:
                assert time.monotonic() < end
                await asyncio.sleep(0.05)
            task.cancel()
            with pytest.raises(asyncio.CancelledError):
                await task
            return events

    thread = threading.Thread(target=escs.run, args=(stop,))
    thread.start()
    try:
        assert asyncio.run(serve()) == [Allocated(125, uid(22), 0, False)]
    finally:
        stop.set()
        thread.join()
    assert escs.escs[0].node_id == 125
