"""Veronte frames, column-wise: every field of a layout cut from all its frames at once.

The extraction is generated from the same `FrameLayout` data the per-frame codec compiles:
the frame's first bytes form one integer (little- or big-endian, as the layout says), each
field is a shift and a mask of it, then the field's kind converts it. A frame the per-frame
decoder would refuse (wrong length, a constant or a mapped value that does not match, a
value past its maximum) is marked not good and left to that decoder, which gives its exact
error.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import numpy.typing as npt
import pyarrow as pa

from veronte4x.codec import Codec, layouts
from veronte4x.codec.compiler import FrameLayout
from veronte4x.codec.fields import ByteOrder, Kind
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

    ``data`` holds each frame's eight first bytes as one little-endian integer.
    """
    table = layout_list(codec)
    index = {id(layout): i for i, layout in enumerate(table)}
    by_command = np.full(256, -1, np.int16)
    for wire, layout in _by_command(codec).items():
        by_command[wire] = index[id(layout)]
    command = (data & np.uint64(0xFF)).astype(np.uint8)
    out = np.where(length > 0, by_command[command], -1).astype(np.int16)
    version = (command == 1) & (length == 1)
    out[version] = index[id(layouts.VERSION_REQUEST)]
    zero = (command == 0) & (length >= 2)
    header = (data >> np.uint64(8)) & np.uint64(0xFF) == 0xFF
    if sender is Sender.ARBITER:
        cex = (length == 4) | ((length == 5) & excess)
        status = np.where(cex, index[id(layouts.STATUS_CEX)], index[id(layouts.STATUS_4X)])
        status = np.where((length < 4) | ((length == 5) & ~cex), -1, status)
        out[zero & header] = status[zero & header]
        out[zero & ~header] = index[id(layouts.SCORE)]
    else:
        out[zero & header] = index[id(layouts.READY)]
        out[zero & ~header] = index[id(layouts.ARBITRATION_VARIABLE)]
    out[(command == 0) & (length < 2)] = -1
    return out


def layout_list(codec: Codec) -> list[FrameLayout]:
    """Every layout this codec decodes with, in a fixed order."""
    return [*layouts.ARBITRATION_AND_VERSION, *dict.fromkeys(_by_command(codec).values())]


def _by_command(codec: Codec) -> dict[int, FrameLayout]:
    """The layout of each non-zero command byte (command 1: the version response)."""
    table: dict[int, FrameLayout] = {1: layouts.VERSION_RESPONSE}
    pwm = layouts.PWM_SET[codec.pwm_packing]
    for command in sorted({wire for wire, _ in pwm.fields[0].mapping}):
        table[command] = pwm
    table.update(layouts.OPAQUE)
    for declared in codec.layouts:
        table[declared.command] = declared.frame
    return table


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
        if f.kind is Kind.CONSTANT:
            good &= raw == f.value
        elif f.kind is Kind.BOOL:
            values[f.label] = raw == 1
        elif f.kind is Kind.MAPPED:
            table = np.full(1 << f.bits, -1, np.int64)
            for wire, value in f.mapping:
                table[wire] = value
            mapped = table[raw]
            good &= mapped >= 0
            values[f.label] = mapped
        elif f.kind is Kind.FLOAT32:
            values[f.label] = raw.astype(np.uint32).view(np.float32)
        elif f.kind in (Kind.UNSIGNED, Kind.SIGNED):
            number: np.ndarray = raw
            if f.kind is Kind.SIGNED:
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
