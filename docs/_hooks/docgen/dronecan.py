"""Markdown tables for the docs, generated from the code's own definitions.

Each function returns Markdown for a ``<!-- generate: docgen.dronecan:name -->``
line of a docs page (see ``docs/_hooks/generate.py``).
"""

from __future__ import annotations

from collections.abc import Sequence

from veronte4x.dronecan import vertiq
from veronte4x.dronecan.can_id import LAYOUTS
from veronte4x.dronecan.definitions import DATA_TYPES, NESTED_SIGNATURES, NUMERIC_VALUE, VALUE
from veronte4x.dronecan.reassembler import TRANSFER_PROBLEMS, Problem
from veronte4x.dronecan.schema import Array, Scalar, Struct, Union, max_bits, min_bits, uses_tao
from veronte4x.dronecan.tail import END_OF_TRANSFER, START_OF_TRANSFER, TOGGLE
from veronte4x.units import unit


def _table(header: tuple[str, ...], rows: Sequence[tuple[object, ...]]) -> str:
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(lines) + "\n"


def can_id_tables() -> str:
    """One table per CAN ID layout: bits, field, width, values."""
    out = []
    for name, fields in LAYOUTS.items():
        rows = []
        top = 28
        for field, width, values in fields:
            bits = f"{top}" if width == 1 else f"{top}..{top - width + 1}"
            rows.append((bits, field, width, values))
            top -= width
        out.append(f"**{name}**\n\n" + _table(("bits", "field", "width", "values"), rows))
    return "\n".join(out)


def tail_byte_table() -> str:
    """The tail byte's fields."""
    rows = [
        ("7", f"{START_OF_TRANSFER:#04x}", "start of transfer", "1 on the first frame"),
        ("6", f"{END_OF_TRANSFER:#04x}", "end of transfer", "1 on the last frame"),
        ("5", f"{TOGGLE:#04x}", "toggle", "0 on the first frame, then alternates"),
        ("4..0", "0x1f", "transfer id", "0..31, the same on every frame"),
    ]
    return _table(("bits", "mask", "field", "value"), rows)


def types_table() -> str:
    """The types: id, kind, signature, CRC seed, payload sizes."""
    rows = []
    for t in DATA_TYPES:
        low = (min_bits(t.schema) - _prefixes_dropped(t.schema) + 7) // 8
        rows.append(
            (
                f"`{t.full_name}`",
                t.kind.name.lower(),
                t.data_type_id,
                f"`{t.signature:#018x}`",
                f"`{t.crc_seed:#06x}`",
                f"{low}..{t.max_payload}" if low != t.max_payload else t.max_payload,
                f"`{t.schema.cls.__name__}`",
            )
        )
    header = ("type", "kind", "id", "signature", "CRC seed", "payload bytes", "class")
    nested = _table(
        ("nested type", "signature"),
        [(f"`{name}`", f"`{sig:#018x}`") for name, sig in NESTED_SIGNATURES.items()],
    )
    return _table(header, rows) + "\n" + nested


def _prefixes_dropped(schema: Struct) -> int:
    """Prefix bits the TAO removes from the minimum size (the tail array's prefix)."""
    last = schema.fields[-1].type if schema.fields else None
    if isinstance(last, Array) and uses_tao(last):
        return last.prefix_bits
    if isinstance(last, Struct):
        return _prefixes_dropped(last)
    return 0


def _describe(t: Scalar | Array | Struct | Union, tao: bool) -> str:
    if isinstance(t, Array):
        if not t.dynamic:
            return f"{t.max_size} items, no prefix"
        if tao and uses_tao(t):
            return "tail array: no length prefix, runs to the end of the payload"
        return f"{t.prefix_bits}-bit length prefix, then the items"
    if isinstance(t, Union):
        names = ", ".join(f"{i} `{m.name}`" for i, m in enumerate(t.members))
        return f"{t.tag_bits}-bit tag ({names}), then the member"
    return ""


def _rows(
    s: Struct,
    prefix: str,
    offset: int | None,
    tao: bool,
    rows: list[tuple[object, ...]],
    top: str = "",
) -> int | None:
    last = len(s.fields) - 1
    for i, f in enumerate(s.fields):
        t = f.type
        name = f"{prefix}{f.name}" if f.name else "(void)"
        if isinstance(t, Struct):
            offset = _rows(t, f"{name}.", offset, tao and i == last, rows, top)
            continue
        where = "variable" if offset is None else str(offset)
        dsdl = f"`{t.dsdl}`" if not isinstance(t, Union) else f"`{t.name.split('.')[-1]}` union"
        width = max_bits(t, tao and i == last)
        fixed = min_bits(t) == width
        size = str(width) if fixed else f"{min_bits(t) if not (tao and i == last) else 0}..{width}"
        note = _describe(t, tao and i == last)
        if f.enum is not None:
            note = f"`{f.enum.__name__}`"
        rows.append((where, size, dsdl, f"`{name}`", unit(top, name) or "", note))
        offset = offset + width if offset is not None and fixed else None
    return offset


def type_tables() -> str:
    """One bit-layout table per top-level type: offset, width, DSDL type, field, unit, notes."""
    out = []
    for t in DATA_TYPES:
        rows: list[tuple[object, ...]] = []
        _rows(t.schema, "", 0, True, rows, t.schema.cls.__name__)
        title = f"### {t.schema.name} ({t.kind.name.lower()} {t.data_type_id})\n\n"
        title += f"Class `{t.schema.cls.__name__}`. "
        if not rows:
            out.append(title + "Empty payload: the frame is the tail byte alone.\n")
            continue
        out.append(
            title + "Offsets in bits from the payload start; fields wider than a byte go as "
            "little-endian bytes, each MSB first. Units as the DSDL definitions give them.\n\n"
            + _table(("offset", "bits", "DSDL", "field", "unit", "notes"), rows)
        )
    return "\n".join(out)


def union_tables() -> str:
    """The members of the param.Value and param.NumericValue unions and their classes."""
    out = []
    for union in (VALUE, NUMERIC_VALUE):
        rows = [
            (
                tag,
                f"`{m.name}`",
                f"`{m.type.dsdl}`" if not isinstance(m.type, Struct) else "Empty",
                f"`{m.cls.__name__}`",
            )
            for tag, m in enumerate(union.members)
        ]
        out.append(
            f"**{union.name}** ({union.tag_bits}-bit tag)\n\n"
            + _table(("tag", "member", "DSDL", "class"), rows)
        )
    return "\n".join(out)


def problems_table() -> str:
    """The reassembler's problem kinds and what each means."""
    rows = [
        (f"`{p.name}`", "transfer lost" if p in TRANSFER_PROBLEMS else "frame ignored", p.value)
        for p in Problem
    ]
    return _table(("problem", "effect", "meaning"), rows)


def vertiq_parameters_table() -> str:
    """Vertiq configuration parameters (seed 004 section 3)."""
    rows = [(f"`{p.value}`", f"`Parameter.{p.name}`", "integer") for p in vertiq.Parameter]
    zero = ", ".join(f"{z.value} {z.name.lower().replace('_', ' ')}" for z in vertiq.ZeroBehavior)
    return _table(("name", "constant", "type"), rows) + f"\n`zero_behavior` values: {zero}.\n"
