"""Periodic sending: the due times of a message sent every ``period`` seconds."""

from __future__ import annotations

import math


class Periodic:
    """Due times ``origin + k x period``, k = 0, 1, 2, ...; computed, never accumulated.

    Attributes:
        origin: When sending started, s.
        period: The period, s.
    """

    __slots__ = ("_index", "origin", "period")

    def __init__(self, origin: float, period: float) -> None:
        self.origin = origin
        self.period = period
        self._index = 0

    @property
    def due(self) -> float:
        """The next due time."""
        return self.origin + self._index * self.period

    def take(self, now: float) -> bool:
        """Whether a send is due at ``now``; if so, move past ``now`` (missed ones are
        dropped: one message per call, like a sender that only wakes up late)."""
        if now < self.due:
            return False
        self._index = max(self._index + 1, math.floor((now - self.origin) / self.period) + 1)
        while self.due <= now:
            self._index += 1
        return True
