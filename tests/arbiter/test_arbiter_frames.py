"""The frames the model sends: Status and Score periods, bytes, enabling and disabling."""

from __future__ import annotations

import struct

import pytest
from arbiter_support import SEED_VALUES, SEED_VARIABLES, Rig, f32

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
    arb = Arbiter(CONFIG)
    assert len(arb.poll(0.0)) == 1  # Status; no scores yet, so no Score frame
    assert len(arb.poll(0.1)) == 0
    assert len(arb.poll(10.0)) == 1  # 40 Status periods and 3 Score periods late
    assert len(arb.poll(10.2)) == 0
    assert len(arb.poll(10.25)) == 1


def test_scores_beyond_float32_go_out_as_infinity() -> None:
    config = ArbiterConfig(variables=[VariableConfig(weight=1e10, absolute=True)])
    rig = Rig(config, {ap: [3e38] for ap in range(3)})
    sent = rig.run_until(0.0)
    assert sent[1] == (0.0, 255, bytes.fromhex("0000") + struct.pack("<f", float("inf")))
