"""The wrong-type policy for times, in the sans-IO models a program drives with its clock
(arbiter, simulated ESC, client protocol, commander): a TypeError naming the method and
the argument, before any state changes."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import pytest

from veronte4x import arbiter, client, dronecan, simulator

NODE_STATUS = dronecan.encode(
    dronecan.NodeStatus(1, dronecan.Health.OK, dronecan.Mode.OPERATIONAL, 0, 0),
    source_node_id=20,
    transfer_id=0,
)[0]
REQUEST = dronecan.GetNodeInfoRequest()


def _model(kind: str) -> Any:
    """A fresh model of ``kind``, typed Any so that the wrong types reach it."""
    if kind == "arbiter":
        return arbiter.Arbiter(arbiter.ArbiterConfig())
    if kind == "esc":
        return simulator.SimulatedEsc(20)
    if kind == "protocol":
        return client.ClientProtocol()
    return client.Commander()


CASES: list[tuple[str, Callable[[Any], Any], str]] = [
    ("esc", lambda m: m.receive(NODE_STATUS.can_id, NODE_STATUS.data, "1"), "receive(): timestamp"),
    ("esc", lambda m: m.poll(None), "poll(): timestamp"),
    ("esc", lambda m: m.power_cycle(True), "power_cycle(): timestamp"),
    (
        "protocol",
        lambda m: m.receive(NODE_STATUS.can_id, NODE_STATUS.data, "1"),
        "receive(): timestamp",
    ),
    ("protocol", lambda m: m.poll("1"), "poll(): now"),
    ("protocol", lambda m: m.request(REQUEST, 20, "1"), "request(): now"),
    ("protocol", lambda m: m.request(REQUEST, 20, 1.0, timeout="1"), "request(): timeout"),
    ("commander", lambda m: m.set([0.5], "1"), "set(): now"),
    ("commander", lambda m: m.poll(True), "poll(): now"),
    ("arbiter", lambda m: m.advance("1"), "advance(): timestamp"),
]


@pytest.mark.parametrize(("kind", "call", "named"), CASES, ids=[f"{k} {n}" for k, _, n in CASES])
def test_a_time_that_is_not_a_number_is_a_type_error(
    kind: str, call: Callable[[Any], Any], named: str
) -> None:
    model = _model(kind)
    with pytest.raises(TypeError) as raised:
        call(model)
    assert str(raised.value).startswith(f"{named} must be a number of seconds, not ")


def test_a_refused_time_changes_nothing() -> None:
    commander = _model("commander")
    with pytest.raises(TypeError):
        commander.set([0.5], "1")
    assert commander.next_time() is None  # nothing to send: the motors stay stopped
    protocol = _model("protocol")
    with pytest.raises(TypeError):
        protocol.request(REQUEST, 20, "1")
    assert protocol.take_frames() == []
