"""Playback: the schedule without a clock, then ``veronte4x play`` across processes."""

from __future__ import annotations

import itertools
import json
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tests.client.cli_support import GROUP, free_port
from veronte4x.capture import Frame, open_frames
from veronte4x.capture.playback import IdFilter, Pacer, PlaybackError, Player

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "capture.log"


def frame(time: float | None, can_id: int = 0x100, channel: str = "can0") -> Frame:
    return Frame(time, channel, can_id, bytes([can_id & 0xFF]))


def everything(player: Player) -> list[tuple[float, Frame]]:
    """Every (due time, frame), asking for each frame exactly when it is due."""
    out = []
    while (due := player.due()) is not None:
        out += [(due, f) for f in player.take(due)]
    return out


def test_frames_are_due_at_their_scaled_offsets() -> None:
    frames = [frame(10.0, 1), frame(10.5, 2), frame(None, 3), frame(12.0, 4)]
    player = Player(frames, speed=2.0)
    player.start(100.0)
    assert everything(player) == [
        (100.0, frames[0]),
        (100.25, frames[1]),
        (100.25, frames[2]),  # no timestamp: with the frame before it
        (101.0, frames[3]),
    ]
    assert player.timing().frames == 4
    assert player.timing().max_late == 0.0


def test_late_frames_go_at_once_and_are_measured() -> None:
    player = Player([frame(0.0), frame(0.1), frame(0.2)])
    player.start(5.0)
    assert list(player.take(4.9)) == []
    assert len(list(player.take(5.15))) == 2  # the first two, 0.15 and 0.05 s late
    assert len(list(player.take(5.2))) == 1
    assert player.due() is None
    timing = player.timing()
    assert (timing.frames, timing.max_late) == (3, pytest.approx(0.15))
    assert timing.mean_late == pytest.approx(0.2 / 3)


def test_loops_follow_each_other_one_mean_spacing_apart() -> None:
    frames = [frame(0.0, 1), frame(1.0, 2), frame(2.0, 3)]
    player = Player(frames, loops=2)
    player.start(0.0)
    assert [due for due, _ in everything(player)] == [0.0, 1.0, 2.0, 3.0, 4.0, 5.0]
    forever = Player(frames, loops=None)
    forever.start(0.0)
    for _ in range(10):
        assert forever.due() is not None
        list(forever.take(forever.due() or 0.0))
    assert forever.timing().frames == 10


def test_time_that_goes_back_does_not_reorder() -> None:
    frames = [frame(5.0, 1), frame(4.0, 2), frame(6.0, 3)]
    player = Player(frames)
    player.start(0.0)
    assert everything(player) == [(0.0, frames[0]), (0.0, frames[1]), (1.0, frames[2])]


def test_filters_and_channel_map() -> None:
    frames = [frame(0.0, 0x0FF), frame(1.0, 0x108, "can1"), frame(2.0, 0x208), frame(3.0, 0x0FF)]
    player = Player(frames, filters=[IdFilter.parse("0FF"), IdFilter.parse("008:0FF")])
    player.start(0.0)
    assert [f.can_id for _, f in everything(player)] == [0x0FF, 0x108, 0x208, 0x0FF]
    player = Player(frames, filters=[IdFilter.parse("100:700")], channels={"can1": "vcan7"})
    player.start(0.0)
    assert everything(player) == [(0.0, frames[1]._replace(channel="vcan7"))]


@pytest.mark.parametrize(
    ("arguments", "message"),
    [
        ({"speed": 0}, "speed 0: expected a positive number"),
        ({"speed": float("nan")}, "speed nan"),
        ({"loops": 0}, "loops 0"),
    ],
)
def test_bad_arguments(arguments: dict[str, float], message: str) -> None:
    with pytest.raises(PlaybackError, match=message):
        Player([], **arguments)  # type: ignore[arg-type]
    with pytest.raises(PlaybackError, match="hexadecimal CAN ID"):
        IdFilter.parse("0xZZ")


@settings(max_examples=200)
@given(
    st.lists(
        st.builds(
            Frame,
            st.one_of(st.none(), st.floats(0, 1e6)),
            st.sampled_from(["can0", "can1"]),
            st.integers(0, 0x7FF),
            st.binary(max_size=8),
            remote=st.booleans(),
            fd=st.booleans(),
            error=st.booleans(),
            brs=st.booleans(),
            esi=st.booleans(),
            dlc=st.integers(0, 15),
        ),
        max_size=40,
    ),
    st.floats(0.01, 100),
)
def test_every_frame_goes_once_unchanged_and_in_order(frames: list[Frame], speed: float) -> None:
    player = Player(frames, speed=speed)
    player.start(0.0)
    dues = everything(player)
    assert [f for _, f in dues] == frames  # error frames, flags and DLCs included
    assert all(a <= b for (a, _), (b, _) in itertools.pairwise(dues))


RECEIVER = textwrap.dedent(
    """
    import json, sys, time
    import can
    group, port, count = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    with can.Bus(interface="udp_multicast", channel=group, port=port) as bus:
        print("ready", flush=True)
        got, end = 0, time.monotonic() + 120
        while got < count and time.monotonic() < end:
            m = bus.recv(1.0)
            if m is None:
                continue
            got += 1
            print(json.dumps([time.monotonic(), m.arbitration_id, m.data.hex(),
                              m.is_extended_id, m.is_remote_frame]), flush=True)
    """
)


def test_play_sends_every_frame_in_order_with_its_spacing(tmp_path: Path) -> None:
    lines = EXAMPLE.read_text().splitlines()
    last = 1763737200.501
    extra = [
        f"({last + 0.1 + i * 0.05:.6f}) can0 1401550A#{bytes([i, 0xC0 | i]).hex()}"
        for i in range(10)
    ] + [f"({last + 0.7:.6f}) can0 123#R"]
    capture = tmp_path / "capture.log"
    capture.write_text("\n".join([*lines, *extra]) + "\n")
    expected = [f for f in open_frames(capture) if isinstance(f, Frame)]
    port = free_port()
    receiver = subprocess.Popen(
        [sys.executable, "-c", RECEIVER, GROUP, str(port), str(len(expected))],
        stdout=subprocess.PIPE,
        text=True,
    )
    try:
        assert receiver.stdout is not None
        assert receiver.stdout.readline().strip() == "ready"
        speed = 2.0
        done = subprocess.run(
            [
                sys.executable,
                "-m",
                "veronte4x",
                "play",
                str(capture),
                "--interface",
                "udp_multicast",
                "--channel",
                GROUP,
                "--bus-option",
                f"port={port}",
                "--speed",
                str(speed),
            ],
            capture_output=True,
            text=True,
            check=False,
        )
        assert done.returncode == 0, done.stderr
        assert done.stderr.startswith(f"veronte4x: sent {len(expected)} frames in ")
        received = [json.loads(line) for line in receiver.stdout]
    finally:
        receiver.wait(timeout=150)
    got = [(r[1], bytes.fromhex(r[2]), r[3], r[4]) for r in received]
    assert got == [(f.can_id, f.data, f.extended, f.remote) for f in expected]
    # Spacing, loosely (the machine is loaded): the playback takes at least 80 % of the
    # capture's span over the speed, and the 50 ms steps of the extended frames are not
    # collapsed into one burst.
    stamps = [f.timestamp for f in expected if f.timestamp is not None]
    span = (max(stamps) - min(stamps)) / speed
    assert received[-1][0] - received[0][0] >= 0.8 * span
    steps = [b[0] - a[0] for a, b in zip(received[-11:-2], received[-10:-1], strict=True)]
    assert sum(steps) >= 0.8 * 8 * 0.05 / speed


def test_play_usage_errors(tmp_path: Path) -> None:
    def play(*args: str) -> subprocess.CompletedProcess[str]:
        return subprocess.run(
            [sys.executable, "-m", "veronte4x", "play", str(EXAMPLE), *args],
            capture_output=True,
            text=True,
            check=False,
        )

    done = play("-i", "virtual", "-c", "x", "--speed", "0")
    assert done.returncode == 2
    assert done.stderr.endswith(
        "veronte4x play: error: argument --speed: '0': expected a positive number, e.g. 2 or 0.5\n"
    )
    done = play("-i", "virtual", "-c", "x", "--filter", "zz")
    assert done.returncode == 2
    assert "filter 'zz': expected a hexadecimal CAN ID or ID:MASK" in done.stderr
    done = play("-i", "virtual", "-c", "x", "--channel-map", "can0")
    assert (done.returncode, done.stderr) == (
        2,
        "veronte4x: --channel-map 'can0': expected CAPTURED=SENT, e.g. can0=vcan1\n",
    )
    done = play("-i", "nosuchinterface", "-c", "x")
    assert done.returncode == 2
    assert done.stderr.startswith("veronte4x: cannot open the CAN bus (interface nosuchinterface")


def test_pacer_spaces_a_stream() -> None:
    pacer = Pacer(speed=2.0)
    assert pacer.delay(100.0, now=50.0) == 0.0
    assert pacer.delay(101.0, now=50.1) == pytest.approx(0.4)
    assert pacer.delay(None, now=50.5) == 0.0
    assert pacer.delay(100.5, now=50.5) == 0.0  # back in time: not before the one before
    assert pacer.delay(104.0, now=51.0) == pytest.approx(1.0)
    with pytest.raises(PlaybackError, match="speed -1"):
        Pacer(-1)


def test_monitor_at_a_speed_shows_the_capture_as_if_live() -> None:
    done = subprocess.run(
        [sys.executable, "-m", "veronte4x", "monitor", str(EXAMPLE), "--speed", "5"],
        capture_output=True,
        text=True,
        check=False,
    )
    assert done.returncode == 0, done.stderr
    plain = subprocess.run(
        [sys.executable, "-m", "veronte4x", "monitor", str(EXAMPLE)],
        capture_output=True,
        text=True,
        check=True,
    )
    assert done.stdout.endswith(plain.stdout)  # the last table is the whole capture's
    assert done.stderr == plain.stderr
