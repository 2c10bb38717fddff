"""The `Runner` and `OperationBatch` at their edges: results asked for too early, requests
that cannot be encoded, cancellations (also from inside another operation), and batches
stopped midway. Sans-IO: simulated ESCs behind a `Peer`, time as an argument."""

from __future__ import annotations

from typing import Any

import pytest

from veronte4x import dronecan
from veronte4x.client import operations as ops
from veronte4x.client.errors import OperationCancelledError
from veronte4x.client.firmware import Phase, UpdateProgress
from veronte4x.client.protocol import ClientProtocol
from veronte4x.dronecan.image_crc import crc64we
from veronte4x.errors import EncodeError
from veronte4x.simulator import SimulatedEsc

from .peer import Peer


def _served(protocol: ClientProtocol, path: bytes) -> bool:
    """Whether the client still serves ``path`` to a node that reads it."""
    request = dronecan.FileReadRequest(0, dronecan.Path(path))
    return protocol.files.read(request)[1].size is not None


def _sent(protocol: ClientProtocol) -> list[tuple[int | None, Any]]:
    """The (destination, message) of each transfer the client has to send now."""
    reassembler = dronecan.Reassembler()
    transfers = [reassembler.feed(f.can_id, f.data, 0.0) for f in protocol.take_frames()]
    return [(t.destination_node_id, t.message) for t in transfers if t is not None]


def test_a_result_asked_for_before_the_end_is_an_error() -> None:
    protocol = ClientProtocol()
    runner = ops.Runner(protocol, timeout=0.5, retries=0)
    peer = Peer([SimulatedEsc(21)])
    task = runner.start(ops.node_info(21), 0.0)
    assert not task.done and task.error is None
    with pytest.raises(RuntimeError, match=r"^the operation is still running$"):
        task.result()
    peer.exchange(protocol, runner, 0.01)
    assert task.result().name == b"iq_motion.esc"


def test_a_request_that_cannot_be_encoded_is_the_operations_error_and_sends_nothing() -> None:
    protocol = ClientProtocol()
    runner = ops.Runner(protocol)
    task = runner.start(ops.node_info(200), 0.0)
    assert isinstance(task.error, EncodeError)
    assert str(task.error) == (
        "uavcan.protocol.GetNodeInfo.destination_node_id = 200: expected 1..127"
    )
    assert protocol.take_frames() == [] and protocol.next_deadline() is None

    def second_choice() -> ops.Operation[Any]:  # an operation may catch it and go on
        try:
            return (yield from ops.node_info(200))
        except EncodeError:
            return (yield from ops.node_info(21))

    task = runner.start(second_choice(), 0.0)
    assert not task.done
    assert _sent(protocol) == [(21, dronecan.GetNodeInfoRequest())]


def test_cancel_forgets_its_own_request_only_and_a_late_answer_is_dropped() -> None:
    protocol = ClientProtocol()
    runner = ops.Runner(protocol, timeout=0.5, retries=0)
    peer = Peer([SimulatedEsc(21), SimulatedEsc(22)])
    first = runner.start(ops.node_info(21), 0.0)
    second = runner.start(ops.node_info(22), 0.0)
    runner.cancel(first)
    assert first.done and first.waiting is None
    assert isinstance(first.error, OperationCancelledError)
    with pytest.raises(OperationCancelledError) as cancelled:
        first.result()  # no result: not None taken for one
    assert str(cancelled.value) == "the operation was cancelled before it finished"
    assert protocol.next_deadline() == 0.5  # the request to node 22 still waits
    peer.exchange(protocol, runner, 0.01)  # both nodes answer; node 21's answer is dropped
    assert second.result().name == b"iq_motion.esc"
    assert isinstance(first.error, OperationCancelledError)
    assert protocol.next_deadline() is None


def test_a_cancelled_update_stops_serving_its_image() -> None:
    protocol = ClientProtocol()
    runner = ops.Runner(protocol, timeout=0.5, retries=0)
    peer = Peer([SimulatedEsc(21)])
    image = bytes(range(256)) * 8
    seen: list[UpdateProgress] = []
    task = runner.start(ops.update_firmware(protocol, 21, image, progress=seen.append), 0.0)
    now = 0.0
    while not seen or seen[-1].phase is not Phase.READING:
        now += 0.01
        peer.exchange(protocol, runner, now)
        assert now < 5
    assert _served(protocol, b"firmware.bin") and runner.next_deadline() is not None
    runner.cancel(task)
    assert task.done and isinstance(task.error, OperationCancelledError)
    assert not _served(protocol, b"firmware.bin")
    assert runner.next_deadline() is None
    runner.poll(now + 60)  # its deadline passes: nothing resumes it
    assert seen[-1].phase is Phase.READING


def test_an_update_cancelled_by_another_operation_is_not_resumed_by_the_same_events() -> None:
    """A progress callback that cancels a sibling update (the tool gives up on the fleet)
    while the sibling waits on the very events that resumed the caller: the sibling is
    not resumed, its image is no longer served, and the caller goes on to the end."""
    protocol = ClientProtocol()
    runner = ops.Runner(protocol, timeout=0.5, retries=0)
    peer = Peer([SimulatedEsc(21), SimulatedEsc(22)])
    image = bytes(range(256)) * 4 + b"end"
    phases: list[tuple[Phase, Phase | None]] = []
    second_seen: list[UpdateProgress] = []

    def first_progress(current: UpdateProgress) -> None:
        phases.append((current.phase, second_seen[-1].phase if second_seen else None))
        if current.phase is Phase.READING and not second.done:
            runner.cancel(second)

    first = runner.start(
        ops.update_firmware(protocol, 21, image, "a.bin", progress=first_progress), 0.0
    )
    second = runner.start(
        ops.update_firmware(protocol, 22, image, "b.bin", progress=second_seen.append), 0.0
    )
    peer.run(protocol, runner, first, 0.01)
    assert first.result().software_version.image_crc == crc64we(image)
    assert second.done and isinstance(second.error, OperationCancelledError)
    assert phases[0] == (Phase.WAITING, None)
    assert (Phase.READING, Phase.WAITING) in phases  # cancelled while it waited to be read
    assert [p.phase for p in second_seen] == [Phase.WAITING]
    assert not _served(protocol, b"a.bin") and not _served(protocol, b"b.bin")


def test_a_batch_stopped_midway_keeps_what_ended_and_forgets_the_rest() -> None:
    """As on Ctrl-C between two waits: the operation that ended keeps its result, the one
    running is cancelled with its request, the one not started never starts."""
    protocol = ClientProtocol()
    runner = ops.Runner(protocol, timeout=0.5, retries=0)
    peer = Peer([SimulatedEsc(21)])
    batch = ops.OperationBatch(runner, [ops.node_info(n) for n in (21, 22, 23)], limit=2)
    assert batch.fill(0.0)
    peer.exchange(protocol, runner, 0.01)  # node 21 answers; there is no node 22
    assert len(peer.requests) == 2
    done, running = batch.tasks
    assert done.done and not running.done
    batch.cancel()
    assert done.result().name == b"iq_motion.esc"
    assert running.done and running.waiting is None
    assert isinstance(running.error, OperationCancelledError)
    assert len(batch.tasks) == 2 and protocol.next_deadline() is None


def test_the_wait_for_frames_ends_at_the_first_deadline_never_before_now() -> None:
    """`Runner.wait` is how long an adapter blocks on the bus: at most ``longest``, and no
    later than the first request timeout or `Listen` time, so that each fires on time."""
    protocol = ClientProtocol()
    runner = ops.Runner(protocol, timeout=0.5, retries=0)
    assert runner.wait(0.0, 0.05) == 0.05 and runner.next_deadline() is None
    runner.start(ops.discover(protocol, 0.25), 0.0)  # resumes at 0.25
    runner.start(ops.node_info(21), 0.0)  # times out at 0.5
    assert (runner.next_deadline(), protocol.next_deadline()) == (0.25, 0.5)
    assert runner.wait(0.0, 1.0) == 0.25
    assert runner.wait(0.0, 0.125) == 0.125
    runner.poll(0.25)  # the listen ends: the request's timeout is next
    assert runner.next_deadline() is None
    assert runner.wait(0.375, 1.0) == 0.125
    assert runner.wait(0.75, 1.0) == 0.0  # overdue: poll at once, never a negative wait
