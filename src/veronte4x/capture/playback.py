"""Play a capture back with its original spacing, scaled: the schedule, without any I/O.

Like can-utils' ``canplayer``, a frame is due at its capture time's offset from the first
frame, divided by the speed, from the moment playback starts. `Player` never reads a clock
or sleeps: the caller says what time it is (`Player.due`, `Player.sent`), waits until the
next frame is due and sends it; an adapter does the waiting (``veronte4x play``). Every
frame goes (error frames too) and is never changed: its CAN FD flags and a remote frame's
DLC are kept, only a channel map renames its channel. Frames are sent in capture order. A
frame without a timestamp is due with the one before it, and a timestamp that goes back
(merged logs) does not move a frame before the one sent before it.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Iterator, Sequence
from dataclasses import dataclass

from veronte4x.capture.frames import Frame
from veronte4x.errors import Veronte4xError


class PlaybackError(Veronte4xError, ValueError):
    """Arguments the player cannot use: a speed that is not positive, a bad filter."""


@dataclass(frozen=True, slots=True)
class IdFilter:
    """``ID:MASK`` as candump takes it: a frame passes if ``can_id & mask == id & mask``.

    Attributes:
        can_id: The ID to compare.
        mask: The bits that matter (0x7FF for an 11-bit ID alone, 0x1FFFFFFF for 29-bit).
    """

    can_id: int
    mask: int

    @classmethod
    def parse(cls, text: str) -> IdFilter:
        """``0FF`` (every bit of the ID) or ``100:700`` (hexadecimal, as candump).

        Raises:
            PlaybackError: Not hexadecimal ``ID`` or ``ID:MASK``.
        """
        ident, _, mask = text.partition(":")
        try:
            can_id = int(ident, 16)
            return cls(can_id, int(mask, 16) if mask else 0x1FFFFFFF)
        except ValueError:
            raise PlaybackError(
                f"filter {text!r}: expected a hexadecimal CAN ID or ID:MASK, e.g. 0FF or 100:700"
            ) from None

    def matches(self, can_id: int) -> bool:
        """Whether a frame with this CAN ID passes."""
        return can_id & self.mask == self.can_id & self.mask


@dataclass(frozen=True, slots=True)
class Timing:
    """How close to their due times the frames went out.

    Attributes:
        frames: Frames sent.
        mean_late: Mean of (sent - due), in seconds.
        max_late: Largest (sent - due), in seconds.
    """

    frames: int
    mean_late: float
    max_late: float


class Player:
    """The schedule of a capture's frames, for any clock.

    Args:
        frames: The capture's frames, in capture order (bad lines already left out).
        speed: 2 plays twice as fast, 0.5 at half speed.
        loops: Times to play the capture, or None for ever.
        filters: Keep only frames that match one of these (none keeps all).
        channels: Capture channel to the channel it goes out on; given, frames of other
            channels are left out.
    """

    def __init__(
        self,
        frames: Iterable[Frame],
        speed: float = 1.0,
        loops: int | None = 1,
        filters: Sequence[IdFilter] = (),
        channels: dict[str, str] | None = None,
    ) -> None:
        if not (isinstance(speed, (int, float)) and math.isfinite(speed) and speed > 0):
            raise PlaybackError(f"speed {speed!r}: expected a positive number, e.g. 2 or 0.5")
        if loops is not None and loops < 1:
            raise PlaybackError(f"loops {loops!r}: expected 1 or more, or None for ever")
        kept: list[tuple[float, Frame]] = []
        offset = 0.0
        first: float | None = None
        for frame in frames:
            if filters and not any(f.matches(frame.can_id) for f in filters):
                continue
            if channels is not None:
                if frame.channel not in channels:
                    continue
                frame = frame._replace(channel=channels[frame.channel])
            if frame.timestamp is not None:
                if first is None:
                    first = frame.timestamp
                offset = max(offset, (frame.timestamp - first) / speed)
            kept.append((offset, frame))
        self._frames = kept
        self._loops = loops
        self._span = kept[-1][0] if kept else 0.0
        # The next loop starts one mean spacing after the last frame, not on top of it.
        self._pause = self._span / (len(kept) - 1) if len(kept) > 1 else 0.0
        self._index = 0
        self._loop = 0
        self._start: float | None = None
        self._late_sum = 0.0
        self._late_max = 0.0
        self._sent = 0

    def __len__(self) -> int:
        """Frames in one loop."""
        return len(self._frames)

    def start(self, now: float) -> None:
        """Start playing: the first frame is due at ``now``."""
        self._start = now

    def due(self) -> float | None:
        """When the next frame is due (on the clock `start` was given), None at the end."""
        if self._start is None:
            raise PlaybackError("call start(now) before due()")
        if not self._frames or (self._loops is not None and self._loop >= self._loops):
            return None
        offset, _ = self._frames[self._index]
        return self._start + self._loop * (self._span + self._pause) + offset

    def take(self, now: float) -> Iterator[Frame]:
        """The frames due at ``now``, in order, each counted as sent at ``now``."""
        while True:
            due = self.due()
            if due is None or due > now:
                return
            _, frame = self._frames[self._index]
            late = now - due
            self._late_sum += late
            self._late_max = max(self._late_max, late)
            self._sent += 1
            self._index += 1
            if self._index == len(self._frames):
                self._index = 0
                self._loop += 1
            yield frame

    def timing(self) -> Timing:
        """How late the frames taken so far were, against their due times."""
        mean = self._late_sum / self._sent if self._sent else 0.0
        return Timing(self._sent, mean, self._late_max)


class Pacer:
    """The same spacing for a stream of timestamped items read one by one (no list kept):
    how long to wait before each, given the time now.

    Args:
        speed: 2 runs twice as fast, 0.5 at half speed.
    """

    def __init__(self, speed: float = 1.0) -> None:
        if not (isinstance(speed, (int, float)) and math.isfinite(speed) and speed > 0):
            raise PlaybackError(f"speed {speed!r}: expected a positive number, e.g. 2 or 0.5")
        self.speed = speed
        self._anchor: tuple[float, float] | None = None  # (first timestamp, time it came)
        self._offset = 0.0

    def delay(self, timestamp: float | None, now: float) -> float:
        """Seconds to wait (0 or more) before the item with this timestamp, seen at ``now``."""
        if timestamp is None:
            return 0.0
        if self._anchor is None:
            self._anchor = (timestamp, now)
        first, start = self._anchor
        self._offset = max(self._offset, (timestamp - first) / self.speed)
        return max(0.0, start + self._offset - now)
