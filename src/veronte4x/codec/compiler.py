"""Compile a frame layout into one decode and one encode function.

A layout (`FrameLayout`) is data: the message class and its ordered fields. `compile_layout`
turns it, once, into two plain Python functions specialised for that layout (constant
folding, precomputed shifts and masks, positional construction of the dataclass), the way
dataclasses and attrs generate their methods. The generated source can be read with
`FrameLayout.source`, and the same layout data renders the docs tables.
"""

from __future__ import annotations

import dataclasses
import re
import struct
import types
from collections.abc import Callable
from dataclasses import dataclass
from functools import cached_property
from typing import Any

from veronte4x.codec.fields import ByteOrder, Field, FieldKind
from veronte4x.codec.float32 import bits_from_float, float_from_bits
from veronte4x.codec.messages import Message
from veronte4x.codegen import compile_source, slot_builder
from veronte4x.errors import DecodeError, EncodeError, LayoutError, boolean, integer, real
from veronte4x.words import counted

FrameDecoder = Callable[[bytes, bool], Message]
"""A layout's decoder: ``decode(data, allow_excess)`` of one frame's bytes."""
FrameEncoder = Callable[[Message], bytes]
"""A layout's encoder: a message to its frame's bytes."""

MAX_FRAME_BYTES = 8
"""Classic CAN: byte 0 is the message type, up to 7 data bytes follow (4x Software Manual, section
3)."""


@dataclass(frozen=True)
class Placed:
    """A field with its position in the frame integer.

    Attributes:
        field: The field.
        start: Bits before the field, counted in layout order.
        shift: Right shift that brings the field to bit 0 of the frame integer.
    """

    field: Field
    start: int
    shift: int


@dataclass(frozen=True)
class FrameLayout:
    """A frame layout: a message class, its ordered fields and where the layout comes from.

    Attributes:
        message: The dataclass the layout decodes to.
        fields: The fields in wire order; a BYTES field may only come last.
        byte_order: How the frame's bytes form the integer the fields are cut from.
        implied: Attributes the layout fixes without sending them (name, value).
        source: Where the layout comes from (seed section or notes).
        title: Short name for docs and errors, defaults to the class name.
        implied_text: What an encoding error says is allowed for an implied attribute.
    """

    message: type[Message]
    fields: tuple[Field, ...]
    byte_order: ByteOrder = ByteOrder.LITTLE
    implied: tuple[tuple[str, Any], ...] = ()
    source: str = ""
    title: str = ""
    implied_text: str = ""

    def __post_init__(self) -> None:
        found = {f.attr for f in self.fields if f.kind is FieldKind.FLOAT32 and f.attr}
        if found:  # the class's fact, read by `veronte4x.values.float_bits`
            self.message._FLOAT32_FIELDS_ = self.message._FLOAT32_FIELDS_ | found

    @property
    def name(self) -> str:
        """The message type's name as errors show it."""
        return self.message.__name__

    @cached_property
    def tail(self) -> Field | None:
        """The trailing BYTES field, if the layout ends with one."""
        last = self.fields[-1] if self.fields else None
        return last if last is not None and last.kind is FieldKind.BYTES else None

    @cached_property
    def fields_by_attr(self) -> dict[str, Field]:
        """The first field of each message attribute."""
        out: dict[str, Field] = {}
        for f in self.fields:
            if f.attr is not None:
                out.setdefault(f.attr, f)
        return out

    @cached_property
    def fixed_bits(self) -> int:
        """Bits before the trailing bytes (or in the whole layout)."""
        return sum(f.bits for f in self.fields if f.kind is not FieldKind.BYTES)

    @cached_property
    def fixed_size(self) -> int:
        """Bytes before the trailing bytes (or of the whole frame)."""
        return -(-self.fixed_bits // 8)

    @cached_property
    def placed(self) -> tuple[Placed, ...]:
        """Every fixed field with its start and shift in the frame integer."""
        out: list[Placed] = []
        start = 0
        total = self.fixed_size * 8
        for f in self.fields:
            if f.kind is FieldKind.BYTES:
                break
            shift = start if self.byte_order is ByteOrder.LITTLE else total - start - f.bits
            out.append(Placed(f, start, shift))
            start += f.bits
        return tuple(out)

    def check(self) -> None:
        """Raise `LayoutError` if the layout cannot describe a Veronte frame."""
        for position, f in enumerate(self.fields):
            if f.bits <= 0:
                raise LayoutError(f"{self.name}: field {f.label} has {f.bits} bits")
            if f.kind is FieldKind.BYTES and (
                position != len(self.fields) - 1 or self.fixed_bits % 8
            ):
                raise LayoutError(f"{self.name}: raw bytes must come last, byte-aligned")
            if f.kind is FieldKind.FLOAT32 and f.bits != 32:
                raise LayoutError(f"{self.name}: float32 field {f.label} must have 32 bits")
            if f.kind is FieldKind.MAPPED and not all(0 <= w < 1 << f.bits for w, _ in f.mapping):
                raise LayoutError(f"{self.name}: a wire value of {f.label} does not fit")
            if f.kind is FieldKind.CONSTANT and not 0 <= f.value < 1 << f.bits:
                raise LayoutError(
                    f"{self.name}: constant {f.value} does not fit {counted(f.bits, 'bit')}"
                )
            if f.scale is not None and f.scale.encoded_min == f.scale.encoded_max:
                raise LayoutError(f"{self.name}: field {f.label} has an empty compression")
        if self.fixed_size > MAX_FRAME_BYTES:
            raise LayoutError(
                f"{self.name}: {self.fixed_bits} bits do not fit a {MAX_FRAME_BYTES}-byte frame"
            )
        if self.tail is not None and self.fixed_size + self.tail.bits // 8 > MAX_FRAME_BYTES:
            raise LayoutError(f"{self.name}: raw bytes overflow a {MAX_FRAME_BYTES}-byte frame")

    @cached_property
    def source_code(self) -> tuple[str, str]:
        """The generated Python source of the decode and encode functions."""
        return _decode_source(self), _encode_source(self)

    @cached_property
    def functions(self) -> tuple[FrameDecoder, FrameEncoder]:
        """The compiled (decode, encode) pair."""
        self.check()
        namespace = _namespace(self)
        decode_src, encode_src = self.source_code
        compile_source(decode_src, namespace, f"decode {self.name}")
        compile_source(encode_src, namespace, f"encode {self.name}")
        return namespace["decode"], namespace["encode"]

    def decode(self, data: bytes, allow_excess: bool = False) -> Message:
        """Decode one frame with this layout; see `veronte4x.codec.Codec.decode`."""
        return self.functions[0](data, allow_excess)

    def encode(self, message: Message) -> bytes:
        """Encode one message with this layout; see `veronte4x.codec.Codec.encode`."""
        return self.functions[1](message)


_F32 = {ByteOrder.LITTLE: struct.Struct("<f"), ByteOrder.BIG: struct.Struct(">f")}
_BITS = tuple(tuple(byte >> bit & 1 == 1 for bit in range(8)) for byte in range(256))
"""Each byte value's eight bits as booleans, bit 0 first."""


def _namespace(layout: FrameLayout) -> dict[str, Any]:
    name = layout.name

    def decode_error(reason: str, data: bytes, label: str | None = None) -> DecodeError:
        return DecodeError(name, reason, data, label)

    def encode_error(label: str, value: object, allowed: str) -> EncodeError:
        return EncodeError(name, label, value, allowed)

    namespace: dict[str, Any] = {
        "_cls": layout.message,
        "_new": object.__new__,
        "_BITS": _BITS,
        "_derr": decode_error,
        "_counted": counted,
        "_eerr": encode_error,
        "_from_bytes": int.from_bytes,
        "_f32": _F32[layout.byte_order].unpack_from,
        "_float_from_bits": float_from_bits,
        "_bits_from_float": bits_from_float,
        "_pack_f32": _F32[ByteOrder.LITTLE].pack,
        "_bytes": bytes,
        "_len": len,
        "_isinstance": isinstance,
        "_integer": integer,
        "_real": real,
        "_boolean": boolean,
        "_int": int,
        "_float": float,
        "_tuple": tuple,
        "_round": round,
        "_raw": (bytes, bytearray),
        "_OverflowError": OverflowError,
        "_ValueError": ValueError,
        "_KeyError": KeyError,
        "_TypeError": TypeError,
    }
    for attr, value in layout.implied:
        namespace[f"_implied_{attr}"] = value
    for f in layout.fields:
        if f.kind is FieldKind.MAPPED:
            # Indexed by the wire value: a tuple is cheaper to index than a dict to query.
            table: list[Any] = [None] * (1 << f.bits)
            for wire, value in f.mapping:
                table[wire] = value
            namespace[f"_from_wire_{f.attr}"] = tuple(table)
            namespace[f"_to_wire_{f.attr}"] = {value: wire for wire, value in f.mapping}
    plan = _struct_plan(layout)
    if plan is not None:
        namespace["_unpack"] = struct.Struct(plan[0]).unpack_from
        namespace["_pack"] = struct.Struct(plan[0]).pack
    for dc_field in _dataclass_fields(layout.message):
        namespace[f"_set_{dc_field.name}"] = _slot_setter(layout.message, dc_field.name)
    namespace["_builder"] = slot_builder(layout.message)
    return namespace


_PER_LAYOUT = re.compile(
    r"\b(_cls|_builder|_derr|_eerr|_f32|_unpack|_unpack_exact|_pack"
    r"|_implied_\w+|_from_wire_\w+|_to_wire_\w+|_set_\w+|_byte\d+)\b"
)
"""The names of a decoder's namespace that belong to its layout (the rest are shared)."""


def inline_decoder(
    layout: FrameLayout, suffix: str, indent: int
) -> tuple[list[str], dict[str, Any]]:
    """The body of a layout's decoder, to inline into a dispatching function.

    The body reads ``data``, ``n`` (its length) and ``excess`` and ends in ``return`` or
    ``raise``; the names of its layout get ``_<suffix>`` so that several bodies share one
    namespace.

    Returns:
        The body's lines, indented by ``indent`` spaces, and the names it needs.
    """
    layout.check()
    namespace = _namespace(layout)
    source = _decode_source(layout)
    # Skip the def line and ``n = _len(data)``: the dispatching function has ``n`` already.
    return _renamed(source.splitlines()[2:], namespace, suffix, indent)


def refuses(layout: FrameLayout, index: int, value: int) -> bool:
    """Whether the layout's decoder refuses every frame whose byte ``index`` is ``value``
    (a constant or a maximum it breaks), from the fields that lie in that byte alone."""
    fields = [p for p in layout.placed if _byte_index(layout, p) == index]
    if not fields or any(p.field.kind not in _TABLED for p in fields):
        return False
    return _byte_entry(fields, value) is None


def _renamed(
    lines: list[str], namespace: dict[str, Any], suffix: str, indent: int
) -> tuple[list[str], dict[str, Any]]:
    """Body lines and namespace with the layout's own names suffixed, the lines re-indented."""
    pad = " " * (indent - 4)
    body = [pad + _PER_LAYOUT.sub(rf"\1_{suffix}", line) for line in lines if line]
    names = {
        (f"{key}_{suffix}" if _PER_LAYOUT.fullmatch(key) else key): value
        for key, value in namespace.items()
    }
    return body, names


def optimistic_decoder(
    layout: FrameLayout,
    suffix: str,
    indent: int,
    otherwise: str,
    assume: frozenset[str] = frozenset(),
) -> tuple[list[str], dict[str, Any]] | None:
    """The body of an optimistic decoder, to inline like `inline_decoder`, or None.

    Only for layouts that one `struct` unpack reads whole (no raw-bytes tail). The body
    unpacks exactly the layout's bytes (a frame of another length raises `struct.error`)
    and, wherever the checked decoder would raise, runs ``otherwise`` instead, which must
    hand the frame to the checked decoder. Fields are decoded exactly as there, except the
    constants whose labels are in ``assume``: the caller has checked those.
    """
    if _struct_plan(layout) is None or layout.tail is not None:
        return None
    layout.check()
    namespace = _namespace(layout)
    namespace["_unpack_exact"] = struct.Struct(_skipping(layout, assume)[0]).unpack
    for index, (_, table) in _byte_tables(layout, assume).items():
        namespace[f"_byte{index}"] = table
    source = _decode_source(layout, otherwise=otherwise, assume=assume)
    return _renamed(source.splitlines()[1:], namespace, suffix, indent)


def _skipping(layout: FrameLayout, assume: frozenset[str]) -> tuple[str, list[str]]:
    """The `struct` plan of a layout with the bytes of the assumed constants as pad bytes."""
    plan = _struct_plan(layout)
    assert plan is not None
    fmt, names = plan
    skipped = {
        f"b{p.start // 8}"
        for p in layout.placed
        if p.field.kind is FieldKind.CONSTANT
        and p.field.label in assume
        and p.field.bits == 8
        and p.start % 8 == 0
    }
    codes = [("x" if name in skipped else code) for code, name in zip(fmt[1:], names, strict=True)]
    return fmt[0] + "".join(codes), [name for name in names if name not in skipped]


def _dataclass_fields(cls: type[Message]) -> tuple[dataclasses.Field[Any], ...]:
    """The fields of a message class (every concrete message is a dataclass)."""
    message_class: Any = cls
    return dataclasses.fields(message_class)


def _slot_setter(cls: type[Message], attr: str) -> Callable[[Message, Any], None]:
    """The slot descriptor's setter: it bypasses the frozen __setattr__, for decoding only."""
    descriptor = getattr(cls, attr, None)
    if not isinstance(descriptor, types.MemberDescriptorType):
        raise LayoutError(f"{cls.__name__}.{attr} is not a slot: declare the class slots=True")
    return descriptor.__set__


def _values(layout: FrameLayout) -> list[tuple[str, str]]:
    """(attribute, expression) for every dataclass field, in the dataclass's order."""
    by_attr: dict[str, list[tuple[int, str]]] = {}
    for number, f in enumerate(layout.fields):
        if f.attr is not None:
            by_attr.setdefault(f.attr, []).append((f.index or 0, f"f{number}"))
    implied = {attr for attr, _ in layout.implied}
    values = []
    for dc_field in _dataclass_fields(layout.message):
        attr = dc_field.name
        if attr in implied:
            values.append((attr, f"_implied_{attr}"))
        elif attr in by_attr:
            parts = sorted(by_attr[attr])
            if layout.fields_by_attr[attr].index is None:
                values.append((attr, parts[0][1]))
            else:
                values.append((attr, "(" + ", ".join(v for _, v in parts) + ",)"))
        else:
            raise LayoutError(f"{layout.name}: the layout does not fill field {attr!r}")
    return values


def _decode_source(
    layout: FrameLayout,
    otherwise: str | None = None,
    assume: frozenset[str] = frozenset(),
) -> str:
    """The source of a layout's decoder.

    With ``otherwise``, an optimistic decoder instead: no length check (its one `struct`
    unpack takes exactly the layout's bytes and raises `struct.error` otherwise), no check
    of the constants labelled in ``assume`` (the caller checked them) and, where the
    checked decoder raises, the statement ``otherwise``.
    """
    size = layout.fixed_size
    lines = ["def decode(data, excess):", "    n = _len(data)"]
    if otherwise is not None:
        lines = ["def decode(data, excess):"]
    elif layout.tail is None:
        lines += [
            f"    if n != {size}:",
            f"        if n < {size} or not excess:",
            f"            raise _derr(_counted(n, 'byte') + '; the layout has {size}', data)",
            f"        data = data[:{size}]",
        ]
    else:
        most = size + layout.tail.bits // 8
        lines += [
            f"    if n < {size} or (n > {most} and not excess):",
            f"        raise _derr(_counted(n, 'byte') + '; the layout has {size} to {most}', data)",
            f"    if n > {most}:",
            f"        data = data[:{most}]",
        ]
    body: list[str] = []
    plan = _struct_plan(layout)
    if plan is not None:
        # Every field lies within one byte or is an aligned float32: one unpack reads them all.
        fmt, names = plan if otherwise is None else _skipping(layout, assume)
        unpack = "_unpack" if otherwise is None else "_unpack_exact"
        unpacked = f"{', '.join(names)}, = " if names else ""  # no names: a length check
        lines.append(f"    {unpacked}{unpack}(data)  # struct {fmt!r}")
    flag_bytes = _flag_bytes(layout)
    for index, numbers in flag_bytes.items():
        byte = f"b{index}" if plan is not None else f"data[{index}]"
        body.append("    " + ", ".join(f"f{n}" for n in numbers) + f" = _BITS[{byte}]")
    grouped = {n for numbers in flag_bytes.values() for n in numbers}
    if otherwise is not None:
        for index, (numbers, _) in _byte_tables(layout, assume).items():
            targets = [
                f"f{n}" for n in numbers if layout.placed[n].field.kind is not FieldKind.CONSTANT
            ]
            body += [
                f"    t{index} = _byte{index}[b{index}]",
                f"    if t{index} is None:",
                f"        {otherwise}",
                *([f"    {', '.join(targets)}, = t{index}"] if targets else []),
            ]
            grouped.update(numbers)
    needs_word = False
    for number, p in enumerate(layout.placed):
        if p.field.kind is FieldKind.CONSTANT and p.field.label in assume:
            continue
        if number not in grouped:
            body += _decode_field(layout, number, p, plan is not None)
            needs_word |= _byte_index(layout, p) is None and p.field.kind is not FieldKind.PADDING
    needs_word &= plan is None
    if needs_word:  # without a tail, data has exactly `size` bytes here
        word = f"data[:{size}]" if layout.tail is not None else "data"
        lines.append(f"    w = _from_bytes({word}, '{layout.byte_order.value}')")
    lines += body
    if layout.tail is not None:
        lines.append(f"    f{len(layout.fields) - 1} = _bytes(data[{size}:])")
    # Fill the slots directly: a frozen dataclass's __init__ costs far more (docs/performance.md).
    if slot_builder(layout.message) is not None:
        lines.append("    o = _builder()")
        lines += [f"    o.{attr} = {value}" for attr, value in _values(layout)]
        lines.append("    o.__class__ = _cls")
    else:
        lines.append("    o = _new(_cls)")
        lines += [f"    _set_{attr}(o, {value})" for attr, value in _values(layout)]
    lines.append("    return o")
    if otherwise is not None:
        lines = [
            line[: len(line) - len(line.lstrip())] + otherwise
            if line.lstrip().startswith("raise _derr(")
            else line
            for line in lines
        ]
    return "\n".join(lines) + "\n"


def _byte_index(layout: FrameLayout, p: Placed) -> int | None:
    """The index of the one byte that holds a field, or None if it spans several."""
    low_byte, high_byte = p.shift // 8, (p.shift + p.field.bits - 1) // 8
    if low_byte != high_byte:
        return None
    return low_byte if layout.byte_order is ByteOrder.LITTLE else layout.fixed_size - 1 - low_byte


def _flag_bytes(layout: FrameLayout) -> dict[int, list[int]]:
    """Bytes made of eight one-bit flags: byte index to field numbers, bit 0 first."""
    by_byte: dict[int, dict[int, int]] = {}
    for number, p in enumerate(layout.placed):
        index = _byte_index(layout, p)
        if p.field.kind is FieldKind.BOOL and index is not None:
            by_byte.setdefault(index, {})[p.shift % 8] = number
    return {index: [bits[b] for b in range(8)] for index, bits in by_byte.items() if len(bits) == 8}


_TABLED = frozenset(
    {FieldKind.CONSTANT, FieldKind.BOOL, FieldKind.UNSIGNED, FieldKind.SIGNED, FieldKind.MAPPED}
)


def _byte_tables(
    layout: FrameLayout, assume: frozenset[str]
) -> dict[int, tuple[list[int], tuple[tuple[Any, ...] | None, ...]]]:
    """For an optimistic decoder: the bytes that hold several fields, each decoded by one
    lookup of the byte's value in a 256-entry table.

    An entry is the tuple of the byte's field values (constants left out) as the checked
    decoder computes them, or None where it would raise (a constant or a maximum not met,
    a wire value the mapping lacks). Only for layouts that one `struct` unpack reads, and
    not for bytes of eight flags (`_BITS` has them).

    Returns:
        Byte index to (the field numbers in the byte, the table).
    """
    if _struct_plan(layout) is None:
        return {}
    flags = _flag_bytes(layout)
    by_byte: dict[int, list[int]] = {}
    for number, p in enumerate(layout.placed):
        f = p.field
        if f.kind is FieldKind.PADDING or (f.kind is FieldKind.CONSTANT and f.label in assume):
            continue
        index = _byte_index(layout, p)
        if index is not None and index not in flags:
            by_byte.setdefault(index, []).append(number)
    tables = {}
    for index, numbers in by_byte.items():
        fields = [layout.placed[n] for n in numbers]
        if len(numbers) > 1 and all(p.field.kind in _TABLED for p in fields):
            tables[index] = (numbers, tuple(_byte_entry(fields, byte) for byte in range(256)))
    return tables


def _byte_entry(fields: list[Placed], byte: int) -> tuple[Any, ...] | None:
    """The values of the fields of one byte for one value of the byte, as `_decode_field`
    computes them, or None where it raises."""
    values: list[Any] = []
    for p in fields:
        f = p.field
        raw = byte >> p.shift % 8 & (1 << f.bits) - 1
        if f.kind is FieldKind.CONSTANT:
            if raw != f.value:
                return None
            continue
        if f.kind is FieldKind.BOOL:
            values.append(raw == 1)
            continue
        if f.kind is FieldKind.MAPPED:
            mapped = dict(f.mapping).get(raw)
            if mapped is None:
                return None
            values.append(mapped)
            continue
        value: float = raw
        if f.kind is FieldKind.SIGNED:
            value = raw - ((raw & 1 << f.bits - 1) << 1)
        if f.maximum is not None and value > f.maximum:
            return None
        if f.scale is not None:
            value = value * f.scale.factor + f.scale.offset
        values.append(value)
    return tuple(values)


def _struct_plan(layout: FrameLayout) -> tuple[str, list[str]] | None:
    """A struct format and its target names when every field is within a byte or an
    aligned float32; None otherwise. Bytes unpack to ``b<index>``, floats to ``f<field>``."""
    floats: dict[int, int] = {}
    for number, p in enumerate(layout.placed):
        if p.field.kind is FieldKind.FLOAT32 and p.shift % 8 == 0:
            floats[p.start // 8] = number
        elif _byte_index(layout, p) is None and p.field.kind is not FieldKind.PADDING:
            return None
    order = "<" if layout.byte_order is ByteOrder.LITTLE else ">"
    fmt, names, index = order, [], 0
    while index < layout.fixed_size:
        if index in floats:
            fmt, index = fmt + "f", index + 4
            names.append(f"f{floats[index - 4]}")
        else:
            fmt, index = fmt + "B", index + 1
            names.append(f"b{index - 1}")
    return fmt, names


def _raw(layout: FrameLayout, p: Placed, unpacked: bool = False) -> str:
    """The expression that extracts a field's wire bits, from one byte when it fits in one."""
    mask = (1 << p.field.bits) - 1
    index = _byte_index(layout, p)
    if index is not None:
        shift = p.shift % 8
        byte = f"b{index}" if unpacked else f"data[{index}]"
        source = f"({byte} >> {shift})" if shift else byte
        return source if p.field.bits + shift == 8 else f"{source} & {mask:#x}"
    return f"(w >> {p.shift}) & {mask:#x}" if p.shift else f"w & {mask:#x}"


def _decode_field(layout: FrameLayout, number: int, p: Placed, unpacked: bool) -> list[str]:
    f = p.field
    raw = _raw(layout, p, unpacked)
    var = f"f{number}"
    label = f.label
    if f.kind is FieldKind.PADDING:
        return []
    if f.kind is FieldKind.CONSTANT:
        return [
            f"    if {raw} != {f.value}:",
            f"        raise _derr('expected {f.value:#x}, got {{:#x}}'.format({raw}), data, "
            f"'{label}')",
        ]
    if f.kind is FieldKind.BOOL:
        return [f"    {var} = ({raw}) == 1"]
    if f.kind is FieldKind.MAPPED:
        wires = ", ".join(str(wire) for wire, _ in f.mapping)
        return [
            f"    {var} = _from_wire_{f.attr}[{raw}]",
            f"    if {var} is None:",
            f"        raise _derr('{{}} is none of {wires}'.format({raw}), data, '{label}')",
        ]
    if f.kind is FieldKind.FLOAT32:
        if p.shift % 8 == 0:
            offset = p.start // 8
            return [
                *([] if unpacked else [f"    {var} = _f32(data, {offset})[0]"]),
                f"    if {var} != {var}:",
                f"        {var} = _float_from_bits(_from_bytes(data[{offset}:{offset + 4}], "
                f"'{layout.byte_order.value}'))",
            ]
        return [f"    {var} = _float_from_bits({raw})"]
    lines = [f"    {var} = {raw}"]
    if f.kind is FieldKind.SIGNED:
        sign = 1 << (f.bits - 1)
        lines.append(f"    {var} -= ({var} & {sign:#x}) << 1")
    if f.maximum is not None:
        lines += [
            f"    if {var} > {f.maximum}:",
            f"        raise _derr('{{}} out of range 0..{f.maximum}'.format({var}), data, "
            f"'{label}')",
        ]
    if f.scale is not None:
        lines.append(f"    {var} = {var} * {f.scale.factor!r} + {f.scale.offset!r}")
    return lines


def _encode_source(layout: FrameLayout) -> str:
    """``encode_bits`` (any layout, NaN payloads exact) and ``encode``: a `struct.pack` of the
    whole frame where every field is within a byte or an aligned float32, else ``encode_bits``.
    """
    source = _encode_function(layout, "encode_bits", packed=False)
    if _struct_plan(layout) is None:
        return source + "encode = encode_bits\n"
    return source + "\n" + _encode_function(layout, "encode", packed=True)


def _encode_function(layout: FrameLayout, name: str, packed: bool) -> str:
    lines = [f"def {name}(m):"]
    for attr, value in layout.implied:
        test = f"m.{attr} is not None" if value is None else f"m.{attr} != _implied_{attr}"
        lines += [
            f"    if {test}:",
            f"        raise _eerr('{attr}', m.{attr}, {layout.implied_text or repr(value)!r})",
        ]
    seen_tuples: set[str] = set()
    body: list[str] = []
    constants: dict[str, int] = {}
    for number, p in enumerate(layout.placed):
        f = p.field
        index = _byte_index(layout, p)
        target, shift = (
            ("w", p.shift) if not packed or index is None else (f"b{index}", p.shift % 8)
        )
        if f.kind is FieldKind.CONSTANT:
            constants[target] = constants.get(target, 0) | f.value << shift
        elif f.kind is not FieldKind.PADDING:
            float_var = f"f{number}" if packed and f.kind is FieldKind.FLOAT32 else None
            body += _encode_field(f, shift, seen_tuples, layout, target, float_var)
    if packed:
        plan = _struct_plan(layout)
        assert plan is not None
        names = plan[1]
        lines += [f"    {b} = {constants.get(b, 0):#x}" for b in names if b.startswith("b")]
        result = "frame"
    else:
        lines.append(f"    w = {constants.get('w', 0):#x}")
        result = f"w.to_bytes({layout.fixed_size}, '{layout.byte_order.value}')"
    lines += body
    if layout.tail is not None:
        most = layout.tail.bits // 8
        lines += [
            f"    v = m.{layout.tail.attr}",
            f"    if not _isinstance(v, _raw) or _len(v) > {most}:",
            f"        raise _eerr('{layout.tail.attr}', v, 'bytes of length 0..{most}')",
        ]
        result += " + _bytes(v)"
    if packed and any(name.startswith("f") for name in names):
        lines += [
            "    try:",
            f"        frame = _pack({', '.join(names)})",
            "    except _OverflowError:  # a float beyond float32: encode_bits names it",
            "        return encode_bits(m)",
        ]
    elif packed:
        lines.append(f"    frame = _pack({', '.join(names)})")
    lines.append(f"    return {result}")
    return "\n".join(lines) + "\n"


def _encode_field(
    f: Field,
    shift: int,
    seen_tuples: set[str],
    layout: FrameLayout,
    target: str = "w",
    float_var: str | None = None,
) -> list[str]:
    """Read, check and place one field: OR it into `target` at `shift`, or for a float of a
    packed encoder keep it in `float_var` (a NaN goes to ``encode_bits`` for its exact bits)."""
    lines: list[str] = []
    assert f.attr is not None
    if f.index is None:
        lines.append(f"    v = m.{f.attr}")
    else:
        count = sum(1 for g in layout.fields if g.attr == f.attr)
        if f.attr not in seen_tuples:
            seen_tuples.add(f.attr)
            lines += [
                f"    t_{f.attr} = m.{f.attr}",
                f"    if not _isinstance(t_{f.attr}, _tuple) or _len(t_{f.attr}) != {count}:",
                f"        raise _eerr('{f.attr}', t_{f.attr}, 'a tuple of {count} values')",
            ]
        lines.append(f"    v = t_{f.attr}[{f.index}]")
    label = f.label
    place = f" << {shift}" if shift else ""
    if f.kind is FieldKind.MAPPED:
        allowed = "one of " + ", ".join(repr(value) for _, value in f.mapping)
        if all(value.__class__ is int for _, value in f.mapping):
            # Integers (a NumPy one too) by value; never a bool or a float equal to one.
            lines += [
                "    if v.__class__ is not _int:",
                "        i = _integer(v)",
                "        if i is None:",
                f"            raise _eerr('{label}', v, {allowed!r})",
                "        v = i",
            ]
        return [
            *lines,
            "    try:",
            f"        v = _to_wire_{f.attr}[v]",
            "    except (_KeyError, _TypeError):",
            f"        raise _eerr('{label}', v, {allowed!r}) from None",
            f"    {target} |= v{place}",
        ]
    if f.kind is FieldKind.BOOL:
        return [
            *lines,
            "    if v is not True and v is not False:",
            "        b = _boolean(v)",
            "        if b is None:",
            f"            raise _eerr('{label}', v, 'a bool')",
            "        v = b",
            f"    {target} |= v{place}",
        ]
    if f.kind is FieldKind.FLOAT32 and float_var is not None:
        return [
            *lines,
            "    if v.__class__ is not _float:",
            "        r = _real(v)",
            "        if r is None:",
            f"            raise _eerr('{label}', v, 'a float')",
            "        v = r",
            "    if v != v:",
            "        return encode_bits(m)",
            f"    {float_var} = v",
        ]
    if f.kind is FieldKind.FLOAT32:
        return [
            *lines,
            "    if v.__class__ is not _float:",
            "        r = _real(v)",
            "        if r is None:",
            f"            raise _eerr('{label}', v, 'a float')",
            "        v = r",
            "    try:",
            "        v = _from_bytes(_pack_f32(v), 'little') if v == v else _bits_from_float(v)",
            "    except _OverflowError:",
            f"        raise _eerr('{label}', v, 'a float within the float32 range') from None",
            f"    {target} |= v{place}",
        ]
    if f.kind is FieldKind.SIGNED:
        low, high = -(1 << (f.bits - 1)), (1 << (f.bits - 1)) - 1
    else:
        low, high = 0, (1 << f.bits) - 1
    if f.maximum is not None:
        high = f.maximum
    mask = (1 << f.bits) - 1
    if f.scale is None:
        lines += [
            "    if v.__class__ is not _int:",
            "        i = _integer(v)",
            "        if i is None:",
            f"            raise _eerr('{label}', v, 'an int in {low}..{high}')",
            "        v = i",
            f"    if not {low} <= v <= {high}:",
            f"        raise _eerr('{label}', v, 'an int in {low}..{high}')",
        ]
    else:
        s = f.scale
        lo_value, hi_value = sorted((low * s.factor + s.offset, high * s.factor + s.offset))
        allowed = f"a number in {lo_value!r}..{hi_value!r} (wire {low}..{high})"
        lines += [
            "    if v.__class__ is not _float:",
            "        r = _real(v)",
            "        if r is None:",
            f"            raise _eerr('{label}', v, {allowed!r})",
            "        v = r",
            "    try:",
            f"        r = _round((v - {s.offset!r}) / {s.factor!r})",
            "    except (_OverflowError, _ValueError):",
            f"        raise _eerr('{label}', v, {allowed!r}) from None",
            f"    if not {low} <= r <= {high}:",
            f"        raise _eerr('{label}', v, {allowed!r})",
            "    v = r",
        ]
    if f.kind is FieldKind.SIGNED:
        lines.append(f"    v &= {mask:#x}")
    lines.append(f"    {target} |= v{place}")
    return lines
