"""Sets of DroneCAN types: the standard set, and vendor namespaces loaded at run time.

A `TypeSet` is immutable: `TypeSet.with_dsdl` returns a new set with more namespaces, so
two sets can be used side by side (two buses, two vendors). Everything that decodes or
encodes DroneCAN takes one as ``types=``; without it, the module-level default is used:
the standard set until `load_dsdl` adds namespaces to it.

The standard set and the vendor namespaces shipped with the package were generated ahead
of time (`veronte4x.dronecan.shipped_source`): building them parses no DSDL. The classes of
a namespace the user loads are generated from its DSDL by the same code (naming rules in
`veronte4x.dronecan.generate`), into a module of their own, with the source in
``linecache`` for tracebacks.
"""

from __future__ import annotations

import itertools
import linecache
import os
import sys
import types as _types
from collections.abc import Callable, Iterable, Mapping
from pathlib import Path
from typing import Any, NamedTuple

from veronte4x.dronecan import messages, standard, standard_data
from veronte4x.dronecan.can_id import TransferKind
from veronte4x.dronecan.codec import CODECS, TypeCodec
from veronte4x.dronecan.definitions import DataType
from veronte4x.dronecan.generate import keys, module_source, plan
from veronte4x.dronecan.parser import Definition, DsdlError, check_references, parse_namespaces
from veronte4x.dronecan.types import (
    DSDL_ROOT,
    data_types,
    is_float16,
    is_float32,
    text_attributes,
    units_of,
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
        definitions: Every parsed definition, by full name (parsed on first use for the
            sets generated ahead of time).
        text_fields: The attributes of each class that hold text
            (`veronte4x.dronecan.types.is_text`).
        units: The unit of each attribute whose DSDL comment names one (``# [Volt]``),
            by class.
    """

    def __init__(
        self,
        codecs: tuple[TypeCodec, ...],
        classes: Mapping[str, type],
        enums: Mapping[tuple[str, str], type],
        members: Mapping[str, tuple[type, ...]],
        definitions: Mapping[str, Definition] | Callable[[], Mapping[str, Definition]],
        loads: tuple[tuple[Path, ...], ...],
        names: Mapping[str, str],
        facts: Facts | None = None,
    ) -> None:
        self.codecs = codecs
        self._names = dict(names)
        self.classes: Mapping[str, type] = _types.MappingProxyType(dict(classes))
        self._enums = dict(enums)
        self._members = dict(members)
        self._parse = definitions if callable(definitions) else None
        if not callable(definitions):
            self._definitions = _types.MappingProxyType(dict(definitions))
        self.loads = loads
        self.roots = tuple(root for load in loads for root in load)
        self.by_class: Mapping[type, TypeCodec] = _types.MappingProxyType(
            {c.data_type.schema.cls: c for c in codecs}
        )
        self.by_id: Mapping[tuple[TransferKind, int], TypeCodec] = _types.MappingProxyType(
            {(c.data_type.kind, c.data_type.data_type_id): c for c in codecs}
        )
        if facts is None:
            facts = _facts(self.definitions, classes, members)
        self.text_fields: Mapping[type, frozenset[str]] = _types.MappingProxyType(facts.text)
        self.units: Mapping[type, Mapping[str, str]] = _types.MappingProxyType(facts.units)
        for fact, found in (  # the class's facts, read by `veronte4x.values`
            ("_TEXT_FIELDS_", self.text_fields),
            ("_FLOAT16_FIELDS_", facts.float16),
            ("_FLOAT32_FIELDS_", facts.float32),
        ):
            for cls, attributes in found.items():
                setattr(cls, fact, attributes)

    @property
    def definitions(self) -> Mapping[str, Definition]:
        """Every definition of the set, by full name (see the class docstring)."""
        if self._parse is not None:
            self._definitions = _types.MappingProxyType(dict(self._parse()))
            self._parse = None
        return self._definitions

    @classmethod
    def standard(cls) -> TypeSet:
        """The standard set: every type of the ``uavcan`` namespace shipped with the package."""
        return _STANDARD

    @classmethod
    def shipped(cls) -> TypeSet:
        """The standard set and every vendor namespace shipped with the package
        (`veronte4x.dronecan.vendor_roots.SHIPPED`), as one load."""
        global _SHIPPED
        if _SHIPPED is None:
            _SHIPPED = _shipped()
        return _SHIPPED

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
    in another process); the shipped load is the shipped set."""
    types = _STANDARD
    if loads and loads[0] == tuple(str(r) for r in TypeSet.shipped().loads[0]):
        types, loads = TypeSet.shipped(), loads[1:]
    for roots in loads:
        types = types.with_dsdl(*roots)
    return types


class Facts(NamedTuple):
    """What a set knows of each class's attributes."""

    text: dict[type, frozenset[str]]
    float16: dict[type, frozenset[str]]
    float32: dict[type, frozenset[str]]
    units: dict[type, dict[str, str]]


def _facts(
    definitions: Mapping[str, Definition],
    classes: Mapping[str, type],
    members: Mapping[str, tuple[type, ...]],
) -> Facts:
    """The facts of the classes of a set, from its definitions."""
    return Facts(
        text_attributes(definitions, classes, members),
        text_attributes(definitions, classes, members, is_float16),
        text_attributes(definitions, classes, members, is_float32),
        units_of(definitions, classes, members),
    )


def _parse_shipped(roots: Iterable[Path]) -> Callable[[], dict[str, Definition]]:
    """What parses the definitions of a set generated ahead of time, when asked for."""

    def parse() -> dict[str, Definition]:
        definitions = parse_namespaces(roots)
        check_references(definitions)
        return definitions

    return parse


def _generated_set(
    codecs: tuple[TypeCodec, ...], modules: Iterable[Any], loads: tuple[tuple[Path, ...], ...]
) -> TypeSet:
    """A set of the class and data modules generated ahead of time: ``modules`` holds
    (class module, data module) pairs."""
    classes: dict[str, type] = {}
    enums: dict[tuple[str, str], type] = {}
    members: dict[str, tuple[type, ...]] = {}
    names: dict[str, str] = {}
    facts = Facts({}, {}, {}, {})
    for classes_module, data in modules:
        classes.update(classes_module.CLASSES)
        enums.update(classes_module.ENUMS)
        members.update(classes_module.UNION_MEMBERS)
        names.update(data.CLASS_NAMES)
        facts.text.update(data.TEXT_FIELDS)
        facts.float16.update(data.FLOAT16_FIELDS)
        facts.float32.update(data.FLOAT32_FIELDS)
        facts.units.update(data.UNITS)
    roots = [DSDL_ROOT / "uavcan", *(r for load in loads for r in load)]
    return TypeSet(codecs, classes, enums, members, _parse_shipped(roots), loads, names, facts)


def _shipped() -> TypeSet:
    """The standard set and the shipped vendor namespaces (`TypeSet.shipped`)."""
    from veronte4x.dronecan import vendor, vendor_data  # generated ahead of time

    codecs = tuple(
        TypeCodec(t, module)
        for t, module in zip(vendor_data.DATA_TYPES, vendor_data.FAST_MODULES, strict=True)
    )
    loads = (tuple((DSDL_ROOT / name).resolve() for name in vendor_data.ROOTS),)
    return _generated_set(
        CODECS + codecs, ((standard, standard_data), (vendor, vendor_data)), loads
    )


_STANDARD = _generated_set(CODECS, ((standard, standard_data),), ())
_SHIPPED: TypeSet | None = None

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
