"""The generated DroneCAN classes (`veronte4x.dronecan.written`) against the dataclasses
`dataclasses.dataclass` makes of the same fields: the same fields, signature, repr,
equality, hash, frozenness, pickling and pattern matching, for every shipped class."""

from __future__ import annotations

import dataclasses
import inspect
import pickle
from typing import Any

import pytest

from veronte4x.display import HtmlDisplay
from veronte4x.dronecan import standard, vendor

CLASSES = sorted(
    {
        cls
        for module in (standard, vendor)
        for cls in (
            *module.CLASSES.values(),
            *(m for members in module.UNION_MEMBERS.values() for m in members),
        )
        if isinstance(cls, type)  # not a union's alias
    },
    key=lambda cls: (cls.__module__, cls.__name__),
)


def reference(cls: type) -> Any:
    """What ``@dataclass(frozen=True, slots=True)`` makes of the fields of ``cls``."""
    fields = [
        (f.name, f.type, dataclasses.field(default=f.default)) for f in dataclasses.fields(cls)
    ]
    made = dataclasses.make_dataclass(
        cls.__name__, fields, bases=(HtmlDisplay,), frozen=True, slots=True
    )
    made.__qualname__ = cls.__qualname__
    return made


def test_every_class_is_written() -> None:
    assert len(CLASSES) > 150
    assert all("__init__" in vars(cls) and "__slots__" in vars(cls) for cls in CLASSES)
    assert all(dataclasses.is_dataclass(cls) for cls in CLASSES)


@pytest.mark.parametrize("cls", CLASSES, ids=lambda cls: cls.__name__)
def test_same_as_dataclass(cls: Any) -> None:
    made = reference(cls)
    assert [repr(f) for f in dataclasses.fields(cls)] == [repr(f) for f in dataclasses.fields(made)]
    parameters = inspect.signature(cls).parameters.values()
    assert list(parameters) == list(inspect.signature(made).parameters.values())
    assert cls.__match_args__ == made.__match_args__
    assert cls.__slots__ == made.__slots__
    assert repr(cls.__dataclass_params__) == repr(made.__dataclass_params__)
    assert set(vars(made)) - {"__weakref__", "__annotations__"} <= set(vars(cls))
    message, other = cls(), made()
    assert repr(message) == repr(other)
    assert message == cls() and hash(message) == hash(other)
    assert message != other  # another class
    assert dataclasses.asdict(message) == dataclasses.asdict(other)
    assert dataclasses.astuple(message) == dataclasses.astuple(other)
    assert dataclasses.replace(message) == message
    copied = pickle.loads(pickle.dumps(message))
    assert copied == message and type(copied) is cls
    for name in cls.__match_args__:
        for change, arguments in ((setattr, (name, 1)), (delattr, (name,))):
            with pytest.raises(dataclasses.FrozenInstanceError) as ours:
                change(message, *arguments)
            with pytest.raises(dataclasses.FrozenInstanceError) as theirs:
                change(other, *arguments)
            assert str(ours.value) == str(theirs.value)


def test_fields_replace_and_matching() -> None:
    status = standard.EscStatus(voltage=12.5, rpm=-300)
    faster = dataclasses.replace(status, rpm=1200)
    assert (faster.voltage, faster.rpm, status.rpm) == (12.5, 1200, -300)
    assert [f.name for f in dataclasses.fields(status)][:2] == ["error_count", "voltage"]
    assert faster != status and faster == standard.EscStatus(voltage=12.5, rpm=1200)
    match faster:
        case standard.EscStatus(count, volts, rpm=rpm):
            assert (count, volts, rpm) == (0, 12.5, 1200)
        case _:
            pytest.fail("no match")
    with pytest.raises(dataclasses.FrozenInstanceError):
        status.rpm = 1  # type: ignore[misc]
