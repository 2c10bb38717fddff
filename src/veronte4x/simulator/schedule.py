"""When a periodic message is due, from timestamps given as arguments.

Due times are ``anchor + k * period`` for k = 0, 1, 2, ..., computed from the count rather
than summed, so they do not drift. A poll up to one period late still emits on the old
grid. A poll later than that emits one message and restarts the grid at the poll time, so a
long gap never produces a burst of stale messages.
"""

from __future__ import annotations

EPSILON = 1e-9
"""Seconds of tolerance when comparing a timestamp to a due time (float rounding)."""


class Periodic:
    """The schedule of one periodic message.

    Args:
        frequency: Messages per second; 0 means none.
        anchor: Time of the first message.
    """

    __slots__ = ("_anchor", "_count", "_period")

    def __init__(self, frequency: float, anchor: float) -> None:
        self._period: float | None = None
        self._anchor = anchor
        self._count = 0
        self.restart(frequency, anchor)

    def restart(self, frequency: float, anchor: float, *, skip_first: bool = False) -> None:
        """Start a new grid at ``anchor``; with ``skip_first`` the first message is one
        period later."""
        self._period = 1.0 / frequency if frequency > 0 else None
        self._anchor = anchor
        self._count = 1 if skip_first else 0

    @property
    def next_time(self) -> float | None:
        """When the next message is due, or None if the frequency is 0."""
        if self._period is None:
            return None
        return self._anchor + self._count * self._period

    def due(self, now: float) -> bool:
        """Whether a message is due at ``now``; if so, count it as sent."""
        due_time = self.next_time
        if due_time is None or now + EPSILON < due_time:
            return False
        self._count += 1
        following = self.next_time
        if following is not None and following <= now + EPSILON:
            self._anchor = now  # late by more than a period: restart the grid at now
            self._count = 1
        return True
