"""candump text to `FrameColumns`, column-wise.

The whole text is one NumPy byte array. Line breaks, spaces and ``#`` are found in one pass
each; every line of the plain log form (``(seconds) interface ID#DATA``, a classic frame,
not an error frame) is then cut, checked and converted for all lines at once: timestamps to
the float the per-frame reader's ``float()`` gives (an exact integer mantissa divided by a
power of ten, one correctly rounded division), identifiers and data from hex through a
lookup table. Every other line (the human view, remote, FD and error frames, raw DLCs, odd
lines) goes through the per-frame reader's own `parse_line`, so that both paths agree
line for line.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass
from typing import BinaryIO

import numpy as np
import numpy.typing as npt

from veronte4x.capture.columnar.frames import MAX_DATA, FrameColumns, concat, from_frames
from veronte4x.capture.frames import BadLine, Frame
from veronte4x.capture.readers.candump import parse_candump

_STAMP = 24
"""Most characters of a timestamp the column parser reads; longer ones go line by line."""
_INTERFACE = 16
"""Most characters of an interface name the column parser reads."""

_NIBBLE = np.full(256, 255, np.uint8)
for _digit, _char in enumerate(b"0123456789abcdef"):
    _NIBBLE[_char] = _digit
for _digit, _char in enumerate(b"ABCDEF", 10):
    _NIBBLE[_char] = _digit
_ODD = np.zeros(256, np.bool_)
"""Bytes that make a line the per-line parser's: other white space than the space (the
per-frame reader splits on it too) and non-ASCII bytes (decoded with replacement there)."""
_ODD[[9, 11, 12, 28, 29, 30, 31]] = True
_ODD[128:] = True
_PAD = 32
"""Line breaks after the text, more than the widest window."""
_POW10 = 10 ** np.arange(19, dtype=np.int64)
_POW10F = 10.0 ** np.arange(23)
_EXACT = 1 << 53
"""Mantissas below this convert to float64 exactly."""


def parse_text(text: bytes, first_line: int = 1) -> FrameColumns | None:
    """Parse candump text into columns.

    Args:
        text: Whole lines of candump text (a last line without a break is taken whole).
        first_line: Line number of the first line.

    Returns:
        The frames and bad lines, or None when the text has a lone carriage return (a line
        break to the per-frame reader that this parser does not split on).
    """
    a = np.full(len(text) + 1 + _PAD, 10, np.uint8)
    a[: len(text)] = np.frombuffer(text, np.uint8)
    size = len(text) + (not text.endswith(b"\n"))
    breaks = np.flatnonzero(a[:size] == 10)
    starts = np.empty(len(breaks), np.int64)
    starts[0] = 0
    starts[1:] = breaks[:-1] + 1
    ends = breaks.copy()
    returns = np.flatnonzero(a == 13)
    if len(returns):
        if not (a[returns + 1] == 10).all():
            return None
        ends[np.searchsorted(breaks, returns)] -= 1
    fast = _log_lines(a, starts, ends)
    slow = np.ones(len(starts), np.bool_)
    slow[fast.line] = False
    slow &= ends > starts
    columns = fast.columns(first_line)
    lines = np.flatnonzero(slow)
    if not len(lines):
        return columns
    items: list[tuple[int, Frame | BadLine]] = []
    for line in lines.tolist():
        raw = text[starts[line] : ends[line]].decode("utf-8", "replace")
        for item in parse_candump((raw,), first_line=first_line + line):
            items.append((first_line + line, item))
    return concat([columns, from_frames(items)])


@dataclass
class _LogLines:
    """The log-form lines of a text the column parser took, one row each."""

    line: npt.NDArray[np.int64]
    stamp: npt.NDArray[np.float64]
    interface: npt.NDArray[np.int32]
    interfaces: list[str]
    can_id: npt.NDArray[np.uint32]
    extended: npt.NDArray[np.bool_]
    length: npt.NDArray[np.int64]
    data: npt.NDArray[np.uint8]

    def columns(self, first_line: int) -> FrameColumns:
        n = len(self.line)
        no = np.zeros(n, np.bool_)
        return FrameColumns(
            order=self.line + first_line,
            timestamp=self.stamp,
            has_time=np.ones(n, np.bool_),
            channel=self.interface,
            channels=self.interfaces,
            can_id=self.can_id,
            extended=self.extended,
            remote=no,
            fd=no,
            error=no,
            length=self.length,
            data=self.data,
        )


def _window(a: npt.NDArray[np.uint8], at: npt.NDArray[np.int64], width: int) -> np.ndarray:
    """``width`` bytes from each position; the text ends in `_PAD` line breaks, so that a
    window never runs past it."""
    return np.lib.stride_tricks.sliding_window_view(a, width)[at]


def _log_lines(
    a: npt.NDArray[np.uint8], starts: npt.NDArray[np.int64], ends: npt.NDArray[np.int64]
) -> _LogLines:
    lines = len(starts)
    ok = a[starts] == 40  # "("
    body = a[: ends[-1] + 1]
    controls = np.count_nonzero(body < 32) - lines - np.count_nonzero(body == 13)
    if controls or body.max() >= 128:
        odd = np.flatnonzero(_ODD[body])
        ok[np.searchsorted(ends, odd)] = False
    spaces = np.flatnonzero(body == 32)
    spaces = np.append(spaces, len(a) - 1)  # a sentinel in the padding
    first = np.searchsorted(spaces, starts)
    ok &= np.searchsorted(spaces, ends) - first == 2  # exactly two spaces
    second = np.minimum(first + 1, len(spaces) - 1)
    space1, space2 = spaces[first], spaces[second]
    hashes = np.append(np.flatnonzero(body == 35), [len(a) - 1, len(a) - 1])
    at_hash = np.searchsorted(hashes, space2)
    hash1, hash2 = hashes[at_hash], hashes[at_hash + 1]
    ok &= (hash1 < ends) & (hash2 >= ends)  # one "#", in the third field
    stamp_size = space1 - starts - 2
    id_size = hash1 - space2 - 1
    data_size = ends - hash1 - 1
    ok &= (stamp_size > 0) & (stamp_size <= _STAMP)
    ok &= (space2 - space1 > 1) & (space2 - space1 <= _INTERFACE + 1)
    ok &= (id_size == 3) | (id_size == 8)
    ok &= (data_size >= 0) & (data_size <= 2 * MAX_DATA) & (data_size % 2 == 0)
    ok &= a[np.maximum(space1 - 1, 0)] == 41  # ")"
    rows = np.flatnonzero(ok)
    space1, space2, hash1 = space1[rows], space2[rows], hash1[rows]
    stamp, good = _stamps(a, starts[rows] + 1, stamp_size[rows])
    can_id, extended, good_id = _identifiers(_window(a, space2 + 1, 8), id_size[rows])
    size = data_size[rows]
    data, good_data = _data(_window(a, hash1 + 1, 2 * MAX_DATA), size)
    interface, names = _interfaces(_window(a, space1 + 1, _INTERFACE), space2 - space1 - 1)
    good &= good_id & good_data
    if good.all():
        return _LogLines(rows, stamp, interface, names, can_id, extended, size // 2, data)
    keep = np.flatnonzero(good)
    return _LogLines(
        rows[keep], stamp[keep], interface[keep], names, can_id[keep], extended[keep],
        size[keep] // 2, data[keep],
    )  # fmt: skip


def _stamps(
    a: npt.NDArray[np.uint8], at: npt.NDArray[np.int64], sizes: npt.NDArray[np.int64]
) -> tuple[np.ndarray, np.ndarray]:
    """Decimal ``digits[.digits]`` to float64, exactly as ``float()``; others not good.

    The timestamps of a capture share one shape (``1436509052.249713``): those of the first
    one's shape go through a fixed-width window and one exact floating-point dot product
    (every partial sum is an integer below 2**53); the rest through `_stamps_any`.
    """
    stamp = np.zeros(len(at))
    good = np.zeros(len(at), np.bool_)
    if not len(at):
        return stamp, good
    size = int(sizes[0])
    window = _window(a, at[:1], size)[0]
    dots = np.flatnonzero(window == 46)
    same = sizes == size
    rows = np.flatnonzero(same)
    chars = _window(a, at[rows], size)
    columns = np.ones(size, np.bool_)
    if len(dots) == 1:
        dot = int(dots[0])
        columns[dot] = False
        fraction = size - 1 - dot
        shaped = chars[:, dot] == 46
    else:
        fraction = 0
        shaped = np.ones(len(rows), np.bool_)
    count = int(columns.sum())
    if 0 < count <= 16:
        padded = np.full((len(rows), 16), 48, np.uint8)  # "0"
        padded[:, 16 - count :] = chars[:, columns]
        words = padded.view("<u8")
        high, high_ok = _eight_digits(words[:, 0])
        low, low_ok = _eight_digits(words[:, 1])
        mantissa = high * np.uint64(100_000_000) + low
        shaped &= high_ok & low_ok & (mantissa < _EXACT)
        stamp[rows] = mantissa.astype(np.float64) / _POW10F[fraction]
        good[rows] = shaped
    rest = np.flatnonzero(~good)
    if len(rest):
        stamp[rest], good[rest] = _stamps_any(_window(a, at[rest], _STAMP), sizes[rest])
    return stamp, good


def _eight_digits(words: npt.NDArray[np.uint64]) -> tuple[np.ndarray, np.ndarray]:
    """Eight ASCII digits per word (first digit in the lowest byte) to their value, and
    whether all eight are digits: three multiply-shift steps that combine neighbours."""
    valid = (words + np.uint64(0x4646464646464646)) | (words - np.uint64(0x3030303030303030))
    valid = (valid & np.uint64(0x8080808080808080)) == 0
    value = words & np.uint64(0x0F0F0F0F0F0F0F0F)
    value = (value * np.uint64(2561)) >> np.uint64(8)
    value = ((value & np.uint64(0x00FF00FF00FF00FF)) * np.uint64(6553601)) >> np.uint64(16)
    value = ((value & np.uint64(0x0000FFFF0000FFFF)) * np.uint64(42949672960001)) >> np.uint64(32)
    return value & np.uint64(0xFFFFFFFF), valid


def _stamps_any(chars: np.ndarray, sizes: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """`_stamps` for timestamps of any shape, up to `_STAMP` characters."""
    inside = np.arange(chars.shape[1]) < sizes[:, None]
    digits = chars - np.uint8(48)
    is_digit = (digits < 10) & inside
    dots = (chars == 46) & inside
    counted = np.cumsum(is_digit, axis=1, dtype=np.int8)
    total = counted[:, -1].astype(np.int64)
    good = (is_digit | dots | ~inside).all(axis=1) & (dots.sum(axis=1) <= 1) & (total > 0)
    good &= total <= 18
    power = np.where(is_digit, np.minimum(total[:, None] - counted, 18), 0)
    mantissa = (np.where(is_digit, digits, 0).astype(np.int64) * _POW10[power]).sum(axis=1)
    before_dot = np.where(dots.any(axis=1), (counted * dots).sum(axis=1), total)
    good &= mantissa < _EXACT
    return mantissa / _POW10F[np.minimum(total - before_dot, 22)], good


def _identifiers(chars: np.ndarray, sizes: np.ndarray) -> tuple[np.ndarray, ...]:
    """3 or 8 hex digits to the identifier; error frames (bit 29) are not good."""
    nibbles = _NIBBLE[chars]
    long = sizes == 8
    nibbles[~long, 3:] = 0
    good = (nibbles.view(np.uint64)[:, 0] & 0xF0F0F0F0F0F0F0F0) == 0
    n = nibbles.astype(np.uint32)
    short_id = n[:, 0] << 8 | n[:, 1] << 4 | n[:, 2]
    long_id = short_id << 20 | n[:, 3] << 16 | n[:, 4] << 12 | n[:, 5] << 8 | n[:, 6] << 4 | n[:, 7]
    can_id = np.where(long, long_id, short_id)
    good &= (can_id & 0x2000_0000) == 0
    return can_id, long, good


def _data(chars: np.ndarray, sizes: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Up to 16 hex digits to up to 8 bytes, zero-padded."""
    nibbles = _NIBBLE[chars]
    bad = np.packbits(nibbles > 15, axis=1, bitorder="little").view("<u2")[:, 0]
    good = (bad & ((1 << sizes) - 1).astype(np.uint16)) == 0
    data = (nibbles[:, 0::2] << 4) | (nibbles[:, 1::2] & 15)
    data[np.arange(MAX_DATA) >= (sizes // 2)[:, None]] = 0
    return data, good


def _interfaces(chars: np.ndarray, sizes: np.ndarray) -> tuple[np.ndarray, list[str]]:
    """Interface names to codes: one pass per distinct name."""
    chars = np.where(np.arange(_INTERFACE) < sizes[:, None], chars, 0).astype(np.uint8)
    words = chars.view("<u8")
    low, high = np.ascontiguousarray(words[:, 0]), np.ascontiguousarray(words[:, 1])
    codes = np.full(len(chars), -1, np.int32)
    names: list[str] = []
    left = np.flatnonzero(codes < 0)
    while len(left):
        row = left[0]
        same = np.flatnonzero((low == low[row]) & (high == high[row]) & (codes < 0))
        codes[same] = len(names)
        names.append(chars[row, : sizes[row]].tobytes().decode("ascii"))
        left = np.flatnonzero(codes < 0)
    return codes, names


BLOCK = 1 << 22
"""Bytes of text parsed at once: small enough for the processor's caches."""


def parse_stream(stream: BinaryIO) -> FrameColumns | None:
    """Parse candump text from a binary stream, block by block; see `parse_text`."""
    parts: list[FrameColumns] = []
    line = 1
    for block in _blocks(stream):
        part = parse_text(block, line)
        if part is None:
            return None
        parts.append(part)
        line += block.count(b"\n") + (not block.endswith(b"\n"))
    return concat(parts) if parts else parse_text(b"")


def _blocks(stream: BinaryIO) -> Iterator[bytes]:
    """Blocks of about `BLOCK` bytes that end at a line break (the last one may not)."""
    rest = b""
    while True:
        chunk = stream.read(BLOCK)
        if not chunk:
            if rest:
                yield rest
            return
        block = rest + chunk
        cut = block.rfind(b"\n")
        if cut < 0:
            rest = block
            continue
        rest = block[cut + 1 :]
        yield block[: cut + 1]
