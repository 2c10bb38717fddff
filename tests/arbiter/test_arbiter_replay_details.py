"""Replay in detail: the timeline with the caller's time format, scores shown as numbers
(NaN included), the CEX-form Status that has no mode bit, and the arbiter's other frames."""

from __future__ import annotations

import struct

from arbiter_support import READY, SEED_VARIABLES, STATUS_AP2_ALL_ALIVE, Rig, failure_capture

from veronte4x.arbiter import ArbiterConfig, Disagreement, replay

CONFIG = ArbiterConfig(variables=SEED_VARIABLES)


def test_the_timeline_in_the_callers_time_format() -> None:
    """Every kind of line takes the time format: decisions, disagreements (their end too),
    bad frames and restarts (the time before the step too); each stretch in time order."""
    capture = failure_capture(status_after=STATUS_AP2_ALL_ALIVE)
    capture += [(3.05, 255, bytes.fromhex("00ff00")), (0.5, 8, READY)]
    lines = replay(capture, CONFIG).timeline(lambda t: f"T{t:.2f}").splitlines()
    assert lines[0] == "T0.00  mode        boot: Idle, checking the system"
    assert lines[-9:] == [
        "T1.60  dead        AP2 dead: arbitration variable 0 missing for 0.1 s",
        "T1.60  switch      AP2 -> AP3: AP2 is dead: AP3 (best score 0.015)",
        "T1.75  DISAGREES   alive AP2: recorded True, model False (until T3.00, 6 frame(s))",
        "T1.75  DISAGREES   selected: recorded AP2, model AP3 (until T3.00, 6 frame(s))",
        "T3.05  BAD FRAME   id 255: Status: 3 bytes; 4 (CEX form) or 6 (4x form) expected "
        "(data: 00 ff 00)",
        "T0.50  RESTART     the capture's time steps back 2.550000 s (from T3.05): the model "
        "starts again, as at boot",
        "T0.50  mode        boot: Idle, checking the system",
        "T0.50  mode        Normal, waiting for Ready: boot checks pass",
        "T0.50  ready       AP1 Ready",
    ]


def _scores_at_boot(*recorded: bytes) -> list[tuple[float, int, bytes]]:
    rig = Rig(CONFIG)
    rig.run_until(0.0)
    return [frame for frame in rig.capture if frame[1] != 255] + [(0.0, 255, r) for r in recorded]


def test_a_recorded_nan_score_disagrees_and_scores_read_as_numbers() -> None:
    capture = _scores_at_boot(
        b"\x00\x01" + struct.pack("<f", 0.02567), b"\x00\x02" + struct.pack("<f", float("nan"))
    )
    off, nan = replay(capture, CONFIG).disagreements
    assert str(off) == (
        "     0.000 s  DISAGREES   score AP2: recorded 0.02567, model 0.02566667497158052 "
        "(0.000-0.000 s, 1 frame(s))"
    )
    assert str(nan) == (
        "     0.000 s  DISAGREES   score AP3: recorded nan, model 0.054999996622403485 "
        "(0.000-0.000 s, 1 frame(s))"
    )


def test_the_arbiters_other_frames_are_neither_compared_nor_bad() -> None:
    """A Version request or an opaque frame on the arbiter's ID decodes: no bad frame, and
    nothing to compare."""
    plain = _scores_at_boot()
    other = _scores_at_boot(bytes.fromhex("01"), bytes.fromhex("0a0001020304"))
    reference, result = replay(plain, CONFIG), replay(other, CONFIG)
    assert (result.errors, result.disagreements) == ((), ())
    assert result.decisions == reference.decisions


def test_a_cex_status_has_no_mode_bit_to_compare() -> None:
    """The same maintenance Status in the 4x form disagrees on the mode; in the CEX form
    (4 bytes, no mode bit) only the fields it has are compared."""
    four_x = [(0.0, 8, READY), (0.25, 255, bytes.fromhex("00ff0010ff7f"))]
    cex = [(0.0, 8, READY), (0.25, 255, bytes.fromhex("00ff0010"))]
    assert [d.field for d in replay(four_x, CONFIG).disagreements] == ["mode"]
    assert replay(cex, CONFIG).disagreements == ()
    wrong = [(0.0, 8, READY), (0.25, 255, bytes.fromhex("00ff0110"))]
    assert replay(wrong, CONFIG).disagreements == (Disagreement(0.25, 0.25, "selected", 1, 0, 1),)
