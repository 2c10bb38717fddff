"""Parsed DSDL definitions as plain data, and back: the disk cache's ``definitions`` entry
(`veronte4x.dronecan.dsdl_cache`), the parsed shipped definitions that every first load of a
user's root is checked and named against (`veronte4x.dronecan.TypeSet.with_dsdl`)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from veronte4x.dronecan.parser import (
    ArrayType,
    Attribute,
    Constant,
    Definition,
    FieldType,
    PrimitiveType,
    Section,
)


def definitions_data(definitions: Mapping[str, Definition]) -> tuple[Any, ...]:
    """Parsed definitions as entry data (`definitions_of` makes them again): the shipped
    ones, which every first load of a user's root is checked and named against."""

    def field_type(t: FieldType) -> Any:
        if isinstance(t, str):
            return t
        if isinstance(t, ArrayType):
            return ("array", field_type(t.item), t.max_size, t.dynamic)
        return ("primitive", t.kind, t.bits, t.cast)

    return tuple(
        (
            d.full_name,
            d.default_id,
            d.service,
            tuple(
                (
                    tuple((a.name, field_type(a.type), a.line, a.comment) for a in s.fields),
                    tuple(
                        (c.name, field_type(c.type), c.value, c.line, c.comment)
                        for c in s.constants
                    ),
                    s.union,
                    s.doc,
                )
                for s in d.sections
            ),
            d.path,
            d.doc,
            d.override_signature,
        )
        for d in definitions.values()
    )


def definitions_of(data: tuple[Any, ...]) -> dict[str, Definition]:
    """The definitions of `definitions_data`, equal to those it was given."""

    def field_type(t: Any) -> FieldType:
        if isinstance(t, str):
            return t
        if t[0] == "array":
            item = field_type(t[1])
            assert not isinstance(item, ArrayType)
            return ArrayType(item, t[2], t[3])
        return PrimitiveType(t[1], t[2], t[3])

    def primitive(t: Any) -> PrimitiveType:
        found = field_type(t)
        assert isinstance(found, PrimitiveType)
        return found

    return {
        full_name: Definition(
            full_name,
            default_id,
            service,
            [
                Section(
                    [Attribute(n, field_type(t), line, note) for n, t, line, note in fields],
                    [Constant(n, primitive(t), v, line, note) for n, t, v, line, note in constants],
                    union,
                    doc,
                )
                for fields, constants, union, doc in sections
            ],
            path,
            doc_text,
            override,
        )
        for full_name, default_id, service, sections, path, doc_text, override in data
    }
