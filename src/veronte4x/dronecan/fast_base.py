"""What the generated DroneCAN fast paths refer to by name: helpers and cached tables.

The code written by `veronte4x.dronecan.compiled` and `veronte4x.dronecan.compiled_tree`
runs in a namespace of `NAMES` and of the objects it names itself (structs, tables,
classes). Compiled at run time (a vendor namespace loaded by the user) those objects are
given as they are; written ahead of time (the modules of `veronte4x.dronecan.fast`, one
per shipped type) each is an expression calling the helpers below, so that a table is
built once per process whichever types need it.
"""

from __future__ import annotations

import binascii
import functools
import itertools
import struct
from collections.abc import Callable
from typing import Any

from veronte4x.dronecan.float16 import (
    FLOAT16_VALUES,
    float16_bits,
    float32_bits,
    float32_value,
    float64_bits,
    float64_value,
)
from veronte4x.dronecan.scalar_code import be_runs
from veronte4x.dronecan.tail import MULTI_FRAME_TAILS


class SlowPath(Exception):
    """Raised by generated code when the generic serializer must take over."""


@functools.cache
def tail_table(count: int) -> tuple[tuple[bytes, ...], ...]:
    """Tail bytes of a transfer of ``count`` frames, as 1-byte strings, per transfer id."""
    return tuple(tuple(bytes((t,)) for t in MULTI_FRAME_TAILS[tid][count]) for tid in range(32))


@functools.cache
def struct_table(code: str, count: int) -> tuple[struct.Struct, ...]:
    """``Struct("<{n}{code}")`` for n = 0 .. ``count``: an array of ``n`` whole items."""
    return tuple(struct.Struct(f"<{n}{code}") for n in range(count + 1))


HALF_TABLE_BITS = 24
"""Widest integer item read through `half_tables` (two tables of at most 4,096 entries);
a wider one is valued from its bit runs, one expression per item."""


@functools.cache
def half_tables(kind: str, bits: int) -> tuple[tuple[int, ...], tuple[int, ...]]:
    """Two tables that decode an integer scalar (``kind`` ``int`` or ``uint``) of ``bits``
    bits, 8 < bits <= `HALF_TABLE_BITS`, from its piece of the stream (a big-endian int):
    the value is ``high[piece >> h] + low[piece & (2**h - 1)]``, ``h`` half the bits rounded
    up. Each bit of the piece stands for one bit of the value (its bit runs are disjoint),
    so a table is built by doubling: the entries so far, then each plus the next bit's
    weight. The sign bit of an ``int`` weighs ``-2**(bits - 1)``; one table per (kind,
    bits) for the whole process."""
    weights = [0] * bits  # the value's weight of each bit of the piece
    for source, width, dest in be_runs(0, bits, bits):
        for k in range(width):
            weight = 1 << (source + k)
            weights[dest + k] = -weight if kind == "int" and source + k == bits - 1 else weight
    low_bits = (bits + 1) // 2

    def table(piece_bits: list[int]) -> tuple[int, ...]:
        entries = [0]
        for weight in piece_bits:
            entries += [e + weight for e in entries]
        return tuple(entries)

    return table(weights[low_bits:]), table(weights[:low_bits])


@functools.cache
def int_array_tables(low: int, high: int) -> tuple[tuple[int, ...], tuple[int, ...]]:
    """The two tables of an array of 9..16-bit ints (RawCommand's int14) from ``low`` to
    ``high``, the whole range of the type: item value (less ``low``) to its stream bits
    (low byte first, then the top bits), and stream bits to item value.

    Made of ranges, not item by item (under a millisecond for 16,384 entries, where a
    loop takes ten): the unsigned value ``256 h + l`` has the stream bits
    ``l << (bits - 8) | h``, so for each ``h`` the stream bits of every ``l`` are one
    range, and for each ``l`` the values of every ``h`` are two (below zero from the
    sign bit on).
    """
    bits = (high - low).bit_length()
    rest, half = bits - 8, 1 << (bits - 1)
    if (low, high) != (-half, half - 1) or rest < 1:
        raise ValueError(f"no int type of 9 to 16 bits ranges from {low} to {high}")
    by_unsigned = list(
        itertools.chain.from_iterable(range(h, 256 << rest, 1 << rest) for h in range(1 << rest))
    )
    to_stream = tuple(by_unsigned[half:] + by_unsigned[:half])  # from the lowest value
    from_stream = tuple(
        itertools.chain.from_iterable(
            values
            for byte in range(256)
            for values in (range(byte, half, 256), range(byte - half, 0, 256))
        )
    )
    return to_stream, from_stream


def shared_table(decode: Callable[[bytes], Any], size: int) -> tuple[Any, ...]:
    """Every message of a frozen type of at most one payload byte (``size`` 0 or 1), by
    that byte, decoded once by ``decode``: the decoders of such a type return these."""
    return tuple(decode(bytes((b,))) for b in range(256)) if size else (decode(b""),)


F16 = FLOAT16_VALUES
f16 = float16_bits
f32 = float32_bits
f32v = float32_value
f64 = float64_bits
f64v = float64_value
from_bytes = int.from_bytes
crc_hqx = binascii.crc_hqx
new = object.__new__
tnew = tuple.__new__
FLOATS = frozenset((float, int))
INTS = frozenset((int,))
TB = tuple(bytes((b,)) for b in range(256))
"""Each byte value as a 1-byte string."""
MFT = MULTI_FRAME_TAILS

NAMES: dict[str, Any] = {
    name: globals()[name]
    for name in (
        *("F16", "f16", "f32", "f32v", "f64", "f64v", "from_bytes", "new", "tnew"),
        *("FLOATS", "INTS", "TB", "MFT", "SlowPath", "crc_hqx", "shared_table"),
    )
}
"""The helpers and constants every generated fast path may use, by the name it uses (the
module's own names, which a module written ahead of time imports)."""
