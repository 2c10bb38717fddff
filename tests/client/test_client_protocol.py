"""The client's sans-IO parts: no bus, times as arguments."""

from __future__ import annotations

from typing import Any

import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from veronte4x import dronecan
from veronte4x.client import (
    Answered,
    ClientProtocol,
    Commander,
    FileServed,
    FileServer,
    FirmwareUpdate,
    NodeTable,
    Phase,
    Requester,
    TimedOut,
    TransferIds,
    UpdateProgress,
)
from veronte4x.client.files import FileRead
from veronte4x.client.firmware import image_crc
from veronte4x.client.protocol import NodeIdConflict, Received
from veronte4x.dronecan.image_crc import crc64we
from veronte4x.errors import EncodeError

K = dronecan.TransferKind


def _response(message: Any, source: int, destination: int, transfer_id: int) -> dronecan.Transfer:
    frames = dronecan.encode(
        message, source_node_id=source, destination_node_id=destination, transfer_id=transfer_id
    )
    return dronecan.decode_frames([(f.can_id, f.data) for f in frames])


_INFO = dronecan.GetNodeInfoResponse(
    dronecan.NodeStatus(1, dronecan.Health.OK, dronecan.Mode.OPERATIONAL, 0, 0),
    dronecan.SoftwareVersion(1, 0, 0, 0, 0),
    dronecan.HardwareVersion(1, 0, bytes(16)),
    b"x",
)


def test_transfer_ids_count_per_stream_and_wrap() -> None:
    ids = TransferIds()
    assert [ids.next(K.REQUEST, 11, 21) for _ in range(33)] == [*range(32), 0]
    assert ids.next(K.REQUEST, 11, 22) == 0
    assert ids.next(K.REQUEST, 1, 21) == 0
    assert ids.next(K.MESSAGE, 1030, None) == 0


def test_requester_matches_only_its_response() -> None:
    requester = Requester(node_id=100)
    handle = requester.request(dronecan.GetNodeInfoRequest(), 21, now=0.0, timeout=1.0)
    requester.take_frames()
    reply = dronecan.RestartNodeResponse(True)
    assert requester.receive(_response(reply, 21, 100, 0)) is None  # other data type
    info = _INFO
    assert requester.receive(_response(info, 22, 100, 0)) is None  # other node
    assert requester.receive(_response(info, 21, 101, 0)) is None  # to another client
    assert requester.receive(_response(info, 21, 100, 5)) is None  # other transfer id
    answered = requester.receive(_response(info, 21, 100, 0))
    assert isinstance(answered, Answered) and answered.request.handle == handle
    assert requester.pending(handle) is None
    assert requester.receive(_response(info, 21, 100, 0)) is None  # answered once


def test_retries_take_new_transfer_ids_and_a_late_answer_counts() -> None:
    requester = Requester(node_id=100)
    handle = requester.request(dronecan.GetNodeInfoRequest(), 21, now=0.0, retries=2)
    assert len(requester.take_frames()) == 1
    assert requester.poll(0.99) == [] and requester.take_frames() == []
    assert requester.poll(1.0) == [] and len(requester.take_frames()) == 1
    pending = requester.pending(handle)
    assert pending is not None and pending.transfer_ids == (0, 1)
    assert requester.next_deadline() == 2.0
    late = requester.receive(_response(_INFO, 21, 100, 0))  # the first attempt's answer
    assert isinstance(late, Answered) and late.request.handle == handle


def test_timeout_after_every_retry() -> None:
    requester = Requester(node_id=100)
    handle = requester.request(dronecan.RestartNodeRequest(1), 5, now=10.0, timeout=0.5, retries=1)
    assert requester.poll(10.5) == []
    (failed,) = requester.poll(11.0)
    assert isinstance(failed, TimedOut)
    assert (failed.request.handle, failed.attempts, failed.request.request_name) == (
        handle,
        2,
        "uavcan.protocol.RestartNode",
    )
    assert requester.next_deadline() is None


def test_only_requests_can_be_requested() -> None:
    with pytest.raises(EncodeError):
        Requester(1).request(dronecan.RawCommand(()), 5, now=0.0)
    with pytest.raises(EncodeError):
        ClientProtocol().broadcast(dronecan.GetNodeInfoRequest())
    with pytest.raises(EncodeError):
        ClientProtocol(node_id=0)


def test_node_table_counts_restarts_and_forgets_silent_nodes() -> None:
    table = NodeTable()
    status = dronecan.NodeStatus(10, dronecan.Health.OK, dronecan.Mode.OPERATIONAL, 0, 0)
    table.observe_status(21, status, 1.0)
    entry = table.observe_status(
        21, dronecan.NodeStatus(0, dronecan.Health.WARNING, dronecan.Mode.OPERATIONAL, 0, 0), 2.0
    )
    assert (entry.restarts, entry.first_seen, entry.last_seen, entry.health) == (
        1,
        1.0,
        2.0,
        dronecan.Health.WARNING,
    )
    assert [e.node_id for e in table.online(4.99)] == [21]
    assert table.online(5.0) == []
    assert [e.node_id for e in table.all()] == [21]


def test_file_server() -> None:
    server = FileServer()
    server.add(b"a.bin", bytes(range(256)) * 2)
    info = server.get_info(dronecan.FileGetInfoRequest(dronecan.Path(b"a.bin")))
    assert (info.size, info.error.value, info.entry_type.flags) == (512, 0, 9)
    missing = server.get_info(dronecan.FileGetInfoRequest(dronecan.Path(b"b.bin")))
    assert missing.error.value == dronecan.FileError.NOT_FOUND
    full, read = server.read(dronecan.FileReadRequest(256, dronecan.Path(b"a.bin")))
    assert full.data == bytes(range(256)) and not read.end_of_file
    end, read = server.read(dronecan.FileReadRequest(512, dronecan.Path(b"a.bin")))
    assert end.data == b"" and read.end_of_file  # a file of whole chunks ends on an empty read
    past, read = server.read(dronecan.FileReadRequest(10**6, dronecan.Path(b"a.bin")))
    assert past.data == b"" and read.end_of_file
    absent, read = server.read(dronecan.FileReadRequest(0, dronecan.Path(b"b.bin")))
    assert absent.error.value == dronecan.FileError.NOT_FOUND and read.size is None


def test_commander_rate_watchdog_and_stop() -> None:
    commander = Commander(rate=10, watchdog=0.35)
    assert commander.poll(0.0) is None  # nothing before the first set
    commander.set([0.5], now=0.0)
    sent = [(t / 100, commander.poll(t / 100)) for t in range(0, 60)]
    commands = [(round(t, 2), c.cmd) for t, c in sent if c is not None]
    assert commands == [
        (0.0, (4096,)),
        (0.1, (4096,)),
        (0.2, (4096,)),
        (0.3, (4096,)),
        (0.4, (0,)),
        (0.5, (0,)),
    ]
    assert commander.stop() == dronecan.RawCommand((0,))
    assert commander.poll(1.0) is None
    with pytest.raises(EncodeError):
        commander.set([1.5], now=1.0)
    with pytest.raises(EncodeError):
        Commander(rate=0)
    for name in ("rate", "watchdog"):
        for bad in (float("inf"), float("nan"), -1.0):
            with pytest.raises(EncodeError) as refused:  # an infinite watchdog never trips
                Commander(**{name: bad})
            assert str(refused.value) == (
                f"Commander.{name} = {bad!r}: expected a finite number above 0"
            )


def test_firmware_update_phases() -> None:
    update = FirmwareUpdate(21, b"fw", 600, now=0.0, start_timeout=2, read_timeout=1)
    assert update.progress.phase is Phase.STARTING
    update.accepted(dronecan.BeginFirmwareUpdateResponse(0), 0.1)
    assert update.poll(2.0).phase is Phase.WAITING
    update.served(22, FileRead(b"fw", 0, 256, 600), 0.5)  # another node's read: not ours
    update.served(21, FileRead(b"other", 0, 256, 600), 0.5)  # another file
    assert update.progress.sent == 0
    for offset in (0, 256):
        update.served(21, FileRead(b"fw", offset, 256, 600), 1.0)
    assert update.poll(1.5).phase is Phase.READING
    update.served(21, FileRead(b"fw", 512, 88, 600), 1.6)
    assert update.progress.phase is Phase.RESTARTING
    busy = dronecan.NodeStatus(3, dronecan.Health.OK, dronecan.Mode.SOFTWARE_UPDATE, 0, 0)
    update.status(NodeTable().observe_status(21, busy, 1.7), 1.7)
    assert update.progress.phase is Phase.RESTARTING
    running = dronecan.NodeStatus(0, dronecan.Health.OK, dronecan.Mode.OPERATIONAL, 0, 0)
    update.status(NodeTable().observe_status(21, running, 2.0), 2.0)
    assert update.poll(100.0).phase is Phase.DONE


@pytest.mark.parametrize(
    ("events", "error", "timed_out"),
    [
        ("refused", "node 21 refused the update: IN_PROGRESS", False),
        ("silent", "node 21 accepted the update but did not read the image within 2 s", True),
        ("left", "node 21 left the update at byte 256 of 600 and runs its old firmware", False),
    ],
)
def test_firmware_update_failures(events: str, error: str, timed_out: bool) -> None:
    update = FirmwareUpdate(21, b"fw", 600, now=0.0, start_timeout=2)
    if events == "refused":
        update.accepted(dronecan.BeginFirmwareUpdateResponse(2), 0.1)
    else:
        update.accepted(dronecan.BeginFirmwareUpdateResponse(0), 0.1)
    if events == "left":
        update.served(21, FileRead(b"fw", 0, 256, 600), 0.5)
        running = dronecan.NodeStatus(0, dronecan.Health.OK, dronecan.Mode.OPERATIONAL, 0, 0)
        update.status(NodeTable().observe_status(21, running, 0.6), 0.6)
    progress = update.poll(3.0)
    assert (progress.phase, progress.error, progress.timed_out) == (Phase.FAILED, error, timed_out)


def test_firmware_update_times_out_at_each_phase_boundary_exactly() -> None:
    """Each phase fails at its timeout to the instant (``>=``), with timed_out set and the
    error text the CLI prints; a moment earlier it still waits."""
    ok = dronecan.BeginFirmwareUpdateResponse(0)
    waiting = FirmwareUpdate(21, b"fw", 600, now=0.0, start_timeout=2)
    waiting.accepted(ok, 0.5)
    assert waiting.poll(2.4375).phase is Phase.WAITING
    assert waiting.poll(2.5) == UpdateProgress(
        21,
        Phase.FAILED,
        0,
        600,
        "node 21 accepted the update but did not read the image within 2 s",
        True,
    )
    reading = FirmwareUpdate(21, b"fw", 600, now=0.0, read_timeout=1)
    reading.accepted(ok, 0.0)
    reading.served(21, FileRead(b"fw", 0, 256, 600), 0.5)
    assert reading.poll(1.4375).phase is Phase.READING
    progress = reading.poll(1.5)
    assert (progress.phase, progress.timed_out) == (Phase.FAILED, True)
    assert (
        progress.error == "node 21 stopped reading the image at byte 256 of 600 (nothing for 1 s)"
    )
    restarting = FirmwareUpdate(21, b"fw", 200, now=0.0, restart_timeout=4)
    restarting.accepted(ok, 0.0)
    restarting.served(21, FileRead(b"fw", 0, 200, 200), 1.0)  # fewer than 256: the end
    assert restarting.poll(4.9375).phase is Phase.RESTARTING
    progress = restarting.poll(5.0)
    assert (progress.phase, progress.timed_out) == (Phase.FAILED, True)
    assert progress.error == ("node 21 read the whole image but did not report running within 4 s")


def test_firmware_update_without_an_answer_keeps_the_error_text() -> None:
    update = FirmwareUpdate(21, b"fw", 600, now=0.0)
    update.no_answer("node 21 did not answer BeginFirmwareUpdate (3 attempts)")
    progress = update.progress
    assert (progress.phase, progress.timed_out) == (Phase.FAILED, True)
    assert progress.error == "node 21 did not answer BeginFirmwareUpdate (3 attempts)"


@pytest.mark.parametrize("node_id", [0, 128, -1, True, 21.0])
def test_a_client_node_id_out_of_1_to_127_is_refused(node_id: Any) -> None:
    with pytest.raises(EncodeError, match=r"ClientProtocol\.node_id = .*: expected a node id"):
        ClientProtocol(node_id=node_id)


def test_a_served_response_keeps_the_priority_and_transfer_id_of_its_request() -> None:
    client = ClientProtocol(node_id=100, priority=30)
    client.files.add(b"fw", b"\x01" * 10)
    request = dronecan.FileGetInfoRequest(dronecan.Path(b"fw"))
    frames = dronecan.encode(
        request, source_node_id=21, destination_node_id=100, transfer_id=9, priority=3
    )
    for frame in frames:
        client.receive(frame.can_id, frame.data, 1.0)
    answer = dronecan.decode_frames([(f.can_id, f.data) for f in client.take_frames()])
    assert (answer.priority, answer.transfer_id, answer.destination_node_id) == (3, 9, 21)


def test_protocol_serves_file_reads_to_any_node() -> None:
    client = ClientProtocol(node_id=100)
    client.files.add(b"fw", b"\x01" * 10)
    request = dronecan.FileReadRequest(4, dronecan.Path(b"fw"))
    frames = dronecan.encode(request, source_node_id=21, destination_node_id=100, transfer_id=7)
    events = [e for f in frames for e in client.receive(f.can_id, f.data, 1.0)]
    assert [type(e).__name__ for e in events] == ["Received", "FileServed"]
    served = events[1]
    assert isinstance(served, FileServed) and served.node_id == 21
    (answer,) = [dronecan.decode_frames([(f.can_id, f.data) for f in client.take_frames()])]
    assert answer.message == dronecan.FileReadResponse(dronecan.FileErrorCode(0), b"\x01" * 6)
    assert (answer.transfer_id, answer.destination_node_id) == (7, 21)


def test_its_own_frames_echoed_back_are_dropped() -> None:
    """udp_multicast loops every frame back to its sender: a client that served a read sees
    its own response come back, and its own requests; neither is read (no event)."""
    client = ClientProtocol(node_id=100)
    client.files.add(b"fw", b"\x01" * 300)
    request = dronecan.FileReadRequest(0, dronecan.Path(b"fw"))
    for frame in dronecan.encode(request, source_node_id=21, destination_node_id=100,
                                 transfer_id=7):  # fmt: skip
        client.receive(frame.can_id, frame.data, 1.0)
    client.requests.request(dronecan.GetNodeInfoRequest(), 21, 1.0)
    echoed = client.take_frames()
    assert len(echoed) == 38 + 1  # the 256-byte response, then the request
    assert [e for f in echoed for e in client.receive(f.can_id, f.data, 1.1)] == []
    status = dronecan.encode(
        dronecan.NodeStatus(5, dronecan.Health.OK, dronecan.Mode.OPERATIONAL, 0, 0),
        source_node_id=101,
        transfer_id=0,
    )
    assert [type(e).__name__ for f in status for e in client.receive(f.can_id, f.data, 1.2)] == [
        "Received",
        "StatusSeen",
    ]


_CLIENT, _ASKED = 100, 21


def _transfer_frames(
    message: Any, source: int, destination: int, transfer_id: int
) -> list[tuple[int, bytes]]:
    frames = dronecan.encode(
        message, source_node_id=source, destination_node_id=destination, transfer_id=transfer_id
    )
    return [(f.can_id, f.data) for f in frames]


_SERVICE_MESSAGES = st.sampled_from(
    [
        _INFO,  # the response the client waits for: one transfer id matches, 31 do not
        dronecan.GetNodeInfoRequest(),
        dronecan.RestartNodeResponse(True),
        dronecan.FileReadRequest(0, dronecan.Path(b"fw")),
        dronecan.FileReadRequest(300, dronecan.Path(b"none")),
    ]
)


@st.composite
def _service_transfer(draw: st.DrawFn) -> list[tuple[int, bytes]]:
    """The frames of one service transfer, most from the node asked to the client.

    Sometimes damaged: a frame dropped, repeated or with a byte changed.
    """
    message = draw(st.just(_INFO) | _SERVICE_MESSAGES)
    nodes = st.sampled_from([_CLIENT, _ASKED]) | st.integers(1, 127)
    source = draw(st.just(_ASKED) | nodes)
    destination = draw((st.just(_CLIENT) | nodes).filter(lambda node: node != source))
    transfer_id = draw(st.sampled_from([0, 0, 1, 31]) | st.integers(0, 31))
    frames = _transfer_frames(message, source, destination, transfer_id)
    fault = draw(st.sampled_from(["none", "none", "drop", "repeat", "byte"]))
    position = draw(st.integers(0, len(frames) - 1))
    if fault == "drop":
        del frames[position]
    elif fault == "repeat":
        frames.insert(position, frames[position])
    elif fault == "byte":
        can_id, data = frames[position]
        index = draw(st.integers(0, len(data) - 1))
        data = data[:index] + bytes([data[index] ^ draw(st.integers(1, 255))]) + data[index + 1 :]
        frames[position] = (can_id, data)
    return frames


_RANDOM_FRAME = st.tuples(st.integers(0, 2**29 - 1), st.binary(min_size=0, max_size=8))
_FRAMES = st.lists(
    _service_transfer() | st.lists(_RANDOM_FRAME, min_size=1, max_size=3), max_size=12
).map(lambda pieces: [frame for piece in pieces for frame in piece])


def _expected(transfer: dronecan.Transfer, waiting: bool) -> list[str]:
    """The events a transfer should give (spec 4.1), ``waiting`` for the GetNodeInfo answer."""
    names = ["Received"]
    if isinstance(transfer.message, dronecan.NodeStatus):
        names.append("StatusSeen")
    if transfer.destination_node_id != _CLIENT:
        return names
    if transfer.kind is K.RESPONSE:
        if (
            waiting
            and transfer.source_node_id == _ASKED
            and isinstance(transfer.message, dronecan.GetNodeInfoResponse)
            and transfer.transfer_id == 0
        ):
            names.append("Answered")
    elif isinstance(transfer.message, dronecan.FileReadRequest):
        names.append("FileServed")
    return names


@settings(max_examples=300)
@given(frames=_FRAMES)
@example(  # the answer with the wrong transfer id, then twice with the right one
    frames=[
        *_transfer_frames(_INFO, _ASKED, _CLIENT, 1),
        *_transfer_frames(_INFO, _ASKED, _CLIENT, 0),
        *_transfer_frames(_INFO, _ASKED, _CLIENT, 0),
    ]
)
def test_any_frames_give_events_or_nothing(frames: list[tuple[int, bytes]]) -> None:
    """Frames of every kind, intact or damaged: each transfer gives exactly its events.

    A GetNodeInfo response from the node asked, to the client, with the request's transfer
    id answers the request once; any other transfer id, source, destination or type does
    not, nor any after a service frame from the client's own id (another tool's: the first
    such frame is a `NodeIdConflict`). A file read request to the client is served with the
    same transfer id; anything else is only reported as received.
    """
    client = ClientProtocol(node_id=_CLIENT)
    client.files.add(b"fw", b"\x01" * 10)
    handle = client.request(dronecan.GetNodeInfoRequest(), _ASKED, now=0.0)
    client.take_frames()
    waiting = True
    conflict = False  # a service frame from the client's id that it did not send
    for number, (can_id, data) in enumerate(frames):
        events = client.receive(can_id, data, number * 0.01)
        if not events:
            continue
        if isinstance(events[0], NodeIdConflict):
            assert (can_id & 0x7F, can_id & 0x80, conflict) == (_CLIENT, 0x80, False)
            assert len(events) == 1
            conflict = True
            continue
        assert isinstance(events[0], Received)
        transfer = events[0].transfer
        assert [type(e).__name__ for e in events] == _expected(transfer, waiting and not conflict)
        for event in events:
            if isinstance(event, Answered):
                waiting = False
                assert event.request.handle == handle
                assert event.transfer.message == _INFO
            elif isinstance(event, FileServed):
                reply = dronecan.decode_frames([(f.can_id, f.data) for f in client.take_frames()])
                assert (reply.source_node_id, reply.destination_node_id) == (
                    _CLIENT,
                    transfer.source_node_id,
                )
                assert (reply.transfer_id, reply.priority) == (
                    transfer.transfer_id,
                    transfer.priority,
                )
        assert client.take_frames() == []
    assert (client.requests.pending(handle) is None) is not waiting
    client.poll(10.0)
    client.take_frames()


@given(st.lists(st.binary(max_size=600), min_size=1, max_size=4))
def test_an_images_crc_is_crc64we_whichever_image_came_before(images: list[bytes]) -> None:
    """`image_crc` remembers the latest image's CRC: it never answers for another image."""
    for image in images + images[::-1]:
        assert image_crc(image) == crc64we(image)
