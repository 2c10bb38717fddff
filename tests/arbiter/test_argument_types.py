"""The library's policy for arguments of the wrong type, at the arbiter model's entry points:
a TypeError naming the method, the argument and the type expected."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import pytest

from veronte4x import arbiter

READY = b"\x00\xff\x01"


def _model() -> Any:
    """A model, typed Any so that the wrong types below reach it."""
    return arbiter.Arbiter(arbiter.ArbiterConfig())


ARBITER: Any = arbiter.Arbiter
CASES: list[tuple[Callable[[Any], Any], str]] = [
    (lambda a: ARBITER("config"), "Arbiter(): config must be an ArbiterConfig, not str"),
    (
        lambda a: ARBITER(arbiter.ArbiterConfig(), checks=True),
        "Arbiter(): checks must be a SystemChecks or None, not bool",
    ),
    (lambda a: a.receive("8", READY, 1.0), "receive(): can_id must be an int, not str"),
    (lambda a: a.receive(True, READY, 1.0), "receive(): can_id must be an int, not bool"),
    (lambda a: a.receive(8, "00ff01", 1.0), "receive(): data must be bytes-like, not str"),
    (
        lambda a: a.receive(8, READY, "1.0"),
        "receive(): timestamp must be a number of seconds, not str",
    ),
    (lambda a: a.advance(None), "advance(): timestamp must be a number of seconds, not NoneType"),
    (lambda a: a.poll(True), "poll(): timestamp must be a number of seconds, not bool"),
    (
        lambda a: a.command_maintenance("now"),
        "command_maintenance(): timestamp must be a number of seconds, not str",
    ),
    (
        lambda a: a.set_checks(1.0, {"cbit": True}),
        "set_checks(): checks must be a SystemChecks, not dict",
    ),
    (lambda a: a.set_fts(1.0, "1", True), "set_fts(): autopilot must be an int, not str"),
    (lambda a: a.set_fts(1.0, True, True), "set_fts(): autopilot must be an int, not bool"),
    (lambda a: a.set_fts(1.0, 1, "no"), "set_fts(): ok must be a bool, not str"),
    (lambda a: a.set_watchdog(1.0, 1, 0), "set_watchdog(): ok must be a bool, not int"),
]


@pytest.mark.parametrize(("call", "message"), CASES, ids=[m for _, m in CASES])
def test_a_wrong_type_is_a_type_error_naming_it(call: Callable[[Any], Any], message: str) -> None:
    model = _model()
    with pytest.raises(TypeError) as raised:
        call(model)
    assert str(raised.value) == message
    assert not model.decisions  # refused before anything happened


def test_integer_timestamps_and_bytes_like_data_are_taken() -> None:
    with_ints, with_floats = _model(), _model()
    with_ints.receive(8, bytearray(READY), 1)
    with_ints.set_fts(2, 0, True)
    with_floats.receive(8, READY, 1.0)
    with_floats.set_fts(2.0, 0, True)
    assert with_ints.poll(3) == with_floats.poll(3.0)
    assert with_ints.decisions == with_floats.decisions
    assert with_ints.decisions  # the boot, at least
