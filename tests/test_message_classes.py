"""Every message class of the codecs is a frozen, slotted dataclass."""

from __future__ import annotations

import dataclasses
import enum
import inspect

import pytest

from veronte4x import codec, dronecan


def _message_classes() -> list[type]:
    found = []
    for module in (codec, dronecan):
        for name in module.__all__:
            value = getattr(module, name)
            if (
                inspect.isclass(value)
                and dataclasses.is_dataclass(value)
                and not issubclass(value, (enum.Enum, tuple, BaseException))
            ):
                found.append(value)
    return found


CLASSES = _message_classes()


def test_the_classes_are_found() -> None:
    assert codec.Status in CLASSES
    assert codec.JetiTemperature in CLASSES
    assert dronecan.Empty in CLASSES
    assert dronecan.GetSetResponse in CLASSES


@pytest.mark.parametrize("cls", CLASSES, ids=lambda c: f"{c.__module__}.{c.__name__}")
def test_frozen_and_slotted(cls: type) -> None:
    params = cls.__dataclass_params__  # type: ignore[attr-defined]
    assert params.frozen
    assert "__slots__" in cls.__dict__
    assert "__dict__" not in dir(cls)
    slots = {name for base in cls.__mro__ for name in base.__dict__.get("__slots__", ())}
    assert {field.name for field in dataclasses.fields(cls)} <= slots
