"""Numbers as people read them: a float as the shortest decimal that reads back the same."""

from __future__ import annotations

import math
import struct

_PACK = {16: struct.Struct("<e"), 32: struct.Struct("<f")}
_CACHE: dict[int, dict[float, float]] = {16: {}, 32: {}}
_CACHE_SIZE = 1 << 16
"""Values remembered per width: telemetry repeats its values (a float16 has only 65536)."""


def shortest(value: float, bits: int = 32) -> float:
    """The float with the shortest decimal form that rounds to the same ``bits``-bit float.

    For a float32 field the decoder holds the exact float32 value, ``0.10000000149011612``;
    its shortest form is ``0.1``. A value that is not a ``bits``-bit float (or not finite)
    comes back unchanged.

    Examples:
        >>> shortest(0.10000000149011612)
        0.1
        >>> shortest(1.0009765625, 16), shortest(1.0009765625, 32)
        (1.001, 1.0009766)
    """
    cache = _CACHE[bits]
    found = cache.get(value)
    if found is not None:
        return found
    found = _shortest(value, _PACK[bits])
    if len(cache) >= _CACHE_SIZE:
        cache.clear()
    if found == found:  # not NaN: a NaN key is never found again
        cache[value] = found
    return found


def _shortest(value: float, packer: struct.Struct) -> float:
    pack, unpack = packer.pack, packer.unpack
    try:
        single = unpack(pack(value))[0]
    except (OverflowError, struct.error):
        return value
    if single != value or not math.isfinite(value):
        return value
    # More digits only come closer to the value, so the digits that read back form a range
    # up to 9 (17 for a float64 value, never reached here): find its start by bisection.
    low, high = 1, 9
    best = float(f"{value:.9g}")
    while low <= high:
        digits = (low + high) // 2
        candidate = float(f"{value:.{digits}g}")
        try:
            same = unpack(pack(candidate))[0] == value
        except OverflowError:  # rounded up past the largest finite value
            same = False
        if same:
            best, high = candidate, digits - 1
        else:
            low = digits + 1
    return best
