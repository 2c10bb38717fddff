"""Fast paths generated from the type definitions, on a type's first use (`codec.TypeCodec.fast`).

For a struct of scalars at fixed bit offsets (NodeStatus, esc.Status, Temperature,
RestartNode, the empty GetNodeInfo request) this module writes Python functions that go
straight from a message to its frames, from a payload to a message, and from the data of
a single frame to a message. RawCommand gets one such function per item count.

How the code stays cheap:

- The fields are cut into byte-aligned groups, packed and unpacked by one
  `struct.Struct`. A whole uint8/16/32/64 or float field is a group of its own: under the
  v0 bit order its bytes are simply little-endian. Any other group is the little-endian
  int of its fields' bit runs. How each scalar is read, checked and written (float16
  rounded inline from its float32 bits) is `scalar_code`'s, shared with `compiled_tree`.
- RawCommand's int14 items go through two tables instead (value to its 14 stream bits and
  back), on one int read big-endian.
- The tail byte of a single-frame transfer is packed with the payload; the CRC of a
  multi-frame transfer is `binascii.crc_hqx` seeded with the type's signature CRC, and
  the tail bytes come from tables.
- Decoded objects are built as an instance of a private class with the same slots as the
  public frozen dataclass, filled by plain attribute stores and then given the public class
  (``__class__`` assignment, which Python allows between classes of identical layout).
  The result is an ordinary instance of the public class, built about four times faster
  than through the frozen ``__init__``. A frozen type of at most one payload byte (an empty
  request, ArmingStatus) builds none: its decoders return one of its messages made in
  advance (`_shared_values`).

Anything unusual (a value out of range or of the wrong type, a payload of the wrong length)
raises inside the generated code; the caller then runs the generic `Serializer`, which
raises the precise error or saturates. Every other type (nested structs, arrays, unions)
gets its fast paths from `compiled_tree`.
"""

from __future__ import annotations

import struct
from collections.abc import Callable
from typing import Any, NamedTuple

from veronte4x.codegen import attribute, compile_source, slot_builder
from veronte4x.dronecan.can_id import TransferKind
from veronte4x.dronecan.fast_base import NAMES, SlowPath, int_array_tables, tail_table
from veronte4x.dronecan.frame import TransferFrame
from veronte4x.dronecan.scalar_code import pack_scalars, unpack_scalars
from veronte4x.dronecan.schema import Array, DataType, Scalar, Struct, StructField
from veronte4x.dronecan.tail import SINGLE_FRAME

FramesFunction = Callable[[Any, int, int, int, Any], list[Any]]
PayloadEncoder = Callable[[Any], bytes]
PayloadDecoder = Callable[[bytes], Any]


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


class _Source:
    """Collects the lines of one generated module and the objects its code refers to.

    Each object named also gets the expression that makes it again (`expressions`), so
    that the same code can be written out as a module of its own (`module_lines`).
    """

    def __init__(self) -> None:
        self.lines: list[str] = []
        self.single = False
        """Whether the code has a ``decode_frame`` (a payload of the type may fit a frame)."""
        self.slow = False
        """Whether the type is nested too deep for generated code (`compiled_tree.MAX_BLOCKS`):
        its fast paths are all `slow`."""
        self.names: dict[str, Any] = dict(NAMES)
        self.expressions: dict[str, str | None] = {}
        """Each name given to an object, to the expression that makes it: a `struct.Struct`
        as ``Struct(format)``; a class or enum None (imported by the module's writer)."""

    def name(self, prefix: str, value: Any, expression: str | None = None) -> str:
        """Make ``value`` visible to the generated code under a fresh name; ``expression``
        makes it again (the source of a struct is known, and a class needs none)."""
        number = len(self.names)
        while f"{prefix}{number}" in self.names:  # F16 is taken, for one
            number += 1
        key = f"{prefix}{number}"
        if expression is None and isinstance(value, struct.Struct):
            expression = f"Struct({value.format!r})"
        if expression is None and not isinstance(value, type):
            raise ValueError(f"generated code names {value!r} without its expression")
        self.names[key] = value
        self.expressions[key] = expression
        return key

    def cls(self, value: type) -> str:
        """Name a class (or enum) for the generated code."""
        return self.name("C", value)

    def builder(self, cls: type) -> str:
        """Name the slot builder of ``cls`` (see `veronte4x.codegen.slot_builder`)."""
        return self.name("B", _slot_builder(cls), f"slot_builder({self.cls(cls)})")

    def module_lines(self, class_name: Callable[[type], str]) -> list[str]:
        """The assignments that make every named object, in the order they were named,
        then the code: a module body (the imports are the writer's). ``class_name`` gives
        the name a class or enum is imported under."""
        made = [
            f"{key} = {class_name(self.names[key]) if expression is None else expression}"
            for key, expression in self.expressions.items()
        ]
        return [*made, "", "", *self.lines]

    def build(self, title: str) -> dict[str, Any]:
        """Run the generated code once (see `veronte4x.codegen.compile_source`); return its
        namespace."""
        return compile_source("\n".join(self.lines), self.names, title)


def _shared(schema: Struct, size: int) -> bool:
    """Whether a type is frozen and of at most one payload byte: its messages can be
    shared, made once each (`veronte4x.dronecan.fast_base.shared_table`) and returned by
    its decoders instead of new ones."""
    params = getattr(schema.cls, "__dataclass_params__", None)
    return size <= 1 and params is not None and params.frozen


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


def can_id_base(data_type: DataType) -> int:
    """The CAN ID bits fixed by the type: type id, request bit and service bit."""
    if data_type.kind is TransferKind.MESSAGE:
        return data_type.data_type_id << 8
    request = 0x8000 if data_type.kind is TransferKind.REQUEST else 0
    return data_type.data_type_id << 16 | request | 0x80


def transport_of(data_type: DataType) -> Transport:
    """What the frames function of a type needs to know about its CAN ID."""
    return Transport(
        TransferFrame,
        can_id_base(data_type),
        data_type.kind is not TransferKind.MESSAGE,
        data_type.crc_seed,
    )


def _emit_stream_frames(src: _Source, size: int, stream: str, transport: Transport) -> None:
    """Emit the end of a frames function: from a big-endian payload int to the frames."""
    frame = src.cls(transport.frame_class)
    can_id = f"prio << 24 | {transport.can_id_base:#x} | src"
    if size <= 7:
        data = f"(({stream}) << 8 | 0x{SINGLE_FRAME:X} | tid).to_bytes({size + 1}, 'big')"
        src.lines.append(f"    return [tnew({frame}, ({can_id}, {data}))]")
        return
    src.lines.append(f"    p = ({stream}).to_bytes({size}, 'big')")
    _emit_multi_frame(src, size, frame, can_id, transport)


def _transport_checks(transport: Transport) -> list[str]:
    """Conditions that are true when a transport argument is out of range."""
    checks = ["src >> 7", "tid >> 5", "prio >> 5", "not src"]
    checks += ["dst >> 7", "not dst"] if transport.service else ["dst is not None"]
    return checks


def _emit_struct_frames(
    src: _Source, size: int, layout: str, values: list[str], transport: Transport
) -> None:
    """Emit the end of a frames function packing the groups with ``struct``."""
    frame = src.cls(transport.frame_class)
    can_id = f"prio << 24 | {transport.can_id_base:#x} | src"
    if transport.service:
        can_id += " | dst << 8"
    if size <= 7:
        packer = src.name("S", struct.Struct(layout + "B"))
        data = f"{packer}.pack({''.join(v + ', ' for v in values)}0x{SINGLE_FRAME:X} | tid)"
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
    tails = src.name("T", tail_table(count), f"tail_table({count})")
    src.lines += [
        f"    b = crc_hqx(p, {transport.crc_seed:#x}).to_bytes(2, 'little') + p",
        f"    c = {can_id}",
        f"    t = {tails}[tid]",
    ]
    items = [f"tnew({frame}, (c, b[{7 * i}:{7 * i + 7}] + t[{i}]))" for i in range(count - 1)]
    items.append(f"tnew({frame}, (c, b[{7 * (count - 1)}:] + t[{count - 1}]))")
    src.lines.append(f"    return [{', '.join(items)}]")


def _emit_decoders(
    src: _Source, schema: Struct, fields: list[StructField], size: int, prefix: str = ""
) -> None:
    """Emit ``decode`` and ``decode_frame`` of a flat struct (names after ``prefix``): one
    `struct` unpack, then the message built by slot stores."""
    builder = src.builder(schema.cls)
    cls = src.cls(schema.cls)
    unpacking = unpack_scalars(
        [f.type for f in fields if isinstance(f.type, Scalar)],
        [f"o.{attribute(f.name)}" if f.name else None for f in fields],
        [f.enum for f in fields],
        src.name,
    )
    for function, length, pad in (("decode", size, ""), ("decode_frame", size + 1, "x")):
        unpacker = src.name("S", struct.Struct(unpacking.format + pad))
        src.lines.append(f"def {prefix}{function}(buf):")
        if function == "decode":  # decode_frame relies on struct's own length check
            src.lines += [f"    if len(buf) != {length}:", "        raise SlowPath"]
        src.lines += [
            f"    {unpacking.targets}= {unpacker}.unpack(buf)"
            if unpacking.targets
            else f"    {unpacker}.unpack(buf)",
            f"    o = {builder}()",
            *(f"    {line}" for line in unpacking.lines),
            f"    o.__class__ = {cls}",
            "    return o",
        ]


def _emit_shared_decoders(
    src: _Source, schema: Struct, fields: list[StructField], size: int
) -> None:
    """Emit ``decode`` and ``decode_frame`` of a type of at most one payload byte (see
    `_shared`): the message from table ``M``, made once by the struct's own decoder."""
    _emit_decoders(src, schema, fields, size, "_")
    table = "M"
    src.lines.append(f"{table} = shared_table(_decode, {size})")
    for function, pad in (("decode", ""), ("decode_frame", "x")):
        unpacker = src.name("S", struct.Struct("<" + "B" * size + pad))  # checks the length
        src.lines.append(f"def {function}(buf):")
        if size == 0:
            src.lines += [f"    {unpacker}.unpack(buf)", f"    return {table}[0]"]
        else:
            src.lines += [
                f"    v, = {unpacker}.unpack(buf)",
                f"    o = {table}[v]",
                "    if o is None:",
                "        raise SlowPath",
                "    return o",
            ]


def struct_source(schema: Struct, transport: Transport) -> _Source | None:
    """Generate the fast paths of a struct of scalars, or None if it is not flat.

    Fields are packed and unpacked with one `Struct` whose items are byte-aligned groups
    (see `veronte4x.dronecan.scalar_code.pack_scalars` and ``unpack_scalars``).
    """
    fields = [f for f in schema.fields if isinstance(f.type, Scalar)]
    if len(fields) != len(schema.fields):
        return None
    scalars = [f.type for f in fields if isinstance(f.type, Scalar)]
    unpack = " ".join(f"v{i} = m.{attribute(f.name)};" for i, f in enumerate(fields) if f.name)
    unpack = unpack or "pass"
    size = (sum(t.bits for t in scalars) + 7) // 8
    src = _Source()
    packing = pack_scalars(scalars, src.name)
    for function, extra in (
        ("frames(m, src, tid, prio, dst)", _transport_checks(transport)),
        ("payload(m)", []),
    ):
        src.lines += [f"def {function}:", f"    {unpack}"]
        checks = packing.checks + extra
        if checks:
            src.lines += [f"    if {' or '.join(checks)}:", "        raise SlowPath"]
        src.lines += [f"    {line}" for line in packing.floats]
        if extra:
            _emit_struct_frames(src, size, packing.format, packing.values, transport)
        else:
            packer = src.name("S", struct.Struct(packing.format))
            src.lines.append(f"    return {packer}.pack({', '.join(packing.values)})")
    if _shared(schema, size):
        _emit_shared_decoders(src, schema, fields, size)
    else:
        _emit_decoders(src, schema, fields, size)
    src.single = size <= 7
    return src


def int_array_source(schema: Struct, transport: Transport) -> _Source | None:
    """Fast paths for a struct whose only field is a TAO array of 9..16-bit ints (RawCommand).

    The items are packed on a big-endian int through two tables: item value to its stream
    bits (low byte first, then the top bits) and stream bits to item value. One function
    per item count; the item count of a payload length follows from the TAO rule (items
    are read while 8 bits or more remain).
    """
    if len(schema.fields) != 1 or not isinstance(schema.fields[0].type, Array):
        return None
    name, array = attribute(schema.fields[0].name), schema.fields[0].type
    item = array.item
    if not isinstance(item, Scalar) or item.kind != "int" or not 8 < item.bits <= 16:
        return None
    if not array.dynamic:
        return None
    bits = item.bits
    low = item.low
    to_stream, from_stream = int_array_tables(low, item.high)
    src = _Source()
    tables = f"int_array_tables({low}, {item.high})"
    enc = src.name("S", to_stream, f"{tables}[0]")
    dec = src.name("D", from_stream, f"{tables}[1]")
    builder, cls = src.builder(schema.cls), src.cls(schema.cls)
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
    src.single = True
    return src


def fast_source(schema: Struct, transport: Transport) -> _Source:
    """The source of the fast paths of any top-level type: `struct_source` for a flat
    struct, `int_array_source` for RawCommand, else
    `veronte4x.dronecan.compiled_tree.tree_source`."""
    from veronte4x.dronecan.compiled_tree import tree_source  # it builds on this module

    return (
        struct_source(schema, transport)
        or int_array_source(schema, transport)
        or tree_source(schema, transport)
    )


def compile_fast(schema: Struct, transport: Transport) -> FastPaths:
    """Compile the fast paths of any top-level type at run time (`fast_source`)."""
    src = fast_source(schema, transport)
    if src.slow:
        return FastPaths(slow, slow, slow, None)
    code = src.build(f"fast paths {schema.name}")
    return FastPaths(
        code["frames"],
        code["payload"],
        code["decode"],
        code["decode_frame"] if src.single else None,
    )


def slow(*args: object) -> Any:
    """The fast path of a type nested too deep for generated code: the generic one."""
    raise SlowPath
