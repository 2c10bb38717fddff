"""DSDL payloads decoded column-wise: every field of all transfers of one type at once.

The reference is `veronte4x.dronecan.serializer.Serializer.decode`, and this module reads
the same bit stream (fields one after the other from the first byte's MSB, scalars wider
than 8 bits as their little-endian bytes then the top bits, dynamic arrays behind a length
prefix or under the tail array optimisation, unions as a tag and the member) with NumPy:
each field is one read over every transfer (or array item) that holds it, each union
member one read over the transfers that chose it, each array one read over all its items.
No Python code runs per transfer; loops run per field, per union member, and per item
index of arrays whose items differ in size.

A transfer the serializer refuses (its payload ends inside a field, an array longer than
its bound, a union tag without a member, a whole byte left after the last field) is
marked, and the caller decodes it alone, to report the serializer's own error.

Columns are named and typed as `veronte4x.capture.columnar.schema` states.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Any, TypeAlias

import numpy as np
import numpy.typing as npt
import pyarrow as pa

from veronte4x.capture.columnar.schema import (
    arrow_values,
    enum_array,
    field_enum_names,
    scalar_type,
    spread,
    struct_array,
    union_array,
    value_type,
    valued_members,
)
from veronte4x.dronecan.schema import (
    Array,
    Scalar,
    Struct,
    StructField,
    Union,
    max_bits,
    min_bits,
    uses_tao,
)

Ints: TypeAlias = npt.NDArray[np.int64]


@dataclass
class UnionValue:
    """A union's values over a group: each element's tag, and each member's elements (by
    position in the group) with their values."""

    tag: Ints
    members: list[tuple[Ints, Any]]


@functools.cache
def integer_dtype(t: Scalar) -> np.dtype[Any]:
    """The NumPy type of an integer scalar's column (its Arrow type's)."""
    return np.dtype(f"{'int' if t.low < 0 else 'uint'}{scalar_type(t).bit_width}")


_WHOLE: dict[int, np.dtype[Any]] = {16: np.dtype("<u2"), 32: np.dtype("<u4"), 64: np.dtype("<u8")}
"""Scalars of whole bytes, which the stream holds as little-endian bytes."""

_WORD_BITS = 49
"""The widest run of stream bits one read of `_Reader.words` holds wherever it starts."""


class _Reader:
    """The payloads of one type's transfers, one after the other in ``payload``.

    Elements of a group (transfers, or the items of their arrays) are given by ``row``
    (the transfer each belongs to, 0..n-1) and ``pos`` (absolute bit position).
    """

    def __init__(self, payload: npt.NDArray[np.uint8], starts: Ints, sizes: Ints) -> None:
        self.octets = np.concatenate([payload, np.zeros(16, np.uint8)])
        self.limit = len(payload)
        # The 7 bytes from each byte on as one big-endian integer (read as the 8 from
        # there, every eighth at once): any run of up to `_WORD_BITS` stream bits is one
        # gather, a shift and a mask.
        words = np.empty(self.limit + 1, np.uint64)
        for k in range(8):
            count = len(words[k::8])
            words[k::8] = self.octets[k : k + 8 * count].view(">u8")
        self.words: Ints = (words >> np.uint64(8)).view(np.int64)
        self.end = 8 * (starts + sizes)
        self.bad = np.zeros(len(starts), np.bool_)

    def check(self, row: Ints, end: Ints) -> None:
        """Mark the transfers whose payload ends before bit ``end``."""
        over = end > self.end[row]
        if over.any():
            self.bad[row[over]] = True

    def bits(self, pos: Ints, width: int) -> Ints:
        """``width`` (at most `_WORD_BITS`) stream bits at each ``pos`` as one integer, the
        first bit the highest, unchecked."""
        word = self.words[np.minimum(pos >> 3, self.limit)]
        value: Ints = (word >> (56 - width - (pos & 7))) & ((1 << width) - 1)
        return value

    def raw(self, row: Ints, pos: Ints, width: int) -> npt.NDArray[np.uint64]:
        """A scalar's raw bits (checked), in v0 byte order."""
        self.check(row, pos + width)
        if width <= 8:
            return self.bits(pos, width).astype(np.uint64)
        full, rest = divmod(width, 8)
        if not rest and width in _WHOLE and not (pos & 7).any():  # whole bytes: one gather
            byte = np.minimum(pos >> 3, self.limit)
            octets = self.octets[byte[:, None] + np.arange(full)]
            whole: npt.NDArray[np.uint64] = octets.view(_WHOLE[width])[:, 0].astype(np.uint64)
            return whole
        if width <= _WORD_BITS:  # one read, its bytes then put in v0 order
            stream = self.bits(pos, width)
            ordered = (stream & ((1 << rest) - 1)) << (8 * full)
            for k in range(full):
                ordered |= ((stream >> (width - 8 * k - 8)) & 0xFF) << (8 * k)
            return ordered.astype(np.uint64)
        value = np.zeros(len(pos), np.uint64)
        for k in range(full):
            value |= self.bits(pos + 8 * k, 8).astype(np.uint64) << np.uint64(8 * k)
        if rest:
            value |= self.bits(pos + 8 * full, rest).astype(np.uint64) << np.uint64(8 * full)
        return value

    def scalar(self, t: Scalar, row: Ints, pos: Ints) -> np.ndarray:
        """A scalar's values as the serializer gives them, in the column's NumPy type."""
        raw = self.raw(row, pos, t.bits)
        if t.kind == "float":
            if t.bits == 16:
                half: np.ndarray = raw.astype(np.uint16).view(np.float16).astype(np.float32)
                return half
            single: np.ndarray = raw.astype(np.uint32).view(np.float32)
            return single if t.bits == 32 else raw.view(np.float64)
        if t.kind == "bool":
            flags: np.ndarray = raw != 0
            return flags
        dtype = integer_dtype(t)
        if t.kind == "int":
            signed = raw.view(np.int64)
            if t.bits < 64:
                signed = signed - (((signed >> (t.bits - 1)) & 1) << t.bits)
            return signed.astype(dtype)
        return raw.astype(dtype)

    def value(
        self, t: Scalar | Array | Struct | Union, row: Ints, pos: Ints, tao: bool
    ) -> tuple[Any, Ints]:
        """A field's values over a group, and the positions after it."""
        if isinstance(t, Scalar):
            if t.kind == "void":
                self.check(row, pos + t.bits)
                return None, pos + t.bits
            return self.scalar(t, row, pos), pos + t.bits
        if isinstance(t, Array):
            return self.array(t, row, pos, tao)
        if isinstance(t, Struct):
            return self.struct(t, row, pos, tao)
        return self.union(t, row, pos, tao)

    def struct(self, s: Struct, row: Ints, pos: Ints, tao: bool) -> tuple[dict[str, Any], Ints]:
        """A struct's field values by name (void fields left out)."""
        out: dict[str, Any] = {}
        last = len(s.fields) - 1
        for i, f in enumerate(s.fields):
            value, pos = self.value(f.type, row, pos, tao and i == last)
            if f.name:
                out[f.name] = value
        return out, pos

    def union(self, u: Union, row: Ints, pos: Ints, tao: bool) -> tuple[UnionValue, Ints]:
        """A union's tag and each member's values over the elements that chose it."""
        tag = self.raw(row, pos, u.tag_bits).astype(np.int64)
        pos = pos + u.tag_bits
        orphan = tag >= len(u.members)
        if orphan.any():
            self.bad[row[orphan]] = True
        after = pos.copy()
        members = []
        for index, member in enumerate(u.members):
            chosen = np.flatnonzero(tag == index)
            value, end = self.value(member.type, row[chosen], pos[chosen], tao)
            after[chosen] = end
            members.append((chosen, value))
        return UnionValue(tag, members), after

    def array(self, t: Array, row: Ints, pos: Ints, tao: bool) -> tuple[pa.Array, Ints]:
        """An array's values (an Arrow list, or binary for uint8 items) over a group."""
        item = t.item
        size = item.bits if isinstance(item, Scalar) else min_bits(item)
        tail = tao and uses_tao(t)
        one_size = isinstance(item, Scalar) or (
            size and size == max_bits(item) and not _tail_array(item)
        )
        if tail and not one_size:
            assert not isinstance(item, Scalar)
            return self.tail_structs(t, item, row, pos)
        if tail:  # items of one size: as many as begin a whole byte or more before the end
            remaining = self.end[row] - pos
            count = np.where(remaining >= 8, (remaining - 8) // size + 1, 0)
            self.check(row, pos + count * size)
        elif t.dynamic:
            count = self.raw(row, pos, t.prefix_bits).astype(np.int64)
            pos = pos + t.prefix_bits
        else:
            count = np.full(len(row), t.max_size, np.int64)
        longer = count > t.max_size
        if longer.any():
            self.bad[row[longer]] = True
            count = np.minimum(count, t.max_size)
        offsets = np.zeros(len(row) + 1, np.int64)
        np.cumsum(count, out=offsets[1:])
        if not isinstance(item, Scalar):
            return self.structs(t, item, row, pos, count, offsets, tao)
        within = np.arange(offsets[-1]) - np.repeat(offsets[:-1], count)
        item_pos = np.repeat(pos, count) + within * item.bits
        self.check(row, pos + count * item.bits)
        values = self.scalar(item, np.repeat(row, count), item_pos)
        return _list(t, offsets, values), pos + count * item.bits

    def structs(
        self,
        t: Array,
        item: Struct | Union,
        row: Ints,
        pos: Ints,
        count: Ints,
        offsets: Ints,
        tao: bool,
    ) -> tuple[pa.Array, Ints]:
        """An array of structs or unions with a known number of items per element. Items of one
        fixed size are read together; others one item index at a time (the last item of
        an element inherits its tail position)."""
        size = min_bits(item)
        if size == max_bits(item) and not (tao and _tail_array(item)):
            within = np.arange(offsets[-1]) - np.repeat(offsets[:-1], count)
            item_pos = np.repeat(pos, count) + within * size
            values, _ = self.value(item, np.repeat(row, count), item_pos, False)
            self.check(row, pos + count * size)
            items = _arrow(item, values, int(offsets[-1]))
            return _list(t, offsets, items), pos + count * size
        pos = pos.copy()
        pieces, places = [], []
        for k in range(int(count.max(initial=0))):
            has = count > k
            groups = [(has & (count != k + 1), False), (has & (count == k + 1), True)]
            for mask, tail in groups if tao else [(has, False)]:
                chosen = np.flatnonzero(mask)
                if not len(chosen):
                    continue
                values, pos[chosen] = self.value(item, row[chosen], pos[chosen], tail)
                pieces.append(_arrow(item, values, len(chosen)))
                places.append(offsets[chosen] + k)
        return _list(t, offsets, _ordered(item, pieces, places, int(offsets[-1]))), pos

    def tail_structs(
        self, t: Array, item: Struct | Union, row: Ints, pos: Ints
    ) -> tuple[pa.Array, Ints]:
        """An array of structs or unions of more than one size under the tail array
        optimisation: items while a whole byte remains, one item index at a time."""
        pos = pos.copy()
        count = np.zeros(len(row), np.int64)
        going = np.ones(len(row), np.bool_)
        found: list[tuple[Ints, pa.Array]] = []
        for k in range(t.max_size + 1):
            going &= (self.end[row] - pos >= 8) & ~self.bad[row]
            chosen = np.flatnonzero(going)
            if not len(chosen):
                break
            if k == t.max_size:
                self.bad[row[chosen]] = True
                break
            values, pos[chosen] = self.value(item, row[chosen], pos[chosen], False)
            count[chosen] += 1
            found.append((chosen, _arrow(item, values, len(chosen))))
        offsets = np.zeros(len(row) + 1, np.int64)
        np.cumsum(count, out=offsets[1:])
        places = [offsets[chosen] + k for k, (chosen, _) in enumerate(found)]
        items = _ordered(item, [values for _, values in found], places, int(offsets[-1]))
        return _list(t, offsets, items), pos


def _tail_array(struct: Struct | Union) -> bool:
    """Whether the tail position changes how a struct reads: its last field ends in a
    dynamic array the tail array optimisation applies to (or may, for a union)."""
    if isinstance(struct, Union):
        return True
    if not struct.fields:
        return False
    t = struct.fields[-1].type
    if isinstance(t, Array):
        return uses_tao(t) or isinstance(t.item, Struct)
    if isinstance(t, Struct):
        return _tail_array(t)
    return isinstance(t, Union)


def _list(t: Array, offsets: Ints, values: Any) -> pa.Array:
    """An array column from item offsets and the items' values."""
    if t.is_bytes:
        data = pa.py_buffer(np.asarray(values, np.uint8).tobytes())
        bounds = pa.py_buffer(offsets.astype(np.int32).tobytes())
        return pa.Array.from_buffers(pa.binary(), len(offsets) - 1, [None, bounds, data])
    items = values if isinstance(values, pa.Array) else pa.array(values, value_type(t.item))
    return pa.ListArray.from_arrays(pa.array(offsets.astype(np.int32)), items)


def _arrow(t: Scalar | Array | Struct | Union, value: Any, size: int) -> pa.Array:
    """``size`` values of an array's items (or of their fields) as Arrow, typed as the
    schema's."""
    if isinstance(t, Scalar):
        return pa.array(value, scalar_type(t))
    if isinstance(t, Array):
        assert isinstance(value, pa.Array)
        return value
    if isinstance(t, Union):
        return union_array(t, value.tag, _members(t, value, size))
    children = [_field(f, value[f.name], size) for f in t.fields if f.name]
    return struct_array(t, children, size)


def _field(f: StructField, value: Any, size: int) -> pa.Array:
    """``size`` values of a struct's field (an enum field's wire values by name)."""
    names = field_enum_names(f)
    return _arrow(f.type, value, size) if names is None else enum_array(names, value)


def _members(t: Union, value: UnionValue, size: int) -> list[pa.Array]:
    """The array of each valued member of ``size`` union values (null where another
    member is set)."""
    valued = [member for _, member in valued_members(t)]
    return [
        spread(_arrow(member.type, member_values, len(chosen)), chosen, size)
        for member, (chosen, member_values) in zip(t.members, value.members, strict=True)
        if member in valued
    ]


def _ordered(
    item: Struct | Union, pieces: list[pa.Array], places: list[Ints], size: int
) -> pa.Array:
    """Items decoded in pieces, put at their places (the places of all ``size`` items)."""
    if not pieces:
        return _no_items(item)
    joined = pa.concat_arrays(pieces)
    where = np.concatenate(places)
    if (where[1:] > where[:-1]).all():  # in order already (one piece, say): no take
        return joined
    order = np.empty(size, np.int64)
    order[where] = np.arange(size)
    return joined.take(pa.array(order))


@functools.cache
def _no_items(item: Struct | Union) -> pa.Array:
    """No items of an array, with the enums' whole dictionaries as every other piece has
    them: made once an item type (an array empty in every transfer of a batch is common:
    Fix2's ``ecef_position_velocity``)."""
    return arrow_values(item, [])


def decode(
    struct: Struct, payload: npt.NDArray[np.uint8], starts: Ints, sizes: Ints
) -> tuple[dict[str, Any], npt.NDArray[np.bool_]]:
    """Decode payloads of one type into its table's columns.

    Args:
        struct: The type.
        payload: Payload bytes.
        starts, sizes: Where each transfer's payload starts in ``payload``, and its bytes.

    Returns:
        The field columns (NumPy or Arrow, one row per transfer), and which transfers the
        serializer refuses (their rows hold anything).
    """
    reader = _Reader(payload, starts, sizes)
    row = np.arange(len(starts), dtype=np.int64)
    values, pos = reader.struct(struct, row, 8 * starts, True)
    reader.bad |= reader.end - pos >= 8
    columns: dict[str, Any] = {}
    _flatten(struct, values, "", columns)
    return columns, reader.bad


def _flatten(struct: Struct, values: dict[str, Any], prefix: str, out: dict[str, Any]) -> None:
    """Field values into the table's columns (``outer.inner``, unions as ``name.type``
    and a nullable column per member with a value)."""
    for f in struct.fields:
        if not f.name:
            continue
        name, t, value = prefix + f.name, f.type, values[f.name]
        if isinstance(t, Struct):
            _flatten(t, value, name + ".", out)
        elif isinstance(t, Union):
            out[f"{name}.type"] = value.tag
            members = _members(t, value, len(value.tag))
            for (field, _), arrow in zip(valued_members(t), members, strict=True):
                out[f"{name}.{field}"] = arrow
        else:
            out[name] = value
