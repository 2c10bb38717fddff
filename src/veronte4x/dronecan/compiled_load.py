"""One load of user DSDL (`veronte4x.dronecan.TypeSet.with_dsdl`) as data: what the
disk cache keeps (`veronte4x.dronecan.dsdl_cache`), and the codecs made from it again.

An entry is a dict of what `marshal` writes (text, numbers, tuples, code objects), no object
of the package, so that reading one runs nothing before it is checked:

- ``classes``: the file name, source and code of the module of classes
  (`veronte4x.dronecan.generate.module_source`), and ``names``, the class name of each key;
- ``notes``: the `DsdlOverrideWarning` texts of the load, shown again on every hit;
  ``again``: the full names of the set's types replaced (compiled again with the load);
- ``schemas``: the schema of every key the new top-level types reach, by key (classes,
  enums and union members are named by their key: the set's tables give them back);
  ``types``: each top-level type (name, kind, id, signature, key, file) and ``fast``, the
  source of its fast paths as `veronte4x.dronecan.compiled` writes them, compiled on the
  type's first use (a load compiles none: a type that never sees a frame costs no compile);
- ``units``: the unit of each attribute with one, by class key.

A load builds the set from its entry on every path, the first (which compiles and writes
it) as the next (which reads it), so both give the same classes, schemas and codecs.
"""

from __future__ import annotations

import functools
import struct
from collections.abc import Mapping
from typing import Any

from veronte4x.codegen import compile_source, slot_builder
from veronte4x.dronecan.can_id import TransferKind
from veronte4x.dronecan.codec import TypeCodec
from veronte4x.dronecan.compiled import FastPaths, fast_source, slow, transport_of
from veronte4x.dronecan.fast_base import (
    NAMES,
    half_tables,
    int_array_tables,
    struct_table,
    tail_table,
)
from veronte4x.dronecan.frame import TransferFrame
from veronte4x.dronecan.schema import Array, DataType, Member, Scalar, Struct, StructField, Union
from veronte4x.dronecan.serializer import enum_table

EAGER_LEAVES = 4096
"""Most scalar fields (an array's item counted once) a type may have for its fast paths to
be written with the entry; a larger one generates them on first use, as without the cache."""

Tables = tuple[Mapping[str, type], Mapping[tuple[str, str], type], Mapping[str, tuple[type, ...]]]
"""A set's classes, enums and union members, by key (see `veronte4x.dronecan.TypeSet`)."""


def entry(
    classes_module: tuple[str, str, Any],
    names: Mapping[str, str],
    notes: list[str],
    again: set[str],
    found: list[DataType],
    units: Mapping[type, Mapping[str, str]],
    tables: Tables,
    fast: bool,
) -> dict[str, Any]:
    """The entry of a load: ``classes_module`` its file name, source and code; ``found``
    its top-level types, ``units`` theirs, ``tables`` the set's with the new classes;
    without ``fast``, no fast paths (each generated on first use: the entry is not kept)."""
    classes, enums, members = tables
    refs: dict[int, str] = {id(TransferFrame): "TransferFrame"}
    for k, cls in classes.items():
        refs.setdefault(id(cls), f"CLASSES[{k!r}]")
    for k, found_members in members.items():
        for index, cls in enumerate(found_members):
            refs.setdefault(id(cls), f"MEMBERS[{k!r}][{index}]")
    for (k, field), enum in enums.items():
        refs.setdefault(id(enum), f"ENUMS[{(k, field)!r}]")
    schemas: dict[str, tuple[Any, ...]] = {}
    for t in found:
        _encode(t.schema, schemas, classes, members)
    return {
        "classes": classes_module,
        "names": dict(names),
        "notes": tuple(notes),
        "again": tuple(sorted(again)),
        "schemas": schemas,
        "types": tuple(
            (t.full_name, t.kind.name, t.data_type_id, t.signature, t.schema.name, t.path)
            for t in found
        ),
        "fast": tuple(_fast(t, refs) if fast else None for t in found),
        "units": tuple(
            (_class_key(cls, classes, members), tuple(sorted(found_units.items())))
            for cls, found_units in units.items()
        ),
    }


def _class_key(
    cls: type, classes: Mapping[str, type], members: Mapping[str, tuple[type, ...]]
) -> tuple[str, int]:
    """(key, -1) of a class of ``classes``; (union key, index) of a union member's."""
    for k, found in classes.items():
        if found is cls:
            return k, -1
    for k, found_members in members.items():
        if cls in found_members:
            return k, found_members.index(cls)
    raise KeyError(cls)


def _encode(
    t: Scalar | Array | Struct | Union,
    schemas: dict[str, tuple[Any, ...]],
    classes: Mapping[str, type],
    members: Mapping[str, tuple[type, ...]],
) -> tuple[Any, ...]:
    """The data of a field type; a struct or union also goes into ``schemas``, by key."""
    if isinstance(t, Scalar):
        return ("scalar", t.kind, t.bits, t.truncated)
    if isinstance(t, Array):
        return ("array", _encode(t.item, schemas, classes, members), t.max_size, t.dynamic)
    if t.name not in schemas:
        if isinstance(t, Struct):
            assert t.cls is classes[t.name], t.name  # how `types.data_types` builds it
            schemas[t.name] = (
                "struct",
                tuple(
                    (
                        f.name,
                        _encode(f.type, schemas, classes, members),
                        f.enum is not None,
                        f.dsdl_name,
                    )
                    for f in t.fields
                ),
            )
        else:
            assert tuple(m.cls for m in t.members) == members[t.name], t.name
            schemas[t.name] = (
                "union",
                tuple(
                    (m.name, _encode(m.type, schemas, classes, members), m.dsdl_name)
                    for m in t.members
                ),
            )
    return ("ref", t.name)


def _leaves(t: Scalar | Array | Struct | Union, memo: dict[int, int]) -> int:
    """The scalar fields of ``t`` as generated code writes them out (an array's item once)."""
    if isinstance(t, Scalar):
        return 1
    if isinstance(t, Array):
        return _leaves(t.item, memo)
    found = memo.get(id(t))
    if found is None:
        parts = t.fields if isinstance(t, Struct) else t.members
        found = memo[id(t)] = sum(_leaves(p.type, memo) for p in parts)
    return found


def _fast(t: DataType, refs: Mapping[int, str]) -> tuple[Any, ...] | None:
    """The fast paths of a type as entry data: (source, single frame), or ``()`` for a type
    nested too deep for generated code; None past `EAGER_LEAVES`."""
    if _leaves(t.schema, {}) > EAGER_LEAVES:
        return None
    src = fast_source(t.schema, transport_of(t))
    if src.slow:
        return ()
    return ("\n".join(src.module_lines(lambda cls: refs[id(cls)])) + "\n", src.single)


def data_types(data: Mapping[str, Any], tables: Tables) -> list[DataType]:
    """The top-level types of an entry, their schemas made with the set's ``tables``."""
    classes, enums, members = tables
    schemas = data["schemas"]
    done: dict[str, Struct | Union] = {}

    def build(k: str) -> Struct | Union:
        found = done.get(k)
        if found is not None:
            return found
        kind, parts = schemas[k]
        made: Struct | Union
        if kind == "struct":
            made = Struct(
                k,
                classes[k],
                tuple(
                    StructField(name, field_type(t), enums[k, dsdl] if enum else None, dsdl)
                    for name, t, enum, dsdl in parts
                ),
            )
        else:
            made = Union(
                k,
                tuple(
                    Member(name, member_type(t), cls, dsdl)
                    for (name, t, dsdl), cls in zip(parts, members[k], strict=True)
                ),
            )
        done[k] = made
        return made

    def field_type(t: tuple[Any, ...]) -> Scalar | Array | Struct | Union:
        if t[0] == "scalar":
            return Scalar(t[1], t[2], t[3])
        if t[0] == "array":
            item = field_type(t[1])
            assert not isinstance(item, Array)
            return Array(item, t[2], t[3])
        return build(t[1])

    def member_type(t: tuple[Any, ...]) -> Scalar | Array | Struct:
        found = field_type(t)
        assert not isinstance(found, Union)
        return found

    found = []
    for full_name, kind, data_type_id, signature, k, path in data["types"]:
        schema = build(k)
        assert isinstance(schema, Struct)
        found.append(DataType(full_name, TransferKind[kind], data_type_id, signature, schema, path))
    return found


def units(data: Mapping[str, Any], tables: Tables) -> dict[type, dict[str, str]]:
    """The units of an entry, by class of the set's ``tables``."""
    classes, _, members = tables
    return {
        (classes[k] if index < 0 else members[k][index]): dict(found)
        for (k, index), found in data["units"]
    }


def codecs(data: Mapping[str, Any], found: list[DataType], tables: Tables) -> tuple[TypeCodec, ...]:
    """The codec of each top-level type of an entry (``found``, from `data_types`)."""
    return tuple(
        TypeCodec(t) if fast is None else _EntryCodec(t, fast, tables)
        for t, fast in zip(found, data["fast"], strict=True)
    )


class _EntryCodec(TypeCodec):
    """A `TypeCodec` whose fast paths are source of an entry, compiled on first use."""

    def __init__(self, data_type: DataType, fast: tuple[Any, ...], tables: Tables) -> None:
        super().__init__(data_type)
        self._entry = fast
        self._tables = tables

    @functools.cached_property
    def fast(self) -> FastPaths:
        """The fast paths of the entry (the source `veronte4x.dronecan.compiled` wrote),
        compiled now (`veronte4x.codegen.compile_source`: a traceback shows their lines)."""
        if not self._entry:
            return FastPaths(slow, slow, slow, None)
        source, single = self._entry
        classes, enums, members = self._tables
        namespace: dict[str, Any] = {
            **NAMES,
            "Struct": struct.Struct,
            "enum_table": enum_table,
            "half_tables": half_tables,
            "int_array_tables": int_array_tables,
            "slot_builder": slot_builder,
            "struct_table": struct_table,
            "tail_table": tail_table,
            "TransferFrame": TransferFrame,
            "CLASSES": classes,
            "ENUMS": enums,
            "MEMBERS": members,
        }
        t = self.data_type
        title = f"dsdl fast paths {t.full_name} {t.kind.name.lower()}"
        compile_source(source, namespace, title)  # an entry this package wrote (`dsdl_cache.read`)
        frame = namespace["decode_frame"] if single else None
        return FastPaths(namespace["frames"], namespace["payload"], namespace["decode"], frame)
