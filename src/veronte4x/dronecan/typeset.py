"""Sets of DroneCAN types: the standard set, and vendor namespaces loaded at run time.

A `TypeSet` is immutable: `TypeSet.with_dsdl` returns a new set with more namespaces, so
two sets can be used side by side (two buses, two vendors). Everything that decodes or
encodes DroneCAN takes one as ``types=``; without it, the module-level default is used:
the standard set until `load_dsdl` adds namespaces to it.

The standard set and the vendor namespaces shipped with the package were generated ahead
of time (`veronte4x.dronecan.shipped_source`): building them parses no DSDL. The classes of
a namespace the user loads are generated from its DSDL by the same code (naming rules in
`veronte4x.dronecan.generate`), into a module of their own, with the source in
``linecache`` for tracebacks, and kept with the source of their fast paths (each type's
compiled on its first use, not by the load) in the disk cache
(`veronte4x.dronecan.dsdl_cache`, `veronte4x.dronecan.compiled_load`) for the next process.
"""

from __future__ import annotations

import dataclasses
import functools
import itertools
import linecache
import os
import sys
import types as _types
import warnings
from collections.abc import Callable, Iterable, Mapping
from pathlib import Path
from typing import TYPE_CHECKING, Any

from veronte4x.dronecan import compiled_load, dsdl_cache, messages, standard, standard_data
from veronte4x.dronecan.can_id import TransferKind
from veronte4x.dronecan.codec import CODECS, TypeCodec
from veronte4x.dronecan.definitions import DataType
from veronte4x.dronecan.vendor_roots import DSDL_ROOT, Override, find_roots, overrides
from veronte4x.errors import DsdlError, argument_type_error

if TYPE_CHECKING:
    from veronte4x.dronecan.parser import Definition

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
            (`veronte4x.dronecan.generate.is_text`: each class's ``_TEXT_FIELDS_``).
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
        units: Mapping[type, Mapping[str, str]],
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
        owners = [c for c in classes.values() if isinstance(c, type)]
        owners += [m for found in members.values() for m in found]
        self.text_fields: Mapping[type, frozenset[str]] = _types.MappingProxyType(
            {c: c._TEXT_FIELDS_ for c in owners if hasattr(c, "_TEXT_FIELDS_")}
        )
        self.units: Mapping[type, Mapping[str, str]] = _types.MappingProxyType(dict(units))

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

        A later root overrides an earlier one type by type, as the roots of the default set
        do (`veronte4x.dronecan.vendor_roots`): a definition of a full name this set or an
        earlier directory has replaces it, with a `DsdlOverrideWarning` naming both files
        (the same definition again, in another file, changes nothing). The types that nest
        a replaced one are compiled again with it; the other classes keep their names.

        Raises:
            DsdlError: A malformed definition (file and line), an unknown nested type, a
                type defined twice in one root, a data type id claimed twice or two types
                left with one class name (naming both files), or a root named ``uavcan``
                (the standard one cannot be replaced or extended).

        What a load compiles is kept on disk (`veronte4x.dronecan.dsdl_cache`, in the
        user's cache directory): a later load of the same files into the same set, in any
        process, reads it back instead of parsing and compiling again.
        """
        roots = [Path(os.fsdecode(d)).resolve() for d in root_namespace_dirs]
        new_roots = [r for r in dict.fromkeys(roots) if r not in self.roots]
        if not new_roots:
            return self
        for root in new_roots:
            if root.name == "uavcan":
                raise DsdlError(root, None, _STANDARD_ROOT)
        folder = dsdl_cache.directory()
        key = None if folder is None else dsdl_cache.load_key(self.loads, new_roots)
        data = None if folder is None or key is None else dsdl_cache.read(folder, key)
        if data is not None:
            for note in data["notes"]:
                warnings.warn(note, DsdlOverrideWarning, stacklevel=2)
            kept = self._without(set(data["again"]))
            module = _run(data["classes"], kept, new_roots)
            lazy = functools.partial(_merged, self, new_roots)
            return self._from_entry(data, kept, module, lazy, new_roots)
        data, kept, module, definitions = self._compiled(new_roots, key is not None)
        types = self._from_entry(data, kept, module, definitions, new_roots)
        # Kept only if no file changed since the key was made (the entry is of the key's).
        now = None if key is None else dsdl_cache.load_key(self.loads, new_roots)
        if folder is not None and key is not None and key == now:
            dsdl_cache.write(folder, key, data)
        return types

    def _compiled(
        self, new_roots: list[Path], fast: bool
    ) -> tuple[dict[str, Any], TypeSet, _types.ModuleType, dict[str, Definition]]:
        """Parse and compile a load (`with_dsdl`): its entry (`compiled_load.entry`, fast
        paths in it with ``fast``), the set it builds on, its module of classes and the
        definitions of the new set."""
        from veronte4x.dronecan.types import data_types, units_of  # for user DSDL only

        definitions, new, notes, again = _planned(self, new_roots, warn=True)
        kept = self._without(again)
        module, made, names = _compile(definitions, new, kept, new_roots)
        tables = _tables(kept, module)
        found = data_types(definitions, new, *tables)
        units = units_of(new, tables[0], tables[2])
        data = compiled_load.entry(made, names, notes, again, found, units, tables, fast)
        return data, kept, module, definitions

    def _from_entry(
        self,
        data: dict[str, Any],
        kept: TypeSet,
        module: _types.ModuleType,
        definitions: Mapping[str, Definition] | Callable[[], Mapping[str, Definition]],
        new_roots: list[Path],
    ) -> TypeSet:
        """The set this one and a load of ``new_roots`` make (``data`` its entry, ``kept``
        this set less what it replaces, ``module`` its classes)."""
        tables = _tables(kept, module)
        found = compiled_load.data_types(data, tables)
        _check_ids(kept.data_types, found)
        codecs = kept.codecs + compiled_load.codecs(data, found, tables)
        loads = (*self.loads, tuple(new_roots))
        units = {**kept.units, **compiled_load.units(data, tables)}
        names = {**kept._names, **data["names"]}
        return TypeSet(codecs, *tables, definitions, loads, names, units)

    def _without(self, names: set[str]) -> TypeSet:
        """This set without the types of these full names (replaced by a later root): the
        tables `with_dsdl` builds on."""
        if not names:
            return self
        gone = {key for key in self.classes if _full_name(key) in names}
        classes = {k: c for k, c in self.classes.items() if k not in gone}
        members = {k: m for k, m in self._members.items() if k not in gone}
        enums = {k: e for k, e in self._enums.items() if k[0] not in gone}
        left = set(classes.values()) | {m for found in members.values() for m in found}
        units = {c: found for c, found in self.units.items() if c in left}
        codecs = tuple(c for c in self.codecs if c.data_type.full_name not in names)
        names_left = {k: n for k, n in self._names.items() if k not in gone}
        return TypeSet(
            codecs,
            classes,
            enums,
            members,
            lambda: {k: d for k, d in self.definitions.items() if k not in names},
            self.loads,
            names_left,
            units,
        )


class DsdlOverrideWarning(UserWarning):
    """A definition of a later root replaced one of the same full name (`TypeSet.with_dsdl`)."""


def _full_name(key: str) -> str:
    """The full name of a key (a service half's without ``.Request``/``.Response``)."""
    return key.removesuffix(".Request").removesuffix(".Response")


def _users(definitions: Mapping[str, Definition], names: set[str]) -> set[str]:
    """``names`` and every definition that nests one of them, however deep."""
    from veronte4x.dronecan.parser import nested_name  # for what a load parses only

    found = set(names)
    while True:
        more = {
            name
            for name, d in definitions.items()
            if name not in found
            and any(nested_name(a.type) in found for section in d.sections for a in section.fields)
        }
        if not more:
            return found
        found |= more


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


def _planned(
    base: TypeSet, new_roots: list[Path], warn: bool
) -> tuple[dict[str, Definition], dict[str, Definition], list[str], set[str]]:
    """What loading ``new_roots`` into ``base`` parses (`TypeSet.with_dsdl`): the
    definitions of the new set, those to compile, the overrides (warned of with ``warn``,
    before the references are checked) and the full names of ``base`` compiled again."""
    from veronte4x.dronecan.parser import check_references, definition_files, parse_namespaces

    parsed = parse_namespaces(new_roots, override=True)
    notes = list(overrides(definition_files(new_roots)))
    new: dict[str, Definition] = {}
    for name, d in parsed.items():
        other = base.definitions.get(name)
        if other is not None and dataclasses.replace(d, path=other.path) == other:
            continue  # the same definition in another file
        if other is not None:
            notes.append(Override(name, Path(other.path), Path(d.path)))
        new[name] = d
    if warn:
        for note in notes:
            warnings.warn(str(note), DsdlOverrideWarning, stacklevel=4)
    definitions = {**base.definitions, **new}
    check_references(definitions)
    again = _users(definitions, {name for name in new if name in base.definitions})
    new = {**{name: definitions[name] for name in again if name not in new}, **new}
    return definitions, new, [str(note) for note in notes], again


def _merged(base: TypeSet, new_roots: list[Path]) -> dict[str, Definition]:
    """The definitions of ``base`` with ``new_roots`` loaded (parsed on first use by a set
    read from the cache)."""
    return _planned(base, new_roots, warn=False)[0]


def _tables(
    kept: TypeSet, module: _types.ModuleType
) -> tuple[dict[str, type], dict[tuple[str, str], type], dict[str, tuple[type, ...]]]:
    """The classes, enums and union members of ``kept`` and those of a load's module."""
    return (
        {**kept.classes, **module.CLASSES},
        {**kept._enums, **module.ENUMS},
        {**kept._members, **module.UNION_MEMBERS},
    )


def _known(base: TypeSet) -> dict[str, Any]:
    """The names a load's module of classes finds its nested types under: the standard
    classes, `veronte4x.dronecan.messages`, and the classes, members and enums of ``base``."""
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
    return known


def _compile(
    definitions: dict[str, Definition],
    new: dict[str, Definition],
    base: TypeSet,
    roots: list[Path],
) -> tuple[_types.ModuleType, tuple[str, str, Any], dict[str, str]]:
    """Generate and run the source of the classes of ``new``: the module, its file name,
    source and code, and the class name of each of its keys."""
    from veronte4x.dronecan.generate import keys, module_source, plan  # for user DSDL only

    known = _known(base)
    p = plan(definitions, known, base._names)
    for key, member_classes in base._members.items():
        p.members[key] = tuple(c.__name__ for c in member_classes)
    generate = [k for d in new.values() for k in keys(d)]
    names = ", ".join(r.name for r in roots)
    doc = f"The types of the DSDL namespaces {names}, compiled at run time."
    source = module_source(p, generate, doc, {})
    filename = f"<dsdl {', '.join(str(r) for r in roots)}>"
    code = compile(source, filename, "exec")  # the source generated above
    made = (filename, source, code)
    return _run(made, base, roots, known), made, {k: p.names[k] for k in generate}


def _run(
    made: tuple[str, str, Any],
    base: TypeSet,
    roots: list[Path],
    known: dict[str, Any] | None = None,
) -> _types.ModuleType:
    """Run the code of a load's module of classes (file name, source, code) in a module of
    its own, with the names of ``base`` (`_known`); the source goes to ``linecache``."""
    filename, source, code = made
    module_name = f"veronte4x.dronecan.loaded.{'_'.join(r.name for r in roots)}_{next(_serial)}"
    module = _types.ModuleType(module_name)
    module.__dict__.update(_known(base) if known is None else known)
    module.__file__ = filename
    linecache.cache[filename] = (len(source), None, source.splitlines(True), filename)
    sys.modules[module_name] = module  # dataclasses look the module up
    exec(code, module.__dict__)  # generated by `_compile`, or read back from the cache
    return module


def _load(loads: tuple[tuple[str, ...], ...]) -> TypeSet:
    """The standard set with ``loads``, one `TypeSet.with_dsdl` each (how a set is rebuilt
    in another process); the shipped load is the shipped set."""
    types = _STANDARD
    if loads and loads[0] == tuple(str(r) for r in TypeSet.shipped().loads[0]):
        types, loads = TypeSet.shipped(), loads[1:]
    for roots in loads:
        types = types.with_dsdl(*roots)
    return types


def _parse_shipped(roots: list[Path]) -> Callable[[], dict[str, Definition]]:
    """What parses the definitions of a set generated ahead of time, when asked for (kept
    in the disk cache, `veronte4x.dronecan.dsdl_cache`: every first load of a user's root
    is checked and named against them)."""

    def parse() -> dict[str, Definition]:
        from veronte4x.dronecan import parsed_data
        from veronte4x.dronecan.parser import check_references, parse_namespaces

        folder = dsdl_cache.directory()
        found = None if folder is None else dsdl_cache.load_key((), roots, "definitions")
        data = None if folder is None or found is None else dsdl_cache.read(folder, found)
        if data is not None:
            return parsed_data.definitions_of(data["definitions"])
        definitions = parse_namespaces(roots)
        check_references(definitions)
        if folder is not None and found is not None:
            entry = {"definitions": parsed_data.definitions_data(definitions)}
            dsdl_cache.write(folder, found, entry)
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
    units: dict[type, dict[str, str]] = {}
    for classes_module, data in modules:
        classes.update(classes_module.CLASSES)
        enums.update(classes_module.ENUMS)
        members.update(classes_module.UNION_MEMBERS)
        names.update(data.CLASS_NAMES)
        units.update(data.UNITS)
    roots = [DSDL_ROOT / "uavcan", *(r for load in loads for r in load)]
    return TypeSet(codecs, classes, enums, members, _parse_shipped(roots), loads, names, units)


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

_default: TypeSet | None = None
"""The default set, once `default_types` has built it."""


def default_set(
    environ: Mapping[str, str] | None = None, home: str | os.PathLike[str] | None = None
) -> TypeSet:
    """The default set of an environment and home directory: the shipped set
    (`TypeSet.shipped`, generated ahead of time), then the user's roots of
    `veronte4x.dronecan.vendor_roots.find_roots` (the subdirectories of
    ``~/uavcan_vendor_specific_types`` and ``~/dronecan_vendor_specific_types``, then
    ``VERONTE4X_DSDL_PATH``) in a load of their own, so that they never rename a shipped
    class; a user's definition of a shipped type replaces it (`TypeSet.with_dsdl`).

    Args:
        environ: The environment (`os.environ` if None).
        home: The home directory (`Path.home` if None).

    Raises:
        DsdlError: A user's root that is no directory, or a malformed definition in one.
    """
    return TypeSet.shipped().with_dsdl(*find_roots(environ, home).roots)


def default_types() -> TypeSet:
    """The set used where no ``types=`` is given: `default_set` of this process, built on
    first use, plus what `load_dsdl` added."""
    global _default
    if _default is None:
        _default = default_set()
    return _default


def set_default_types(types: TypeSet) -> None:
    """Make ``types`` the default set (``default_set()`` goes back to the start)."""
    global _default
    if not isinstance(types, TypeSet):
        raise argument_type_error("set_default_types", "types", "a TypeSet", types)
    _default = types


def load_dsdl(*root_namespace_dirs: str | bytes | os.PathLike[str] | os.PathLike[bytes]) -> TypeSet:
    """Add the types of vendor root namespace directories to the default set; return it.

    After this, everything that decodes or encodes DroneCAN without an explicit
    ``types=`` knows them. Loading a directory again does nothing; a definition of a type
    the set has replaces it (`TypeSet.with_dsdl`). For two sets side by side, use
    ``TypeSet.shipped().with_dsdl(...)`` and pass it as ``types=``.

    Raises:
        DsdlError: A malformed definition (file and line), an unknown nested type, or a
            data type id claimed twice (naming both files). The default set is then
            unchanged.
    """
    global _default
    _default = default_types().with_dsdl(*root_namespace_dirs)
    return _default


def types_or_default(types: TypeSet | None, where: str) -> TypeSet:
    """``types``, or the default set for None; TypeError for anything else."""
    if types is None:
        return _default if _default is not None else default_types()
    if not isinstance(types, TypeSet):
        raise argument_type_error(where, "types", "a TypeSet", types)
    return types
