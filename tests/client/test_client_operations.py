"""The sans-IO operations and their runner: many operations at once over one protocol."""

from __future__ import annotations

from typing import Any

import pytest

from veronte4x import dronecan
from veronte4x.client import FileServer, NoResponseError, ParameterError, Phase, paramfile
from veronte4x.client import operations as ops
from veronte4x.client.protocol import ClientProtocol
from veronte4x.dronecan.image_crc import crc64we
from veronte4x.simulator import SimulatedEsc


def _exchange(
    protocol: ClientProtocol,
    runner: ops.Runner,
    escs: list[SimulatedEsc],
    now: float,
    sent: tuple[dronecan.Reassembler, list[Any]] | None = None,
) -> None:
    """One round trip: the client's frames to every ESC, the ESCs' frames back; with
    ``sent``, each message the client sent is added to its list."""
    frames = protocol.take_frames()
    if sent is not None:
        reassembler, messages = sent
        for frame in frames:
            transfer = reassembler.feed(frame.can_id, frame.data, now)
            if transfer is not None:
                messages.append(transfer.message)
    for esc in escs:
        for frame in frames:
            esc.receive(frame.can_id, frame.data, now)
    for esc in escs:
        for frame in esc.poll(now):
            runner.feed(protocol.receive(frame.can_id, frame.data, now), now)
    runner.feed(protocol.poll(now), now)
    runner.poll(now)


def test_operations_on_different_nodes_run_side_by_side() -> None:
    protocol = ClientProtocol()
    runner = ops.Runner(protocol, timeout=0.5, retries=0)
    escs = [SimulatedEsc(21, 0), SimulatedEsc(22, 1)]
    walks = [runner.start(ops.list_params(node), 0.0) for node in (21, 22)]
    rounds = 0
    while not all(t.done for t in walks):
        rounds += 1
        _exchange(protocol, runner, escs, 0.001 * rounds)
    assert rounds == 6  # five parameters and the empty reply: one round each, both nodes at once
    assert [[p.value for p in t.result()][2] for t in walks] == [
        dronecan.IntegerValue(0),
        dronecan.IntegerValue(1),
    ]


def test_errors_end_only_their_operation() -> None:
    protocol = ClientProtocol()
    runner = ops.Runner(protocol, timeout=0.5, retries=0)
    escs = [SimulatedEsc(21)]
    missing = runner.start(ops.get_param(21, "no_such"), 0.0)
    silent = runner.start(ops.node_info(99), 0.0)
    good = runner.start(ops.set_param(21, "esc_index", 3), 0.0)
    for step in range(1, 4):
        _exchange(protocol, runner, escs, 0.01 * step)
    with pytest.raises(ParameterError, match=r"^node 21 has no parameter 'no_such'$"):
        missing.result()
    assert not silent.done
    _exchange(protocol, runner, escs, 0.6)
    assert isinstance(silent.error, NoResponseError)
    assert good.result().value == dronecan.IntegerValue(3)


def test_listen_resumes_at_its_time_and_cancel_forgets_the_request() -> None:
    protocol = ClientProtocol()
    runner = ops.Runner(protocol)
    found = runner.start(ops.discover(protocol, 1.0), 0.0)
    assert runner.next_deadline() == 1.0
    runner.poll(0.5)
    assert not found.done
    runner.poll(1.0)
    assert found.result() == []
    task = runner.start(ops.node_info(21), 2.0)
    runner.cancel(task)
    assert task.done and protocol.next_deadline() is None


def test_a_shared_file_is_served_until_its_last_user_is_done() -> None:
    server = FileServer()
    server.add(b"fw.bin", b"abc")
    server.add(b"fw.bin", b"abc")
    server.remove(b"fw.bin")
    request = dronecan.FileReadRequest(0, dronecan.Path(b"fw.bin"))
    assert server.read(request)[0].data == b"abc"
    server.remove(b"fw.bin")
    assert server.read(request)[1].size is None


@pytest.mark.parametrize("delay", [0.0, 0.005])
def test_two_updates_of_one_image_at_once(delay: float) -> None:
    protocol = ClientProtocol()
    runner = ops.Runner(protocol, timeout=0.5)
    escs = [SimulatedEsc(n, i, response_delay=delay) for i, n in enumerate((21, 22))]
    image = bytes(range(256)) * 4 + b"end"
    seen: dict[int, list[Any]] = {21: [], 22: []}
    updates = [
        runner.start(
            ops.update_firmware(protocol, node, image, "fw.bin", progress=seen[node].append), 0.0
        )
        for node in (21, 22)
    ]
    now = 0.0
    while not all(t.done for t in updates):
        now += 0.01
        _exchange(protocol, runner, escs, now)
        assert now < 5
    for task in updates:
        assert task.result().software_version.image_crc == crc64we(image)
    assert [p[-1].phase for p in seen.values()] == [Phase.DONE, Phase.DONE]
    assert (
        protocol.files.read(dronecan.FileReadRequest(0, dronecan.Path(b"fw.bin")))[1].size is None
    )


def test_a_node_that_falls_silent_mid_apply_is_not_saved() -> None:
    """Two changes; the node answers the first set and its read-back, then falls silent: the
    failure says what was set, and no ExecuteOpcode SAVE is ever sent."""
    protocol = ClientProtocol()
    runner = ops.Runner(protocol, timeout=0.2, retries=0)
    esc = SimulatedEsc(21)
    changes = [
        paramfile.Change("esc_index", 0, dronecan.IntegerValue(3)),
        paramfile.Change("zero_behavior", 0, dronecan.IntegerValue(1)),
    ]
    applied: list[str] = []
    task = runner.start(ops.apply_changes(21, changes, applied), 0.0)
    sent: list[Any] = []
    reassembler = dronecan.Reassembler()
    now = 0.0
    while not task.done:
        now += 0.01
        frames = protocol.take_frames()
        for frame in frames:
            transfer = reassembler.feed(frame.can_id, frame.data, now)
            if transfer is not None:
                sent.append(transfer.message)
        if len(applied) < 1 or now < 0.05:  # silent once esc_index is set and read back
            for frame in frames:
                esc.receive(frame.can_id, frame.data, now)
            for frame in esc.poll(now):
                runner.feed(protocol.receive(frame.can_id, frame.data, now), now)
        runner.feed(protocol.poll(now), now)
        assert now < 5
    assert applied == ["esc_index"]
    assert isinstance(task.error, NoResponseError)
    assert not any(isinstance(m, dronecan.ExecuteOpcodeRequest) for m in sent)
    assert esc.state.parameters["esc_index"] == 3 and esc.state.parameters["zero_behavior"] == 0


def test_a_refused_value_stops_the_apply_before_the_save() -> None:
    protocol = ClientProtocol()
    runner = ops.Runner(protocol, timeout=0.2, retries=0)
    esc = SimulatedEsc(21)
    out_of_range = paramfile.Change("esc_index", 0, dronecan.IntegerValue(30))
    task = runner.start(ops.apply_changes(21, [out_of_range]), 0.0)
    sent: list[Any] = []
    tap = (dronecan.Reassembler(), sent)
    for step in range(1, 5):
        _exchange(protocol, runner, [esc], 0.01 * step, tap)
    with pytest.raises(ParameterError, match=r"^node 21: 30 is out of range for esc_index"):
        task.result()
    assert [type(m) for m in sent] == [dronecan.GetSetRequest]  # the set, and no SAVE
    assert esc.state.parameters["esc_index"] == 0
