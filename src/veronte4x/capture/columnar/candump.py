"""candump text to `FrameColumns`, column-wise.

The whole text is one NumPy byte array. Line breaks, spaces and ``#`` are found in one pass
each; every line of the plain log form (``(seconds) interface ID#DATA``, a classic frame,
not an error frame) is then cut, checked and converted for all lines at once: timestamps to
the float the per-frame reader's ``float()`` gives (an exact integer mantissa divided by a
power of ten, one correctly rounded division) and, from the same integer, to the exact
microseconds of the text; identifiers and data from hex through a lookup table. Every other
line (the human view, remote, FD and error frames, raw DLCs, odd lines, times with more
than six decimals or past 2242) goes through the per-frame reader's own `parse_line`, so
that both paths agree line for line.
"""

from __future__ import annotations

import os
from collections import deque
from collections.abc import Callable, Iterator
from concurrent.futures import Future, ThreadPoolExecutor
from dataclasses import dataclass
from typing import BinaryIO

import numpy as np
import numpy.typing as npt

from veronte4x.capture.columnar.frames import (
    MAX_DATA,
    NO_TIME,
    FrameColumns,
    concat,
    from_frames,
)
from veronte4x.capture.frames import BadLine, Frame
from veronte4x.capture.readers.candump import parse_candump

_STAMP = 24
"""Most characters of a timestamp the column parser reads; longer ones go line by line."""
_INTERFACE = 16
"""Most characters of an interface name the column parser reads."""

_ODD = np.zeros(256, np.bool_)
"""Bytes that make a line the per-line parser's: control characters (white space to the
per-frame reader's split, among others) and non-ASCII bytes (decoded with replacement
there). The column parser's byte arithmetic relies on lines having none."""
_ODD[:32] = True
_ODD[[10, 13]] = False
_ODD[128:] = True
_ONES = np.uint64(0x0101010101010101)
_HIGH = np.uint64(0x8080808080808080)
_PAD = 96
"""Line breaks after the text, more than the widest window (`_fixed_lines`' rows)."""
_POW10 = 10 ** np.arange(19, dtype=np.int64)
_POW10F = 10.0 ** np.arange(23)
_EXACT = 1 << 53
"""Mantissas below this convert to float64 exactly."""
_SAFE_MICROS = (1 << 33) * 1_000_000
"""Times below 2**33 seconds (year 2242) of at most six decimals: their float gives back
their microseconds. Others go line by line, where the reader keeps them exact."""


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
    return parse_block(a, len(text) + (not text.endswith(b"\n")), first_line)[0]


def parse_block(
    a: npt.NDArray[np.uint8], size: int, first_line: int
) -> tuple[FrameColumns | None, int]:
    """`parse_text` of ``a[:size]``: whole lines, each ending in a line break, followed by
    at least `_PAD` more line breaks. Also returns the number of lines.

    Lines of one fixed layout (`_fixed_lines`) are read first, a few layouts at most; the
    other lines, if any, are copied into a text of their own for `_parse_any`."""
    a = a[: size + _PAD]
    breaks = np.flatnonzero(a[:size] == 10)
    starts = np.empty(len(breaks), np.int64)
    starts[0] = 0
    starts[1:] = breaks[:-1] + 1
    ends = breaks - (a[np.maximum(breaks - 1, 0)] == 13)  # a CR before the line break
    ends = np.maximum(ends, starts)
    rest = np.flatnonzero(ends > starts)
    if not len(rest):  # blank lines only
        return _parse_any(a, size, first_line)
    parts = []
    for _ in range(_LAYOUTS):
        layout = _layout(a, starts, ends, rest)
        if layout is None:
            break
        found, failed = _fixed_lines(a, starts[rest], ends[rest], layout)
        found.line = rest[found.line]
        if len(found.line):
            parts.append(found.columns(first_line))
        rest = rest[failed]
        if not len(rest):
            return concat(parts), len(breaks)
    if len(rest):
        # The other lines, each with its line break, one after the other.
        sizes = breaks[rest] + 1 - starts[rest]
        offsets = np.cumsum(sizes) - sizes
        index = np.arange(int(sizes.sum())) + np.repeat(starts[rest] - offsets, sizes)
        text = np.full(len(index) + _PAD, 10, np.uint8)
        text[: len(index)] = a[index]
        others, _ = _parse_any(text, len(index), 1)
        if others is None:
            return None, len(breaks)
        parts.append(_renumbered(others, rest + first_line))
    return concat(parts), len(breaks)


_LAYOUTS = 4
"""Fixed layouts tried per text (a log of merged captures may have several)."""


def _renumbered(columns: FrameColumns, lines: npt.NDArray[np.int64]) -> FrameColumns:
    """Columns of a text made of some lines of another, numbered from 1, given the line
    numbers of those lines in the other text (``lines[k]``: the number of its line k+1)."""
    columns.order = lines[columns.order - 1]
    columns.bad_lines = [
        (int(lines[order - 1]), bad._replace(line_number=int(lines[bad.line_number - 1])))
        for order, bad in columns.bad_lines
    ]
    return columns


def _parse_any(
    a: npt.NDArray[np.uint8], size: int, first_line: int
) -> tuple[FrameColumns | None, int]:
    """`parse_block` for lines of any form: every field found by where the text's spaces and
    "#" are."""
    a = a[: size + _PAD]
    breaks = np.flatnonzero(a[:size] == 10)
    starts = np.empty(len(breaks), np.int64)
    starts[0] = 0
    starts[1:] = breaks[:-1] + 1
    ends = breaks.copy()
    returns = np.flatnonzero(a[:size] == 13)
    if len(returns):
        if not (a[returns + 1] == 10).all():
            return None, len(breaks)
        ends[np.searchsorted(breaks, returns)] -= 1
    clean = _clean_lines(a, starts, ends)
    hash_marks = np.flatnonzero(a[:size] == 35)  # "#": found once, for both forms
    fast = _log_lines(a, starts, ends, clean, hash_marks)
    slow = ends > starts
    slow[fast.line] = False
    parts = [fast.columns(first_line)]
    hashes = np.bincount(np.searchsorted(ends, hash_marks), minlength=len(starts))
    human = np.flatnonzero(slow & clean & (hashes[: len(starts)] == 0))
    if len(human):
        found = _human_lines(a, starts, ends, human)
        slow[found.line] = False
        parts.append(found.columns(first_line))
    columns = concat(parts)
    lines = np.flatnonzero(slow)
    if not len(lines):
        return columns, len(breaks)
    items: list[tuple[int, Frame | BadLine]] = []
    for line in lines.tolist():
        raw = a[starts[line] : ends[line]].tobytes().decode("utf-8", "replace")
        for item in parse_candump((raw,), first_line=first_line + line):
            items.append((first_line + line, item))
    return concat([columns, from_frames(items)]), len(breaks)


@dataclass(frozen=True)
class _Layout:
    """Where the fields of a log-form line are: ``(`` a timestamp of ``stamp`` characters
    with its dot at ``dot`` (-1 for none), ``) `` an interface name of ``name`` characters,
    a space, then the identifier."""

    stamp: int
    dot: int
    name: int

    @property
    def ident(self) -> int:
        """Where the identifier starts."""
        return self.stamp + self.name + 4


def _layout(
    a: npt.NDArray[np.uint8],
    starts: npt.NDArray[np.int64],
    ends: npt.NDArray[np.int64],
    lines: npt.NDArray[np.int64],
) -> _Layout | None:
    """The layout of the first of a few ``lines`` that has one `_fixed_lines` reads."""
    for line in lines[:8].tolist():
        text = a[starts[line] : ends[line]].tobytes()
        close = text.find(b") ")
        space = text.find(b" ", close + 2)
        stamp = text[1:close]
        if not text.startswith(b"(") or close < 0 or space < 0:
            continue
        digits = len(stamp) - stamp.count(b".")
        name = space - close - 2  # an empty name is no frame (the per-frame reader's rule)
        if stamp.replace(b".", b"", 1).isdigit() and digits <= 16 and 0 < name <= 16:
            return _Layout(len(stamp), stamp.find(b"."), name)
    return None


def _fixed_lines(
    a: npt.NDArray[np.uint8],
    starts: npt.NDArray[np.int64],
    ends: npt.NDArray[np.int64],
    layout: _Layout,
) -> tuple[_LogLines, npt.NDArray[np.int64]]:
    """The lines of the log form and of one layout, every character checked where it must
    be; also returns the others (as indices into ``starts``).

    Each line is copied into a row of a matrix, and each field read at its fixed place in
    the rows (an identifier of 3 or 8 digits moves the data: both places are read), so
    that no search over the text is needed. A line taken here is one `_log_lines` takes,
    with the same values."""
    ident = layout.ident
    width = ident + 33  # a word read at the last data digit stays in the row
    rows = np.lib.stride_tricks.sliding_window_view(a, width)[starts]
    words: npt.NDArray[np.uint64] = np.ndarray(
        shape=(len(starts), width - 7), dtype="<u8", buffer=rows, strides=(width, 1)
    )
    close = layout.stamp + 1
    ok = rows[:, 0] == 40  # "("
    ok &= (rows[:, close] == 41) & (rows[:, close + 1] == 32) & (rows[:, ident - 1] == 32)
    short = rows[:, ident + 3] == 35  # "#" after 3 digits
    ok &= short | (rows[:, ident + 8] == 35)
    data_size = ends - starts - np.where(short, ident + 4, ident + 9)
    ok &= (data_size >= 0) & (data_size <= 2 * MAX_DATA) & (data_size % 2 == 0)
    stamp, micros, good = _shaped_stamps(words, layout, len(starts))
    ok &= good
    can_id, extended, good = _identifiers(words[:, ident], np.where(short, 3, 8), strict=True)
    ok &= good
    data, good = _data(
        np.where(short, words[:, ident + 4], words[:, ident + 9]),
        np.where(short, words[:, ident + 12], words[:, ident + 17]),
        data_size,
        strict=True,
    )
    ok &= good
    taken = np.flatnonzero(ok)
    names_at = close + 2
    interface, names = _interfaces(
        words[taken, names_at],
        words[taken, names_at + 8],
        np.full(len(taken), layout.name, np.int64),
    )
    named = np.array([_plain_name(name) for name in names] or [True], np.bool_)
    if not named.all():
        ok[taken[~named[interface]]] = False
        keep = np.flatnonzero(named[interface])
        taken, interface = taken[keep], interface[keep]
    data_bytes = data.view(np.uint8).reshape(-1, MAX_DATA)
    if len(taken) == len(starts):  # every line (as most often): no copies
        lines = _LogLines(
            taken, stamp, interface, names, can_id, extended, data_size // 2, data_bytes, micros
        )
        return lines, np.zeros(0, np.int64)
    lines = _LogLines(
        taken,
        stamp[taken],
        interface,
        names,
        can_id[taken],
        extended[taken],
        data_size[taken] // 2,
        data_bytes[taken],
        micros[taken],
    )
    return lines, np.flatnonzero(~ok)


def _plain_name(name: str) -> bool:
    """An interface name `_fixed_lines` takes: printable ASCII, no space and no "#", not
    empty."""
    return bool(name) and all(33 <= ord(c) <= 126 and c != "#" for c in name)


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
    micros: npt.NDArray[np.int64]
    has_time: npt.NDArray[np.bool_] | None = None

    def columns(self, first_line: int) -> FrameColumns:
        n = len(self.line)
        no = np.zeros(n, np.bool_)
        has_time = np.ones(n, np.bool_) if self.has_time is None else self.has_time
        return FrameColumns(
            order=self.line + first_line,
            timestamp=self.stamp,
            has_time=has_time,
            channel=self.interface,
            channels=self.interfaces,
            can_id=self.can_id,
            extended=self.extended,
            remote=no,
            fd=no,
            error=no,
            length=self.length,
            data=self.data,
            time=np.where(has_time, self.micros, NO_TIME),
        )


def _window(a: npt.NDArray[np.uint8], at: npt.NDArray[np.int64], width: int) -> np.ndarray:
    """``width`` bytes from each position; the text ends in `_PAD` line breaks, so that a
    window never runs past it."""
    return np.lib.stride_tricks.sliding_window_view(a, width)[at]


def _clean_lines(
    a: npt.NDArray[np.uint8], starts: npt.NDArray[np.int64], ends: npt.NDArray[np.int64]
) -> npt.NDArray[np.bool_]:
    """Lines with no control character and no non-ASCII byte (see `_ODD`)."""
    clean = np.ones(len(starts), np.bool_)
    body = a[: ends[-1] + 1]
    # Line breaks are not odd (the last line's may lie past ``body`` when it is CRLF).
    breaks = np.count_nonzero(body == 10) + np.count_nonzero(body == 13)
    controls = np.count_nonzero(body < 32) - breaks
    if controls or body.max() >= 128:
        clean[np.searchsorted(ends, np.flatnonzero(_ODD[body]))] = False
    return clean


def _log_lines(
    a: npt.NDArray[np.uint8],
    starts: npt.NDArray[np.int64],
    ends: npt.NDArray[np.int64],
    clean: npt.NDArray[np.bool_],
    hash_marks: npt.NDArray[np.int64],
) -> _LogLines:
    """The plain log-form lines: ``(seconds) interface ID#DATA``, a classic data frame
    (``hash_marks``: where the text has a "#")."""
    ok = clean & (a[starts] == 40)  # "("
    body = a[: ends[-1] + 1]
    spaces = np.flatnonzero(body == 32)
    spaces = np.append(spaces, len(a) - 1)  # a sentinel in the padding
    first = np.searchsorted(spaces, starts)
    ok &= np.searchsorted(spaces, ends) - first == 2  # exactly two spaces
    second = np.minimum(first + 1, len(spaces) - 1)
    space1, space2 = spaces[first], spaces[second]
    hashes = np.append(hash_marks, [len(a) - 1, len(a) - 1])
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
    words = _words(a)
    space1, space2, hash1 = space1[rows], space2[rows], hash1[rows]
    stamp, micros, good = _stamps(a, words, starts[rows] + 1, stamp_size[rows])
    can_id, extended, good_id = _identifiers(words[space2 + 1], id_size[rows])
    size = data_size[rows]
    data, good_data = _data(words[hash1 + 1], words[hash1 + 9], size)
    interface, names = _interfaces(words[space1 + 1], words[space1 + 9], space2 - space1 - 1)
    good &= good_id & good_data
    data_bytes = data.view(np.uint8).reshape(-1, MAX_DATA)
    if good.all():
        return _LogLines(
            rows, stamp, interface, names, can_id, extended, size // 2, data_bytes, micros
        )
    keep = np.flatnonzero(good)
    return _LogLines(
        rows[keep],
        stamp[keep],
        interface[keep],
        names,
        can_id[keep],
        extended[keep],
        size[keep] // 2,
        data_bytes[keep],
        micros[keep],
    )


def _human_lines(
    a: npt.NDArray[np.uint8],
    starts: npt.NDArray[np.int64],
    ends: npt.NDArray[np.int64],
    lines: npt.NDArray[np.int64],
) -> _LogLines:
    """The plain human-view lines: ``[(time)] interface ID [n] XX XX ...``, a classic data
    frame and nothing after its bytes (lines with "#" are left to `parse_line`). The time is
    seconds (``candump -t a``, ``-t d``, ``-t z``) or ``YYYY-MM-DD HH:MM:SS.ffffff``
    (``-t A``)."""
    body = a[: ends[-1] + 1]
    separator = (body == 32) | (body == 10) | (body == 13)
    begins = ~separator
    begins[1:] &= separator[:-1]
    finishes = ~separator
    finishes[:-1] &= separator[1:]
    token_start = np.append(np.flatnonzero(begins), len(body))  # a sentinel token
    token_end = np.append(np.flatnonzero(finishes) + 1, len(body))
    last = len(token_start) - 1
    first = np.searchsorted(token_start, starts[lines])
    count = np.searchsorted(token_start, ends[lines]) - first
    stamped = (a[token_start[first]] == 40) & (count > 0)  # "("
    date_end = token_end[first]
    dated = stamped & (date_end - token_start[first] == 11) & (a[date_end - 3] == 45)  # "-"
    dated &= token_start[np.minimum(first + 1, last)] == date_end + 1
    dated &= token_end[np.minimum(first + 1, last)] == date_end + 17
    stamped = stamped.astype(np.int64) + dated  # tokens the time takes
    head = first + stamped  # the interface's token
    size_token = np.minimum(head + 2, last)
    size_at = token_start[size_token]
    size_len = token_end[size_token] - size_at
    words = _words(a)
    size_word = words[size_at]
    size_one = (size_len == 3) & ((size_word & np.uint64(0xFF00FF)) == np.uint64(0x5D005B))
    size = ((size_word >> np.uint64(8)) & np.uint64(0xFF)).astype(np.int64) - 48  # "[n]"
    ok = (count >= 3) & size_one & (size >= 0) & (size <= MAX_DATA)
    ok &= count == 3 + stamped + size
    rows = np.flatnonzero(ok)
    lines, first, head, size, stamped = (
        lines[rows],
        first[rows],
        head[rows],
        size[rows],
        stamped[rows],
    )
    ident = head + 1
    id_size = token_end[ident] - token_start[ident]
    iface_size = token_end[head] - token_start[head]
    can_id, extended, good = _identifiers(words[token_start[ident]], id_size)
    good &= ((id_size == 3) | (id_size == 8)) & (iface_size <= _INTERFACE)
    stamp = np.zeros(len(lines))
    micros = np.zeros(len(lines), np.int64)
    timed = np.flatnonzero(stamped == 1)
    if len(timed):
        at, end = token_start[first[timed]], token_end[first[timed]]
        good[timed] &= a[end - 1] == 41  # ")"
        stamp[timed], micros[timed], timed_ok = _stamps(a, words, at + 1, end - at - 2)
        good[timed] &= timed_ok & (end - at - 2 > 0) & (end - at - 2 <= _STAMP)
    dated_rows = np.flatnonzero(stamped == 2)
    if len(dated_rows):
        dated = _date_stamps(a, token_start[first[dated_rows]] + 1)
        stamp[dated_rows], micros[dated_rows], good_dates = dated
        good[dated_rows] &= good_dates
    # The data bytes: one two-character token each.
    owner = np.repeat(np.arange(len(lines)), size)
    position = np.arange(len(owner)) - np.repeat(np.cumsum(size) - size, size)
    token = head[owner] + 3 + position
    pair = words[token_start[token]]
    nibbles, pair_ok = _hex(pair, _MASKS[np.full(len(token), 2)])
    pair_ok &= token_end[token] - token_start[token] == 2
    value = ((nibbles & np.uint64(15)) << np.uint64(4)) | (
        (nibbles >> np.uint64(8)) & np.uint64(15)
    )
    good &= np.bincount(owner, weights=~pair_ok, minlength=len(lines)) == 0
    data = np.zeros((len(lines), MAX_DATA), np.uint8)
    data[owner, position] = value.astype(np.uint8)
    interface, names = _interfaces(
        words[token_start[head]], words[token_start[head] + 8], iface_size
    )
    keep = np.flatnonzero(good)
    return _LogLines(
        lines[keep],
        stamp[keep],
        interface[keep],
        names,
        can_id[keep],
        extended[keep],
        size[keep],
        data[keep],
        micros[keep],
        stamped[keep] > 0,
    )


_DAYS_IN_MONTH = np.array([0, 31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31], np.int64)


def _date_stamps(
    a: npt.NDArray[np.uint8], at: npt.NDArray[np.int64]
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``YYYY-MM-DD HH:MM:SS.ffffff)`` at ``at`` to seconds since the epoch (UTC), exactly as
    ``datetime.strptime(...).replace(tzinfo=utc).timestamp()`` gives them (whole
    microseconds divided once by a million), and to the microseconds. Dates ``datetime``
    refuses, and those past 2242, are not good."""
    digits = {k: a[at + k].astype(np.int64) - 48 for k in (*range(4), 5, 6, 8, 9)}
    digits.update({k: a[at + k].astype(np.int64) - 48 for k in (11, 12, 14, 15, 17, 18)})
    digits.update({k: a[at + k].astype(np.int64) - 48 for k in range(20, 26)})
    good = np.ones(len(at), np.bool_)
    for value in digits.values():
        good &= (value >= 0) & (value <= 9)
    for k, char in ((4, 45), (7, 45), (10, 32), (13, 58), (16, 58), (19, 46), (26, 41)):
        good &= a[at + k] == char

    def number(*places: int) -> np.ndarray:
        total = np.zeros(len(at), np.int64)
        for k in places:
            total = total * 10 + digits[k]
        return total

    year, month, day = number(0, 1, 2, 3), number(5, 6), number(8, 9)
    hour, minute, second = number(11, 12), number(14, 15), number(17, 18)
    micro = number(20, 21, 22, 23, 24, 25)
    leap = (year % 4 == 0) & ((year % 100 != 0) | (year % 400 == 0))
    month_ok = (month >= 1) & (month <= 12)
    length = _DAYS_IN_MONTH[np.where(month_ok, month, 0)] + (leap & (month == 2))
    good &= (year >= 1) & month_ok & (day >= 1) & (day <= length)
    good &= (hour <= 23) & (minute <= 59) & (second <= 59)
    # Days since 1970-01-01 of a proleptic Gregorian date (H. Hinnant's days_from_civil).
    shifted = year - (month <= 2)
    era = shifted // 400
    of_era = shifted - era * 400
    of_year = (153 * (month + np.where(month > 2, -3, 9)) + 2) // 5 + day - 1
    days = era * 146097 + of_era * 365 + of_era // 4 - of_era // 100 + of_year - 719468
    total = ((days * 86400 + hour * 3600 + minute * 60 + second) * 1_000_000) + micro
    good &= np.abs(total) < _SAFE_MICROS
    return total.astype(np.float64) / 1e6, total, good


def _words(a: npt.NDArray[np.uint8]) -> npt.NDArray[np.uint64]:
    """The eight bytes from every position of the text as one little-endian integer: an
    overlapping view, so that ``words[p]`` reads the eight characters at ``p``."""
    words: npt.NDArray[np.uint64] = np.ndarray(
        shape=(len(a) - 7,), dtype="<u8", buffer=a, strides=(1,)
    )
    return words


_MASKS = np.array([(1 << (8 * n)) - 1 for n in range(9)], np.uint64)


def _byte_mask(count: npt.NDArray[np.int64]) -> npt.NDArray[np.uint64]:
    """A mask of the ``count`` low bytes of a word (none below 0, all eight above 8)."""
    masks: npt.NDArray[np.uint64] = _MASKS[np.clip(count, 0, 8)]
    return masks


def _hex(
    word: npt.NDArray[np.uint64], mask: npt.NDArray[np.uint64], strict: bool = False
) -> tuple[np.ndarray, ...]:
    """Eight hex characters per word to their nibbles, one per byte, and whether every
    character under ``mask`` is a hex digit. The words hold no control character unless
    ``strict`` (control characters 0x10 to 0x19 would pass for digits; a non-ASCII byte
    never passes, and its carries reach only the bytes after it)."""
    lower = word | (_ONES * np.uint64(0x20))
    digit = (lower + _ONES * np.uint64(0x50)) & ~(lower + _ONES * np.uint64(0x46))
    letter = (lower + _ONES * np.uint64(0x1F)) & ~(lower + _ONES * np.uint64(0x19))
    good = (~(digit | letter) & mask & _HIGH) == 0
    if strict:  # a hex digit has bit 5 or bit 6 set, a control character neither
        marked = ((word >> np.uint64(5)) | (word >> np.uint64(6))) & mask & _ONES
        good &= marked == (mask & _ONES)
    nibbles = (lower & (_ONES * np.uint64(15))) + np.uint64(9) * ((lower >> np.uint64(6)) & _ONES)
    return nibbles, good


def _pack(nibbles: npt.NDArray[np.uint64]) -> npt.NDArray[np.uint64]:
    """Eight nibbles, one per byte, to the four bytes they spell (first nibble high)."""
    pairs = ((nibbles << np.uint64(4)) | (nibbles >> np.uint64(8))) & np.uint64(0x00FF00FF00FF00FF)
    pairs = (pairs | (pairs >> np.uint64(8))) & np.uint64(0x0000FFFF0000FFFF)
    packed: npt.NDArray[np.uint64] = (pairs | (pairs >> np.uint64(16))) & np.uint64(0xFFFFFFFF)
    return packed


def _stamps(
    a: npt.NDArray[np.uint8],
    words: npt.NDArray[np.uint64],
    at: npt.NDArray[np.int64],
    sizes: npt.NDArray[np.int64],
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Decimal ``digits[.digits]`` to float64, exactly as ``float()``, and to whole
    microseconds; others, and those `_SAFE_MICROS` leaves out, not good.

    The timestamps of a capture share one shape (``1436509052.249713``): for those of the
    first one's shape, the digits are moved into two words of eight (zero-padded in front)
    with a few shifts, converted eight at a time, and the exact integer divided by a power
    of ten once; the rest go through `_stamps_any`.
    """
    stamp = np.zeros(len(at))
    micros = np.zeros(len(at), np.int64)
    good = np.zeros(len(at), np.bool_)
    if not len(at):
        return stamp, micros, good
    size = int(sizes[0])
    shape = bytes(a[at[0] : at[0] + size])
    dot = shape.find(b".")
    digits = size - (dot >= 0)
    rows = np.flatnonzero(sizes == size)
    if 0 < digits <= 16 and shape.count(b".") <= 1:
        base = at[rows]
        stamp[rows], micros[rows], shaped = _shaped(lambda k: words[base + k], size, dot, len(rows))
        if dot >= 0:
            shaped &= a[base + dot] == 46
        good[rows] = shaped
    rest = np.flatnonzero(~good)
    if len(rest):
        stamp[rest], micros[rest], good[rest] = _stamps_any(
            _window(a, at[rest], _STAMP), sizes[rest]
        )
    return stamp, micros, good


def _shaped(
    word_at: Callable[[int], npt.NDArray[np.uint64]], size: int, dot: int, count: int
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """`_stamps` of ``count`` timestamps of one shape: ``size`` characters, digits but for
    a dot at ``dot`` (-1: none, not checked here), at most 16 digits; ``word_at(k)``: the
    eight characters from the k-th of each. Gives the floats, microseconds and which are
    good."""
    digits = size - (dot >= 0)
    runs = [(0, dot), (dot + 1, size - dot - 1)] if dot >= 0 else [(0, size)]
    halves = [np.zeros(count, np.uint64), np.zeros(count, np.uint64)]
    pad = 16 - digits
    for half in range(2):
        zeros = [j - 8 * half for j in range(8 * half, 8 * half + 8) if j < pad]
        for j in zeros:
            halves[half] |= np.uint64(48) << np.uint64(8 * j)
    target = pad
    for source, length in runs:
        while length:
            half, offset = divmod(target, 8)
            piece = min(length, 8 - offset)
            mask = np.uint64((1 << (8 * piece)) - 1)
            halves[half] |= (word_at(source) & mask) << np.uint64(8 * offset)
            target, source, length = target + piece, source + piece, length - piece
    high, high_ok = _eight_digits(halves[0])
    low, low_ok = _eight_digits(halves[1])
    mantissa = high * np.uint64(100_000_000) + low
    decimals = size - dot - 1 if dot >= 0 else 0
    shaped = high_ok & low_ok & (mantissa < _EXACT) & (decimals <= 6)
    stamp = mantissa.astype(np.float64) / _POW10F[decimals]
    micros, safe = _micros(mantissa.astype(np.int64), np.full(count, decimals))
    return stamp, micros, shaped & safe


def _shaped_stamps(
    words: npt.NDArray[np.uint64], layout: _Layout, count: int
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The timestamps of lines of one layout (``words[:, k]``: each line's eight characters
    from its k-th), as `_stamps` gives them."""
    stamp, micros, good = _shaped(lambda k: words[:, 1 + k], layout.stamp, layout.dot, count)
    if layout.dot >= 0:
        good &= (words[:, 1 + layout.dot] & np.uint64(0xFF)) == np.uint64(46)
    return stamp, micros, good


def _micros(
    mantissa: npt.NDArray[np.int64], decimals: npt.NDArray[np.int64]
) -> tuple[npt.NDArray[np.int64], npt.NDArray[np.bool_]]:
    """``mantissa / 10**decimals`` seconds (mantissas from 0 to 2**53) in microseconds, and
    whether they are `_SAFE_MICROS`: up to six decimals, below 2**33 seconds (others 0)."""
    places = np.clip(decimals, 0, 6)
    safe = (decimals <= 6) & (mantissa < (1 << 33) * _POW10[places])
    micros = np.where(safe, mantissa, 0) * _POW10[6 - places]
    return micros, safe


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


def _stamps_any(chars: np.ndarray, sizes: np.ndarray) -> tuple[np.ndarray, ...]:
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
    decimals = total - before_dot
    micros, safe = _micros(mantissa, decimals)
    good &= safe
    return mantissa / _POW10F[np.minimum(decimals, 22)], micros, good


def _identifiers(
    word: np.ndarray, sizes: np.ndarray, strict: bool = False
) -> tuple[np.ndarray, ...]:
    """3 or 8 hex digits to the identifier; error frames (bit 29) are not good (``strict``:
    see `_hex`)."""
    long = sizes == 8
    nibbles, good = _hex(word, _byte_mask(sizes), strict)
    short_id = (
        (nibbles & np.uint64(15)) << np.uint64(8)
        | ((nibbles >> np.uint64(8)) & np.uint64(15)) << np.uint64(4)
        | (nibbles >> np.uint64(16)) & np.uint64(15)
    )
    long_id = _pack(nibbles).astype(np.uint32).byteswap().astype(np.uint64)
    can_id = np.where(long, long_id, short_id).astype(np.uint32)
    good &= (can_id & 0x2000_0000) == 0
    return can_id, long, good


def _data(
    first: npt.NDArray[np.uint64],
    second: npt.NDArray[np.uint64],
    sizes: npt.NDArray[np.int64],
    strict: bool = False,
) -> tuple[np.ndarray, np.ndarray]:
    """Up to 16 hex digits (in two words of eight) to up to 8 bytes, zero-padded, as one
    little-endian word (``strict``: see `_hex`)."""
    high, good_high = _hex(first, _byte_mask(sizes), strict)
    low, good_low = _hex(second, _byte_mask(sizes - 8), strict)
    data = (_pack(high) | _pack(low) << np.uint64(32)) & _byte_mask(sizes // 2)
    return data, good_high & good_low


def _interfaces(
    first: npt.NDArray[np.uint64], second: npt.NDArray[np.uint64], sizes: npt.NDArray[np.int64]
) -> tuple[np.ndarray, list[str]]:
    """Interface names (up to 16 characters, in two words) to codes: a pass per name."""
    low = first & _byte_mask(sizes)
    high = second & _byte_mask(sizes - 8)
    codes = np.full(len(sizes), -1, np.int32)
    names: list[str] = []
    left = np.flatnonzero(codes < 0)
    while len(left):
        row = left[0]
        same = (low == low[row]) & (high == high[row]) & (sizes == sizes[row])
        same = np.flatnonzero(same & (codes < 0))
        codes[same] = len(names)
        text = (int(low[row]) | int(high[row]) << 64).to_bytes(16, "little")
        names.append(text[: sizes[row]].decode("latin-1"))  # ASCII but in `_fixed_lines`
        left = np.flatnonzero(codes < 0)
    return codes, names


BLOCK = 1 << 22
"""Bytes of text parsed at once: small enough for the processor's caches."""


def parse_stream(stream: BinaryIO, workers: int | None = None) -> FrameColumns | None:
    """Parse candump text from a binary stream, block by block; see `parse_text`.

    Blocks are read straight into the arrays the parser works on and parsed on ``workers``
    threads (default: one per processor); NumPy releases the interpreter lock in its
    loops, so they run side by side. Each block numbers its lines from 1; the numbers are
    shifted once the blocks before it are counted.
    """
    workers = workers or os.cpu_count() or 1
    parts: list[FrameColumns] = []
    pending: deque[Future[tuple[FrameColumns | None, int]]] = deque()
    line = 0
    with ThreadPoolExecutor(workers) as pool:
        for block, size in read_blocks(stream):
            pending.append(pool.submit(parse_block, block, size, 1))
            while pending and (len(pending) > 2 * workers or pending[0].done()):
                columns, lines = pending.popleft().result()
                if columns is None:
                    return None
                parts.append(_shifted(columns, line))
                line += lines
        for future in pending:
            columns, lines = future.result()
            if columns is None:
                return None
            parts.append(_shifted(columns, line))
            line += lines
    return concat(parts) if parts else parse_text(b"")


def _shifted(columns: FrameColumns, offset: int) -> FrameColumns:
    """Columns numbered from line 1 renumbered from line ``offset + 1``."""
    if offset:
        columns.order += offset
        columns.bad_lines = [
            (order + offset, bad._replace(line_number=bad.line_number + offset))
            for order, bad in columns.bad_lines
        ]
    return columns


def read_blocks(
    stream: BinaryIO, block: int = BLOCK
) -> Iterator[tuple[npt.NDArray[np.uint8], int]]:
    """Blocks of about ``block`` bytes of whole lines, read into arrays padded for
    `parse_block`: each comes as (array, size of its text; a last line without a line
    break gets one)."""
    carry = np.zeros(0, np.uint8)  # the start of a line the last block cut
    while True:
        a = np.empty(len(carry) + block + 1 + _PAD, np.uint8)
        a[: len(carry)] = carry
        end = len(carry) + _read_into(stream, a.data[len(carry) : len(carry) + block])
        if end == len(carry):  # the end of the stream
            if end:
                a[end:] = 10  # a last line without a line break
                yield a, end + 1
            return
        cut = _last_break(a, end)
        if cut < 0:
            carry = a[:end].copy()
            continue
        carry = a[cut + 1 : end].copy()
        a[cut + 1 :] = 10
        yield a, cut + 1


def _read_into(stream: BinaryIO, view: memoryview) -> int:
    """Fill ``view`` from the stream as far as it goes; return the bytes read."""
    done = 0
    while done < len(view):
        got = stream.readinto(view[done:])  # type: ignore[attr-defined]
        if not got:
            break
        done += got
    return done


def _last_break(a: npt.NDArray[np.uint8], end: int) -> int:
    """The index of the last line break before ``end``, or -1."""
    start = end
    while start > 0:
        start = max(0, start - (1 << 16))
        found = a[start:end].tobytes().rfind(b"\n")
        if found >= 0:
            return start + found
        end = start
    return -1
