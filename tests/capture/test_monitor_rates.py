"""The monitor's live timing per row (``monitor --rates``): period, jitter, longest gap and
the stopped and slow flags, on generated traffic with known periods."""

from __future__ import annotations

import itertools
import math
import random

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from veronte4x import dronecan
from veronte4x.capture import Record, Role
from veronte4x.capture.monitor import MonitorState, Row, render_text
from veronte4x.capture.rates import STOP_PERIODS, Stream
from veronte4x.codec import Ready

OCTAVE_BIN = 2 ** (1 / 64)
"""Periods are medians to 1/64 octave."""


def node_status(stamp: float, node: int) -> Record:
    message = dronecan.NodeStatus(int(stamp), dronecan.Health.OK, dronecan.Mode.OPERATIONAL, 0, 0)
    can_id = 0x10015500 | node
    return Record(stamp, "can0", can_id, Role.DRONECAN, None, node, message, None, "", b"")


def ready(stamp: float) -> Record:
    return Record(stamp, "can0", 9, Role.AUTOPILOT, 1, None, Ready(True), None, "", b"")


def row(state: MonitorState, sender: str, now: float | None = None) -> Row:
    (found,) = [r for r in state.rows(now=now) if r.sender == sender]
    return found


def close(got: float, period: float) -> bool:
    return period / OCTAVE_BIN <= got <= period * OCTAVE_BIN


@settings(max_examples=60)
@given(
    st.sampled_from([0.001, 0.01, 0.02, 0.1, 0.5, 1.0]),
    st.integers(3, 200),
    st.floats(0.0, 0.2),
    st.integers(0, 2**32 - 1),
)
def test_known_periods_with_jitter(period: float, count: int, spread: float, seed: int) -> None:
    rng = random.Random(seed)
    state = MonitorState(rates=True)
    stamps = [1000.0 + i * period + rng.uniform(-spread, spread) * period / 2 for i in range(count)]
    stamps.sort()
    for stamp in stamps:
        state.add(node_status(stamp, 20))
    got = row(state, "node 20")
    periods = [b - a for a, b in itertools.pairwise(stamps)]
    assert got.count == count
    median = sorted(periods)[(len(periods) - 1) // 2]  # the lower one of an even count
    assert close(got.period, median)
    mean = sum(periods) / len(periods)
    jitter = math.sqrt(sum((p - mean) ** 2 for p in periods) / (len(periods) - 1))
    assert got.jitter == pytest.approx(jitter, rel=1e-6, abs=1e-12)
    assert got.longest_gap == pytest.approx(max(periods), rel=1e-9)
    assert got.flags == ()  # "now" is its own last record


def test_a_node_whose_node_status_falls_silent_is_stopped_after_3_periods() -> None:
    state = MonitorState(rates=True)
    for tick in range(100):  # node 20 at 1 Hz for 10 s, node 21 for 100 s, AP2 at 10 Hz
        stamp = 1000.0 + tick
        if tick < 10:
            state.add(node_status(stamp, 20))
        state.add(node_status(stamp, 21))
        for tenth in range(10):
            state.add(ready(stamp + tenth / 10))
    last = 1009.0
    assert close(row(state, "node 20", last).period, 1.0)
    assert row(state, "node 20", last + STOP_PERIODS * 1.0 * 0.99).flags == ()
    assert row(state, "node 20", last + STOP_PERIODS * 1.0 * OCTAVE_BIN + 0.01).flags == (
        "stopped",
    )
    assert row(state, "node 20").flags == ("stopped",)  # now: the latest record, 1099.9 s
    assert row(state, "node 21").flags == ()
    assert row(state, "AP2").flags == ()
    # Everything falls silent: at 1099.9 + 0.4 s the 10 Hz stream has stopped, 1 Hz not yet.
    rows = {r.sender: r.flags for r in state.rows(now=1100.3)}
    assert rows == {"AP2": ("stopped",), "node 20": ("stopped",), "node 21": ()}


def test_a_stream_at_half_its_rate_is_slow_then_stopped() -> None:
    stream = Stream()
    for tick in range(100):
        stream.add(tick * 0.1)
    last = 9.9
    for tick in range(1, 17):
        stream.add(last + tick * 0.25)  # 16 periods at 2.5 times the usual one
    assert close(stream.usual() or 0.0, 0.1)
    assert stream.flags(stream.last) == ("slow",)
    # Silent against the recent cadence: 3 x 0.25 s, not 3 x 0.1 s.
    assert stream.flags(stream.last + 0.5) == ("slow",)
    assert stream.flags(stream.last + 0.8) == ("stopped", "slow")


def test_one_record_has_no_period_and_is_never_stopped() -> None:
    state = MonitorState(rates=True)
    state.add(node_status(5.0, 30))
    got = row(state, "node 30", 500.0)
    assert (got.count, math.isnan(got.period), math.isnan(got.jitter)) == (1, True, True)
    assert got.flags == ()


def test_records_out_of_order_do_not_make_negative_periods() -> None:
    state = MonitorState(rates=True)
    for stamp in (1.0, 2.0, 1.5, 3.0, 4.0):
        state.add(node_status(stamp, 20))
    got = row(state, "node 20")
    assert close(got.period, 1.0) and got.longest_gap == 1.0


def test_the_plain_table_shows_timing_only_with_rates() -> None:
    plain, timed = MonitorState(), MonitorState(rates=True)
    for tick in range(6):
        for state in (plain, timed):
            state.add(node_status(10.0 + tick, 20))
            if tick < 2:
                state.add(ready(10.0 + tick))
    head = "sender   type              id    count   rate/s  errors  fields"
    assert render_text(plain).splitlines()[2] == head
    lines = render_text(timed).splitlines()
    assert lines[2].split() == [
        "sender", "type", "id", "count", "rate/s", "period", "jitter", "gap", "state",
        "errors", "fields",
    ]  # fmt: skip
    ap2 = lines[3].split()
    assert ap2[:5] == ["AP2", "Ready", "009", "2", "0.0"]
    assert ap2[5:11] == ["1", "s", "-", "1", "s", "STOPPED"]  # silent 4 s at 15 s
    node = lines[4].split()
    assert node[6:11] == ["1", "s", "0", "µs", "1"] and "STOPPED" not in node  # "node 20"


def test_a_stream_in_bursts_is_stopped_against_its_cycle() -> None:
    # As the demo flight's ArbitrationVariables: three 0.1 ms apart, every 20 ms. The median
    # period is the 0.1 ms; a silence of one cycle is not a stop, one of over 3 cycles is.
    stream = Stream()
    for cycle in range(50):
        for number in range(3):
            stream.add(cycle * 0.02 + number * 0.0001)
    assert close(stream.usual() or 0.0, 0.0001)
    assert stream.flags(stream.last + 0.0198) == ()
    assert stream.flags(stream.last + STOP_PERIODS * 0.0198 * 0.99) == ()
    assert stream.flags(stream.last + STOP_PERIODS * 0.0198 * 1.01) == ("stopped",)


@pytest.mark.parametrize("seconds", [0.2, 0.5, 1.0, 1.9, 2.0, 5.0])
def test_rate_counts_the_streams_complete_intervals_not_the_capture_span(seconds: float) -> None:
    """A 10 Hz stream reads 10/s from its second record on, however young the capture (it
    read 2.5/s at 0.5 s, counted over the capture's span), and a 5 Hz one beside it 5/s
    (BatteryInfo read 20.8/s in the demo's first 2 s): on a stepped clock, record by record."""
    state = MonitorState()
    state.add(ready(999.0))  # the capture starts a second before the streams
    for i in range(round(seconds * 10) + 1):
        stamp = 1000.0 + i / 10
        state.add(node_status(stamp, 20))
        if i % 2 == 0:
            state.add(node_status(stamp, 21))
        if i:
            assert row(state, "node 20").rate == pytest.approx(10.0)
        if i >= 2:
            assert row(state, "node 21").rate == pytest.approx(5.0)


def test_a_stream_slower_than_the_window_reads_its_last_interval_until_it_stops() -> None:
    state = MonitorState()
    for stamp in (1000.0, 1003.0, 1006.0):  # the arbiter's Scores: every 3 s
        state.add(node_status(stamp, 20))
    assert row(state, "node 20").rate == pytest.approx(1 / 3)
    assert row(state, "node 20", now=1006.0 + STOP_PERIODS * 3.0).rate == pytest.approx(1 / 3)
    assert row(state, "node 20", now=1006.1 + STOP_PERIODS * 3.0).rate == 0.0


def test_one_stream_per_channel() -> None:
    """The same node's NodeStatus on two channels is two streams, each 1 Hz, each its
    period; merged they read as one at 0 µs periods."""
    state = MonitorState(rates=True)
    for tick in range(5):
        for channel in ("can0", "can1"):
            state.add(node_status(1000.0 + tick, 20)._replace(channel=channel))
    rows = state.rows()
    assert [(r.sender, r.channel, r.count) for r in rows] == [
        ("node 20", "can0", 5),
        ("node 20", "can1", 5),
    ]
    for got in rows:
        assert got.rate == pytest.approx(1.0) and close(got.period, 1.0) and got.flags == ()
    assert [line.split()[:3] for line in render_text(state).splitlines()[3:]] == [
        ["node", "20", "can0"],
        ["node", "20", "can1"],
    ]


def test_rate_of_records_at_one_instant_is_zero() -> None:
    state = MonitorState()
    state.add(node_status(1000.0, 20))
    assert row(state, "node 20").rate == 0.0
