"""Publication: NodeStatus at 1 Hz, telemetry at telem_frequency, transfer ids, gaps."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from veronte4x import dronecan
from veronte4x.simulator import SimulatedEsc
from veronte4x.simulator.schedule import Periodic

from .support import decode, names


def _timeline(esc: SimulatedEsc, times: list[float]) -> list[tuple[float, str, int]]:
    return [
        (t, type(x.message).__name__, x.transfer_id) for t in times for x in decode(esc.poll(t))
    ]


def test_first_poll_bytes_and_ids() -> None:
    esc = SimulatedEsc(20)
    frames = esc.poll(0.0)
    # NodeStatus: priority 16, type 341, node 20; uptime 0, OK, OPERATIONAL; tail 0xC0.
    assert frames[0] == dronecan.TransferFrame(0x10015514, bytes.fromhex("00000000000000c0"))
    assert [f.can_id for f in frames] == [0x10015514] + [0x10040A14] * 3 + [0x10045614]
    # esc.Status in three frames (CRC first), device.Temperature in one; transfer id 0.
    assert [f.data[-1] for f in frames[1:]] == [0x80, 0x20, 0x40, 0xC0]


def test_rates_over_two_seconds() -> None:
    esc = SimulatedEsc(20, telem_frequency=10)
    times = [i * 0.05 for i in range(41)]  # 0 .. 2.0 s every 50 ms
    line = _timeline(esc, times)
    node = [(t, tid) for t, name, tid in line if name == "NodeStatus"]
    status = [(t, tid) for t, name, tid in line if name == "EscStatus"]
    temperature = [tid for _, name, tid in line if name == "Temperature"]
    assert node == [(0.0, 0), (times[20], 1), (times[40], 2)]
    assert [t for t, _ in status] == times[::2]
    assert [tid for _, tid in status] == list(range(21))
    assert temperature == list(range(21))


def test_transfer_ids_wrap_modulo_32_per_type() -> None:
    esc = SimulatedEsc(20, telem_frequency=100)
    line = _timeline(esc, [i / 100 for i in range(40)])
    assert [tid for _, name, tid in line if name == "EscStatus"] == [*range(32), *range(8)]
    assert [tid for _, name, tid in line if name == "NodeStatus"] == [0]


def test_zero_frequency_publishes_only_node_status() -> None:
    esc = SimulatedEsc(20, telem_frequency=0)
    assert _timeline(esc, [0.0, 0.5, 1.0, 1.5]) == [
        (0.0, "NodeStatus", 0),
        (1.0, "NodeStatus", 1),
    ]
    assert esc.next_time() == 2.0


def test_a_long_gap_gives_one_of_each_and_restarts_the_grid() -> None:
    esc = SimulatedEsc(20, telem_frequency=10)
    esc.poll(0.0)
    assert names(esc.poll(10.0)) == ["NodeStatus", "EscStatus", "Temperature"]
    assert esc.poll(10.05) == []
    assert names(esc.poll(10.1)) == ["EscStatus", "Temperature"]
    assert names(esc.poll(10.9)) == ["EscStatus", "Temperature"]
    assert names(esc.poll(11.0)) == ["NodeStatus", "EscStatus", "Temperature"]


def test_late_poll_within_a_period_keeps_the_grid() -> None:
    esc = SimulatedEsc(20, telem_frequency=10)
    esc.poll(0.0)
    assert names(esc.poll(0.15)) == ["EscStatus", "Temperature"]
    assert names(esc.poll(0.2)) == ["EscStatus", "Temperature"]
    assert esc.poll(0.25) == []


def test_nothing_before_start_time_and_uptime_from_it() -> None:
    esc = SimulatedEsc(20, start_time=5.0)
    assert esc.poll(4.9) == []
    (status, *_) = decode(esc.poll(5.0))
    assert status.message.uptime_sec == 0
    assert esc.next_time() == 5.1
    (status, *_) = decode(esc.poll(7.5))
    assert status.message.uptime_sec == 2
    assert esc.state.uptime_sec == 2


def test_priority_of_published_messages() -> None:
    esc = SimulatedEsc(20, priority=3)
    assert {t.priority for t in decode(esc.poll(0.0))} == {3}


def test_periodic_tolerates_float_rounding() -> None:
    schedule = Periodic(10, 0.0)
    assert [schedule.due(t) for t in (0.0, 0.1, 0.2, 0.30000000000000004 - 1e-12, 0.3)] == [
        True,
        True,
        True,
        True,
        False,
    ]
    schedule.restart(0, 1.0)
    assert schedule.next_time is None
    assert not schedule.due(100.0)


@settings(max_examples=200)
@given(
    st.lists(st.floats(0.0, 30.0, allow_nan=False), min_size=1, max_size=60),
    st.sampled_from([0, 1, 7, 10, 50]),
)
def test_any_poll_sequence_is_bounded_and_counts_ids(gaps: list[float], frequency: int) -> None:
    esc = SimulatedEsc(20, telem_frequency=frequency)
    now = 0.0
    expected = {"NodeStatus": 0, "EscStatus": 0, "Temperature": 0}
    for gap in gaps:
        now += gap
        transfers = decode(esc.poll(now))
        kinds = [type(t.message).__name__ for t in transfers]
        assert len(kinds) == len(set(kinds)) <= 3
        for t in transfers:
            name = type(t.message).__name__
            assert t.transfer_id == expected[name]
            expected[name] = (expected[name] + 1) % 32
        next_time = esc.next_time()
        assert next_time is not None and next_time > now


@pytest.mark.parametrize("frequency", [1, 3, 10, 1000])
def test_next_time_is_when_poll_sends(frequency: int) -> None:
    esc = SimulatedEsc(20, telem_frequency=frequency)
    esc.poll(0.0)
    due = esc.next_time()
    assert due is not None
    assert esc.poll(due - 1e-6) == []
    assert esc.poll(due) != []
