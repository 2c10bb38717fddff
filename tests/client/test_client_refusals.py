"""What the sans-IO operations do when a node says no, or says something else than it was
told: each refusal ends the operation with its one-line error and sends nothing after it.

A `Peer` stands on the other side of the frames: a `SimulatedEsc`, except for the requests
its ``answer`` takes over.
"""

from __future__ import annotations

from typing import Any

import pytest

from veronte4x import dronecan
from veronte4x.client import RejectedError, paramfile
from veronte4x.client import operations as ops
from veronte4x.client.errors import FirmwareUpdateFailedError
from veronte4x.client.firmware import Phase, UpdateProgress
from veronte4x.client.protocol import ClientProtocol
from veronte4x.dronecan import vertiq
from veronte4x.dronecan.image_crc import crc64we
from veronte4x.simulator import SimulatedEsc

from .peer import Peer


def _run(peer: Peer, operation: ops.Operation[Any], step: float = 0.01) -> ops.Task[Any]:
    """Run ``operation`` against ``peer`` to its end (at most 60 s of its time)."""
    protocol = ClientProtocol()
    runner = ops.Runner(protocol, timeout=0.5, retries=0)
    task = runner.start(operation, 0.0)
    peer.run(protocol, runner, task, step)
    assert protocol.next_deadline() is None  # nothing left waiting for an answer
    return task


def _esc_index(value: int) -> dronecan.GetSetResponse:
    """What node 21 answers for ``esc_index`` holding ``value``."""
    return dronecan.GetSetResponse(
        dronecan.IntegerValue(value),
        dronecan.IntegerValue(0),
        dronecan.IntegerValue(19),
        dronecan.IntegerValue(0),
        b"esc_index",
    )


def _is_set(request: Any) -> bool:
    return isinstance(request, dronecan.GetSetRequest) and not isinstance(
        request.value, dronecan.Empty
    )


def test_a_node_that_keeps_its_old_value_is_a_rejection() -> None:
    peer = Peer([SimulatedEsc(21)], lambda r: _esc_index(0) if _is_set(r) else None)
    task = _run(peer, ops.set_param(21, "esc_index", 3))
    assert isinstance(task.error, RejectedError)
    assert str(task.error) == "node 21 kept esc_index at 0 instead of 3"
    assert peer.requests == [
        vertiq.get_parameter("esc_index"),
        dronecan.GetSetRequest(0, dronecan.IntegerValue(3), b"esc_index"),
    ]


def test_a_read_back_that_differs_stops_the_apply_before_the_save() -> None:
    """The node answers the set with the new value but reads back the old one: the apply
    stops there, says what it read, and sends no ExecuteOpcode SAVE."""
    reads = 0

    def answer(request: Any) -> Any:
        nonlocal reads
        if isinstance(request, dronecan.GetSetRequest) and not _is_set(request):
            reads += 1
            if reads == 2:  # the read-back after the set
                return _esc_index(0)
        return None

    peer = Peer([SimulatedEsc(21)], answer)
    changes = [
        paramfile.Change("esc_index", 0, dronecan.IntegerValue(3)),
        paramfile.Change("zero_behavior", 0, dronecan.IntegerValue(1)),
    ]
    applied: list[str] = []
    task = _run(peer, ops.apply_changes(21, changes, applied))
    assert isinstance(task.error, RejectedError)
    assert str(task.error) == "node 21 reads esc_index back as 0, not 3"
    assert applied == []
    assert len(peer.requests) == 3  # read, set, read back: nothing of zero_behavior, no save
    assert peer.escs[0].state.parameters["zero_behavior"] == 0


def test_an_apply_sets_reads_back_every_change_then_saves_once() -> None:
    peer = Peer([SimulatedEsc(21)])
    changes = [
        paramfile.Change("esc_index", 0, dronecan.IntegerValue(3)),
        paramfile.Change("zero_behavior", 0, dronecan.IntegerValue(1)),
    ]
    task = _run(peer, ops.apply_changes(21, changes))
    assert [(p.name, p.value) for p in task.result()] == [
        ("esc_index", dronecan.IntegerValue(3)),
        ("zero_behavior", dronecan.IntegerValue(1)),
    ]
    saves = [r for r in peer.requests if isinstance(r, dronecan.ExecuteOpcodeRequest)]
    assert saves == [dronecan.ExecuteOpcodeRequest(dronecan.Opcode.SAVE, 0)]
    assert peer.requests[-1] == saves[0]  # the save comes last, after every read-back
    assert len(peer.requests) == 7
    assert peer.escs[0].state.parameters["esc_index"] == 3
    assert peer.escs[0].state.parameters["zero_behavior"] == 1


def test_nothing_to_apply_sends_nothing() -> None:
    peer = Peer([SimulatedEsc(21)])
    task = _run(peer, ops.apply_changes(21, []))
    assert task.result() == []
    assert peer.requests == []


@pytest.mark.parametrize(
    ("code", "verb"), [(dronecan.Opcode.SAVE, "save"), (dronecan.Opcode.ERASE, "erase")]
)
def test_a_refused_opcode_names_the_node_the_opcode_and_its_error(
    code: dronecan.Opcode, verb: str
) -> None:
    refuse = dronecan.ExecuteOpcodeResponse(argument=5, ok=False)
    peer = Peer(
        [SimulatedEsc(21)],
        lambda r: refuse if isinstance(r, dronecan.ExecuteOpcodeRequest) else None,
    )
    task = _run(peer, ops.opcode(21, code))
    assert isinstance(task.error, RejectedError)
    assert str(task.error) == f"node 21 refused to {verb} its parameters (error 5)"
    assert peer.requests == [dronecan.ExecuteOpcodeRequest(code, 0)]


@pytest.mark.parametrize("bootloader", [False, True])
def test_a_refused_restart_is_a_rejection_and_the_node_runs_on(bootloader: bool) -> None:
    refuse = dronecan.RestartNodeResponse(ok=False)
    peer = Peer(
        [SimulatedEsc(21)], lambda r: refuse if isinstance(r, dronecan.RestartNodeRequest) else None
    )
    task = _run(peer, ops.restart(21, bootloader=bootloader))
    assert isinstance(task.error, RejectedError)
    assert str(task.error) == "node 21 refused to restart"
    magic = vertiq.BOOTLOADER_MAGIC if bootloader else vertiq.RESTART_MAGIC
    assert peer.requests == [dronecan.RestartNodeRequest(magic)]
    assert not peer.escs[0].state.in_bootloader


def test_an_update_whose_node_reports_another_crc_fails_after_the_update() -> None:
    """The node pulls the whole image and runs again, but reports another image CRC (a
    flash gone wrong): the update fails with both CRCs, not as a timeout, and the file is
    no longer served."""
    image = bytes(range(256)) * 3 + b"tail"
    wrong = crc64we(image) ^ 1
    info = dronecan.GetNodeInfoResponse(
        dronecan.NodeStatus(5, dronecan.Health.OK, dronecan.Mode.OPERATIONAL, 0, 0),
        dronecan.SoftwareVersion(1, 0, dronecan.SoftwareVersionFlag.IMAGE_CRC, 0, wrong),
        dronecan.HardwareVersion(1, 0, bytes(16)),
        b"iq_motion.esc",
    )
    peer = Peer(
        [SimulatedEsc(21)], lambda r: info if isinstance(r, dronecan.GetNodeInfoRequest) else None
    )
    seen: list[UpdateProgress] = []
    protocol = ClientProtocol()
    runner = ops.Runner(protocol, timeout=0.5, retries=0)
    update = ops.update_firmware(protocol, 21, image, "fw.bin", progress=seen.append)
    task = runner.start(update, 0.0)
    peer.run(protocol, runner, task, 0.01)
    assert isinstance(task.error, FirmwareUpdateFailedError)
    assert str(task.error) == (
        f"node 21 reports image CRC {wrong:#018x}, but the image's CRC-64-WE is "
        f"{crc64we(image):#018x}"
    )
    assert not task.error.timed_out
    assert seen[-1] == UpdateProgress(21, Phase.DONE, len(image), len(image))
    assert isinstance(peer.requests[-1], dronecan.GetNodeInfoRequest)
    request = dronecan.FileReadRequest(0, dronecan.Path(b"fw.bin"))
    assert protocol.files.read(request)[1].size is None  # no longer served


def test_a_parameter_walk_stops_at_the_13_bit_index_limit() -> None:
    """A node that never answers a walk with an empty value: the walk asks indices 0 to
    8191 (GetSet's index is 13 bits), one request each, and returns what it got."""
    walk = ops.list_params(21)
    step = next(walk)
    asked = []
    with pytest.raises(StopIteration) as end:
        while True:
            assert isinstance(step, ops.Call) and step.node_id == 21
            assert (step.timeout, step.retries) == (None, None)
            asked.append(step.message.index)
            assert step.message == vertiq.get_parameter_by_index(asked[-1])
            name = f"p{asked[-1]}".encode()
            step = walk.send(dronecan.GetSetResponse(dronecan.IntegerValue(asked[-1]), name=name))
    assert asked == list(range(ops.MAX_PARAMETERS)) and ops.MAX_PARAMETERS == 8192
    found = end.value.value
    assert len(found) == 8192
    assert (found[-1].name, found[-1].value, found[-1].index) == (
        "p8191",
        dronecan.IntegerValue(8191),
        8191,
    )
