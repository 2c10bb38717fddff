"""The frames the model sends: Status and Score periods, bytes, enabling and disabling."""

from __future__ import annotations

import struct

import pytest
from arbiter_support import (
    READY,
    SEED_VALUES,
    SEED_VARIABLES,
    STATUS_AP2_ALL_ALIVE,
    Rig,
    f32,
    variable,
)

from veronte4x.arbiter import Arbiter, ArbiterConfig, SystemChecks, VariableConfig, compute_scores

CONFIG = ArbiterConfig(variables=SEED_VARIABLES)


def wire_scores() -> dict[int, float]:
    """The seed example's scores from the float32 values that travel on the bus."""
    values = {ap: [f32(v) for v in row] for ap, row in SEED_VALUES.items()}
    return compute_scores(values, SEED_VARIABLES)


def test_status_every_0_25_s_and_scores_every_3_s() -> None:
    rig = Rig(CONFIG)
    sent = rig.run_until(6.0)
    status_times = [t for t, _, data in sent if data[1] == 0xFF]
    score_times = [t for t, _, data in sent if data[1] != 0xFF]
    assert status_times == [k * 0.25 for k in range(25)]
    assert score_times == [0.0] * 3 + [3.0] * 3 + [6.0] * 3
    assert {can_id for _, can_id, _ in sent} == {255}


def test_status_and_score_bytes() -> None:
    rig = Rig(CONFIG)
    sent = rig.run_until(0.0)
    scores = wire_scores()
    assert sent == [
        # selected AP2 (1) with arbitration on; AP1-AP3 alive and ready; every check OK.
        (0.0, 255, bytes.fromhex("00ff8177ffff")),
        (0.0, 255, b"\x00\x00" + struct.pack("<f", scores[0])),
        (0.0, 255, b"\x00\x01" + struct.pack("<f", scores[1])),
        (0.0, 255, b"\x00\x02" + struct.pack("<f", scores[2])),
    ]
    assert struct.unpack("<f", sent[2][2][2:])[0] == pytest.approx(0.02567, abs=1e-5)


def test_status_bytes_4_and_5_follow_the_checks() -> None:
    arb = Arbiter(CONFIG)
    arb.poll(0.0)
    arb.set_checks(0.1, SystemChecks(can_a_ok=False, ap3_voltage_ok=False))
    # Byte 4: CBIT and CAN A fail; byte 5: power and AP3 voltage fail, Normal mode.
    assert arb.poll(0.25) == [(255, bytes.fromhex("00ff0000eebe"))]


def test_disabled_status_and_score_send_nothing_in_normal() -> None:
    rig = Rig(ArbiterConfig(variables=SEED_VARIABLES, send_status=False, send_score=False))
    assert rig.run_until(7.0) == []


def test_score_only() -> None:
    rig = Rig(ArbiterConfig(variables=SEED_VARIABLES, send_status=False, score_period=1.0))
    sent = rig.run_until(2.0)
    assert [(t, data[1]) for t, _, data in sent] == [
        (t, ap) for t in (0.0, 1.0, 2.0) for ap in range(3)
    ]


def test_a_late_poll_sends_each_message_once() -> None:
    """The autopilots keep talking every 0.05 s; the arbiter is polled at a few times only.

    A poll 40 Status periods and 3 Score periods late sends one Status and one Score per
    autopilot, and the due times stay on the grid of their start (Status next at 10.25 s,
    Scores at 12.0 s).
    """
    arb = Arbiter(CONFIG)
    status = (255, STATUS_AP2_ALL_ALIVE)
    scores = [(255, bytes([0, ap]) + struct.pack("<f", s)) for ap, s in wire_scores().items()]
    polls = {0.0: [status, *scores], 0.1: [], 10.0: [status, *scores], 10.2: []}
    polls |= {10.25: [status], 11.95: [status], 12.0: [status, *scores]}
    sent = {}
    for tick in range(round(12.0 / 0.05) + 1):
        time = round(tick * 0.05, 9)
        for autopilot, can_id in enumerate(CONFIG.autopilot_ids[:3]):
            arb.receive(can_id, READY, time)
            for number, value in enumerate(SEED_VALUES[autopilot]):
                arb.receive(can_id, variable(number, value), time)
        if time in polls:
            sent[time] = arb.poll(time)
    assert sent == polls


def test_a_late_poll_with_no_autopilot_heard_sends_one_status() -> None:
    arb = Arbiter(CONFIG)
    # Nothing selected, not arbitrating, nothing alive or ready, every check OK; no scores.
    nobody = [(255, bytes.fromhex("00ff0000ffff"))]
    assert [arb.poll(t) for t in (0.0, 0.1, 10.0, 10.2, 10.25)] == [nobody, [], nobody, [], nobody]


def test_scores_beyond_float32_go_out_as_infinity() -> None:
    config = ArbiterConfig(variables=[VariableConfig(weight=1e10, absolute=True)])
    rig = Rig(config, {ap: [3e38] for ap in range(3)})
    sent = rig.run_until(0.0)
    assert sent[1] == (0.0, 255, bytes.fromhex("0000") + struct.pack("<f", float("inf")))
