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
    rows = np.flatnonzero(fast.ok)
    slow = np.flatnonzero(~fast.ok & (ends > starts))
    columns = fast.columns(rows, first_line)
    if not len(slow):
        return columns
    items: list[tuple[int, Frame | BadLine]] = []
    for line in slow.tolist():
        raw = text[starts[line] : ends[line]].decode("utf-8", "replace")
        for item in parse_candump((raw,), first_line=first_line + line):
            items.append((first_line + line, item))
    return concat([columns, from_frames(items)])


class _LogLines:
    """The log-form lines of a text, parsed column-wise; `ok` marks the lines it took."""

    def __init__(self) -> None:
        self.ok: npt.NDArray[np.bool_] = np.zeros(0, np.bool_)
        self.stamp: npt.NDArray[np.float64] = np.zeros(0)
        self.interface: npt.NDArray[np.int32] = np.zeros(0, np.int32)
        self.interfaces: list[str] = []
        self.can_id: npt.NDArray[np.uint32] = np.zeros(0, np.uint32)
        self.extended: npt.NDArray[np.bool_] = np.zeros(0, np.bool_)
        self.length: npt.NDArray[np.int64] = np.zeros(0, np.int64)
        self.data: npt.NDArray[np.uint8] = np.zeros((0, MAX_DATA), np.uint8)

    def columns(self, rows: npt.NDArray[np.int64], first_line: int) -> FrameColumns:
        n = len(rows)
        no = np.zeros(n, np.bool_)
        return FrameColumns(
            order=rows + first_line,
            timestamp=self.stamp[rows],
            has_time=np.ones(n, np.bool_),
            channel=self.interface[rows],
            channels=self.interfaces,
            can_id=self.can_id[rows],
            extended=self.extended[rows],
            remote=no,
            fd=no,
            error=no,
            length=self.length[rows],
            data=self.data[rows],
        )


def _window(a: npt.NDArray[np.uint8], at: npt.NDArray[np.int64], width: int) -> np.ndarray:
    """``width`` bytes from each position; the text ends in `_PAD` line breaks, so that a
    window never runs past it."""
    return np.lib.stride_tricks.sliding_window_view(a, width)[at]


def _log_lines(
    a: npt.NDArray[np.uint8], starts: npt.NDArray[np.int64], ends: npt.NDArray[np.int64]
) -> _LogLines:
    out = _LogLines()
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
    stamp, good = _stamps(a, starts[rows] + 1, stamp_size[rows])
    can_id, extended, good_id = _identifiers(_window(a, space2[rows] + 1, 8), id_size[rows])
    data, good_data = _data(_window(a, hash1[rows] + 1, 2 * MAX_DATA), data_size[rows])
    interface, names = _interfaces(
        _window(a, space1[rows] + 1, _INTERFACE), space2[rows] - space1[rows] - 1
    )
    good &= good_id & good_data
    ok[rows] = good
    out.ok = ok
    out.stamp = _scatter(rows, stamp, lines, np.float64)
    out.can_id = _scatter(rows, can_id, lines, np.uint32)
    out.extended = _scatter(rows, extended, lines, np.bool_)
    out.length = _scatter(rows, data_size[rows] // 2, lines, np.int64)
    out.interface = _scatter(rows, interface, lines, np.int32)
    out.interfaces = names
    full = np.zeros((lines, MAX_DATA), np.uint8)
    full[rows] = data
    out.data = full
    return out


def _scatter(rows: np.ndarray, values: np.ndarray, size: int, dtype: type) -> np.ndarray:
    out: np.ndarray = np.zeros(size, dtype)
    out[rows] = values
    return out


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
    digits = chars - np.uint8(48)
    weights = np.zeros(size)
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
    if 0 < count <= 17:
        weights[columns] = 10.0 ** np.arange(count - 1, -1, -1)
        shaped &= (digits[:, columns] < 10).all(axis=1)
        mantissa = digits.astype(np.float64) @ weights  # exact below 2**53, else >= 2**53
        stamp[rows] = mantissa / _POW10F[fraction]
        good[rows] = shaped & (mantissa < _EXACT)
    rest = np.flatnonzero(~good)
    if len(rest):
        stamp[rest], good[rest] = _stamps_any(_window(a, at[rest], _STAMP), sizes[rest])
    return stamp, good


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
    power = np.where(is_digit, total[:, None] - counted, 0)
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
    nibbles[np.arange(2 * MAX_DATA) >= sizes[:, None]] = 0
    words = nibbles.view(np.uint64)
    good = ((words[:, 0] | words[:, 1]) & 0xF0F0F0F0F0F0F0F0) == 0
    return (nibbles[:, 0::2] << 4) | nibbles[:, 1::2], good


def _interfaces(chars: np.ndarray, sizes: np.ndarray) -> tuple[np.ndarray, list[str]]:
    """Interface names to codes: one pass per distinct name."""
    inside = np.arange(_INTERFACE) < sizes[:, None]
    chars = np.where(inside, chars, 0).astype(np.uint8)
    keys = np.ascontiguousarray(chars).view(np.uint64)
    codes = np.full(len(chars), -1, np.int32)
    names: list[str] = []
    left = np.arange(len(chars))
    while len(left):
        row = left[0]
        same = (keys[left] == keys[row]).all(axis=1)
        codes[left[same]] = len(names)
        names.append(chars[row, : sizes[row]].tobytes().decode("ascii"))
        left = left[~same]
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
