"""Rates, jitter, gaps, flags and bus load on generated traffic with known periods."""

from __future__ import annotations

import itertools
import math
import random
import statistics
import subprocess
import sys
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from veronte4x import codec, dronecan
from veronte4x.capture import BusMap
from veronte4x.capture.rates import RateTracker, StreamRate, detect_bitrate, frame_bits

Traffic = list[tuple[float, int, bytes, bool]]


def test_frame_bits_follow_davis_et_al() -> None:
    assert frame_bits(8, extended=False) == 135
    assert frame_bits(8, extended=False, stuffing=False) == 111
    assert frame_bits(8, extended=True) == 160
    assert frame_bits(0, extended=True) == 80
    assert frame_bits(0, extended=False) == 55


def node_status(node: int, tid: int) -> list[dronecan.TransferFrame]:
    message = dronecan.NodeStatus(
        uptime_sec=tid, health=dronecan.Health.OK, mode=0, sub_mode=0,
        vendor_specific_status_code=0,
    )  # fmt: skip
    return dronecan.encode(message, source_node_id=node, transfer_id=tid % 32)


def esc_status(node: int, tid: int) -> list[dronecan.TransferFrame]:
    message = dronecan.EscStatus(
        error_count=0, voltage=24.0, current=1.0, temperature=300.0, rpm=1000,
        power_rating_pct=10, esc_index=0,
    )  # fmt: skip
    return dronecan.encode(message, source_node_id=node, transfer_id=tid % 32)


def traffic(seed: int) -> tuple[Traffic, dict[str, list[float]]]:
    """Ten seconds: a jittery 100 Hz Status, a 20 Hz Score, a NodeStatus that stops at 5 s,
    an esc.Status at 100 Hz that drops to 20 Hz at 5 s, multi-frame GetNodeInfo responses."""
    rng = random.Random(seed)
    frames: list[tuple[float, int, bytes, bool]] = []
    times: dict[str, list[float]] = {}

    def stream(label: str, stamps: list[float], made: list[list[tuple[int, bytes, bool]]]) -> None:
        times[label] = stamps
        for stamp, parts in zip(stamps, made, strict=True):
            frames.extend((stamp + i * 1e-4, c, d, e) for i, (c, d, e) in enumerate(parts))

    status = codec.encode(codec.Status(1, True, (True,) * 4, (True,) * 4))
    stamps = [i * 0.01 + rng.uniform(-0.001, 0.001) for i in range(1000)]
    stream("arbiter 0FF Status", stamps, [[(255, status, False)]] * len(stamps))
    score = codec.encode(codec.Score(0, 0.5))
    stamps = [i * 0.05 + 0.003 for i in range(200)]
    stream("arbiter 0FF Score 0", stamps, [[(255, score, False)]] * len(stamps))
    stamps = [i * 1.0 + 0.0005 for i in range(6)]
    made = [[(f.can_id, f.data, True) for f in node_status(20, i)] for i in range(6)]
    stream("uavcan.protocol.NodeStatus from node 20", stamps, made)
    stamps = [i * 0.01 + 0.0071 for i in range(500)] + [5 + i * 0.05 + 0.0071 for i in range(100)]
    made = [[(f.can_id, f.data, True) for f in esc_status(21, i)] for i in range(600)]
    stream("uavcan.equipment.esc.Status from node 21", stamps, made)
    info = dronecan.GetNodeInfoResponse(
        status=dronecan.NodeStatus(1, dronecan.Health.OK, 0, 0, 0),
        software_version=dronecan.SoftwareVersion(1, 2, 0, 0, 0),
        hardware_version=dronecan.HardwareVersion(1, 0, bytes(16), b""),
        name=b"com.vertiq.esc",
    )
    stamps = [2.5, 7.5]
    made = [
        [
            (f.can_id, f.data, True)
            for f in dronecan.encode(info, source_node_id=21, transfer_id=i, destination_node_id=10)
        ]
        for i in range(2)
    ]
    assert all(len(m) > 1 for m in made)
    stream("uavcan.protocol.GetNodeInfo response 21->10", stamps, made)
    frames.sort(key=lambda f: f[0])
    return frames, times


def by_label(tracker: RateTracker, now: float) -> dict[str, StreamRate]:
    return {s.label: s for s in tracker.streams(now)}


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_generated_traffic_with_known_periods(seed: int) -> None:
    frames, times = traffic(seed)
    tracker = RateTracker(bitrate=1_000_000)
    for stamp, can_id, data, extended in frames:
        tracker.add(stamp, can_id, data, extended, "can0")
    got = by_label(tracker, now=10.0)
    # Status and Score share CAN ID 255: a stream each, told apart by bytes 0 and 1.
    assert sorted(got) == sorted(times)
    for label, stamps in times.items():
        stream = got[label]
        periods = [b - a for a, b in itertools.pairwise(stamps)]
        assert stream.count == len(stamps), label
        assert stream.rate == pytest.approx(len(periods) / (stamps[-1] - stamps[0]), rel=1e-9)
        assert stream.longest_gap == pytest.approx(max(periods), rel=1e-9)
        assert stream.silent == pytest.approx(10.0 - stamps[-1], rel=1e-9)
        if len(periods) > 1:
            assert stream.jitter == pytest.approx(statistics.stdev(periods), rel=1e-6)
        median = statistics.median(periods)
        assert abs(math.log2(stream.period / median)) <= 1 / 64 + 1e-9, label
    assert got["uavcan.protocol.NodeStatus from node 20"].flags == ("stopped",)
    assert got["uavcan.equipment.esc.Status from node 21"].flags == ("slow",)
    # Every 50 ms period after the drop is longer than 3 usual (10 ms) ones.
    assert got["uavcan.equipment.esc.Status from node 21"].gaps == 99
    assert got["arbiter 0FF Status"].flags == got["arbiter 0FF Score 0"].flags == ()
    (load,) = tracker.load()
    bits = sum(frame_bits(len(d), e) for _, _, d, e in frames)
    span = frames[-1][0] - frames[0][0]
    assert (load.frames, load.bits, load.bitrate, load.detected) == (
        len(frames),
        bits,
        10**6,
        False,
    )
    assert load.percent == pytest.approx(100 * bits / (span * 1e6), rel=1e-12)


def test_a_node_that_comes_back_has_a_gap_and_is_not_stopped() -> None:
    tracker = RateTracker()
    for i in [*range(5), *range(10, 15)]:
        (frame,) = node_status(30, i)
        tracker.add(float(i), frame.can_id, frame.data, True)
    (stream,) = tracker.streams()
    assert (stream.gaps, stream.flags, stream.longest_gap) == (1, (), 6.0)
    (stream,) = tracker.streams(now=18.5)
    assert stream.flags == ("stopped",)


@pytest.mark.parametrize("bitrate", [125_000, 250_000, 500_000, 1_000_000])
def test_bitrate_detected_from_back_to_back_frames(bitrate: int) -> None:
    tracker = RateTracker()
    time = 0.0
    for i in range(50):
        data = bytes(8)
        tracker.add(time, 0x100 + i % 3, data, False, "can1")
        time += frame_bits(8, False) / bitrate  # a full bus, worst-case stuffing
    (load,) = tracker.load()
    assert (load.bitrate, load.detected) == (bitrate, True)
    assert load.percent == pytest.approx(100 * 50 / 49, rel=1e-9)


def test_no_bitrate_when_timestamps_are_too_coarse() -> None:
    tracker = RateTracker()
    tracker.add(1.0, 0x100, bytes(8))
    tracker.add(1.000001, 0x101, bytes(8))
    (load,) = tracker.load()
    assert load.bitrate is None
    assert math.isnan(load.percent)
    assert detect_bitrate(0.0) == 125_000


@settings(max_examples=200)
@given(
    st.lists(
        st.tuples(
            st.floats(0, 1e4, allow_nan=False),
            st.integers(0, 2**29 - 1),
            st.binary(max_size=8),
            st.booleans(),
            st.sampled_from(["can0", "can1"]),
        ),
        max_size=60,
    )
)
def test_arbitrary_frames_give_figures(frames: list[tuple[float, int, bytes, bool, str]]) -> None:
    tracker = RateTracker(BusMap(extended=True, arbiter_id=0x100))
    for stamp, can_id, data, extended, channel in sorted(frames):
        tracker.add(stamp, can_id & (0x1FFFFFFF if extended else 0x7FF), data, extended, channel)
    streams = tracker.streams()
    assert sum(s.count for s in streams) <= len(frames)
    assert all(s.longest_gap >= 0 for s in streams)
    assert sum(load.frames for load in tracker.load()) == len(frames)


def test_stats_rates_in_a_subprocess(tmp_path: Path) -> None:
    frames, _ = traffic(4)
    path = tmp_path / "traffic.log"
    path.write_text(
        "".join(
            f"({1_700_000_000 + t:.6f}) can0 {c:{'08X' if e else '03X'}}#{d.hex()}\n"
            for t, c, d, e in frames
        )
    )
    done = subprocess.run(
        [sys.executable, "-m", "veronte4x", "stats", str(path), "--rates", "--bitrate", "500000"],
        capture_output=True,
        text=True,
        check=False,
    )
    assert (done.returncode, done.stderr) == (0, "")
    lines = done.stdout.splitlines()
    rates = lines[lines.index("rates:") + 1 :]
    node = next(line for line in rates if "NodeStatus from node 20" in line)
    assert node.startswith("  can0 uavcan.protocol.NodeStatus from node 20: 6 at 1 Hz, jitter ")
    assert node.endswith("longest gap 1000 ms  stopped")
    esc = next(line for line in rates if "esc.Status from node 21" in line)
    assert esc.endswith(", 99 gaps  slow")
    tracker = RateTracker(bitrate=500_000)
    for stamp, can_id, data, extended in frames:
        tracker.add(1_700_000_000 + stamp, can_id, data, extended, "can0")
    (load,) = tracker.load()
    assert lines[-2:] == [
        "bus load (worst-case bit stuffing):",
        f"  can0: {len(frames)} frames, {load.percent:.3g} % of 500 kbit/s (given)",
    ]


def test_monitor_rates_after_its_table(tmp_path: Path) -> None:
    example = Path(__file__).resolve().parents[2] / "examples" / "capture.log"
    done = subprocess.run(
        [sys.executable, "-m", "veronte4x", "monitor", str(example), "--rates"],
        capture_output=True,
        text=True,
        check=False,
    )
    assert done.returncode == 0
    lines = done.stdout.splitlines()
    assert "  can0 AP1 008 Ready: 1 at -, jitter -, longest gap -" in lines
    assert lines[-1] == "  can0: 39 frames, 6.51 % of 125 kbit/s (detected: the lowest that fits)"
