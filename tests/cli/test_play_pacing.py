"""``veronte4x play`` keeps the capture's spacing: checked on a clock the test sets, no
time measured."""

from __future__ import annotations

import threading

from veronte4x.capture import Record, Role
from veronte4x.cli.play import paced


class _Stop(threading.Event):
    """A stop event that records each wait and returns at once, moving the clock on."""

    def __init__(self, clock: list[float]) -> None:
        super().__init__()
        self.clock = clock
        self.waits: list[float] = []

    def wait(self, timeout: float | None = None) -> bool:
        assert timeout is not None
        self.waits.append(round(timeout, 9))
        self.clock[0] += timeout
        return False


def _record(stamp: float) -> Record:
    return Record(stamp, "can0", 9, Role.AUTOPILOT, 1, None, None, None, "", b"")


def test_each_record_waits_for_its_place_even_a_short_gap() -> None:
    """A mutation survivor: waits under one second skipped (``wait > 1``), so a capture of
    ten-millisecond frames went out at once."""
    clock = [100.0]
    stop = _Stop(clock)
    stamps = [5.0, 5.01, 5.02, 5.5, 7.0, 7.0]
    out = list(paced(map(_record, stamps), 2.0, stop, clock=lambda: clock[0]))
    assert [r.timestamp for r in out] == stamps
    assert stop.waits == [0.005, 0.005, 0.24, 0.75]  # at twice the speed; none for 0 s
