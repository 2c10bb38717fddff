"""The demo data is traffic a bus could carry (issue 39, item 5): both generators write
frames in time order, each ending at least one frame's length (at 1 Mbit/s, without the
stuffing bits) after the one before, and ESCs that differ, one warming up."""

from __future__ import annotations

import itertools
import runpy
import statistics
from collections import defaultdict
from pathlib import Path

import pytest

from veronte4x import capture
from veronte4x.capture import Frame
from veronte4x.capture.rates import frame_bits

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"
BITRATE = 1_000_000


@pytest.fixture(scope="module")
def flight(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """20 s of the demo flight (examples/make_capture.py), its failure at 10 s."""
    path = tmp_path_factory.mktemp("demo") / "flight.log"
    runpy.run_path(str(EXAMPLES / "make_capture.py"))["generate"](1 / 3, 10.0, 4).write(path)
    return path


@pytest.fixture(scope="module")
def vehicle(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """10 s of the demo DroneCAN vehicle bus (examples/make_vehicle_bus.py)."""
    path = tmp_path_factory.mktemp("demo") / "vehicle.log"
    runpy.run_path(str(EXAMPLES / "make_vehicle_bus.py"))["write"](path, 10.0)
    return path


def _frames(path: Path) -> list[tuple[float, Frame]]:
    """The capture's frames with their timestamps, each frame having one."""
    frames = [f for f in capture.open_frames(path) if isinstance(f, Frame)]
    assert len(frames) > 10_000
    return [(f.timestamp, f) for f in frames if f.timestamp is not None]


@pytest.mark.parametrize("demo", ["flight", "vehicle"])
def test_frames_come_in_time_order_one_frame_length_apart_at_most_1_mbit(
    demo: str, request: pytest.FixtureRequest
) -> None:
    frames = _frames(request.getfixturevalue(demo))
    assert len(frames) == sum(1 for f in capture.open_frames(request.getfixturevalue(demo)))
    too_close = [
        (before, after)
        for (before, _), (after, frame) in itertools.pairwise(frames)
        if after - before < frame_bits(len(frame.data), frame.extended, stuffing=False) / BITRATE
    ]
    assert too_close == []
    counts = capture.stats(capture.read(request.getfixturevalue(demo)))
    assert (sum(counts.errors.values()), sum(counts.unknown.values())) == (0, 0)


def test_the_flights_escs_differ_and_one_warms_up(flight: Path) -> None:
    currents: dict[int, list[float]] = defaultdict(list)
    temperatures: dict[int, list[float]] = defaultdict(list)
    for record in capture.read(flight):
        if type(record.message).__name__ == "EscStatus" and record.node_id is not None:
            currents[record.node_id].append(record.message.current)
            temperatures[record.node_id].append(record.message.temperature)
    assert sorted(currents) == [20, 21, 22, 23]
    means = {node: round(statistics.fmean(values), 1) for node, values in currents.items()}
    assert len(set(means.values())) == 4, means
    warming = {
        node: statistics.fmean(values[-20:]) - statistics.fmean(values[:20])
        for node, values in temperatures.items()
    }
    # the seeded flight: node 23 (ESC_MODELS[3]) warms most, node 22 is mounted warmer
    assert max(warming, key=warming.__getitem__) == 23, warming
    starts = {node: statistics.fmean(values[:20]) for node, values in temperatures.items()}
    assert max(starts, key=starts.__getitem__) == 22, starts
    assert starts[22] - min(starts.values()) > 4.0, starts
