"""Veronte frames, column-wise: every field of a layout cut from all its frames at once.

The extraction is generated from the same `FrameLayout` data the per-frame codec compiles:
the frame's first bytes form one integer (little- or big-endian, as the layout says), each
field is a shift and a mask of it, then the field's kind converts it. A frame the per-frame
decoder would refuse (wrong length, a constant or a mapped value that does not match, a
value past its maximum) is marked not good and left to that decoder, which gives its exact
error.
"""

from __future__ import annotations

import weakref
from typing import Any

import numpy as np
import numpy.typing as npt
import pyarrow as pa

from veronte4x.codec import Codec
from veronte4x.codec.compiler import FrameLayout
from veronte4x.codec.fields import ByteOrder, FieldKind
from veronte4x.codec.messages import Sender

Columns = dict[str, Any]


def targets(
    codec: Codec,
    sender: Sender,
    data: npt.NDArray[np.uint64],
    length: npt.NDArray[np.int64],
    excess: bool,
) -> npt.NDArray[np.int16]:
    """Which layout decodes each frame of one sender: an index into `layout_list`, or -1
    where the per-frame decoder must decide (unknown command, too short to tell).

    The routing is the codec's route table (`veronte4x.codec.routes`), applied to all the
    frames at once. ``data`` holds each frame's eight first bytes as one little-endian
    integer.
    """
    by_command, told = _routing(codec, sender)
    command = (data & np.uint64(0xFF)).astype(np.uint8)
    out = np.where(length > 0, by_command[command], -1).astype(np.int16)
    if not told:
        return out
    byte1 = (data >> np.uint64(8)) & np.uint64(0xFF)
    for wire, headed, groups in told:
        mine = (command == wire) & (length > 0)
        out[mine] = -1
        if headed:
            mine &= length >= 2
        rest = mine.copy()
        for header, forms in groups:
            if header is None:
                chosen, rest = rest, np.zeros_like(rest)
            else:
                chosen = rest & (byte1 == header)
                rest &= ~chosen
            out[chosen] = _form(forms, length[chosen], excess)
    return out


_Forms = list[tuple[int, int]]
"""A message's forms, largest first: (fixed size, index into `layout_list`)."""
_Told = list[tuple[int, bool, list[tuple[int | None, _Forms]]]]
"""Commands of several routes: (command, whether a group has a header, the groups of forms
by header)."""
_ROUTING: weakref.WeakKeyDictionary[Codec, dict[Sender, tuple[np.ndarray, _Told]]] = (
    weakref.WeakKeyDictionary()
)


def _routing(codec: Codec, sender: Sender) -> tuple[npt.NDArray[np.int16], _Told]:
    """One sender's routing by the codec's route table, made once: the layout of each
    command byte with one route (-1 for none or several), and the commands of several."""
    of_codec = _ROUTING.setdefault(codec, {})
    found = of_codec.get(sender)
    if found is not None:
        return found
    table = codec.routes
    index = {id(layout): i for i, layout in enumerate(layout_list(codec))}
    by_command = np.full(256, -1, np.int16)
    told: _Told = []
    for command in table.commands():
        group = table.of(command)
        if len(group) == 1 and group[0].sender is None and group[0].header is None:
            by_command[command] = index[id(group[0].frame)]
            continue
        groups = table.for_sender(command, sender)
        told.append(
            (
                command,
                any(forms[0].header is not None for forms in groups),
                [
                    (forms[0].header, [(r.frame.fixed_size, index[id(r.frame)]) for r in forms])
                    for forms in groups
                ],
            )
        )
    of_codec[sender] = by_command, told
    return by_command, told


def _form(forms: _Forms, length: npt.NDArray[np.int64], excess: bool) -> npt.NDArray[np.int16]:
    """The layout of each frame of one message's forms, by length (see
    `veronte4x.codec.routes`): the largest form it holds, a smaller one only if exact or with
    ``excess``; -1 otherwise."""
    out = np.full(len(length), -1, np.int16)
    above: int | None = None
    for size, index in forms:
        if above is None:
            fits = length >= size
        else:
            fits = (length == size) | ((length > size) & (length < above) & excess)
        out[fits] = index
        above = size
    return out


_LAYOUTS: weakref.WeakKeyDictionary[Codec, list[FrameLayout]] = weakref.WeakKeyDictionary()


def layout_list(codec: Codec) -> list[FrameLayout]:
    """Every layout this codec decodes with, in the order of its route table (made once
    per codec: a codec does not change)."""
    found = _LAYOUTS.get(codec)
    if found is None:
        found = _LAYOUTS[codec] = codec.routes.layouts()
    return found


def decode(
    layout: FrameLayout, data: npt.NDArray[np.uint64], length: npt.NDArray[np.int64], excess: bool
) -> tuple[npt.NDArray[np.bool_], Columns]:
    """Decode frames that all take one layout (``data``: as for `targets`).

    Returns:
        Which frames decoded (the others are the per-frame decoder's), and each field's
        values by column name (NumPy arrays, or Arrow arrays for raw bytes).
    """
    size = layout.fixed_size
    if layout.tail is None:
        good = (length == size) | ((length > size) & excess)
    else:
        good = (length >= size) & (length <= size + layout.tail.bits // 8)
    word = _word(data, size, layout.byte_order)
    values: dict[str, np.ndarray] = {}
    for p in layout.placed:
        f = p.field
        raw = (word >> np.uint64(p.shift)) & np.uint64((1 << f.bits) - 1)
        if f.kind is FieldKind.CONSTANT:
            good &= raw == f.value
        elif f.kind is FieldKind.BOOL:
            values[f.label] = raw == 1
        elif f.kind is FieldKind.MAPPED:
            table = np.full(1 << f.bits, -1, np.int64)
            for wire, value in f.mapping:
                table[wire] = value
            mapped = table[raw]
            good &= mapped >= 0
            values[f.label] = mapped
        elif f.kind is FieldKind.FLOAT32:
            values[f.label] = raw.astype(np.uint32).view(np.float32)
        elif f.kind in (FieldKind.UNSIGNED, FieldKind.SIGNED):
            number: np.ndarray = raw
            if f.kind is FieldKind.SIGNED:
                number = raw.astype(np.int64)
                number = number - ((number >> (f.bits - 1)) & 1) * (1 << f.bits)
            if f.maximum is not None:
                good &= raw <= f.maximum
            if f.scale is not None:
                number = number * f.scale.factor + f.scale.offset
            values[f.label] = number
    columns: Columns = {}
    for name, value in values.items():
        columns[name.replace("[", "_").rstrip("]")] = value
    if layout.tail is not None and layout.tail.attr is not None:
        columns[layout.tail.attr] = _tail(data, length, size)
    for attr, value in layout.implied:
        columns[attr] = pa.nulls(len(data)) if value is None else value
    return good, columns


def _word(data: npt.NDArray[np.uint64], size: int, order: ByteOrder) -> npt.NDArray[np.uint64]:
    """The first ``size`` bytes of each frame as one integer."""
    if size == 0:
        return np.zeros(len(data), np.uint64)
    word: npt.NDArray[np.uint64] = data & np.uint64((1 << (8 * size)) - 1)
    if order is ByteOrder.BIG:
        word = word.byteswap() >> np.uint64(8 * (8 - size))
    return word


def _tail(words: npt.NDArray[np.uint64], length: npt.NDArray[np.int64], size: int) -> pa.Array:
    """The bytes past ``size`` of each frame, as a binary array."""
    data = words.astype("<u8").view(np.uint8).reshape(-1, 8)
    sizes = np.maximum(length - size, 0)
    keep = np.arange(data.shape[1]) < (size + sizes)[:, None]
    keep[:, :size] = False
    offsets = np.zeros(len(data) + 1, np.int32)
    np.cumsum(sizes, out=offsets[1:])
    return pa.BinaryArray.from_buffers(
        pa.binary(), len(data), [None, pa.py_buffer(offsets), pa.py_buffer(data[keep].tobytes())]
    )
