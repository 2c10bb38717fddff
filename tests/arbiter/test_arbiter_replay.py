"""Replay: the timeline of a capture, and where the recorded arbiter disagrees."""

from __future__ import annotations

import math
import random
import struct
from pathlib import Path

import pytest
from arbiter_support import (
    READY,
    SEED_VARIABLES,
    STATUS_AP2_ALL_ALIVE,
    Rig,
    failure_capture,
)

from veronte4x.arbiter import (
    ArbiterConfig,
    DecisionKind,
    Disagreement,
    DisorderedError,
    InputError,
    Restart,
    SystemChecks,
    replay,
)
from veronte4x.capture import open_frames
from veronte4x.capture.frames import Frame

CONFIG = ArbiterConfig(variables=SEED_VARIABLES)


def test_replay_explains_the_switch_an_injected_failure_causes() -> None:
    result = replay(failure_capture(), CONFIG)
    dead = [d for d in result.decisions if d.kind is DecisionKind.DEAD]
    switches = [d for d in result.decisions if d.kind is DecisionKind.SWITCH]
    assert [(d.time, d.reason) for d in dead] == [
        (pytest.approx(1.6), "AP2 dead: arbitration variable 0 missing for 0.1 s")
    ]
    assert [(d.time, d.autopilot, d.reason) for d in switches] == [
        (0.0, 1, "AP1 -> AP2: AP2 0.0257 < AP1 0.057 x (1 - 0)"),
        (pytest.approx(1.6), 2, "AP2 -> AP3: AP2 is dead: AP3 (best score 0.015)"),
    ]
    assert result.disagreements == ()
    assert result.errors == ()
    assert result.state.selected == 2
    lines = result.timeline().splitlines()
    assert lines[-2:] == [
        "     1.600 s  dead        AP2 dead: arbitration variable 0 missing for 0.1 s",
        "     1.600 s  switch      AP2 -> AP3: AP2 is dead: AP3 (best score 0.015)",
    ]


def test_replay_reports_a_recorded_status_that_disagrees() -> None:
    # The "real" arbiter kept AP2 selected and alive after it went silent.
    result = replay(failure_capture(status_after=STATUS_AP2_ALL_ALIVE), CONFIG)
    assert result.disagreements == (
        Disagreement(1.75, 3.0, "alive AP2", True, False, 6),
        Disagreement(1.75, 3.0, "selected", 1, 2, 6),
    )
    assert str(result.disagreements[1]) == (
        "     1.750 s  DISAGREES   selected: recorded AP2, model AP3 (1.750-3.000 s, 6 frame(s))"
    )
    assert "DISAGREES   alive AP2: recorded True, model False" in result.timeline()


def test_model_output_replayed_agrees_with_itself() -> None:
    rig = Rig(ArbiterConfig(variables=SEED_VARIABLES, score_period=0.5))
    rig.run_until(1.0)
    rig.mute(0)
    rig.run_until(4.0)
    result = replay(rig.capture, rig.config)
    assert result.disagreements == ()
    assert list(result.decisions) == list(rig.arb.decisions)


def test_replay_compares_scores_beyond_float32_rounding() -> None:
    rig = Rig(CONFIG)
    rig.run_until(0.0)
    capture = [frame for frame in rig.capture if frame[1] != 255]
    capture.append((0.0, 255, b"\x00\x01" + struct.pack("<f", 0.02567)))  # 0.0256667: off
    capture.append((0.0, 255, b"\x00\x02" + struct.pack("<f", 0.055000003)))  # rounding only
    result = replay(capture, CONFIG)
    (only,) = result.disagreements
    assert (only.field, only.start, only.modelled) == (
        "score AP2",
        0.0,
        pytest.approx(0.025667, abs=1e-6),
    )
    assert only.recorded == pytest.approx(0.02567)


def test_replay_flags_status_while_the_model_is_idle_and_bad_frames() -> None:
    capture = [
        (0.0, 8, READY),
        (0.25, 255, bytes.fromhex("00ff0000ffff")),
        (0.3, 9, bytes.fromhex("00ff")),  # too short for a Ready
        (0.4, 255, bytes.fromhex("00ff00")),  # not a Status
    ]
    result = replay(capture, CONFIG, checks=SystemChecks(pdi_ok=False))
    assert result.disagreements == (
        Disagreement(0.25, 0.25, "mode", "Status sent", "Idle, no Status", 1),
    )
    assert [(e.time, e.can_id) for e in result.errors] == [(0.3, 9), (0.4, 255)]
    assert "Ready" in result.errors[0].error
    assert "BAD FRAME   id 9" in result.timeline()


def test_replay_compares_the_mode_bit() -> None:
    capture = [(0.0, 8, READY), (0.25, 255, bytes.fromhex("00ff0010ff7f"))]
    (only,) = replay(capture, CONFIG).disagreements
    assert (only.field, only.recorded, only.modelled) == ("mode", "Maintenance", "Normal")


def test_a_frame_a_little_late_is_taken_at_the_latest_time() -> None:
    """Two adjacent lines swapped 100 us apart, as a logger merging two queues writes them."""
    capture = failure_capture()
    capture = [(t + 0.0001, i, d) if i == 9 else (t, i, d) for t, i, d in capture]
    capture.sort(key=lambda frame: frame[0])
    swapped = list(capture)
    at = next(n for n, (t, can_id, _) in enumerate(swapped) if can_id == 9 and t > 0.1)
    assert swapped[at - 1][1] == 10
    swapped[at - 1], swapped[at] = swapped[at], swapped[at - 1]
    assert swapped[at][0] == swapped[at - 1][0] - 0.0001
    result, reference = replay(swapped, CONFIG), replay(capture, CONFIG)
    assert result.late == 1 and reference.late == 0
    assert result.restarts == ()
    assert result.decisions == reference.decisions
    assert result.disagreements == reference.disagreements


def test_two_logs_joined_restart_the_model() -> None:
    once = replay(failure_capture(), CONFIG)
    twice = replay(failure_capture() * 2, CONFIG)
    firsts = (len(once.decisions), len(once.disagreements), len(once.errors))
    assert twice.restarts == (Restart(0.0, 3.0, firsts),)
    assert twice.decisions == once.decisions * 2
    assert twice.disagreements == once.disagreements * 2
    assert twice.late == 0
    lines = twice.timeline().splitlines()
    half = len(once.timeline().splitlines())
    assert lines[:half] == once.timeline().splitlines()
    assert lines[half] == (
        "     0.000 s  RESTART     the capture's time steps back 3.000000 s (from 3.000 s): "
        "the model starts again, as at boot"
    )
    assert lines[half + 1 :] == once.timeline().splitlines()


def test_a_capture_out_of_time_order_is_refused() -> None:
    shuffled = failure_capture()
    random.Random(1).shuffle(shuffled)
    with pytest.raises(DisorderedError) as raised:
        replay(shuffled, CONFIG)
    assert isinstance(raised.value, InputError)
    assert raised.value.steps == 11


def test_a_timestamp_that_is_no_number_is_refused() -> None:
    with pytest.raises(InputError):
        replay([(1.0, 8, READY), (math.nan, 8, READY)], CONFIG)


def test_replay_of_a_candump_file_as_in_the_how_to(tmp_path: Path) -> None:
    log = tmp_path / "flight.log"
    log.write_text(
        "".join(
            f"({time:.6f}) can0 {can_id:03X}#{data.hex().upper()}\n"
            for time, can_id, data in failure_capture()
        )
    )
    frames = [
        (f.timestamp, f.can_id, f.data)
        for f in open_frames(str(log))
        if isinstance(f, Frame) and f.timestamp is not None and not (f.remote or f.error)
    ]
    result = replay(frames, CONFIG)
    assert result.disagreements == ()
    assert result.decisions[-1].reason == "AP2 -> AP3: AP2 is dead: AP3 (best score 0.015)"
