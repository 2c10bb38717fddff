"""Periodic due times: computed from the origin, one send per call, missed ones dropped."""

from __future__ import annotations

from hypothesis import given
from hypothesis import strategies as st

from veronte4x.arbiter.periodic import Periodic


def test_due_times_and_missed_sends_dropped() -> None:
    periodic = Periodic(10.0, 0.5)
    assert periodic.due == 10.0
    assert not periodic.take(9.999)
    assert periodic.take(10.0)  # exactly at the due time
    assert periodic.due == 10.5
    assert not periodic.take(10.25)
    assert periodic.take(11.7)  # late: 10.5 and 11.0 and 11.5 are dropped, one send
    assert periodic.due == 12.0
    assert not periodic.take(11.9)


def test_a_due_time_that_floor_division_overshoots_is_skipped() -> None:
    """(2.0999999999999996 - 0) / 0.7 is 2.9999999999999996, floored to 2: the next due
    time 3 x 0.7 is ``now`` itself, so one more period is needed to lie past ``now``."""
    now = 2.0999999999999996
    assert now == 3 * 0.7
    periodic = Periodic(0.0, 0.7)
    assert periodic.take(now)
    assert periodic.due == 4 * 0.7
    assert not periodic.take(now)


@given(
    st.floats(-1e6, 1e6),
    st.floats(1e-3, 100.0),
    st.lists(st.floats(0.0, 1000.0), min_size=1, max_size=20),
)
def test_after_a_send_the_next_due_time_lies_past_now(
    origin: float, period: float, steps: list[float]
) -> None:
    periodic = Periodic(origin, period)
    now = origin
    for step in steps:
        now += step
        due = periodic.due
        assert periodic.take(now) is (now >= due)
        assert periodic.due > now or periodic.due == due
        assert periodic.due >= due
