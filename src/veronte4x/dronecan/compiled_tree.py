"""Fast paths generated for any type: nested structs, arrays, unions, the tail array rule.

`compiled` covers flat structs of scalars and RawCommand; this module writes the decoder,
encoder and frames function of every other type from the same definitions, as one Python
function each, nesting and loops written out (no call per field or per nested struct).

The bit stream (see `serializer`) is read and written in pieces:

- A *chunk* is a run of scalar fields of one struct. It is packed and unpacked by one
  `struct.Struct` over its bytes, as `compiled` does for a whole flat struct (fields cut into
  byte-aligned groups, a whole uint8/16/32/64 or float field as itself).
- The decoder knows statically where each piece starts: a fixed bit count after the
  position ``p`` that only dynamic arrays and unions move, and whether ``p`` is a whole
  number of bytes. Where a piece starts on a byte boundary it is read from the payload as
  it is (``unpack_from``, a slice for ``uint8`` arrays); elsewhere from the payload as one
  big-endian int ``x``, shifted so that reads past the end give zeros.
- Arrays of whole-byte scalars are one ``struct`` call; other scalar arrays one list
  comprehension (an integer item of 9 to 24 bits from two tables, `half_tables`);
  arrays of structs a loop; a union an ``if`` per member.
- The encoder appends every piece to one int ``a`` and its bit count, then pads to bytes.

Anything unusual raises inside the generated code (`SlowPath` for a value it does not take
or a payload that does not fit the type, `struct.error` for a range `struct` refuses or a
payload too short for a read), and the caller runs the generic `Serializer`, which gives
the precise error, or saturates. The decoder checks every count and union tag before
using it and the payload length at the end, so arbitrary bytes never raise anything else.
A type whose code would nest more than `MAX_BLOCKS` blocks (Python compiles at most 20
nested loops) gets functions that always raise `SlowPath`: the generic serializer does it.
"""

from __future__ import annotations

import struct
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import NamedTuple

from veronte4x.codegen import attribute
from veronte4x.dronecan.compiled import Transport, _Source, _transport_checks
from veronte4x.dronecan.fast_base import HALF_TABLE_BITS, half_tables, struct_table
from veronte4x.dronecan.scalar_code import (
    HALF_EXPR,
    Namer,
    be_runs,
    gather,
    is_whole,
    pack_scalars,
    read_code,
    scalar_checks,
    scalar_terms,
    scalar_value,
    unpack_scalars,
)
from veronte4x.dronecan.schema import (
    Array,
    Scalar,
    Struct,
    StructField,
    Union,
    max_bits,
    min_bits,
    tao_min_bits,
    uses_tao,
)
from veronte4x.dronecan.tail import SINGLE_FRAME


def _from_piece(t: Scalar, var: str, name: Namer) -> str:
    """The value of scalar ``t`` from ``var``, the ``t.bits``-bit piece of the stream it
    fills, as a big-endian int."""
    return scalar_value(t, gather(var, be_runs(0, t.bits, t.bits), t.bits), None, name)


def _to_piece(t: Scalar, var: str) -> str:
    """The ``t.bits``-bit piece of the stream (a big-endian int) of checked value ``var``."""
    return " | ".join(scalar_terms(t, var, be_runs(0, t.bits, t.bits)))


def _mod8(t: Scalar | Array | Struct | Union) -> int | None:
    """The bit length of any value of ``t`` modulo 8, where it does not depend on the value."""
    if isinstance(t, Scalar):
        return t.bits % 8
    if isinstance(t, Array):
        item = _mod8(t.item)
        if item is None:
            return None
        if not t.dynamic:
            return t.max_size * item % 8
        return t.prefix_bits % 8 if item == 0 else None
    if isinstance(t, Struct):
        total = 0
        for f in t.fields:
            part = _mod8(f.type)
            if part is None:
                return None
            total += part
        return total % 8
    members = {_mod8(m.type) for m in t.members}
    if len(members) != 1 or None in members:
        return None
    (member,) = members
    assert member is not None
    return (t.tag_bits + member) % 8


def _static(t: Scalar | Array | Struct | Union) -> bool:
    """Whether every value of ``t`` has the same bit length."""
    return min_bits(t) == max_bits(t)


def _tail_differs(t: Scalar | Array | Struct | Union) -> bool:
    """Whether ``t`` in tail position holds an array under the tail array rule."""
    if isinstance(t, Array):
        return uses_tao(t) or (not isinstance(t.item, Scalar) and _tail_differs(t.item))
    if isinstance(t, Struct):
        return bool(t.fields) and _tail_differs(t.fields[-1].type)
    if isinstance(t, Union):
        return any(_tail_differs(m.type) for m in t.members)
    return False


MAX_BLOCKS = 18
"""Most blocks (loops and ifs) one generated function nests."""


class _TooDeep(Exception):
    """Raised by a `_Writer` asked for more than `MAX_BLOCKS` nested blocks."""


class _Writer:
    """Lines of one generated function, indented, with fresh local names."""

    def __init__(self, src: _Source) -> None:
        self.src = src
        self.lines: list[str] = []
        self.depth = 1
        self.count = 0

    def emit(self, line: str) -> None:
        self.lines.append("    " * self.depth + line)

    def _structs(self, code: str, count: int) -> str:
        """Name the structs of 0 .. ``count`` whole items of `struct` code ``code``."""
        return self.src.name("A", struct_table(code, count), f"struct_table({code!r}, {count})")

    def fresh(self, prefix: str) -> str:
        self.count += 1
        return f"{prefix}{self.count}"

    @contextmanager
    def block(self, head: str) -> Iterator[None]:
        if self.depth > MAX_BLOCKS:
            raise _TooDeep
        self.emit(head)
        self.depth += 1
        yield
        self.depth -= 1


class _Chunk(NamedTuple):
    """Consecutive scalar fields: their types, targets (None for void) and enums."""

    scalars: list[Scalar]
    names: list[str | None]
    enums: list[type | None]


def _chunks(fields: tuple[StructField, ...]) -> Iterator[_Chunk | tuple[int, StructField]]:
    """The fields of a struct, runs of scalars as one `_Chunk`, others with their index."""
    run = _Chunk([], [], [])
    for i, f in enumerate(fields):
        if isinstance(f.type, Scalar):
            run.scalars.append(f.type)
            run.names.append(attribute(f.name) if f.name else None)
            run.enums.append(f.enum)
            continue
        if run.scalars:
            yield run
            run = _Chunk([], [], [])
        attribute(f.name)  # generated code reads and writes it
        yield i, f
    if run.scalars:
        yield run


class _Decoder(_Writer):
    """Writes ``decode(buf)`` (or ``decode_frame(buf)``, the tail byte last) of a type."""

    def __init__(self, src: _Source, schema: Struct, frame: bool) -> None:
        super().__init__(src)
        self.schema = schema
        self.frame = frame
        self.off = 0  # static bits after p
        self.pmod: int | None = 0  # p % 8 where known
        self.uses_x = False
        self.static = _static(schema)
        size = (max_bits(schema) + 7) // 8
        # x is shifted by pad bits: every read ends before the end of x (reads stop at the
        # largest size plus the 7 bits a chunk's last byte may take beyond its fields).
        self.pad = 8 if self.static else 8 * (size + 2)

    def mod(self) -> int | None:
        return None if self.pmod is None else (self.pmod + self.off) % 8

    def at(self, extra: int = 0) -> str:
        """The current bit position plus ``extra``."""
        return f"(p + {self.off + extra})" if self.off + extra else "p"

    def byte_at(self) -> str:
        """The current byte index (where ``mod() == 0``)."""
        if self.pmod != 0:
            return f"{self.at()} >> 3"
        return f"(p >> 3) + {self.off // 8}" if self.off else "p >> 3"

    def bits(self, width: int) -> str:
        """The next ``width`` bits as a big-endian int."""
        self.uses_x = True
        return f"(x >> (q - {self.at(width)})) & {(1 << width) - 1:#x}"

    def flush(self) -> None:
        if self.off:
            self.emit(f"p += {self.off}")
            if self.pmod is not None:
                self.pmod = (self.pmod + self.off) % 8
            self.off = 0

    def advance(self, bits: str, mod: int | None) -> None:
        """Move p by ``bits`` (an expression) whose value is ``mod`` modulo 8."""
        self.emit(f"p += {self.off} + {bits}" if self.off else f"p += {bits}")
        self.pmod = None if self.pmod is None or mod is None else (self.pmod + self.off + mod) % 8
        self.off = 0

    def function(self, name: str) -> list[str]:
        value = self.struct(self.schema, True)
        payload_bits = "((len(buf) - 1) << 3)" if self.frame else "(len(buf) << 3)"
        head = [f"def {name}(buf):"]
        if self.static:
            size = (max_bits(self.schema) + 7) // 8 + self.frame
            head += [f"    if len(buf) != {size}:", "        raise SlowPath"]
        else:
            head.append(f"    t = {payload_bits}")
        if self.uses_x:
            head += [
                f"    x = from_bytes(buf, 'big') << {self.pad - 8 * self.frame}",
                f"    q = {payload_bits} + {self.pad}",
            ]
        head.append("    p = 0")
        if not self.static:
            self.emit(f"e = {self.at()}")
            self.emit("if e > t or t - e > 7:")
            self.emit("    raise SlowPath")
        self.emit(f"return {value}")
        return head + self.lines

    def struct(self, s: Struct, tao: bool) -> str:
        """Decode a struct; return the name of the variable holding it."""
        values: list[tuple[str, str]] = []
        last = len(s.fields) - 1
        for part in _chunks(s.fields):
            if isinstance(part, _Chunk):
                names = [None if n is None else self.fresh("v") for n in part.names]
                self.chunk(part.scalars, names, part.enums)
                values += [
                    (field, name)
                    for field, name in zip(part.names, names, strict=True)
                    if field is not None and name is not None
                ]
            else:
                i, f = part
                values.append((f.name, self.value(f.type, tao and i == last)))
        return self.build(s.cls, values)

    def build(self, cls: type, values: list[tuple[str, str]]) -> str:
        o = self.fresh("o")
        self.emit(f"{o} = {self.src.builder(cls)}()")
        for field, name in values:
            self.emit(f"{o}.{field} = {name}")
        self.emit(f"{o}.__class__ = {self.src.cls(cls)}")
        return o

    def value(self, t: Array | Struct | Union | Scalar, tao: bool) -> str:
        if isinstance(t, Scalar):
            name = self.fresh("v")
            self.chunk([t], [name], [None])
            return name
        if isinstance(t, Struct):
            return self.struct(t, tao)
        if isinstance(t, Array):
            return self.array(t, tao)
        return self.union(t, tao)

    def chunk(
        self, scalars: list[Scalar], names: list[str | None], enums: list[type | None]
    ) -> None:
        """Decode consecutive scalars into the variables ``names``."""
        width = sum(t.bits for t in scalars)
        if self.mod() != 0 and all(t.kind != "float" for t in scalars):
            self.piece(scalars, names, enums)
            return
        size = (width + 7) // 8
        unpacking = unpack_scalars(scalars, names, enums, self.src.name)
        unpacker = self.src.name("S", struct.Struct(unpacking.format))
        if self.mod() == 0:
            source = f"{unpacker}.unpack_from(buf, {self.byte_at()})"
        else:
            source = f"{unpacker}.unpack(({self.bits(8 * size)}).to_bytes({size}, 'big'))"
        self.emit(f"{unpacking.targets}= {source}")
        for line in unpacking.lines:
            self.emit(line)
        self.off += width

    def piece(
        self, scalars: list[Scalar], names: list[str | None], enums: list[type | None]
    ) -> None:
        """Decode scalars without floats from one read of the stream, through bit runs."""
        width = sum(t.bits for t in scalars)
        r = self.fresh("r")
        self.emit(f"{r} = {self.bits(width)}")
        offset = 0
        for t, name, enum in zip(scalars, names, enums, strict=True):
            if name is not None:
                raw = gather(r, be_runs(offset, t.bits, width), width)
                self.emit(f"{name} = {scalar_value(t, raw, enum, self.src.name)}")
            offset += t.bits
        self.off += width

    def prefix_count(self, t: Array) -> str:
        """Emit the item count of a dynamic array (not under the tail rule); return its name."""
        k = self.fresh("k")
        self.emit(f"{k} = {self.bits(t.prefix_bits)}")
        self.off += t.prefix_bits
        if t.max_size < (1 << t.prefix_bits) - 1:
            self.emit(f"if {k} > {t.max_size}:")
            self.emit("    raise SlowPath")
        return k

    def tail_count(self, t: Array, item_bits: int) -> str:
        """Emit the item count of an array under the tail rule, items of ``item_bits``."""
        k, r = self.fresh("k"), self.fresh("r")
        self.emit(f"{r} = t - {self.at()}")
        self.emit(f"{k} = ({r} - 8) // {item_bits} + 1 if {r} > 7 else 0")
        self.emit(f"if {k} > {t.max_size} or {k} * {item_bits} > {r}:")
        self.emit("    raise SlowPath")
        return k

    def array(self, t: Array, tao: bool) -> str:
        item = t.item
        tail = tao and uses_tao(t)
        if not isinstance(item, Scalar):
            return self.struct_array(t, item, tao)
        if not t.dynamic:
            k: str = str(t.max_size)
        elif tail:
            k = self.tail_count(t, item.bits)
        else:
            k = self.prefix_count(t)
        v = self.fresh("a")
        static = not t.dynamic
        total = item.bits * t.max_size if static else f"{k} * {item.bits}"
        if t.is_bytes or is_whole(item):
            nbytes = t.max_size * item.bits // 8 if static else f"{k} * {item.bits // 8}"
            if self.mod() == 0:
                start = self.fresh("s")
                self.emit(f"{start} = {self.byte_at()}")
                data = f"buf[{start}:{start} + {nbytes}]"
            else:
                self.uses_x = True
                mask = (
                    f"{(1 << (8 * int(nbytes))) - 1:#x}" if static else f"~(-1 << ({nbytes} << 3))"
                )
                data = f"((x >> (q - {self.at()} - ({total}))) & {mask}).to_bytes({nbytes}, 'big')"
            if t.is_bytes:
                self.emit(f"{v} = {data}")
            else:
                code = read_code(item)
                if static:
                    unpacker = self.src.name("S", struct.Struct(f"<{t.max_size}{code}"))
                    self.emit(f"{v} = {unpacker}.unpack({data})")
                else:
                    table = self._structs(code, t.max_size)
                    self.emit(f"{v} = {table}[{k}].unpack({data})")
        elif item.kind in ("int", "uint") and 8 < item.bits <= HALF_TABLE_BITS:
            self.uses_x = True
            y, i = self.fresh("y"), self.fresh("i")
            high, low = half_tables(item.kind, item.bits)
            tables = f"half_tables({item.kind!r}, {item.bits})"
            low_bits = (item.bits + 1) // 2
            # The items as one int, first item on top; each item from two tables.
            self.emit(f"{y} = x >> (q - {self.at()} - ({total}))")
            high_name = self.src.name("H", high, f"{tables}[0]")
            self.emit(
                f"{v} = tuple([{high_name}[({y} >> ({i} + {low_bits}))"
                f" & {len(high) - 1:#x}] + {self.src.name('L', low, f'{tables}[1]')}[({y} >> {i})"
                f" & {len(low) - 1:#x}] for {i} in range(({total}) - {item.bits}, -1,"
                f" -{item.bits})])"
            )
        else:
            self.uses_x = True
            z, i, r = self.fresh("z"), self.fresh("i"), self.fresh("r")
            self.emit(f"{z} = q - {self.at()} - {item.bits}")
            # One comprehension (Python compiles ``for r in [value]`` to an assignment).
            self.emit(
                f"{v} = tuple([{_from_piece(item, r, self.src.name)}"
                f" for {i} in range({z}, {z} - {total}, -{item.bits})"
                f" for {r} in [(x >> {i}) & {(1 << item.bits) - 1:#x}]])"
            )
        if static:
            self.off += item.bits * t.max_size
        else:
            self.advance(f"{k} * {item.bits}", 0 if item.bits % 8 == 0 else None)
        return v

    def struct_array(self, t: Array, item: Struct | Union, tao: bool) -> str:
        """An array of structs or unions: its items one by one."""
        tail = tao and uses_tao(t)
        items = self.fresh("a")
        static = _static(item)
        size = min_bits(item)
        mod = _mod8(item)
        if not t.dynamic:
            k = str(t.max_size)
        elif tail and static:
            k = self.tail_count(t, size)
        elif tail:
            k = ""
        else:
            k = self.prefix_count(t)
        self.flush()
        self.emit(f"{items} = []")
        outer = self.pmod
        self.pmod = outer if mod == 0 else None
        last_tail = tao and not tail and _tail_differs(item)
        if k:
            loop = f"for _ in range({k} - 1):" if last_tail else f"for _ in range({k}):"
        else:
            loop = "while t - p > 7:"
        with self.block(loop):
            if not k:
                self.emit(f"if len({items}) == {t.max_size}:")
                self.emit("    raise SlowPath")
            self.emit(f"{items}.append({self.value(item, False)})")
            self.flush()
        if last_tail:
            self.pmod = None
            with self.block(f"if {k}:"):
                self.emit(f"{items}.append({self.value(item, True)})")
                self.flush()
        self.pmod = outer if mod == 0 else None
        return f"tuple({items})"

    def union(self, u: Union, tao: bool) -> str:
        tag = self.fresh("u")
        self.emit(f"{tag} = {self.bits(u.tag_bits)}")
        self.off += u.tag_bits
        self.flush()
        v = self.fresh("w")
        start = self.pmod
        ends = set()
        for index, member in enumerate(u.members):
            self.pmod = start
            with self.block(f"{'if' if index == 0 else 'elif'} {tag} == {index}:"):
                inner = self.value(member.type, tao)
                if isinstance(member.type, Struct):
                    self.emit(f"{v} = {inner}")
                else:
                    self.emit(f"{v} = {self.build(member.cls, [('value', inner)])}")
                self.flush()
            ends.add(self.pmod)
        with self.block("else:"):
            self.emit("raise SlowPath")
        self.pmod = ends.pop() if len(ends) == 1 else None
        return v


class _Encoder(_Writer):
    """Writes ``payload(m)`` of a type: the stream in int ``a``, its bit count ``n`` + off."""

    def __init__(self, src: _Source, schema: Struct) -> None:
        super().__init__(src)
        self.schema = schema
        self.off = 0

    def put(self, width: int, value: str) -> None:
        self.emit(f"a = a << {width} | {value}")
        self.off += width

    def function(self) -> list[str]:
        self.struct(self.schema, "m", True, check=False)
        head = ["def payload(m):", "    a = 0", "    n = 0"]
        if self.off:
            self.emit(f"n += {self.off}")
        self.emit("return (a << (-n & 7)).to_bytes((n + 7) >> 3, 'big')")
        return head + self.lines

    def struct(self, s: Struct, base: str, tao: bool, check: bool = True) -> None:
        if check:
            self.emit(f"if {base}.__class__ is not {self.src.cls(s.cls)}:")
            self.emit("    raise SlowPath")
        last = len(s.fields) - 1
        for part in _chunks(s.fields):
            if isinstance(part, _Chunk):
                self.chunk(part.scalars, [None if n is None else f"{base}.{n}" for n in part.names])
            else:
                i, f = part
                self.value(f.type, f"{base}.{f.name}", tao and i == last)

    def value(self, t: Scalar | Array | Struct | Union, expr: str, tao: bool) -> None:
        if isinstance(t, Scalar):
            self.chunk([t], [expr])
        elif isinstance(t, Struct):
            var = self.fresh("s")
            self.emit(f"{var} = {expr}")
            self.struct(t, var, tao)
        elif isinstance(t, Array):
            self.array(t, expr, tao)
        else:
            self.union(t, expr, tao)

    def chunk(self, scalars: list[Scalar], exprs: list[str | None]) -> None:
        width = sum(t.bits for t in scalars)
        names = "; ".join(f"v{i} = {e}" for i, e in enumerate(exprs) if e is not None)
        if names:
            self.emit(names)
        if all(t.kind != "float" for t in scalars):
            self.integers(scalars)
            return
        packing = pack_scalars(scalars, self.src.name)
        if packing.checks:
            self.emit(f"if {' or '.join(packing.checks)}:")
            self.emit("    raise SlowPath")
        for line in packing.floats:
            self.emit(line)
        packer = self.src.name("S", struct.Struct(packing.format))
        packed = f"from_bytes({packer}.pack({', '.join(packing.values)}), 'big')"
        pad = -width % 8
        self.put(width, f"{packed} >> {pad}" if pad else packed)

    def counted(self, emit: Callable[[], None]) -> None:
        """Emit code run a variable number of times, adding its static bits to ``n``."""
        start, self.off = self.off, 0
        emit()
        if self.off:
            self.emit(f"n += {self.off}")
        self.off = start

    def integers(self, scalars: list[Scalar]) -> None:
        """Append scalars without floats, ``v0``, ``v1``, ..., through their bit runs."""
        width = sum(t.bits for t in scalars)
        checks, terms, offset = [], [], 0
        for i, t in enumerate(scalars):
            checks += scalar_checks(t, f"v{i}")
            terms += scalar_terms(t, f"v{i}", be_runs(offset, t.bits, width))
            offset += t.bits
        if checks:
            self.emit(f"if {' or '.join(checks)}:")
            self.emit("    raise SlowPath")
        self.put(width, f"({' | '.join(terms) or '0'})")

    def array(self, t: Array, expr: str, tao: bool) -> None:
        item = t.item
        tail = tao and uses_tao(t)
        v = self.fresh("a")
        self.emit(f"{v} = {expr}")
        kind = "bytes" if t.is_bytes else "tuple"
        size = f"len({v}) > {t.max_size}" if t.dynamic else f"len({v}) != {t.max_size}"
        self.emit(f"if {v}.__class__ is not {kind} or {size}:")
        self.emit("    raise SlowPath")
        if t.dynamic and not tail:
            self.put(t.prefix_bits, f"len({v})")
        if t.is_bytes:
            self.emit(f"a = a << (len({v}) << 3) | from_bytes({v}, 'big')")
            self.emit(f"n += len({v}) << 3")
            return
        if isinstance(item, Struct):
            last_tail = tao and not tail and _tail_differs(item)
            e = self.fresh("e")
            with self.block(f"for {e} in {v}[:-1]:" if last_tail else f"for {e} in {v}:"):
                self.counted(lambda: self.struct(item, e, False))
            if last_tail:
                with self.block(f"if {v}:"):
                    self.counted(lambda: self.struct(item, f"{v}[-1]", True))
            return
        if isinstance(item, Union):
            last_tail = tao and not tail and _tail_differs(item)
            e = self.fresh("e")
            with self.block(f"for {e} in {v}[:-1]:" if last_tail else f"for {e} in {v}:"):
                self.counted(lambda: self.union(item, e, False))
            if last_tail:
                with self.block(f"if {v}:"):
                    self.counted(lambda: self.union(item, f"{v}[-1]", True))
            return
        bits = f"len({v}) * {item.bits}"
        if is_whole(item):
            allowed = "FLOATS" if item.kind == "float" else "INTS"
            self.emit(f"if not {allowed}.issuperset(map(type, {v})):")
            self.emit("    raise SlowPath")
            count = f"len({v})"
            if item.kind == "float" and item.bits in (16, 32):
                singles = self._structs("f", t.max_size)
                raw = self._structs("I", t.max_size)
                if item.bits == 16:
                    half = HALF_EXPR.format(a="b", m="(b & 0x7FFFFFFF)", v="c")
                    fixed, slow, code = f"{half} for b, c in zip(w, {v})", "f16", "H"
                else:  # struct keeps the sign and payload of a NaN; DroneCAN writes one NaN
                    fixed = "0x7FC00000 if b & 0x7FFFFFFF > 0x7F800000 else b for b in w"
                    slow, code = "f32", "I"
                # Beyond the float32 range struct refuses: each item goes through float16_bits
                # or float32_bits then.
                with self.block("try:"):
                    self.emit(f"w = {raw}[{count}].unpack({singles}[{count}].pack(*{v}))")
                with self.block("except OverflowError:"):
                    self.emit(f"{v} = [{slow}(c) for c in {v}]")
                with self.block("else:"):
                    self.emit(f"{v} = [{fixed}]")
            else:
                code = read_code(item)
            packer = self._structs(code, t.max_size)
            self.emit(f"a = a << ({bits}) | from_bytes({packer}[{count}].pack(*{v}), 'big')")
        else:
            e = self.fresh("e")
            with self.block(f"for {e} in {v}:"):
                self.emit(f"if {' or '.join(scalar_checks(item, e))}:")
                self.emit("    raise SlowPath")
                self.emit(f"a = a << {item.bits} | {_to_piece(item, e)}")
        self.emit(f"n += {bits}")

    def union(self, u: Union, expr: str, tao: bool) -> None:
        v, c = self.fresh("w"), self.fresh("c")
        self.emit(f"{v} = {expr}")
        self.emit(f"{c} = {v}.__class__")
        start = self.off
        for tag, member in enumerate(u.members):
            self.off = 0
            cls = self.src.cls(member.cls)
            with self.block(f"{'if' if tag == 0 else 'elif'} {c} is {cls}:"):
                self.emit(f"a = a << {u.tag_bits} | {tag}")
                inner = v if isinstance(member.type, Struct) else f"{v}.value"
                if isinstance(member.type, Struct):
                    self.struct(member.type, v, tao, check=False)
                else:
                    self.value(member.type, inner, tao)
                self.emit(f"n += {self.off + u.tag_bits}")
        with self.block("else:"):
            self.emit("raise SlowPath")
        self.off = start


def tree_source(schema: Struct, transport: Transport) -> _Source:
    """Generate the fast paths of any struct (see the module docstring); a type nested too
    deep gets a source marked ``slow``."""
    try:
        return _tree_source(schema, transport)
    except _TooDeep:
        src = _Source()
        src.slow = True
        return src


def _tree_source(schema: Struct, transport: Transport) -> _Source:
    src = _Source()
    src.lines += _Encoder(src, schema).function()
    frame = src.cls(transport.frame_class)
    can_id = f"prio << 24 | {transport.can_id_base:#x} | src"
    if transport.service:
        can_id += " | dst << 8"
    src.lines += [
        "def frames(m, src, tid, prio, dst):",
        f"    if {' or '.join(_transport_checks(transport))}:",
        "        raise SlowPath",
        "    p = payload(m)",
        "    if len(p) < 8:",
        f"        return [tnew({frame}, ({can_id}, p + TB[0x{SINGLE_FRAME:X} | tid]))]",
        f"    b = crc_hqx(p, {transport.crc_seed:#x}).to_bytes(2, 'little') + p",
        f"    c = {can_id}",
        "    t = MFT[tid][(len(b) + 6) // 7]",
        f"    return [tnew({frame}, (c, b[7 * i:7 * i + 7] + TB[e])) for i, e in enumerate(t)]",
    ]
    src.lines += _Decoder(src, schema, False).function("decode")
    src.single = tao_min_bits(schema) <= 56  # a payload may fit one frame
    if src.single:
        src.lines += _Decoder(src, schema, True).function("decode_frame")
    return src
