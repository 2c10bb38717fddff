"""The one rule for numbers, by destination, decided by the schema, never by the value.

- Machine formats (JSON lines, CSV, Parquet, Arrow, ``to_builtin``) carry the exact decoded
  value: a float as Python's ``repr`` of it (`exact`), ``1023.984375``, a float16 field's
  ``298.25``, a float32 field's ``0.10000000149011612``. JSON has no NaN or infinity: they
  are the strings `NAN`, `INFINITY` and `MINUS_INFINITY` (``"NaN"``, ``"Infinity"``,
  ``"-Infinity"``), in CSV the same words; a missing value stays ``null`` (an empty cell).
- Text for people (``decode``'s text, ``monitor``, HTML views) may show the shortest decimal
  that reads back as the same float **at the field's declared width** (`for_people`):
  float16 and float32 fields as the DSDL or the Veronte layout declares them; a float64 (a
  DBC signal, a scaled Veronte field) as its ``repr``. The width comes from the field's
  declaration (`veronte4x.capture.readable.float_bits`), never from the value.
"""

from __future__ import annotations

import math
import struct

NAN = "NaN"
"""A NaN in JSON lines and CSV."""
INFINITY = "Infinity"
"""Positive infinity in JSON lines and CSV."""
MINUS_INFINITY = "-Infinity"
"""Negative infinity in JSON lines and CSV."""

_PACK = {16: struct.Struct("<e"), 32: struct.Struct("<f")}
_CACHE: dict[int, dict[float, float]] = {16: {}, 32: {}}
_CACHE_SIZE = 1 << 16
"""Values remembered per width: telemetry repeats its values (a float16 has only 65536).
Zeros (whose two signs compare equal) and NaNs (equal to nothing) are never keys, so two
keys are equal only when their bits are."""


def exact(value: float) -> float | str:
    """A float as machine formats carry it: itself when finite (written as its ``repr``),
    else `NAN`, `INFINITY` or `MINUS_INFINITY`.

    Examples:
        >>> exact(1023.984375), exact(-0.0), exact(float("nan")), exact(float("-inf"))
        (1023.984375, -0.0, 'NaN', '-Infinity')
    """
    if value - value == 0.0:  # finite: inf - inf and NaN - NaN are NaN
        return value
    if value != value:
        return NAN
    return INFINITY if value > 0 else MINUS_INFINITY


def for_people(value: float, bits: int) -> float:
    """A float as text for people shows it: the shortest form at its declared width.

    ``bits`` is the field's declared width, 16, 32 or 64; a float64 comes back unchanged.

    Examples:
        >>> for_people(0.10000000149011612, 32), for_people(0.10000000149011612, 64)
        (0.1, 0.10000000149011612)
        >>> for_people(1023.984375, 32), for_people(1023.984375, 64)
        (1023.9844, 1023.984375)
    """
    return value if bits == 64 else shortest(value, bits)


def shortest(value: float, bits: int = 32) -> float:
    """The float with the shortest decimal form that rounds to the same ``bits``-bit float.

    For a float32 field the decoder holds the exact float32 value, ``0.10000000149011612``;
    its shortest form is ``0.1``. A value that is not a ``bits``-bit float (or not finite)
    comes back unchanged, and so does a zero, with its sign. For text only: use
    `for_people`, which takes the field's declared width.

    Examples:
        >>> shortest(0.10000000149011612)
        0.1
        >>> shortest(1.0009765625, 16), shortest(1.0009765625, 32)
        (1.001, 1.0009766)
    """
    if not value:  # 0.0 and -0.0 are their own shortest forms
        return value
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
