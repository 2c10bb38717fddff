"""Another sender with the client's node id is told from the client's own echoes (issue 41,
item 7): a bus that loops frames back gives the client its own frames, which it drops;
a service frame from its id that it did not send makes it refuse (sans-IO, no bus)."""

from __future__ import annotations

import pytest

from veronte4x import dronecan
from veronte4x.client import NodeIdConflictError
from veronte4x.client.operations import Runner, get_param
from veronte4x.client.protocol import ClientProtocol, NodeIdConflict, SentFrames
from veronte4x.dronecan import vertiq
from veronte4x.node.requests import Answered
from veronte4x.simulator import SimulatedEsc


def test_sent_frames_take_each_echo_once_and_forget_the_oldest() -> None:
    sent = SentFrames(size=2)
    sent.add(1, b"a")
    sent.add(1, b"a")
    assert [sent.echo(1, b"a") for _ in range(3)] == [True, True, False]
    sent.add(2, b"b")  # the first (1, b"a") forgotten, with its echo
    sent.add(3, b"c")  # and the second
    assert not sent.echo(1, b"a")
    assert sent.echo(2, b"b") and sent.echo(3, b"c") and not sent.echo(3, b"c")
    unechoed = SentFrames(size=1)
    unechoed.add(4, b"d")  # a bus without echoes: forgotten unechoed
    unechoed.add(5, b"e")
    assert not unechoed.echo(4, b"d") and unechoed.echo(5, b"e")


def test_echoes_of_every_frame_sent_are_not_a_conflict() -> None:
    """A parameter read and a served file read, each frame looped back as udp_multicast
    does, and a RawCommand's: no conflict, and the read is answered."""
    protocol, esc = ClientProtocol(), SimulatedEsc(21)
    protocol.files.add(b"fw.bin", bytes(600))
    runner = Runner(protocol)
    task = runner.start(get_param(21, "esc_index"), now=0.0)
    read = dronecan.encode(
        dronecan.FileReadRequest(0, dronecan.Path(b"fw.bin")),
        source_node_id=21,
        destination_node_id=127,
        transfer_id=0,
    )
    for frame in read:
        protocol.receive(frame.can_id, frame.data, 0.0)
    frames = protocol.take_frames() + protocol.message_frames(dronecan.RawCommand((0,)))
    assert len(frames) > 30  # the request and the 256-byte answer's frames
    for frame in frames:
        assert protocol.receive(frame.can_id, frame.data, 0.0) == []  # echoes: dropped
        esc.receive(frame.can_id, frame.data, 0.0)
    for frame in esc.poll(0.01):
        runner.feed(protocol.receive(frame.can_id, frame.data, 0.01), 0.01)
    assert protocol.conflict is None
    assert task.result().name == "esc_index"


def test_a_request_from_the_own_id_not_sent_here_fails_the_waiting_and_refuses() -> None:
    protocol, esc = ClientProtocol(), SimulatedEsc(21)
    runner = Runner(protocol)
    task = runner.start(get_param(21, index=0), now=0.0)
    for frame in protocol.take_frames():
        esc.receive(frame.can_id, frame.data, 0.0)
    other = ClientProtocol()  # another tool at 127: the same transfer id, another index
    other.request(vertiq.get_parameter_by_index(2), 21, now=0.0)
    [frame] = other.take_frames()
    esc.receive(frame.can_id, frame.data, 0.0)
    [event] = protocol.receive(frame.can_id, frame.data, 0.0)
    assert isinstance(event, NodeIdConflict)
    runner.feed([event], 0.0)
    with pytest.raises(NodeIdConflictError, match=r"GetSet request to node 21\)"):
        task.result()
    for answer in esc.poll(0.01):  # the answers that came after: none taken
        events = protocol.receive(answer.can_id, answer.data, 0.01)
        assert not [e for e in events if isinstance(e, Answered)]
    with pytest.raises(NodeIdConflictError, match=r"^another tool or node on the bus sends"):
        protocol.request(vertiq.get_parameter("esc_index"), 21, now=0.02)
    assert protocol.next_deadline() is None  # nothing left pending
