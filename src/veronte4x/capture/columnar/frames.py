"""Frames as columns: what the columnar readers produce and the columnar engine consumes.

The column form of `veronte4x.capture.Frame`: one NumPy array per attribute, a row per frame,
in capture order, plus the lines that are no frame (`veronte4x.capture.BadLine`), each with
the position it takes in that order.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt

from veronte4x.capture.frames import BadLine, Frame, Seconds, micros
from veronte4x.times import END_MICROS, FIRST_MICROS

MAX_DATA = 8
"""Data bytes a row of `FrameColumns.data` holds; longer (CAN FD) data lives in `long_data`."""
_NO_FLAGS = (False, False, 0)
"""`FrameColumns.flags` of a row that has none."""
NO_TIME = np.iinfo(np.int64).min
"""`FrameColumns.time` of a frame whose time has no table value (none, not finite, or
outside the years 1 to 9999)."""


@dataclass
class FrameColumns:
    """Frames as NumPy columns, in capture order.

    Attributes:
        order: Position of each frame in the capture (a line number or a message index),
            increasing; bad lines take the positions between.
        timestamp: Seconds; NaN where `has_time` is False.
        has_time: The frame has a timestamp.
        channel: Index into `channels` of each frame's interface.
        channels: Interface names.
        can_id: The identifier (without the error flag).
        extended: 29-bit identifier.
        remote: Remote frame.
        fd: CAN FD frame.
        error: Error frame.
        length: Number of data bytes.
        data: The first eight data bytes of each frame, zero-padded.
        long_data: The data of frames with more than eight bytes, by row.
        flags: ``(brs, esi, dlc)`` as in `Frame`, by row, for the rows where one is set (the
            CAN FD flags, a remote frame's DLC).
        bad_lines: Lines that are no frame, with their position in the capture order.
        time: The log's time in whole microseconds since the epoch (UTC), exact where
            ``timestamp`` is rounded, `NO_TIME` where it has no table value; None when
            made: taken from ``timestamp`` (`nearest_micros`).
    """

    order: npt.NDArray[np.int64]
    timestamp: npt.NDArray[np.float64]
    has_time: npt.NDArray[np.bool_]
    channel: npt.NDArray[np.int32]
    channels: list[str]
    can_id: npt.NDArray[np.uint32]
    extended: npt.NDArray[np.bool_]
    remote: npt.NDArray[np.bool_]
    fd: npt.NDArray[np.bool_]
    error: npt.NDArray[np.bool_]
    length: npt.NDArray[np.int64]
    data: npt.NDArray[np.uint8]
    long_data: dict[int, bytes] = field(default_factory=dict)
    flags: dict[int, tuple[bool, bool, int]] = field(default_factory=dict)
    bad_lines: list[tuple[int, BadLine]] = field(default_factory=list)
    time: npt.NDArray[np.int64] = None  # type: ignore[assignment]

    def __post_init__(self) -> None:
        if self.time is None:
            self.time = nearest_micros(self.timestamp, self.has_time)

    def __len__(self) -> int:
        return len(self.order)

    def take(
        self, rows: npt.NDArray[np.int64], order: npt.NDArray[np.int64] | None = None
    ) -> FrameColumns:
        """The frames of ``rows``, in that order (numbered ``order`` if given)."""
        odd = self.long_data or self.flags
        where = {int(old): new for new, old in enumerate(rows)} if odd else {}
        return FrameColumns(
            order=self.order[rows] if order is None else order,
            timestamp=self.timestamp[rows],
            has_time=self.has_time[rows],
            channel=self.channel[rows],
            channels=self.channels,
            can_id=self.can_id[rows],
            extended=self.extended[rows],
            remote=self.remote[rows],
            fd=self.fd[rows],
            error=self.error[rows],
            length=self.length[rows],
            data=self.data[rows],
            long_data={where[r]: d for r, d in self.long_data.items() if r in where},
            flags={where[r]: f for r, f in self.flags.items() if r in where},
            bad_lines=self.bad_lines,
            time=self.time[rows],
        )

    def frame(self, row: int) -> Frame:
        """The frame of one row, as the per-frame readers give it."""
        data = self.long_data.get(row)
        if data is None:
            data = self.data[row, : self.length[row]].tobytes()
        brs, esi, dlc = self.flags.get(row, _NO_FLAGS)
        return Frame(
            self.seconds(row),
            self.channels[self.channel[row]],
            int(self.can_id[row]),
            data,
            bool(self.extended[row]),
            bool(self.remote[row]),
            bool(self.fd[row]),
            bool(self.error[row]),
            brs,
            esi,
            dlc,
        )

    def seconds(self, row: int) -> float | None:
        """The timestamp of one row as the per-frame readers give it (a `Seconds` where the
        float alone does not hold `time`)."""
        if not self.has_time[row]:
            return None
        seconds, exact = float(self.timestamp[row]), int(self.time[row])
        if exact == NO_TIME or micros(seconds) == exact:
            return seconds
        return Seconds(seconds, exact)

    def fed(self, row: int) -> float:
        """The timestamp the reassembler is fed for one row: `seconds`, 0.0 for none."""
        seconds = self.seconds(row)
        return 0.0 if seconds is None else seconds

    def frames_of(self, rows: npt.NDArray[np.int64]) -> list[Frame]:
        """The frames of ``rows``, as `frame` gives them, built a column at a time."""
        names = self.channels
        stamps = np.where(self.has_time[rows], self.timestamp[rows], np.nan).tolist()
        exact = self.time[rows]
        nearest = nearest_micros(self.timestamp[rows], self.has_time[rows])
        odd = np.flatnonzero((exact != NO_TIME) & (exact != nearest))
        for at in odd.tolist():
            stamps[at] = Seconds(stamps[at], int(exact[at]))
        lengths = self.length[rows].tolist()
        blob = self.data[rows].tobytes()
        long_data, flags = self.long_data, self.flags
        new = tuple.__new__
        out = []
        for at, (row, stamp, channel, can_id, size, extended, remote, fd, error) in enumerate(
            zip(
                rows.tolist(),
                stamps,
                self.channel[rows].tolist(),
                self.can_id[rows].tolist(),
                lengths,
                self.extended[rows].tolist(),
                self.remote[rows].tolist(),
                self.fd[rows].tolist(),
                self.error[rows].tolist(),
                strict=True,
            )
        ):
            data = long_data.get(row) if long_data else None
            if data is None:
                data = blob[at * MAX_DATA : at * MAX_DATA + size]
            time = None if stamp != stamp else stamp  # NaN: no timestamp
            row_frame = (time, names[channel], can_id, data, extended, remote, fd, error)
            extra = flags.get(row, _NO_FLAGS) if flags else _NO_FLAGS
            out.append(new(Frame, (*row_frame, *extra)))
        return out


def from_frames(items: list[tuple[int, Frame | BadLine]]) -> FrameColumns:
    """Columns from frames made one by one (python-can readers, odd candump lines).

    Args:
        items: (position in the capture, frame or bad line), in capture order.
    """
    frames = [(order, item) for order, item in items if isinstance(item, Frame)]
    channels: dict[str, int] = {}
    n = len(frames)
    data = np.zeros((n, MAX_DATA), np.uint8)
    long_data: dict[int, bytes] = {}
    flags: dict[int, tuple[bool, bool, int]] = {}
    lengths = np.zeros(n, np.int64)
    for row, (_, frame) in enumerate(frames):
        if frame.brs or frame.esi or frame.dlc:
            flags[row] = (frame.brs, frame.esi, frame.dlc)
        size = len(frame.data)
        lengths[row] = size
        if size > MAX_DATA:
            long_data[row] = frame.data
        elif size:
            data[row, :size] = np.frombuffer(frame.data, np.uint8)
    stamps = [f.timestamp for _, f in frames]
    return FrameColumns(
        order=np.array([o for o, _ in frames], np.int64),
        timestamp=np.array([np.nan if s is None else s for s in stamps], np.float64),
        has_time=np.array([s is not None for s in stamps], np.bool_),
        time=micros_of(stamps),
        channel=np.array(
            [channels.setdefault(f.channel, len(channels)) for _, f in frames], np.int32
        ),
        channels=list(channels),
        can_id=np.array([f.can_id for _, f in frames], np.uint32),
        extended=np.array([f.extended for _, f in frames], np.bool_),
        remote=np.array([f.remote for _, f in frames], np.bool_),
        fd=np.array([f.fd for _, f in frames], np.bool_),
        error=np.array([f.error for _, f in frames], np.bool_),
        length=lengths,
        data=data,
        long_data=long_data,
        flags=flags,
        bad_lines=[(o, b) for o, b in items if isinstance(b, BadLine)],
    )


def concat(parts: list[FrameColumns]) -> FrameColumns:
    """Join column blocks whose orders do not overlap, keeping capture order."""
    if len(parts) == 1:
        return parts[0]
    channels: dict[str, int] = {}
    remapped = []
    for part in parts:
        codes = np.array(
            [channels.setdefault(c, len(channels)) for c in part.channels] or [0], np.int32
        )
        remapped.append(codes[part.channel] if len(part) else part.channel)
    order = np.concatenate([p.order for p in parts])
    filled = [p for p in parts if len(p)]
    in_sequence = all(a.order[-1] < b.order[0] for a, b in itertools.pairwise(filled))
    sort = order if in_sequence else np.argsort(order, kind="stable")
    long_data: dict[int, bytes] = {}
    flags: dict[int, tuple[bool, bool, int]] = {}
    if any(p.long_data or p.flags for p in parts):
        offsets = np.cumsum([0] + [len(p) for p in parts])
        rank = np.arange(len(order))
        if not in_sequence:
            rank[sort] = np.arange(len(sort))
        long_data = {
            int(rank[offsets[i] + row]): data
            for i, p in enumerate(parts)
            for row, data in p.long_data.items()
        }
        flags = {
            int(rank[offsets[i] + row]): odd
            for i, p in enumerate(parts)
            for row, odd in p.flags.items()
        }

    def joined(name: str) -> np.ndarray:
        joined: np.ndarray = np.concatenate([getattr(p, name) for p in parts])
        return joined if in_sequence else joined[sort]

    return FrameColumns(
        order=order if in_sequence else order[sort],
        timestamp=joined("timestamp"),
        has_time=joined("has_time"),
        channel=np.concatenate(remapped) if in_sequence else np.concatenate(remapped)[sort],
        channels=list(channels),
        can_id=joined("can_id"),
        extended=joined("extended"),
        remote=joined("remote"),
        fd=joined("fd"),
        error=joined("error"),
        length=joined("length"),
        data=joined("data"),
        long_data=long_data,
        flags=flags,
        bad_lines=sorted((b for p in parts for b in p.bad_lines), key=lambda b: b[0]),
        time=joined("time"),
    )


_FIRST_SECONDS = FIRST_MICROS // 1_000_000
_END_SECONDS = END_MICROS // 1_000_000


def nearest_micros(
    seconds: npt.NDArray[np.float64], has_time: npt.NDArray[np.bool_]
) -> npt.NDArray[np.int64]:
    """`veronte4x.capture.frames.micros` of every float, column-wise: the whole
    microseconds nearest to each (half to even), `NO_TIME` where it has none."""
    ok = has_time & np.isfinite(seconds)
    ok &= (seconds >= _FIRST_SECONDS) & (seconds < _END_SECONDS)
    clean = np.where(ok, seconds, 0.0)
    whole = np.floor(clean)
    part = (clean - whole) * 1e6  # the subtraction is exact, the product rounds once
    found = whole.astype(np.int64) * 1_000_000 + np.rint(part).astype(np.int64)
    # The product is within 2**-33 of the exact value: only near a tie can rint misround.
    doubt = np.flatnonzero(ok & (np.abs(part - np.floor(part) - 0.5) < 1e-6))
    for row in doubt.tolist():
        exact = micros(float(seconds[row]))
        found[row] = NO_TIME if exact is None else exact
    ok &= (found >= FIRST_MICROS) & (found < END_MICROS)
    return np.where(ok, found, NO_TIME)


def micros_of(stamps: list[float | None]) -> npt.NDArray[np.int64]:
    """`FrameColumns.time` of frames' timestamps (those a `Seconds` holds, else nearest)."""
    floats = np.array([np.nan if s is None else s for s in stamps], np.float64)
    found = nearest_micros(floats, np.ones(len(stamps), np.bool_))
    for row, stamp in enumerate(stamps):
        if type(stamp) is Seconds:
            exact = micros(stamp)
            found[row] = NO_TIME if exact is None else exact
    return found
