"""Sets of DroneCAN types: the standard set, and vendor namespaces loaded at run time.

A `TypeSet` is immutable: `TypeSet.with_dsdl` returns a new set with more namespaces, so
two sets can be used side by side (two buses, two vendors). Everything that decodes or
encodes DroneCAN takes one as ``types=``; without it, the module-level default is used:
the standard set until `load_dsdl` adds namespaces to it.

The classes of a vendor namespace are generated from its DSDL by the same code as
`veronte4x.dronecan.standard` (naming rules in `veronte4x.dronecan.generate`), compiled at
run time into a module of their own, with the source in ``linecache`` for tracebacks.
"""

from __future__ import annotations

import itertools
import linecache
import os
import sys
import types as _types
from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import Any

from veronte4x.dronecan import messages, standard
from veronte4x.dronecan.can_id import TransferKind
from veronte4x.dronecan.codec import CODECS, TypeCodec
from veronte4x.dronecan.definitions import DataType
from veronte4x.dronecan.generate import keys, module_source, plan
from veronte4x.dronecan.parser import Definition, DsdlError, check_references, parse_namespaces
from veronte4x.dronecan.types import (
    data_types,
    is_float16,
    is_float32,
    standard_definitions,
    text_attributes,
)
from veronte4x.errors import argument_type_error

_serial = itertools.count(1)


class TypeSet:
    """An immutable set of DroneCAN types: the standard ``uavcan`` namespace and more.

    Build one with `TypeSet.standard` and `TypeSet.with_dsdl`; look a class up by its
    DSDL full name with ``types["com.example.Foo"]`` (``...Request``/``...Response`` for
    the halves of a service).

    Attributes:
        codecs: The payload codec of every top-level type.
        by_id: The `TypeCodec` of each (kind, data type id).
        by_class: The `TypeCodec` of each message, request and response class.
        classes: Class of each key (full name, ``.Request``/``.Response`` for a service).
        roots: The vendor root namespace directories loaded, in order.
        loads: The same, as they were loaded: one tuple per `with_dsdl` (class names
            depend on what was loaded together; a set rebuilt in another process loads
            them the same way, so its classes have the same names).
        definitions: Every parsed definition, by full name.
        text_fields: The attributes of each class that hold text
            (`veronte4x.dronecan.types.is_text`).
    """

    def __init__(
        self,
        codecs: tuple[TypeCodec, ...],
        classes: Mapping[str, type],
        enums: Mapping[tuple[str, str], type],
        members: Mapping[str, tuple[type, ...]],
        definitions: Mapping[str, Definition],
        loads: tuple[tuple[Path, ...], ...],
        names: Mapping[str, str],
    ) -> None:
        self.codecs = codecs
        self._names = dict(names)
        self.classes: Mapping[str, type] = _types.MappingProxyType(dict(classes))
        self._enums = dict(enums)
        self._members = dict(members)
        self.definitions: Mapping[str, Definition] = _types.MappingProxyType(dict(definitions))
        self.loads = loads
        self.roots = tuple(root for load in loads for root in load)
        self.by_class: Mapping[type, TypeCodec] = _types.MappingProxyType(
            {c.data_type.schema.cls: c for c in codecs}
        )
        self.by_id: Mapping[tuple[TransferKind, int], TypeCodec] = _types.MappingProxyType(
            {(c.data_type.kind, c.data_type.data_type_id): c for c in codecs}
        )
        self.text_fields: Mapping[type, frozenset[str]] = _types.MappingProxyType(
            text_attributes(definitions, classes, members)
        )
        for fact, found in (  # the class's facts, read by `veronte4x.values`
            ("_TEXT_FIELDS_", self.text_fields),
            ("_FLOAT16_FIELDS_", text_attributes(definitions, classes, members, is_float16)),
            ("_FLOAT32_FIELDS_", text_attributes(definitions, classes, members, is_float32)),
        ):
            for cls, attributes in found.items():
                setattr(cls, fact, attributes)

    @classmethod
    def standard(cls) -> TypeSet:
        """The standard set: every type of the ``uavcan`` namespace shipped with the package."""
        return _STANDARD

    @property
    def data_types(self) -> tuple[DataType, ...]:
        """Every top-level type (messages, requests, responses) of the set."""
        return tuple(c.data_type for c in self.codecs)

    def __getitem__(self, key: str) -> type:
        """The class of a DSDL full name (``.Request``/``.Response`` for a service half).

        Raises:
            KeyError: No such type in the set.
        """
        return self.classes[key]

    def __contains__(self, key: object) -> bool:
        return key in self.classes

    def __repr__(self) -> str:
        roots = ", ".join(repr(str(r)) for r in self.roots)
        return f"TypeSet({len(self.codecs)} types{', ' + roots if roots else ''})"

    def __reduce__(self) -> tuple[Any, ...]:
        # Classes compiled at run time do not pickle: another process loads the same
        # directories again (Dask workers must see them, as they see the output).
        return (_load, (tuple(tuple(str(r) for r in load) for load in self.loads),))

    def with_dsdl(
        self, *root_namespace_dirs: str | bytes | os.PathLike[str] | os.PathLike[bytes]
    ) -> TypeSet:
        """A new set: this one plus the types of these root namespace directories.

        Each directory is a root namespace (``.../ardupilot``, ``.../com``): its name is the
        first component of the full names. A directory already in the set is skipped. A
        path of bytes (a name that is not UTF-8) is read as `os.fsdecode` reads it.

        Raises:
            DsdlError: A malformed definition (file and line), an unknown nested type, a
                type defined twice, a data type id claimed twice (naming both files), or a
                root named ``uavcan`` (the standard one cannot be replaced or extended).
        """
        roots = [Path(os.fsdecode(d)).resolve() for d in root_namespace_dirs]
        new_roots = [r for r in dict.fromkeys(roots) if r not in self.roots]
        if not new_roots:
            return self
        for root in new_roots:
            if root.name == "uavcan":
                raise DsdlError(root, None, _STANDARD_ROOT)
        new = parse_namespaces(new_roots)
        for name, d in new.items():
            other = self.definitions.get(name)
            if other is not None:
                raise DsdlError(d.path, None, f"{name} is also defined in {other.path}")
        definitions = {**self.definitions, **new}
        check_references(definitions)
        classes, enums, members, names = _compile(definitions, new, self, new_roots)
        found = data_types(definitions, new, classes, enums, members)
        _check_ids(self.data_types, found)
        codecs = self.codecs + tuple(TypeCodec(t) for t in found)
        loads = (*self.loads, tuple(new_roots))
        return TypeSet(codecs, classes, enums, members, definitions, loads, names)


_STANDARD_ROOT = (
    "uavcan is the standard root namespace, built into veronte4x: "
    "a vendor namespace needs a root of its own"
)
"""Why a root namespace directory named ``uavcan`` is refused."""


def _check_ids(old: Iterable[DataType], new: Iterable[DataType]) -> None:
    """Raise `DsdlError` for a data type id claimed twice (naming both files)."""
    claimed: dict[tuple[bool, int], DataType] = {}
    for t in (*old, *new):
        where = (t.kind is not TransferKind.MESSAGE, t.data_type_id)
        other = claimed.get(where)
        if other is not None and other.full_name != t.full_name:
            kind = "service" if where[0] else "message"
            raise DsdlError(
                t.path,
                None,
                f"{kind} data type id {t.data_type_id} of {t.full_name} is also that of "
                f"{other.full_name} ({other.path}); give one of them another id",
            )
        claimed[where] = t


def _compile(
    definitions: dict[str, Definition],
    new: dict[str, Definition],
    base: TypeSet,
    roots: list[Path],
) -> tuple[
    dict[str, type], dict[tuple[str, str], type], dict[str, tuple[type, ...]], dict[str, str]
]:
    """Generate and run the source of the classes of ``new``; the tables of the whole set."""
    known: dict[str, Any] = {name: getattr(standard, name) for name in standard.__all__} | {
        name: getattr(messages, name) for name in dir(messages) if not name.startswith("_")
    }
    for key, cls in base.classes.items():
        known.setdefault(base._names[key], cls)
    for member_classes in base._members.values():
        for cls in member_classes:
            known.setdefault(cls.__name__, cls)
    for enum in base._enums.values():
        known.setdefault(enum.__name__, enum)
    p = plan(definitions, known, base._names)
    for key, member_classes in base._members.items():
        p.members[key] = tuple(c.__name__ for c in member_classes)
    generate = [k for d in new.values() for k in keys(d)]
    names = ", ".join(r.name for r in roots)
    module_name = f"veronte4x.dronecan.loaded.{'_'.join(r.name for r in roots)}_{next(_serial)}"
    doc = f"The types of the DSDL namespaces {names}, compiled at run time ({module_name})."
    source = module_source(p, generate, doc, {})
    filename = f"<dsdl {', '.join(str(r) for r in roots)}>"
    module = _types.ModuleType(module_name, doc)
    module.__dict__.update(known)
    module.__file__ = filename
    linecache.cache[filename] = (len(source), None, source.splitlines(True), filename)
    sys.modules[module_name] = module  # dataclasses look the module up
    exec(compile(source, filename, "exec"), module.__dict__)  # the source generated above
    classes = {**base.classes, **module.CLASSES}
    enums = {**base._enums, **module.ENUMS}
    members = {**base._members, **module.UNION_MEMBERS}
    return classes, enums, members, p.names


def _load(loads: tuple[tuple[str, ...], ...]) -> TypeSet:
    """The standard set with ``loads``, one `TypeSet.with_dsdl` each (how a set is rebuilt
    in another process)."""
    types = _STANDARD
    for roots in loads:
        types = types.with_dsdl(*roots)
    return types


_STANDARD = TypeSet(
    CODECS,
    standard.CLASSES,
    standard.ENUMS,
    standard.UNION_MEMBERS,
    standard_definitions(),
    (),
    {
        key: next(n for n, v in vars(standard).items() if v is cls and not n.startswith("_"))
        for key, cls in standard.CLASSES.items()
    },
)

_default = _STANDARD


def default_types() -> TypeSet:
    """The set used where no ``types=`` is given: the standard one plus `load_dsdl`'s."""
    return _default


def set_default_types(types: TypeSet) -> None:
    """Make ``types`` the default set (``TypeSet.standard()`` goes back to the start)."""
    global _default
    if not isinstance(types, TypeSet):
        raise argument_type_error("set_default_types", "types", "a TypeSet", types)
    _default = types


def load_dsdl(*root_namespace_dirs: str | bytes | os.PathLike[str] | os.PathLike[bytes]) -> TypeSet:
    """Add the types of vendor root namespace directories to the default set; return it.

    After this, everything that decodes or encodes DroneCAN without an explicit
    ``types=`` knows them. Loading a directory again does nothing. For two sets side by
    side, use ``TypeSet.standard().with_dsdl(...)`` and pass it as ``types=``.

    Raises:
        DsdlError: A malformed definition (file and line), an unknown nested type, or a
            data type id claimed twice (naming both files). The default set is then
            unchanged.
    """
    global _default
    _default = _default.with_dsdl(*root_namespace_dirs)
    return _default


def types_or_default(types: TypeSet | None, where: str) -> TypeSet:
    """``types``, or the default set for None; TypeError for anything else."""
    if types is None:
        return _default
    if not isinstance(types, TypeSet):
        raise argument_type_error(where, "types", "a TypeSet", types)
    return types
