"""Fast paths generated at import time from the type definitions.

For a struct of scalars at fixed bit offsets (NodeStatus, esc.Status, Temperature,
RestartNode, the empty GetNodeInfo request) this module writes Python functions that go
straight from a message to its frames, from a payload to a message, and from the data of
a single frame to a message. RawCommand gets one such function per item count.

How the code stays cheap:

- The payload is built as one int read little-endian. Under the v0 bit order
  (notes/dronecan-wire.md "Serialization rules") a byte-aligned field wider than a byte
  then lands unchanged, and any other field splits into a few runs of bits;
  :func:`bit_runs` derives them bit by bit from the rule and merges neighbours.
- RawCommand's int14 items go through two tables instead (value to its 14 stream bits and
  back), on an int read big-endian.
- float16 fields are rounded inline from their float32 bits (round half away from zero,
  as in :mod:`~veronte4x.dronecan.float16`); zeros, subnormals, out-of-range values,
  infinity and NaN call :func:`~veronte4x.dronecan.float16.float16_bits`.
- The tail byte of a single-frame transfer is part of the same int; the CRC is
  :func:`binascii.crc_hqx` seeded with the type's signature CRC.
- Decoded objects are built as an instance of a private class with the same slots as the
  public frozen dataclass, filled by plain attribute stores and then given the public class
  (``__class__`` assignment, which Python allows between classes of identical layout).
  The result is an ordinary instance of the public class, built twice as fast as through
  the frozen ``__init__``.

Anything unusual (a value out of range or of the wrong type, a payload of the wrong length)
raises inside the generated code; the caller then runs the generic
:class:`~veronte4x.dronecan.serializer.Serializer`, which raises the precise error or
saturates.
"""

from __future__ import annotations

import struct
from binascii import crc_hqx
from collections.abc import Callable, Sequence
from typing import Any, NamedTuple

from veronte4x.dronecan.float16 import FLOAT16_VALUES, float16_bits, float32_bits, float32_value
from veronte4x.dronecan.schema import Array, Scalar, Struct
from veronte4x.dronecan.serializer import enum_table
from veronte4x.dronecan.tail import MULTI_FRAME_TAILS

FramesFunction = Callable[[Any, int, int, int, Any], list[Any]]
PayloadEncoder = Callable[[Any], bytes]
Decoder = Callable[[bytes], Any]


class SlowPath(Exception):
    """Raised by generated code when the generic serializer must take over."""


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
    decode: Decoder
    decode_frame: Decoder | None


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


def _unpack_expr(t: Scalar, offset: int) -> str:
    parts = []
    for source, width, dest in bit_runs(offset, t.bits):
        value = f"(x >> {dest}) & {(1 << width) - 1:#x}" if dest else f"x & {(1 << width) - 1:#x}"
        parts.append(f"(({value}) << {source})" if source else f"({value})")
    return " | ".join(parts)


def _tail_table(count: int) -> tuple[tuple[bytes, ...], ...]:
    """Tail bytes of a transfer of ``count`` frames, as 1-byte strings, per transfer id."""
    if count == 1:
        return tuple((bytes((0xC0 | tid,)),) for tid in range(32))
    return tuple(tuple(bytes((t,)) for t in MULTI_FRAME_TAILS[tid][count]) for tid in range(32))


class _Source:
    """Collects the lines of one generated module and the objects its code refers to."""

    def __init__(self) -> None:
        self.lines: list[str] = []
        self.names: dict[str, Any] = {
            "SlowPath": SlowPath,
            "f16": float16_bits,
            "f32": float32_bits,
            "F16": FLOAT16_VALUES,
            "f32v": float32_value,
            "from_bytes": int.from_bytes,
            "crc_hqx": crc_hqx,
            "new": object.__new__,
            "tnew": tuple.__new__,
        }

    def name(self, prefix: str, value: Any) -> str:
        """Make ``value`` visible to the generated code under a fresh name."""
        key = f"{prefix}{len(self.names)}"
        self.names[key] = value
        return key

    def build(self) -> dict[str, Any]:
        """Run the generated code once; return its namespace."""
        exec("\n".join(self.lines), self.names)
        return self.names


class Transport(NamedTuple):
    """What the frames functions need to know about the CAN ID of a type."""

    frame_class: type
    can_id_base: int
    service: bool
    crc_seed: int


def _values(src: _Source, scalars: Sequence[Scalar], transport: Transport | None) -> list[str]:
    """Emit the checks and float conversions of v0, v1, ...; return the payload int terms."""
    checks = []
    floats = []
    terms: list[str] = []
    offset = 0
    for i, t in enumerate(scalars):
        if t.kind in ("uint", "int"):
            checks.append(f"{t.low} <= v{i} <= {t.high}")
        elif t.kind == "bool":
            checks.append(f"(v{i} is True or v{i} is False)")
        elif t.kind == "float" and t.bits == 16:
            floats.append(i)
        elif t.kind == "float":
            src.lines.append(f"    v{i} = f32(v{i})")
        if t.kind != "void":
            terms.extend(_pack_terms(f"v{i}", t, offset))
        offset += t.bits
    if transport is not None:
        checks += ["1 <= src <= 127", "0 <= tid <= 31", "0 <= prio <= 31"]
        checks.append("1 <= dst <= 127" if transport.service else "dst is None")
    if checks:
        src.lines += [f"    if not ({' and '.join(checks)}):", "        raise SlowPath"]
    if floats:
        pack = src.name("F", struct.Struct(f"<{len(floats)}f"))
        unpack = src.name("U", struct.Struct(f"<{len(floats)}I"))
        names = ", ".join(f"a{i}" for i in floats)
        src.lines.append(
            f"    {names}, = {unpack}.unpack({pack}.pack({', '.join(f'v{i}' for i in floats)}))"
        )
        for i in floats:
            src.lines += [
                f"    m{i} = a{i} & 0x7FFFFFFF",
                f"    v{i} = ((m{i} - 0x37FFF000) >> 13 | (a{i} >> 16) & 0x8000"
                f" if 0x38800000 <= m{i} < 0x477FF000"
                f" else (a{i} >> 16) & 0x8000 if m{i} < 0x33000000 else f16(v{i}))",
            ]
    return terms


def _emit_frames(
    src: _Source, size: int, payload: str, transport: Transport, order: str = "little"
) -> None:
    """Emit the end of a frames function: from the payload int expression to the frames.

    ``order`` says how the payload int reads its bytes: ``little`` or ``big``.
    """
    frame = src.name("Frame", transport.frame_class)
    can_id = f"prio << 24 | {transport.can_id_base:#x} | src"
    if transport.service:
        can_id += " | dst << 8"
    if size <= 7 and order == "little":
        data = f"({payload} | (0xC0 | tid) << {8 * size}).to_bytes({size + 1}, 'little')"
    elif size <= 7:
        data = f"(({payload}) << 8 | 0xC0 | tid).to_bytes({size + 1}, 'big')"
    if size <= 7:
        src.lines.append(f"    return [tnew({frame}, ({can_id}, {data}))]")
        return
    count = (size + 2 + 6) // 7
    tails = src.name("T", _tail_table(count))
    src.lines += [
        f"    p = ({payload}).to_bytes({size}, '{order}')",
        f"    b = crc_hqx(p, {transport.crc_seed:#x}).to_bytes(2, 'little') + p",
        f"    c = {can_id}",
        f"    t = {tails}[tid]",
    ]
    items = [f"tnew({frame}, (c, b[{7 * i}:{7 * i + 7}] + t[{i}]))" for i in range(count - 1)]
    items.append(f"tnew({frame}, (c, b[{7 * (count - 1)}:] + t[{count - 1}]))")
    src.lines.append(f"    return [{', '.join(items)}]")


def _builder(cls: type) -> type:
    """A plain class with the same slots as ``cls``, to build instances of ``cls`` fast."""
    return type(f"_{cls.__name__}Builder", (), {"__slots__": cls.__slots__})  # type: ignore[attr-defined]


def compile_struct(schema: Struct, transport: Transport) -> FastPaths | None:
    """Generate the fast paths of a struct of scalars, or None if it is not flat."""
    fields = [f for f in schema.fields if isinstance(f.type, Scalar)]
    if len(fields) != len(schema.fields):
        return None
    scalars = [f.type for f in fields if isinstance(f.type, Scalar)]
    named = [(i, f) for i, f in enumerate(fields) if f.name]
    unpack = " ".join(f"v{i} = m.{f.name};" for i, f in named) or "pass"
    size = (sum(t.bits for t in scalars) + 7) // 8
    src = _Source()
    for function, head in (
        ("frames", "frames(m, src, tid, prio, dst)"),
        ("payload", "payload(m)"),
    ):
        src.lines += [f"def {head}:", f"    {unpack}"]
        terms = _values(src, scalars, transport if function == "frames" else None)
        expression = " | ".join(terms) or "0"
        if function == "frames":
            _emit_frames(src, size, expression, transport)
        else:
            src.lines.append(f"    return ({expression}).to_bytes({size}, 'little')")
    builder = src.name("B", _builder(schema.cls))
    cls = src.name("C", schema.cls)
    for function, length in (("decode", size), ("decode_frame", size + 1)):
        src.lines += [
            f"def {function}(buf):",
            f"    if len(buf) != {length}:",
            "        raise SlowPath",
            "    x = from_bytes(buf, 'little')",
            f"    o = new({builder})",
        ]
        offset = 0
        for f in fields:
            t = f.type
            assert isinstance(t, Scalar)
            if f.name:
                raw = _unpack_expr(t, offset)
                if t.kind == "int":
                    raw = f"(({raw}) ^ {1 << (t.bits - 1):#x}) - {1 << (t.bits - 1):#x}"
                elif t.kind == "float":
                    raw = f"F16[{raw}]" if t.bits == 16 else f"f32v({raw})"
                elif t.kind == "bool":
                    raw = f"({raw}) != 0"
                elif f.enum is not None:
                    raw = f"{src.name('E', enum_table(f.enum, t.bits))}[{raw}]"
                src.lines.append(f"    o.{f.name} = {raw}")
            offset += t.bits
        src.lines += [f"    o.__class__ = {cls}", "    return o"]
    code = src.build()
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
    if item.kind != "int" or not 8 < item.bits <= 16 or not array.dynamic:
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
    builder, cls = src.name("B", _builder(schema.cls)), src.name("C", schema.cls)
    frames_by_count, payload_by_count = [], []
    decoders: dict[int, str] = {}
    for count in range(array.max_size + 1):
        size = (count * bits + 7) // 8
        pad = 8 * size - count * bits
        names = "".join(f"v{i}, " for i in range(count))
        checks = [f"{low} <= v{i} <= {item.high}" for i in range(count)]
        stream = " | ".join(
            f"{enc}[v{i} - {low}] << {(count - 1 - i) * bits + pad}" for i in range(count)
        )
        stream = stream or "0"
        for function, extra in (
            (f"frames{count}", ["1 <= src <= 127", "0 <= tid <= 31", "0 <= prio <= 31"]),
            (f"payload{count}", []),
        ):
            head = f"{function}(m, src, tid, prio, dst)" if extra else f"{function}(m)"
            all_checks = checks + extra + (["dst is None"] if extra else [])
            src.lines += [f"def {head}:", f"    {names}= m" if count else "    pass"]
            if all_checks:
                src.lines += [f"    if not ({' and '.join(all_checks)}):", "        raise SlowPath"]
            if extra:
                _emit_frames(src, size, stream, transport, "big")
            else:
                src.lines.append(f"    return ({stream}).to_bytes({size}, 'big')")
        frames_by_count.append(f"frames{count}")
        payload_by_count.append(f"payload{count}")
        items = "".join(
            f"{dec}[(x >> {(count - 1 - i) * bits + pad}) & {(1 << bits) - 1:#x}], "
            for i in range(count)
        )
        decoders[size] = f"decode{size}"
        src.lines += [
            f"def decode{size}(buf):",
            "    x = from_bytes(buf, 'big')",
            f"    o = new({builder})",
            f"    o.{name} = ({items})",
            f"    o.__class__ = {cls}",
            "    return o",
            f"def decode_frame{size}(buf):",
            f"    return decode{size}(buf[:{size}])",
        ]
    src.names["FR"] = src.names["PL"] = ()
    src.lines += [
        "def frames(m, src, tid, prio, dst):",
        f"    c = m.{name}",
        "    return FR[len(c)](c, src, tid, prio, dst)",
        "def payload(m):",
        f"    c = m.{name}",
        "    return PL[len(c)](c)",
    ]
    code = src.build()
    code["FR"] = tuple(code[f] for f in frames_by_count)
    code["PL"] = tuple(code[f] for f in payload_by_count)
    decode_by_length: list[Decoder | None] = [None] * (max(decoders) + 2)
    frame_by_length: list[Decoder | None] = [None] * (max(decoders) + 2)
    for size, function in decoders.items():
        decode_by_length[size] = code[function]
        if size <= 7:
            frame_by_length[size + 1] = code[f"decode_frame{size}"]

    def decode(buf: bytes) -> Any:
        decoder = decode_by_length[len(buf)] if len(buf) < len(decode_by_length) else None
        if decoder is None:
            raise SlowPath
        return decoder(buf)

    def decode_frame(buf: bytes) -> Any:
        decoder = frame_by_length[len(buf)] if len(buf) < len(frame_by_length) else None
        if decoder is None:
            raise SlowPath
        return decoder(buf)

    return FastPaths(code["frames"], code["payload"], decode, decode_frame)
