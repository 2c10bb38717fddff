"""RawCommand at a fixed rate, with a watchdog that zeroes the throttle (sans-IO).

A ground tool that drives motors must stop them when it stops: the caller refreshes the
setpoint with `Commander.set`; when no refresh came for ``watchdog`` seconds, the commands
sent carry zero throttle (each ESC then does what its ``zero_behavior`` parameter says,
Vertiq "Standard DroneCAN Support", Zero Behavior).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

from veronte4x.dronecan import vertiq
from veronte4x.dronecan.messages import RawCommand
from veronte4x.errors import EncodeError, check_seconds

DEFAULT_RATE = 50.0
"""RawCommand per second unless told otherwise."""

DEFAULT_WATCHDOG = 0.5
"""Seconds without a refresh after which the throttle drops to zero."""

STOP_REPEATS = 3
"""Zero-throttle commands sent when a command stream stops (one may be lost on a busy bus)."""

EPSILON = 1e-9
"""Seconds of tolerance when comparing a time with a due time (float rounding)."""


class Commander:
    """When to send which RawCommand, from throttles set by the caller and the time.

    Args:
        rate: Commands per second, finite and above 0.
        watchdog: Seconds a setpoint stays valid after `set`, finite and above 0 (an
            infinite one would never stop the motors).

    Raises:
        EncodeError: A rate or watchdog that is not a positive number.

    Examples:
        >>> commander = Commander(rate=10, watchdog=0.25)
        >>> commander.set({0: 0.5, 1: -0.5}, now=0.0)
        >>> commander.poll(0.0)
        RawCommand(cmd=(4096, -4096))
        >>> commander.poll(0.05) is None  # not due yet
        True
        >>> commander.poll(0.3)  # no refresh for 0.3 s: zero throttle, same ESC count
        RawCommand(cmd=(0, 0))
        >>> commander.tripped
        True
    """

    def __init__(self, rate: float = DEFAULT_RATE, watchdog: float = DEFAULT_WATCHDOG) -> None:
        for name, value in (("rate", rate), ("watchdog", watchdog)):
            if (
                isinstance(value, bool)
                or not isinstance(value, (int, float))
                or not 0 < value < math.inf
            ):
                raise EncodeError("Commander", name, value, "a finite number above 0")
        self.period = 1.0 / rate
        self.watchdog = watchdog
        self._cmd: tuple[int, ...] = ()
        self._refreshed: float | None = None
        self._anchor: float | None = None
        self._count = 0
        self.tripped = False
        """Whether the watchdog has zeroed the throttle since the last `set`."""

    def set(self, throttles: Sequence[float] | Mapping[int, float], now: float) -> None:
        """New throttle fractions in [-1, 1] (by ESC index), valid for ``watchdog`` seconds.

        Raises:
            EncodeError: A fraction out of range, more than 20 ESCs or a bad index.
            TypeError: A throttle that is not a number, or ``now`` that is not one.
        """
        now = check_seconds("set", "now", now)
        self._cmd = vertiq.raw_command(throttles).cmd
        self._refreshed = now
        self.tripped = False
        if self._anchor is None:
            self._anchor, self._count = now, 0

    def stop(self) -> RawCommand:
        """Zero every throttle now; the command to send at once. `set` starts again."""
        self._refreshed = None
        self._anchor = None
        return RawCommand((0,) * len(self._cmd))

    def stop_commands(self) -> list[RawCommand]:
        """`stop`, as the commands to send when a stream ends: zero throttle `STOP_REPEATS`
        times, or none when nothing was ever set."""
        zero = self.stop()
        return [zero] * STOP_REPEATS if zero.cmd else []

    def wait(self, now: float, longest: float) -> float:
        """Seconds from ``now`` to the next command, at most ``longest``."""
        due = self.next_time()
        return longest if due is None else max(0.0, min(longest, due - now))

    def poll(self, now: float) -> RawCommand | None:
        """The command to send at ``now``, or None if none is due.

        Due times are ``first set + k * period``, counted rather than summed so that they do
        not drift; a poll more than a period late sends once and restarts the grid.
        """
        now = check_seconds("poll", "now", now)
        due = self.next_time()
        if due is None or now + EPSILON < due:
            return None
        self._count += 1
        following = self.next_time()
        if following is not None and following <= now + EPSILON:
            self._anchor, self._count = now, 1
        if self._refreshed is not None and now - self._refreshed >= self.watchdog:
            self.tripped = True
        return RawCommand((0,) * len(self._cmd) if self.tripped else self._cmd)

    def next_time(self) -> float | None:
        """When `poll` next has a command, or None when stopped."""
        if self._anchor is None:
            return None
        return self._anchor + self._count * self.period
