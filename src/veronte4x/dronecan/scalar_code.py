"""The generated code of scalar fields: where their bits are, their value, and back.

The one home of how the fast paths of `compiled` (flat structs) and `compiled_tree` (any
type) read a scalar from its bits (bit runs gathered into an int, sign extension, float16,
float32 and float64, bool, enum members) and write one (type and range checks, float
rounding, bit runs placed in an int); and of how a run of scalars is cut into byte-aligned
groups that one `struct.Struct` packs and unpacks.

Bits are addressed in two ways. `bit_runs` places a scalar in the payload read as one
little-endian int (the groups of a chunk); `be_runs` in a piece of the stream read as one
big-endian int (the decoder's window ``x``, the encoder's accumulator ``a``).

The expressions refer to the helpers of `veronte4x.dronecan.fast_base.NAMES` by name: the
namespace of the generated code must hold them.
"""

from __future__ import annotations

import struct
from collections.abc import Callable, Sequence
from typing import Any, NamedTuple, Protocol

from veronte4x.dronecan.schema import Scalar
from veronte4x.dronecan.serializer import enum_table


class Namer(Protocol):
    """Makes an object visible to the generated code under a fresh name (prefix, object,
    and the expression that makes it again; a `struct.Struct` or a class needs none)."""

    def __call__(self, prefix: str, value: Any, expression: str | None = None) -> str: ...


_UINT_CODES = {8: "B", 16: "H", 32: "I", 64: "Q"}


def stream_position(offset: int, bits: int, bit: int) -> int:
    """Stream position (0 = MSB of byte 0) of bit ``bit`` of a scalar at ``offset``.

    Scalars of up to 8 bits are written MSB first. Wider ones as their little-endian bytes,
    each MSB first, then the top ``bits % 8`` bits MSB first.
    """
    if bits <= 8:
        return offset + bits - 1 - bit
    full = bits // 8 * 8
    if bit < full:
        return offset + bit // 8 * 8 + 7 - bit % 8
    return offset + full + (bits - full) - 1 - (bit - full)


def _runs(offset: int, bits: int, place: Callable[[int], int]) -> list[tuple[int, int, int]]:
    """Runs ``(source bit, width, int bit)`` of a scalar, stream position ``p`` being bit
    ``place(p)`` of the int; neighbours merged."""
    runs: list[tuple[int, int, int]] = []
    for bit in range(bits):
        dest = place(stream_position(offset, bits, bit))
        if runs and runs[-1][0] + runs[-1][1] == bit and runs[-1][2] + runs[-1][1] == dest:
            source, width, start = runs[-1]
            runs[-1] = (source, width + 1, start)
        else:
            runs.append((bit, 1, dest))
    return runs


def bit_runs(offset: int, bits: int) -> list[tuple[int, int, int]]:
    """Runs ``(source bit, width, payload bit)`` of a scalar in the little-endian payload int."""
    return _runs(offset, bits, lambda pos: pos // 8 * 8 + 7 - pos % 8)


def be_runs(offset: int, bits: int, width: int) -> list[tuple[int, int, int]]:
    """Runs ``(source bit, width, int bit)`` of a scalar at ``offset`` of a ``width``-bit
    piece of the stream, the piece read as a big-endian int (stream bit 0 its top bit)."""
    return _runs(offset, bits, lambda pos: width - 1 - pos)


def _grouped(expr: str) -> str:
    """``expr`` in parentheses unless it is a name or already in one pair of them."""
    if expr.isidentifier():
        return expr
    if expr.startswith("("):
        depth = 0
        for i, char in enumerate(expr):
            depth += {"(": 1, ")": -1}.get(char, 0)
            if depth == 0:
                if i == len(expr) - 1:
                    return expr
                break
    return f"({expr})"


def is_whole(t: Scalar) -> bool:
    """Whether `struct` reads and writes ``t`` as it is: an 8/16/32/64-bit int or a float
    (DSDL has float16, float32 and float64 only)."""
    return t.kind in ("uint", "int", "float") and t.bits in _UINT_CODES


def read_code(t: Scalar) -> str:
    """The `struct` code that reads a whole scalar (see `is_whole`) as its value."""
    if t.kind == "float":
        return {16: "e", 32: "f", 64: "d"}[t.bits]
    code = _UINT_CODES[t.bits]
    return code.lower() if t.kind == "int" else code


# Decoding --------------------------------------------------------------------------------


def gather(var: str, runs: Sequence[tuple[int, int, int]], var_bits: int) -> str:
    """The raw bits of a scalar (an unsigned int) gathered from the ``var_bits``-bit int
    ``var`` through its ``runs`` (bit ``dest`` of ``var`` onwards is bit ``source``)."""
    parts = []
    for source, width, dest in runs:
        value = f"({var} >> {dest})" if dest else var
        if dest + width != var_bits:  # the top run of var needs no mask
            value = f"({value} & {(1 << width) - 1:#x})"
        parts.append(f"{value} << {source}" if source else value)
    return " | ".join(parts)


def enum_value(raw: str, enum: type | None, name: Namer, bits: int) -> str:
    """An unsigned field's value from its raw bits: the enum member where there is one."""
    if enum is None:
        return raw
    table = name("E", enum_table(enum, bits), f"enum_table({name('C', enum)}, {bits})")
    return f"{table}[{raw}]"


def scalar_value(t: Scalar, raw: str, enum: type | None, name: Namer) -> str:
    """The value of scalar ``t`` from ``raw``, the expression of its bits as an unsigned int
    (as the generic serializer decodes it: enums on unsigned fields only)."""
    if t.kind == "int":
        sign = 1 << (t.bits - 1)
        return f"({_grouped(raw)} ^ {sign:#x}) - {sign:#x}"
    if t.kind == "bool":
        return f"{_grouped(raw)} != 0"
    if t.kind == "float":
        return f"F16[{raw}]" if t.bits == 16 else f"f{t.bits}v({raw})"
    return enum_value(raw, enum, name, t.bits)


# Encoding --------------------------------------------------------------------------------


def scalar_checks(t: Scalar, var: str, range_checked: bool = False) -> list[str]:
    """Conditions true when ``var`` is no value the generated code writes into ``t``.

    A bool field takes True and False; an integer field an int (a bool is an int to Python,
    but not a value of an integer field; a NumPy integer, whose arithmetic wraps at its own
    width, goes to the generic serializer, which takes it by `veronte4x.errors.integer`)
    within its range, unless ``range_checked`` (`struct` checks it); a float field a
    Python float or int.
    """
    if t.kind == "void":
        return []
    if t.kind == "bool":
        return [f"({var} is not True and {var} is not False)"]
    if t.kind == "float":
        return [f"({var}.__class__ is not float and {var}.__class__ is not int)"]
    checks = [
        f"({var}.__class__ is not int and ({var}.__class__ is bool or not isinstance({var}, int)))"
    ]
    if not range_checked:
        low = f"({var} + {1 << (t.bits - 1)})" if t.kind == "int" else var
        checks.append(f"{low} >> {t.bits}")
    return checks


def scalar_terms(t: Scalar, var: str, runs: Sequence[tuple[int, int, int]]) -> list[str]:
    """The terms that place the bits of checked value ``var`` (an int, negative for a
    negative ``int`` field) through its ``runs`` (bit ``source`` onwards goes to ``dest``);
    OR them together."""
    if t.kind == "void":
        return []
    terms = []
    for source, width, dest in runs:
        value = f"({var} >> {source})" if source else var
        if source + width != t.bits or t.kind == "int":  # a negative int has more bits
            value = f"({value} & {(1 << width) - 1:#x})"
        terms.append(f"{value} << {dest}" if dest else value)
    return terms


HALF_EXPR = (
    "({m} - 0x37FFF000) >> 13 | ({a} >> 16) & 0x8000 if 0x38800000 <= {m} < 0x477FF000"
    " else ({a} >> 16) & 0x8000 if {m} < 0x33000000 else f16({v})"
)
"""The float16 bits of float ``{v}`` from its float32 bits ``{a}`` (``{m}`` without the sign):
rounded inline in the normal range and to a signed zero far below it, `float16_bits`
elsewhere (subnormals, overflow, infinity, NaN)."""


def float_bits(scalars: Sequence[Scalar], name: Namer) -> list[str]:
    """Statements that turn every float field ``v<i>`` of ``scalars`` into its raw bits.

    float32 and float64 through `float32_bits` and `float64_bits`; all float16 fields
    through one `struct` call to their float32 bits, then `HALF_EXPR` (``h<i>`` and
    ``hm<i>`` hold the float32 bits and their magnitude).
    """
    lines = [
        f"v{i} = f{t.bits}(v{i})"
        for i, t in enumerate(scalars)
        if t.kind == "float" and t.bits > 16
    ]
    halves = [i for i, t in enumerate(scalars) if t.kind == "float" and t.bits == 16]
    if not halves:
        return lines
    pack = name("F", struct.Struct(f"<{len(halves)}f"))
    unpack = name("U", struct.Struct(f"<{len(halves)}I"))
    targets = "".join(f"h{i}, " for i in halves)
    values = ", ".join(f"v{i}" for i in halves)
    # Beyond the float32 range struct refuses: every half then goes through float16_bits.
    lines += [
        "try:",
        f"    {targets}= {unpack}.unpack({pack}.pack({values}))",
        "except OverflowError:",
        f"    {' = '.join(f'h{i}' for i in halves)} = 0x7F800000",
    ]
    for i in halves:
        lines += [
            f"hm{i} = h{i} & 0x7FFFFFFF",
            f"v{i} = ({HALF_EXPR.format(a=f'h{i}', m=f'hm{i}', v=f'v{i}')})",
        ]
    return lines


# Runs of scalars, packed and unpacked by one struct ----------------------------------------


class Group(NamedTuple):
    """Fields that together fill whole bytes, starting on a byte boundary."""

    start: int
    bits: int
    members: tuple[int, ...]


def groups(scalars: Sequence[Scalar]) -> list[Group]:
    """Cut a field list at every byte boundary; the last group is padded to a byte."""
    found: list[Group] = []
    start, offset, members = 0, 0, []
    for i, t in enumerate(scalars):
        members.append(i)
        offset += t.bits
        if offset % 8 == 0:
            found.append(Group(start, offset - start, tuple(members)))
            start, members = offset, []
    if members:
        found.append(Group(start, (offset - start + 7) // 8 * 8, tuple(members)))
    return found


def _direct(group: Group, scalars: Sequence[Scalar]) -> bool:
    """Whether a group is one field that `struct` packs and unpacks as is.

    Not a float16: it is read as its bits and valued from `FLOAT16_VALUES`, so that the
    same payload decodes to the same float object, NaN included, as the generic serializer.
    """
    t = scalars[group.members[0]]
    return (
        len(group.members) == 1
        and is_whole(t)
        and t.bits == group.bits
        and not (t.kind == "float" and t.bits == 16)
    )


def _offset(group: Group, scalars: Sequence[Scalar], member: int) -> int:
    """Bit offset of field ``member`` in its group."""
    return sum(scalars[j].bits for j in range(group.members[0], member))


class Unpacking(NamedTuple):
    """How to decode a run of scalars with one `struct.Struct`.

    Attributes:
        format: The struct format of the run's bytes (``<`` first).
        targets: ``g0, g1, ...,`` the names the struct's items are unpacked into.
        lines: Statements that then set each named field's target to its value.
    """

    format: str
    targets: str
    lines: list[str]


def unpack_scalars(
    scalars: Sequence[Scalar],
    targets: Sequence[str | None],
    enums: Sequence[type | None],
    name: Namer,
) -> Unpacking:
    """Decode consecutive scalars (from a byte boundary) into ``targets`` (None: skipped).

    A whole 8/16/32/64-bit integer, float32 or float64 field that fills its group is one
    struct item, read as its value; other groups are read as little-endian ints and their
    fields gathered from their bit runs (see `bit_runs`, relative to the group's first
    byte), float16 fields valued from `FLOAT16_VALUES`.
    """
    codes, lines = ["<"], []
    found = groups(scalars)
    for k, group in enumerate(found):
        var = f"g{k}"
        direct = _direct(group, scalars)
        if direct:
            codes.append(read_code(scalars[group.members[0]]))
        elif group.bits in _UINT_CODES:
            codes.append(_UINT_CODES[group.bits])
        else:
            codes.append(f"{group.bits // 8}s")
            lines.append(f"{var} = from_bytes({var}, 'little')")
        for i in group.members:
            t, target = scalars[i], targets[i]
            if target is None or t.kind == "void":
                continue
            if direct:
                value = enum_value(var, enums[i], name, t.bits) if t.kind == "uint" else var
            else:
                raw = gather(var, bit_runs(_offset(group, scalars, i), t.bits), group.bits)
                value = scalar_value(t, raw, enums[i], name)
            lines.append(f"{target} = {value}")
    return Unpacking("".join(codes), "".join(f"g{k}, " for k in range(len(found))), lines)


class Packing(NamedTuple):
    """How to encode a run of scalars ``v0``, ``v1``, ... with one `struct.Struct`.

    Attributes:
        format: The struct format of the run's bytes (``<`` first).
        values: The expression of each struct item.
        checks: Conditions true when a value is refused (then the generic serializer
            decides); to be tested before ``floats`` runs.
        floats: Statements that turn the float fields into their raw bits.
    """

    format: str
    values: list[str]
    checks: list[str]
    floats: list[str]


def pack_scalars(scalars: Sequence[Scalar], name: Namer) -> Packing:
    """Encode consecutive scalars ``v0``, ``v1``, ... (to a byte boundary) with one struct.

    A whole 8/16/32/64-bit integer, float32 or float64 field that fills its group is one
    struct item (``struct`` checks its range; floats as their raw bits, rounded as DroneCAN
    rounds); other groups are built from their fields' bit runs (see `bit_runs`) and range-checked
    explicitly.
    """
    codes, values, checks = ["<"], [], []
    for group in groups(scalars):
        direct = _direct(group, scalars)
        terms = []
        for i in group.members:
            t = scalars[i]
            checks += scalar_checks(t, f"v{i}", range_checked=direct)
            if not direct:
                terms += scalar_terms(t, f"v{i}", bit_runs(_offset(group, scalars, i), t.bits))
        if direct:
            t = scalars[group.members[0]]
            code = _UINT_CODES[t.bits]  # a float as its raw bits
            codes.append(code.lower() if t.kind == "int" else code)
            values.append(f"v{group.members[0]}")
        elif group.bits in _UINT_CODES:
            codes.append(_UINT_CODES[group.bits])
            values.append(" | ".join(terms) or "0")
        else:
            size = group.bits // 8
            codes.append(f"{size}s")
            values.append(f"{_grouped(' | '.join(terms) or '0')}.to_bytes({size}, 'little')")
    return Packing("".join(codes), values, checks, float_bits(scalars, name))
