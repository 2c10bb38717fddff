"""Numbers as people read them: a float as the shortest decimal that reads back the same."""

from __future__ import annotations

import math
import struct

_PACK = {16: struct.Struct("<e"), 32: struct.Struct("<f")}


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
    packer = _PACK[bits]
    try:
        single = packer.unpack(packer.pack(value))[0]
    except (OverflowError, struct.error):
        return value
    if single != value or not math.isfinite(value):
        return value
    for digits in range(1, 18):
        candidate = float(f"{value:.{digits}g}")
        try:
            if packer.unpack(packer.pack(candidate))[0] == value:
                return candidate
        except OverflowError:  # rounded up past the largest finite value
            continue
    return value  # pragma: no cover - 9 digits always suffice for a float32
