"""Generic DSDL v0 serializer: runs any `schema` definition.

Bit order: fields follow each other with no
alignment, each byte filled from its MSB. A scalar wider than 8 bits is cut into
little-endian bytes; the full low bytes go first, each MSB first, then the remaining
``bits % 8`` top bits. Dynamic arrays carry a ``max_size.bit_length()``-bit length prefix,
except under the tail array optimisation (TAO): the last field of the top-level type
(reached through nested last fields and selected union members) with items of 8 bits or
more drops it, and its decoder reads items while 8 bits or more remain. Void fields are
zeros. The payload is padded with zero bits to a whole byte.

This module validates every value, so it is also the encoder's slow path for errors and
for saturation; `compiled` holds the fast paths.
"""

from __future__ import annotations

import functools
from collections.abc import Iterator
from typing import Any

from veronte4x.dronecan.float16 import (
    FLOAT16_VALUES,
    float16_bits,
    float32_bits,
    float32_value,
    float64_bits,
    float64_value,
)
from veronte4x.dronecan.schema import Array, Member, Scalar, Struct, StructField, Union, uses_tao
from veronte4x.errors import DecodeError, EncodeError, boolean, integer, real
from veronte4x.words import counted


class _Writer:
    """Accumulates the bit stream in one int, first bit most significant."""

    __slots__ = ("acc", "bits")

    def __init__(self) -> None:
        self.acc = 0
        self.bits = 0

    def put(self, value: int, bits: int) -> None:
        """Append a scalar of ``bits`` bits in v0 order (little-endian byte chunks)."""
        if bits <= 8:
            self.acc = (self.acc << bits) | value
        else:
            full, rest = divmod(bits, 8)
            chunks = int.from_bytes(
                (value & ((1 << (8 * full)) - 1)).to_bytes(full, "little"), "big"
            )
            self.acc = (((self.acc << (8 * full)) | chunks) << rest) | (value >> (8 * full))
        self.bits += bits

    def put_bytes(self, data: bytes) -> None:
        """Append whole bytes."""
        self.acc = (self.acc << (8 * len(data))) | int.from_bytes(data, "big")
        self.bits += 8 * len(data)

    def payload(self) -> bytes:
        """The stream padded with zero bits to whole bytes."""
        pad = -self.bits % 8
        return (self.acc << pad).to_bytes((self.bits + pad) // 8, "big")


class _Reader:
    """Reads the bit stream of a payload, first bit most significant."""

    __slots__ = ("data", "name", "pos", "total", "value")

    def __init__(self, data: bytes, name: str) -> None:
        self.data = data
        self.name = name
        self.value = int.from_bytes(data, "big")
        self.total = 8 * len(data)
        self.pos = 0

    def remaining(self) -> int:
        return self.total - self.pos

    def take(self, bits: int, field: str) -> int:
        """Read ``bits`` raw bits."""
        end = self.pos + bits
        if end > self.total:
            raise DecodeError(
                self.name,
                f"payload ends before {counted(bits, 'bit')} at bit {self.pos} ({self.total} bits)",
                self.data,
                field or None,
            )
        self.pos = end
        return (self.value >> (self.total - end)) & ((1 << bits) - 1)

    def get(self, bits: int, field: str) -> int:
        """Read a scalar of ``bits`` bits in v0 order."""
        if bits <= 8:
            return self.take(bits, field)
        full, rest = divmod(bits, 8)
        low = self.take(8 * full, field)
        top = self.take(rest, field) if rest else 0
        return int.from_bytes(low.to_bytes(full, "big"), "little") | (top << (8 * full))


TABLE_BITS = 16
"""Widest enum field whose `enum_table` is a tuple (65,536 entries); a wider one's (a
``uint23`` of flags: ``ardupilot.gnss.Status.status``) is an `EnumValues` that looks each
value up when asked."""


class EnumValues:
    """The `enum_table` of a wide enum field: each raw value's member, or the int itself,
    looked up by index (as a tuple's, from 0)."""

    def __init__(self, known: dict[int, Any], bits: int) -> None:
        self._known = known
        self._size = 1 << bits

    def __len__(self) -> int:
        return self._size

    def __getitem__(self, index: int) -> Any:
        if not 0 <= index < self._size:
            raise IndexError(index)
        return self._known.get(index, index)

    def __iter__(self) -> Iterator[Any]:
        return (self._known.get(i, i) for i in range(self._size))


@functools.cache
def enum_table(enum: type, bits: int) -> tuple[Any, ...] | EnumValues:
    """Map each raw value to its enum member, or keep the int where the enum has none: a
    tuple, or an `EnumValues` for a field wider than `TABLE_BITS`."""
    known = {int(member): member for member in enum}  # type: ignore[attr-defined]
    if bits > TABLE_BITS:
        return EnumValues(known, bits)
    return tuple(known.get(i, i) for i in range(1 << bits))


def _check_int(name: str, field: str, t: Scalar, value: object, saturate: bool) -> int:
    number = integer(value)
    if number is None:
        raise EncodeError(name, field, value, f"an int for {t.dsdl}")
    assert isinstance(number, int)
    if t.kind == "bool" and number not in (0, 1):
        raise EncodeError(name, field, value, "a bool")
    if number < t.low or number > t.high:
        if not saturate:
            raise EncodeError(name, field, value, f"an int in {t.low}..{t.high} ({t.dsdl})")
        if not t.truncated:
            number = t.low if number < t.low else t.high
    return number & ((1 << t.bits) - 1)


def scalar_bits(name: str, field: str, t: Scalar, value: object, saturate: bool) -> int:
    """Validate one scalar value and return its raw bits (two's complement, IEEE).

    NumPy integer, float and bool scalars are accepted where Python's are; a value is
    never narrowed silently (a float is no int, an out-of-range int an error)."""
    if t.kind == "float":
        exact = real(value)
        if exact is None:
            raise EncodeError(name, field, value, f"a float for {t.dsdl}")
        number = float(exact)
        if t.bits == 64:
            return float64_bits(number)
        return float16_bits(number) if t.bits == 16 else float32_bits(number)
    if t.kind == "bool" and boolean(value) is not None:
        return 1 if value else 0
    return _check_int(name, field, t, value, saturate)


class Serializer:
    """Encoder and decoder of one top-level struct, driven by its definition."""

    def __init__(self, schema: Struct) -> None:
        self.schema = schema
        self.name = schema.name

    # -- encoding ------------------------------------------------------------------------

    def encode(self, obj: object, saturate: bool = False) -> bytes:
        """Serialize ``obj``; raise EncodeError for any value the type cannot hold."""
        if not isinstance(obj, self.schema.cls):
            raise EncodeError(self.name, "", obj, f"a {self.schema.cls.__name__}")
        w = _Writer()
        self._put_struct(w, self.schema, obj, "", True, saturate)
        return w.payload()

    def _put_struct(
        self, w: _Writer, s: Struct, obj: object, path: str, tao: bool, saturate: bool
    ) -> None:
        last = len(s.fields) - 1
        for i, f in enumerate(s.fields):
            if isinstance(f.type, Scalar) and f.type.kind == "void":
                w.put(0, f.type.bits)
                continue
            self._put(w, f, getattr(obj, f.name), path + f.name, tao and i == last, saturate)

    def _put(
        self,
        w: _Writer,
        f: StructField | Member,
        value: object,
        path: str,
        tao: bool,
        saturate: bool,
    ) -> None:
        t = f.type
        if isinstance(t, Scalar):
            w.put(scalar_bits(self.name, path, t, value, saturate), t.bits)
        elif isinstance(t, Array):
            self._put_array(w, t, value, path, tao, saturate)
        elif isinstance(t, Struct):
            if not isinstance(value, t.cls):
                raise EncodeError(self.name, path, value, f"a {t.cls.__name__}")
            self._put_struct(w, t, value, path + ".", tao, saturate)
        else:
            self._put_union(w, t, value, path, tao, saturate)

    def _put_array(
        self, w: _Writer, t: Array, value: object, path: str, tao: bool, saturate: bool
    ) -> None:
        if t.is_bytes:
            if not isinstance(value, (bytes, bytearray)):
                raise EncodeError(self.name, path, value, f"bytes for {t.dsdl}")
            items: Any = value
        elif isinstance(value, (tuple, list)):
            items = value
        else:
            raise EncodeError(self.name, path, value, f"a tuple of ints for {t.dsdl}")
        count = len(items)
        if count > t.max_size or (not t.dynamic and count != t.max_size):
            bound = "at most" if t.dynamic else "exactly"
            raise EncodeError(
                self.name, path, value, f"{bound} {counted(t.max_size, 'item')} ({t.dsdl})"
            )
        if t.dynamic and not (tao and uses_tao(t)):
            w.put(count, t.prefix_bits)
        if t.is_bytes:
            w.put_bytes(bytes(items))
            return
        item_type = t.item
        if isinstance(item_type, Union):
            last = -1 if t.dynamic and tao and uses_tao(t) else count - 1
            for i, item in enumerate(items):
                self._put_union(w, item_type, item, f"{path}[{i}]", tao and i == last, saturate)
            return
        if isinstance(item_type, Struct):
            # Items of a TAO array are whole; otherwise the last one inherits the tail position.
            last = -1 if t.dynamic and tao and uses_tao(t) else count - 1
            for i, item in enumerate(items):
                if not isinstance(item, item_type.cls):
                    raise EncodeError(
                        self.name, f"{path}[{i}]", item, f"a {item_type.cls.__name__}"
                    )
                self._put_struct(w, item_type, item, f"{path}[{i}].", tao and i == last, saturate)
            return
        for i, item in enumerate(items):
            w.put(scalar_bits(self.name, f"{path}[{i}]", item_type, item, saturate), item_type.bits)

    def _put_union(
        self, w: _Writer, u: Union, value: object, path: str, tao: bool, saturate: bool
    ) -> None:
        for tag, member in enumerate(u.members):
            if type(value) is member.cls:
                w.put(tag, u.tag_bits)
                inner = value if isinstance(member.type, Struct) else value.value  # type: ignore[attr-defined]
                self._put(w, member, inner, f"{path}.{member.name}", tao, saturate)
                return
        names = ", ".join(mb.cls.__name__ for mb in u.members)
        raise EncodeError(self.name, path, value, f"one of {names}")

    # -- decoding ------------------------------------------------------------------------

    def decode(self, payload: bytes) -> Any:
        """Deserialize a whole payload; raise DecodeError if it does not fit the type."""
        r = _Reader(payload, self.name)
        obj = self._get_struct(r, self.schema, "", True)
        if r.remaining() >= 8:
            raise DecodeError(
                self.name,
                f"{counted(r.remaining() // 8, 'byte')} left after the last field",
                payload,
            )
        return obj

    def _get_struct(self, r: _Reader, s: Struct, path: str, tao: bool) -> Any:
        values = []
        last = len(s.fields) - 1
        for i, f in enumerate(s.fields):
            if isinstance(f.type, Scalar) and f.type.kind == "void":
                r.take(f.type.bits, "")
                continue
            values.append(self._get(r, f.type, f.enum, path + f.name, tao and i == last))
        return s.cls(*values)

    def _get(
        self,
        r: _Reader,
        t: Scalar | Array | Struct | Union,
        enum: type | None,
        path: str,
        tao: bool,
    ) -> Any:
        if isinstance(t, Scalar):
            raw = r.get(t.bits, path)
            return self._scalar(t, raw, enum)
        if isinstance(t, Array):
            return self._get_array(r, t, path, tao)
        if isinstance(t, Struct):
            return self._get_struct(r, t, path + ".", tao)
        tag = r.take(t.tag_bits, path)
        if tag >= len(t.members):
            raise DecodeError(self.name, f"union tag {tag} has no member", r.data, path)
        member = t.members[tag]
        inner = self._get(r, member.type, None, f"{path}.{member.name}", tao)
        return inner if isinstance(member.type, Struct) else member.cls(inner)

    @staticmethod
    def _scalar(t: Scalar, raw: int, enum: type | None) -> Any:
        if t.kind == "int":
            return raw - ((raw >> (t.bits - 1)) << t.bits)
        if t.kind == "float":
            if t.bits == 64:
                return float64_value(raw)
            return FLOAT16_VALUES[raw] if t.bits == 16 else float32_value(raw)
        if t.kind == "bool":
            return bool(raw)
        return raw if enum is None else enum_table(enum, t.bits)[raw]

    def _get_array(self, r: _Reader, t: Array, path: str, tao: bool) -> Any:
        item_type = t.item
        if not isinstance(item_type, Scalar):
            return self._get_struct_array(r, t, item_type, path, tao)
        if tao and uses_tao(t):
            count = 0
            remaining = r.remaining()
            while remaining - count * item_type.bits >= 8:
                count += 1
            if count * item_type.bits > remaining:
                raise DecodeError(
                    self.name,
                    f"{counted(remaining, 'bit')} left, not a whole {item_type.dsdl}",
                    r.data,
                    path,
                )
        elif t.dynamic:
            count = r.take(t.prefix_bits, path)
        else:
            count = t.max_size
        if count > t.max_size:
            raise DecodeError(
                self.name,
                f"{counted(count, 'item')}, more than {t.max_size} ({t.dsdl})",
                r.data,
                path,
            )
        if t.is_bytes:
            return r.take(8 * count, path).to_bytes(count, "big") if count else b""
        return tuple(
            self._scalar(item_type, r.get(item_type.bits, path), None) for _ in range(count)
        )

    def _get_struct_array(
        self, r: _Reader, t: Array, item: Struct | Union, path: str, tao: bool
    ) -> tuple[Any, ...]:
        """An array of structs or unions."""
        items: list[Any] = []
        if tao and uses_tao(t):
            while r.remaining() >= 8:
                if len(items) == t.max_size:
                    raise DecodeError(
                        self.name,
                        f"more than {counted(t.max_size, 'item')} ({t.dsdl})",
                        r.data,
                        path,
                    )
                items.append(self._get(r, item, None, f"{path}[{len(items)}]", False))
            return tuple(items)
        count = r.take(t.prefix_bits, path) if t.dynamic else t.max_size
        if count > t.max_size:
            raise DecodeError(
                self.name,
                f"{counted(count, 'item')}, more than {t.max_size} ({t.dsdl})",
                r.data,
                path,
            )
        for i in range(count):
            items.append(self._get(r, item, None, f"{path}[{i}]", tao and i == count - 1))
        return tuple(items)
