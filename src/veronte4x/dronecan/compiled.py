"""Fast paths generated from the type definitions, on a type's first use (`codec.TypeCodec.fast`).

For a struct of scalars at fixed bit offsets (NodeStatus, esc.Status, Temperature,
RestartNode, the empty GetNodeInfo request) this module writes Python functions that go
straight from a message to its frames, from a payload to a message, and from the data of
a single frame to a message. RawCommand gets one such function per item count.

How the code stays cheap:

- The fields are cut into byte-aligned groups, packed and unpacked by one
  `struct.Struct`. A whole uint8/16/32/64 field is a group of its own: under the v0 bit
  order its bytes are simply little-endian.
  Any other group is the little-endian int of its fields' bit runs, which `bit_runs`
  derives bit by bit from the rule, merging neighbours.
- RawCommand's int14 items go through two tables instead (value to its 14 stream bits and
  back), on one int read big-endian.
- float16 fields are rounded inline from their float32 bits (round half away from zero,
  as in `float16`); zeros, subnormals, out-of-range values, infinity and NaN call
  `float16_bits`.
- The tail byte of a single-frame transfer is packed with the payload; the CRC of a
  multi-frame transfer is `binascii.crc_hqx` seeded with the type's signature CRC, and
  the tail bytes come from tables.
- Decoded objects are built as an instance of a private class with the same slots as the
  public frozen dataclass, filled by plain attribute stores and then given the public class
  (``__class__`` assignment, which Python allows between classes of identical layout).
  The result is an ordinary instance of the public class, built about four times faster
  than through the frozen ``__init__``.

Anything unusual (a value out of range or of the wrong type, a payload of the wrong length)
raises inside the generated code; the caller then runs the generic `Serializer`, which
raises the precise error or saturates. Every other type (nested structs, arrays, unions)
gets its fast paths from `compiled_tree`.
"""

from __future__ import annotations

import struct
from binascii import crc_hqx
from collections.abc import Callable, Sequence
from typing import Any, NamedTuple

from veronte4x.codegen import compile_source, slot_builder
from veronte4x.dronecan.float16 import (
    FLOAT16_VALUES,
    float16_bits,
    float32_bits,
    float32_value,
    float64_bits,
    float64_value,
)
from veronte4x.dronecan.schema import Array, Scalar, Struct
from veronte4x.dronecan.serializer import enum_table
from veronte4x.dronecan.tail import MULTI_FRAME_TAILS

FramesFunction = Callable[[Any, int, int, int, Any], list[Any]]
PayloadEncoder = Callable[[Any], bytes]
PayloadDecoder = Callable[[bytes], Any]


class SlowPath(Exception):
    """Raised by generated code when the generic serializer must take over."""


ENCODE_FALLBACK = (SlowPath, TypeError, IndexError, OverflowError, struct.error)
"""What the generated encoders raise on values they do not handle (out of range, of
another type, of another length): the generic serializer then decides. Nothing else is
caught, so a fault in the generated code itself is not hidden."""


DECODE_FALLBACK = (SlowPath, struct.error)
"""What the generated decoders raise on a payload they do not decode (of another length,
a count or union tag out of range, a read past the end): the generic serializer then
decodes it or raises the precise `DecodeError`."""


class FastPaths(NamedTuple):
    """The generated functions of one type.

    Attributes:
        frames: ``frames(message, source, transfer_id, priority, destination)`` to frames.
        payload: ``payload(message)`` to payload bytes.
        decode: ``decode(payload)`` to a message.
        decode_frame: ``decode_frame(data)`` from the data of a single-frame transfer (tail
            byte included), or None where the type never fits one frame.
    """

    frames: FramesFunction
    payload: PayloadEncoder
    decode: PayloadDecoder
    decode_frame: PayloadDecoder | None


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


def bit_runs(offset: int, bits: int) -> list[tuple[int, int, int]]:
    """Runs ``(source bit, width, payload bit)`` of a scalar in the little-endian payload int."""
    runs: list[tuple[int, int, int]] = []
    for bit in range(bits):
        pos = stream_position(offset, bits, bit)
        dest = pos // 8 * 8 + 7 - pos % 8
        if runs and runs[-1][0] + runs[-1][1] == bit and runs[-1][2] + runs[-1][1] == dest:
            source, width, start = runs[-1]
            runs[-1] = (source, width + 1, start)
        else:
            runs.append((bit, 1, dest))
    return runs


def _pack_terms(var: str, t: Scalar, offset: int) -> list[str]:
    terms = []
    for source, width, dest in bit_runs(offset, t.bits):
        value = f"({var} >> {source})" if source else var
        if not (source + width == t.bits and t.kind != "int"):
            value = f"({value} & {(1 << width) - 1:#x})"
        terms.append(f"({value} << {dest})" if dest else value)
    return terms


def _unpack_expr(t: Scalar, offset: int, var: str = "x") -> str:
    parts = []
    for source, width, dest in bit_runs(offset, t.bits):
        mask = (1 << width) - 1
        value = f"({var} >> {dest}) & {mask:#x}" if dest else f"{var} & {mask:#x}"
        parts.append(f"(({value}) << {source})" if source else f"({value})")
    return " | ".join(parts)


def _tail_table(count: int) -> tuple[tuple[bytes, ...], ...]:
    """Tail bytes of a transfer of ``count`` frames, as 1-byte strings, per transfer id."""
    return tuple(tuple(bytes((t,)) for t in MULTI_FRAME_TAILS[tid][count]) for tid in range(32))


class _Source:
    """Collects the lines of one generated module and the objects its code refers to."""

    def __init__(self) -> None:
        self.lines: list[str] = []
        self.names: dict[str, Any] = {
            "SlowPath": SlowPath,
            "f16": float16_bits,
            "f32": float32_bits,
            "f64": float64_bits,
            "f64v": float64_value,
            "F16": FLOAT16_VALUES,
            "f32v": float32_value,
            "from_bytes": int.from_bytes,
            "crc_hqx": crc_hqx,
            "new": object.__new__,
            "tnew": tuple.__new__,
        }

    def name(self, prefix: str, value: Any) -> str:
        """Make ``value`` visible to the generated code under a fresh name."""
        number = len(self.names)
        while f"{prefix}{number}" in self.names:  # F16 is taken, for one
            number += 1
        key = f"{prefix}{number}"
        self.names[key] = value
        return key

    def build(self, title: str) -> dict[str, Any]:
        """Run the generated code once (see `veronte4x.codegen.compile_source`); return its
        namespace."""
        return compile_source("\n".join(self.lines), self.names, title)


def _slot_builder(cls: type) -> type:
    made = slot_builder(cls)
    assert made is not None, cls  # every DroneCAN class is a plain slotted dataclass
    return made


class Transport(NamedTuple):
    """What the frames functions need to know about the CAN ID of a type."""

    frame_class: type
    can_id_base: int
    service: bool
    crc_seed: int


def _emit_stream_frames(src: _Source, size: int, stream: str, transport: Transport) -> None:
    """Emit the end of a frames function: from a big-endian payload int to the frames."""
    frame = src.name("TransferFrame", transport.frame_class)
    can_id = f"prio << 24 | {transport.can_id_base:#x} | src"
    if size <= 7:
        data = f"(({stream}) << 8 | 0xC0 | tid).to_bytes({size + 1}, 'big')"
        src.lines.append(f"    return [tnew({frame}, ({can_id}, {data}))]")
        return
    src.lines.append(f"    p = ({stream}).to_bytes({size}, 'big')")
    _emit_multi_frame(src, size, frame, can_id, transport)


class _Group(NamedTuple):
    """Fields that together fill whole bytes, starting on a byte boundary."""

    start: int
    bits: int
    members: tuple[int, ...]


_STRUCT_CODES = {8: "B", 16: "H", 32: "I", 64: "Q"}


def _groups(scalars: Sequence[Scalar]) -> list[_Group]:
    """Cut a field list at every byte boundary; the last group is padded to a byte."""
    groups: list[_Group] = []
    start, offset, members = 0, 0, []
    for i, t in enumerate(scalars):
        members.append(i)
        offset += t.bits
        if offset % 8 == 0:
            groups.append(_Group(start, offset - start, tuple(members)))
            start, members = offset, []
    if members:
        groups.append(_Group(start, (offset - start + 7) // 8 * 8, tuple(members)))
    return groups


def _direct(group: _Group, scalars: Sequence[Scalar]) -> bool:
    """Whether a group is one field that ``struct`` packs as is (it also range-checks it)."""
    if len(group.members) != 1:
        return False
    t = scalars[group.members[0]]
    return t.bits == group.bits and t.bits in _STRUCT_CODES and t.kind in ("uint", "int", "float")


def _layout(src: _Source, scalars: Sequence[Scalar]) -> tuple[str, list[str], list[str]]:
    """The struct format of a flat struct, the packed value of each group and the checks.

    Direct groups are packed as is (``struct`` checks their range); the others are built
    from their fields' bit runs (see `bit_runs`, relative to the group's first byte)
    and get explicit checks, each an expression that is non-zero when the value is out of
    range (``v >> bits`` for an unsigned field).
    """
    codes, values, checks = ["<"], [], []
    # A bool is an int to Python and to struct, but not a value of an int or float field:
    # the generic serializer refuses it, so the generated code must too. Any other integer
    # (a NumPy scalar: its arithmetic wraps at its own width) goes to the generic
    # serializer, which takes it by `veronte4x.errors.integer`.
    checks += [
        f"v{i}.__class__ is bool"
        if t.kind == "float"
        else f"(v{i}.__class__ is bool or not isinstance(v{i}, int))"
        for i, t in enumerate(scalars)
        if t.kind in ("uint", "int", "float")
    ]
    for group in _groups(scalars):
        if _direct(group, scalars):
            t = scalars[group.members[0]]
            code = _STRUCT_CODES[t.bits]
            codes.append(code.lower() if t.kind == "int" else code)
            values.append(f"v{group.members[0]}")
            continue
        terms = []
        for i in group.members:
            t = scalars[i]
            if t.kind == "uint":
                checks.append(f"v{i} >> {t.bits}")
            elif t.kind == "int":
                checks.append(f"(v{i} + {1 << (t.bits - 1)}) >> {t.bits}")
            elif t.kind == "bool":
                checks.append(f"(v{i} is not True and v{i} is not False)")
            if t.kind != "void":
                offset = sum(scalars[j].bits for j in range(group.members[0], i))
                terms.extend(_pack_terms(f"v{i}", t, offset))
        value = " | ".join(terms) or "0"
        size = group.bits // 8
        if group.bits in _STRUCT_CODES:
            codes.append(_STRUCT_CODES[group.bits])
            values.append(value)
        else:
            codes.append(f"{size}s")
            values.append(f"({value}).to_bytes({size}, 'little')")
    return "".join(codes), values, checks


def _floats(src: _Source, scalars: Sequence[Scalar], indent: str = "    ") -> None:
    """Emit the conversion of every float field v<i> to its raw bits, in place."""
    halves = [i for i, t in enumerate(scalars) if t.kind == "float" and t.bits == 16]
    for i, t in enumerate(scalars):
        if t.kind == "float" and t.bits in (32, 64):
            src.lines.append(f"{indent}v{i} = f{t.bits}(v{i})")
    if not halves:
        return
    pack = src.name("F", struct.Struct(f"<{len(halves)}f"))
    unpack = src.name("U", struct.Struct(f"<{len(halves)}I"))
    names = "".join(f"a{i}, " for i in halves)
    values = ", ".join(f"v{i}" for i in halves)
    # Beyond the float32 range struct refuses: every half then goes through float16_bits.
    src.lines += [
        f"{indent}try:",
        f"{indent}    {names}= {unpack}.unpack({pack}.pack({values}))",
        f"{indent}except OverflowError:",
        f"{indent}    {' = '.join(f'a{i}' for i in halves)} = 0x7F800000",
    ]
    for i in halves:
        src.lines += [
            f"{indent}m{i} = a{i} & 0x7FFFFFFF",
            f"{indent}v{i} = ({HALF_EXPR.format(a=f'a{i}', m=f'm{i}', v=f'v{i}')})",
        ]


HALF_EXPR = (
    "({m} - 0x37FFF000) >> 13 | ({a} >> 16) & 0x8000 if 0x38800000 <= {m} < 0x477FF000"
    " else ({a} >> 16) & 0x8000 if {m} < 0x33000000 else f16({v})"
)
"""The float16 bits of float ``{v}`` from its float32 bits ``{a}`` (``{m}`` without the sign):
rounded inline in the normal range and to a signed zero far below it, `float16_bits`
elsewhere (subnormals, overflow, infinity, NaN)."""


def _transport_checks(transport: Transport) -> list[str]:
    """Conditions that are true when a transport argument is out of range."""
    checks = ["src >> 7", "tid >> 5", "prio >> 5", "not src"]
    checks += ["dst >> 7", "not dst"] if transport.service else ["dst is not None"]
    return checks


def _emit_struct_frames(
    src: _Source, size: int, layout: str, values: list[str], transport: Transport
) -> None:
    """Emit the end of a frames function packing the groups with ``struct``."""
    frame = src.name("TransferFrame", transport.frame_class)
    can_id = f"prio << 24 | {transport.can_id_base:#x} | src"
    if transport.service:
        can_id += " | dst << 8"
    if size <= 7:
        packer = src.name("S", struct.Struct(layout + "B"))
        data = f"{packer}.pack({''.join(v + ', ' for v in values)}0xC0 | tid)"
        src.lines.append(f"    return [tnew({frame}, ({can_id}, {data}))]")
        return
    packer = src.name("S", struct.Struct(layout))
    src.lines.append(f"    p = {packer}.pack({', '.join(values)})")
    _emit_multi_frame(src, size, frame, can_id, transport)


def _emit_multi_frame(
    src: _Source, size: int, frame: str, can_id: str, transport: Transport
) -> None:
    """Emit the end of a frames function that splits payload ``p`` into a multi-frame
    transfer: the transfer CRC first, 7 bytes a frame, each with its tail byte (spec 4.1)."""
    count = (size + 2 + 6) // 7
    tails = src.name("T", _tail_table(count))
    src.lines += [
        f"    b = crc_hqx(p, {transport.crc_seed:#x}).to_bytes(2, 'little') + p",
        f"    c = {can_id}",
        f"    t = {tails}[tid]",
    ]
    items = [f"tnew({frame}, (c, b[{7 * i}:{7 * i + 7}] + t[{i}]))" for i in range(count - 1)]
    items.append(f"tnew({frame}, (c, b[{7 * (count - 1)}:] + t[{count - 1}]))")
    src.lines.append(f"    return [{', '.join(items)}]")


def compile_struct(schema: Struct, transport: Transport) -> FastPaths | None:
    """Generate the fast paths of a struct of scalars, or None if it is not flat.

    Fields are packed with one `Struct` whose items are the byte-aligned
    groups of `_groups`: a whole uint8/16/32/64 field as is, anything else as the
    little-endian int of its bit runs.
    """
    fields = [f for f in schema.fields if isinstance(f.type, Scalar)]
    if len(fields) != len(schema.fields):
        return None
    scalars = [f.type for f in fields if isinstance(f.type, Scalar)]
    unpack = " ".join(f"v{i} = m.{f.name};" for i, f in enumerate(fields) if f.name) or "pass"
    size = (sum(t.bits for t in scalars) + 7) // 8
    src = _Source()
    layout, values, checks = _layout(src, scalars)
    for function, extra in (
        ("frames(m, src, tid, prio, dst)", _transport_checks(transport)),
        ("payload(m)", []),
    ):
        src.lines += [f"def {function}:", f"    {unpack}"]
        if checks or extra:
            src.lines += [f"    if {' or '.join(checks + extra)}:", "        raise SlowPath"]
        _floats(src, scalars)
        if extra:
            _emit_struct_frames(src, size, layout, values, transport)
        else:
            packer = src.name("S", struct.Struct(layout))
            src.lines.append(f"    return {packer}.pack({', '.join(values)})")
    builder = src.name("B", _slot_builder(schema.cls))
    cls = src.name("C", schema.cls)
    groups = _groups(scalars)
    for function, length, pad in (("decode", size, ""), ("decode_frame", size + 1, "x")):
        unpacker = src.name("S", struct.Struct(layout + pad))
        names = "".join(f"g{k}, " for k in range(len(groups)))
        src.lines.append(f"def {function}(buf):")
        if function == "decode":  # decode_frame relies on struct's own length check
            src.lines += [f"    if len(buf) != {length}:", "        raise SlowPath"]
        src.lines.append(
            f"    {names}= {unpacker}.unpack(buf)" if groups else f"    {unpacker}.unpack(buf)"
        )
        src.lines.append(f"    o = {builder}()")
        for k, group in enumerate(groups):
            if not _direct(group, scalars) and group.bits not in _STRUCT_CODES:
                src.lines.append(f"    g{k} = from_bytes(g{k}, 'little')")
            for i in group.members:
                t, f = scalars[i], fields[i]
                if not f.name:
                    continue
                if _direct(group, scalars):
                    raw = f"g{k}"
                else:
                    offset = sum(scalars[j].bits for j in range(group.members[0], i))
                    raw = _unpack_expr(t, offset, f"g{k}")
                    if t.kind == "int":
                        sign = 1 << (t.bits - 1)
                        raw = f"(({raw}) ^ {sign:#x}) - {sign:#x}"
                if t.kind == "float":
                    raw = f"F16[{raw}]" if t.bits == 16 else f"f{t.bits}v({raw})"
                elif t.kind == "bool":
                    raw = f"({raw}) != 0"
                elif f.enum is not None:
                    raw = f"{src.name('E', enum_table(f.enum, t.bits))}[{raw}]"
                src.lines.append(f"    o.{f.name} = {raw}")
        src.lines += [f"    o.__class__ = {cls}", "    return o"]
    code = src.build(f"fast paths {schema.name}")
    return FastPaths(
        code["frames"], code["payload"], code["decode"], code["decode_frame"] if size <= 7 else None
    )


def compile_int_array(schema: Struct, transport: Transport) -> FastPaths | None:
    """Fast paths for a struct whose only field is a TAO array of 9..16-bit ints (RawCommand).

    The items are packed on a big-endian int through two tables: item value to its stream
    bits (low byte first, then the top bits) and stream bits to item value. One function
    per item count; the item count of a payload length follows from the TAO rule (items
    are read while 8 bits or more remain).
    """
    if len(schema.fields) != 1 or not isinstance(schema.fields[0].type, Array):
        return None
    name, array = schema.fields[0].name, schema.fields[0].type
    item = array.item
    if not isinstance(item, Scalar) or item.kind != "int" or not 8 < item.bits <= 16:
        return None
    if not array.dynamic:
        return None
    bits, rest = item.bits, item.bits - 8
    low = item.low
    to_stream = tuple(
        ((v & 0xFF) << rest) | ((v & ((1 << bits) - 1)) >> 8) for v in range(low, item.high + 1)
    )
    from_stream = [0] * (1 << bits)
    for v in range(low, item.high + 1):
        from_stream[((v & 0xFF) << rest) | ((v & ((1 << bits) - 1)) >> 8)] = v
    src = _Source()
    enc, dec = src.name("S", to_stream), src.name("D", tuple(from_stream))
    builder, cls = src.name("B", _slot_builder(schema.cls)), src.name("C", schema.cls)
    offset = -low
    sizes = []
    for count in range(array.max_size + 1):
        size = (count * bits + 7) // 8
        sizes.append(size)
        pad = 8 * size - count * bits
        names = "".join(f"v{i}, " for i in range(count))
        checks = [
            f"v{i}.__class__ is bool or not isinstance(v{i}, int) or (v{i} + {offset}) >> {bits}"
            for i in range(count)
        ]
        shifts = [(count - 1 - i) * bits + pad for i in range(count)]
        stream = " | ".join(f"{enc}[v{i} + {offset}] << {shifts[i]}" for i in range(count)) or "0"
        for head, extra in (
            (f"frames{count}(m, src, tid, prio, dst)", _transport_checks(transport)),
            (f"payload{count}(m)", []),
        ):
            src.lines += [f"def {head}:", f"    {names}= m" if count else "    pass"]
            if checks or extra:
                src.lines += [f"    if {' or '.join(checks + extra)}:", "        raise SlowPath"]
            if extra:
                _emit_stream_frames(src, size, stream, transport)
            else:
                src.lines.append(f"    return ({stream}).to_bytes({size}, 'big')")
        mask = (1 << bits) - 1
        items = "".join(f"{dec}[(x >> {shift}) & {mask:#x}], " for shift in shifts)
        for function, drop in ((f"decode{size}", ""), (f"decode_frame{size + 1}", " >> 8")):
            src.lines += [
                f"def {function}(buf):",
                f"    x = from_bytes(buf, 'big'){drop}",
                f"    o = {builder}()",
                f"    o.{name} = ({items})",
                f"    o.__class__ = {cls}",
                "    return o",
            ]
    longest = sizes[-1] + 2
    payloads = [f"decode{n}" if n in sizes else "bad" for n in range(longest)]
    frames = [f"decode_frame{n}" if n - 1 in sizes and n <= 8 else "bad" for n in range(longest)]
    src.lines += [
        "def bad(buf):",
        "    raise SlowPath",
        f"FR = ({''.join(f'frames{n}, ' for n in range(array.max_size + 1))})",
        f"PL = ({''.join(f'payload{n}, ' for n in range(array.max_size + 1))})",
        f"DP = ({', '.join(payloads)})",
        f"DF = ({', '.join(frames)})",
        "def frames(m, src, tid, prio, dst):",
        f"    c = m.{name}",
        "    if c.__class__ is not tuple:",  # the generic serializer takes tuples only
        "        raise SlowPath",
        "    return FR[len(c)](c, src, tid, prio, dst)",
        "def payload(m):",
        f"    c = m.{name}",
        "    if c.__class__ is not tuple:",
        "        raise SlowPath",
        "    return PL[len(c)](c)",
        "def decode(buf):",
        f"    return (DP[len(buf)] if len(buf) < {longest} else bad)(buf)",
        "def decode_frame(buf):",
        f"    return (DF[len(buf)] if len(buf) < {longest} else bad)(buf)",
    ]
    code = src.build(f"fast paths {schema.name}")
    return FastPaths(code["frames"], code["payload"], code["decode"], code["decode_frame"])
