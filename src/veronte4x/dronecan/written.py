"""Frozen slotted dataclasses whose ``__init__`` is written in their own source.

`dataclasses.dataclass` writes the methods of each class as source and compiles them when
the class is made: about 0.3 ms a class, 50 ms and more for a module of DSDL types at
import. The classes generated from DSDL (`veronte4x.dronecan.generate`) declare their
``__slots__`` and write their ``__init__`` instead, compiled once into the module's
bytecode; `frozen_dataclass` adds what ``@dataclass(frozen=True, slots=True)`` would
(``__repr__``, ``__eq__``, ``__hash__``, the frozen ``__setattr__`` and ``__delattr__``,
``__match_args__``, the fields; ``__getstate__``/``__setstate__`` for pickling as
`dataclasses` itself writes them) from functions made once here. The result is a
dataclass like any other: `dataclasses.fields`, `dataclasses.replace`,
`dataclasses.asdict`, `dataclasses.is_dataclass`, pickling and pattern matching see no
difference, nor do type checkers (PEP 681).
"""

from __future__ import annotations

import inspect
from collections.abc import Callable
from dataclasses import FrozenInstanceError, dataclass
from operator import attrgetter
from typing import TYPE_CHECKING, Any, ClassVar, TypeVar

if TYPE_CHECKING:
    from typing_extensions import dataclass_transform
else:

    def dataclass_transform(**_: Any) -> Callable[[Any], Any]:
        """Type checkers only: the decorator makes dataclasses (PEP 681)."""
        return lambda decorator: decorator


_T = TypeVar("_T", bound=type)


@dataclass(frozen=True, slots=True)
class _Model:
    """The fields and parameters every written class copies, as `dataclasses` makes them
    (so that nothing here depends on the module's private names)."""

    field: int = 0
    CONSTANT: ClassVar[int] = 0


_FIELD = _Model.__dataclass_fields__["field"]
_CLASS_VARIABLE = _Model.__dataclass_fields__["CONSTANT"]


_FIELD_SLOTS: tuple[str, ...] = type(_FIELD).__slots__
"""What a `dataclasses.Field` holds (copied slot by slot: four times `copy.copy`'s speed)."""


def _field(model: Any, name: str, annotation: Any, default: Any) -> Any:
    made = object.__new__(type(model))
    for slot in _FIELD_SLOTS:
        setattr(made, slot, getattr(model, slot))
    made.name = name
    made.type = annotation
    made.default = default
    return made


_SHARED = tuple(
    (name, function)
    for name, function in vars(_Model).items()
    if name in ("__getstate__", "__setstate__", "__replace__")
)
"""The methods `dataclasses` gives every frozen slotted class alike (pickling; 3.13's
`copy.replace`), taken from a class it made."""


@dataclass_transform(frozen_default=True)
def frozen_dataclass(cls: _T) -> _T:
    """Make ``cls`` a frozen slotted dataclass: its fields are its ``__slots__``, their
    defaults those of its ``__init__``, their types its annotations (any other annotation
    a ``ClassVar``)."""
    names: tuple[str, ...] = cls.__dict__["__slots__"]
    defaults = dict(zip(names, cls.__dict__["__init__"].__defaults__ or (), strict=True))
    fields = {
        name: _field(_FIELD, name, annotation, defaults[name])
        if name in defaults
        else _field(_CLASS_VARIABLE, name, annotation, getattr(cls, name))
        for name, annotation in inspect.get_annotations(cls).items()
    }
    owner: type[Any] = cls
    values = attrgetter(*names) if len(names) > 1 else None
    single = names[0] if len(names) == 1 else None

    def fields_of(self: Any) -> tuple[Any, ...]:
        if values is not None:
            found: tuple[Any, ...] = values(self)
            return found
        return (getattr(self, single),) if single is not None else ()

    def __repr__(self: Any) -> str:
        shown = ", ".join(f"{name}={getattr(self, name)!r}" for name in names)
        return f"{self.__class__.__qualname__}({shown})"

    def __eq__(self: Any, other: object) -> bool:
        if other.__class__ is self.__class__:
            return fields_of(self) == fields_of(other)
        return NotImplemented

    def __hash__(self: Any) -> int:
        return hash(fields_of(self))

    def __setattr__(self: Any, name: str, value: Any) -> None:
        if type(self) is owner or name in names:
            raise FrozenInstanceError(f"cannot assign to field {name!r}")
        super(owner, self).__setattr__(name, value)

    def __delattr__(self: Any, name: str) -> None:
        if type(self) is owner or name in names:
            raise FrozenInstanceError(f"cannot delete field {name!r}")
        super(owner, self).__delattr__(name)

    made: dict[str, Any] = {
        "__repr__": __repr__,
        "__eq__": __eq__,
        "__hash__": __hash__,
        "__setattr__": __setattr__,
        "__delattr__": __delattr__,
    }
    for name, function in made.items():
        function.__qualname__ = f"{cls.__qualname__}.{name}"
    made |= dict(_SHARED)
    made["__match_args__"] = names
    made["__dataclass_fields__"] = fields
    made["__dataclass_params__"] = vars(_Model)["__dataclass_params__"]
    for name, value in made.items():
        setattr(cls, name, value)
    return cls
