"""DSDL definitions as data types: schemas, ids and signatures, from the parsed files.

`standard_definitions` parses the ``uavcan`` namespace shipped with the package (the
DroneCAN standard DSDL, MIT licence, in ``veronte4x/dronecan/dsdl``); `data_types`
joins definitions to their classes (`veronte4x.dronecan.standard` for those, source
compiled at run time for a vendor namespace) and computes every signature.
"""

from __future__ import annotations

import functools
import re
from collections.abc import Mapping

from veronte4x.dronecan.can_id import TransferKind
from veronte4x.dronecan.generate import attribute_names, keys
from veronte4x.dronecan.parser import (
    ArrayType,
    Attribute,
    Definition,
    FieldType,
    PrimitiveType,
    check_references,
    parse_namespaces,
    signature,
)
from veronte4x.dronecan.schema import (
    Array,
    DataType,
    Member,
    Scalar,
    Struct,
    StructField,
    Union,
)
from veronte4x.dronecan.vendor_roots import DSDL_ROOT


@functools.cache
def standard_definitions() -> dict[str, Definition]:
    """Every definition of the standard ``uavcan`` namespace, by full name."""
    definitions = parse_namespaces([DSDL_ROOT / "uavcan"])
    check_references(definitions)
    return definitions


class _Builder:
    """Turns definitions into `schema` objects, given each key's class."""

    def __init__(
        self,
        definitions: Mapping[str, Definition],
        classes: Mapping[str, type],
        enums: Mapping[tuple[str, str], type],
        members: Mapping[str, tuple[type, ...]],
    ) -> None:
        self.definitions = definitions
        self.classes = classes
        self.enums = enums
        self.members = members
        self.done: dict[str, Struct | Union] = {}

    def build(self, key: str) -> Struct | Union:
        found = self.done.get(key)
        if found is not None:
            return found
        full_name = key.removesuffix(".Request").removesuffix(".Response")
        d = self.definitions[full_name]
        section = d.sections[keys(d).index(key)]
        built: Struct | Union
        attributes = attribute_names(key, section)
        if section.union:
            built = Union(
                key,
                tuple(
                    Member(
                        attributes[a.name],
                        self._member_type(d, a.type, a.line),
                        cls,
                        a.name,
                    )
                    for a, cls in zip(section.fields, self.members[key], strict=True)
                ),
            )
        else:
            built = Struct(
                key,
                self.classes[key],
                tuple(
                    StructField(
                        attributes.get(a.name, ""),
                        self._type(d, a.type, a.line),
                        self.enums.get((key, a.name)),
                        a.name,
                    )
                    for a in section.fields
                ),
            )
        self.done[key] = built
        return built

    def _member_type(self, d: Definition, t: FieldType, line: int) -> Scalar | Array | Struct:
        found = self._type(d, t, line)
        assert not isinstance(found, Union)  # refused by `generate.plan`, naming the line
        return found

    def _type(self, d: Definition, t: FieldType, line: int) -> Scalar | Array | Struct | Union:
        if isinstance(t, str):
            return self.build(t)
        if isinstance(t, ArrayType):
            item = self._type(d, t.item, line)
            assert not isinstance(item, Array)  # refused by the parser, naming the line
            return Array(item, t.max_size, t.dynamic)
        return _scalar(t)


def _scalar(t: PrimitiveType) -> Scalar:
    return Scalar(t.kind, t.bits, t.cast == "truncated")


def data_types(
    definitions: Mapping[str, Definition],
    new: Mapping[str, Definition],
    classes: Mapping[str, type],
    enums: Mapping[tuple[str, str], type],
    members: Mapping[str, tuple[type, ...]],
) -> list[DataType]:
    """The top-level types of ``new`` (the rest of ``definitions`` may be nested in them)."""
    builder = _Builder(definitions, classes, enums, members)
    found = []
    kinds = (TransferKind.REQUEST, TransferKind.RESPONSE)
    signatures: dict[str, int] = {}
    for d in new.values():
        if d.default_id is None:
            continue
        value = signature(d.full_name, definitions, signatures)
        for i, key in enumerate(keys(d)):
            schema = builder.build(key)
            assert isinstance(schema, Struct)  # `generate.plan` refuses top-level unions
            kind = kinds[i] if d.service else TransferKind.MESSAGE
            found.append(DataType(d.full_name, kind, d.default_id, value, schema, d.path))
    return found


UNIT = re.compile(r"\[([^\[\]]*[A-Za-z%][^\[\]]*)\]")
"""A unit in a DSDL comment: ``# [Volt]``, ``# [meter/second]``, ``# [%]`` (a letter or
``%`` in it: ``[0, 100]`` is a range, not a unit)."""


def unit(attribute: Attribute) -> str | None:
    """The unit of a field from its DSDL comment (``# [Volt]``), or None."""
    found = UNIT.search(attribute.comment)
    return found.group(1).strip() if found else None


def units_of(
    definitions: Mapping[str, Definition],
    classes: Mapping[str, type],
    members: Mapping[str, tuple[type, ...]],
) -> dict[type, dict[str, str]]:
    """The unit of each attribute whose DSDL comment names one (`unit`), by class; of a
    union's member, its ``value``."""
    found: dict[type, dict[str, str]] = {}
    for d in definitions.values():
        for key, section in zip(keys(d), d.sections, strict=True):
            if key not in classes:
                continue
            attributes = attribute_names(key, section)
            for index, a in enumerate(section.fields):
                text = unit(a)
                if text is None:
                    continue
                if section.union:
                    found.setdefault(members[key][index], {})["value"] = text
                else:
                    found.setdefault(classes[key], {})[attributes[a.name]] = text
    return found


def nested_signatures(definitions: Mapping[str, Definition]) -> dict[str, int]:
    """The signature of each nested type (documentation only: never on the wire)."""
    signatures: dict[str, int] = {}
    return {
        name: signature(name, definitions, signatures)
        for name, d in definitions.items()
        if d.default_id is None
    }
