"""Alive and Dead (seed 002, "Alive status"): each way of dying, for good; one and none alive."""

from __future__ import annotations

import pytest
from arbiter_support import READY, SEED_VARIABLES, Rig, variable

from veronte4x.arbiter import Arbiter, ArbiterConfig, ArbiterPhase, DecisionKind, Method

CONFIG = ArbiterConfig(variables=SEED_VARIABLES)


def deaths(arb: Arbiter) -> list[tuple[float, str]]:
    return [(d.time, d.reason) for d in arb.decisions if d.kind is DecisionKind.DEAD]


def started() -> Rig:
    rig = Rig(CONFIG)
    rig.run_until(1.0)
    assert rig.arb.state.alive == (True, True, True, False)
    assert rig.arb.state.selected == 1  # AP2, the best of the seed example
    return rig


def test_a_missing_variable_kills_after_0_1_s() -> None:
    rig = started()
    rig.mute(0, 2)  # AP1 stops sending variable 2 after t = 1.0
    rig.run_until(1.05)
    assert rig.arb.state.alive == (True, True, True, False)
    rig.run_until(1.1)
    assert deaths(rig.arb) == [
        (pytest.approx(1.1), "AP1 dead: arbitration variable 2 missing for 0.1 s")
    ]
    assert rig.arb.state.alive == (False, True, True, False)
    assert rig.arb.state.dead == (True, False, False, False)


def test_a_missing_ready_kills() -> None:
    rig = started()
    rig.mute(2, "ready")
    rig.run_until(1.2)
    assert deaths(rig.arb) == [(pytest.approx(1.1), "AP3 dead: Ready missing for 0.1 s")]


def test_the_death_is_dated_when_the_message_went_missing() -> None:
    rig = started()
    rig.mute(0)
    rig.arb.advance(3.0)  # nothing between 1.0 and 3.0: found late, dated right
    assert deaths(rig.arb)[0][0] == pytest.approx(1.1)


def test_exactly_0_1_s_is_too_late() -> None:
    arb = Arbiter(ArbiterConfig())  # no variables: only Ready counts
    for can_id in (8, 9, 10):
        arb.receive(can_id, READY, 0.0)
    arb.receive(8, READY, 0.0625)
    arb.receive(9, READY, 0.0625)
    arb.receive(10, READY, 0.0625)
    arb.receive(8, READY, 0.125)  # 0.0625 s gap: in time
    arb.receive(9, READY, 0.1625)  # 0.1 s gap: too late
    assert deaths(arb) == [
        (0.1625, "AP2 dead: Ready missing for 0.1 s"),
        (0.1625, "AP3 dead: Ready missing for 0.1 s"),
    ]


def test_a_message_never_received_kills_0_1_s_after_the_start() -> None:
    arb = Arbiter(CONFIG)
    for can_id in (8, 9, 10):
        arb.receive(can_id, READY, 0.0)
    arb.advance(0.1)
    assert deaths(arb) == [
        (0.1, "AP1 dead: arbitration variable 0 not received within 0.1 s of arbitration start"),
        (0.1, "AP2 dead: arbitration variable 0 not received within 0.1 s of arbitration start"),
        (0.1, "AP3 dead: arbitration variable 0 not received within 0.1 s of arbitration start"),
    ]
    assert arb.state.alive == (False, False, False, False)
    assert arb.state.selected == 0  # all dead: the preferred one
    assert arb.status_message().cbit_ok is False


def test_not_ready_kills() -> None:
    rig = started()
    rig.not_ready.add(1)
    rig.run_until(1.05)
    assert deaths(rig.arb) == [(1.05, "AP2 dead: Not Ready received")]
    assert rig.arb.state.ready == (True, False, True, False)
    assert rig.arb.state.selected == 2  # AP3 is the better of the two left
    assert rig.arb.decisions[-1].reason == "AP2 -> AP3: AP2 is dead: AP3 (best score 0.015)"


@pytest.mark.parametrize(
    ("signal", "cause"),
    [("set_fts", "FTS input bad (system not OK)"), ("set_watchdog", "watchdog input bad")],
)
def test_fts_and_watchdog_kill(signal: str, cause: str) -> None:
    rig = started()
    getattr(rig.arb, signal)(1.02, 1, False)
    assert deaths(rig.arb) == [(1.02, f"AP2 dead: {cause}")]
    getattr(rig.arb, signal)(1.03, 1, True)
    rig.run_until(5.0)
    assert rig.arb.state.alive == (True, False, True, False)


def test_bad_signals_before_the_start_kill_at_the_start() -> None:
    arb = Arbiter(CONFIG)
    arb.set_watchdog(0.0, 2, False)
    assert deaths(arb) == []
    for can_id in (8, 9, 10):
        arb.receive(can_id, READY, 0.01)
    assert deaths(arb) == [(0.01, "AP3 dead: watchdog input bad")]


def test_dead_is_for_good() -> None:
    rig = started()
    rig.mute(1)
    rig.run_until(1.5)
    rig.silent[1].clear()  # AP2 comes back, sending everything, with the best values
    rig.values[1] = [0.0967, 0.2833, 0.0]
    rig.run_until(10.0)
    assert rig.arb.state.alive == (True, False, True, False)
    assert rig.arb.state.selected != 1
    assert rig.arb.state.ready == (True, True, True, False)


def test_one_alive_is_selected_whatever_its_score() -> None:
    config = ArbiterConfig(variables=SEED_VARIABLES, hysteresis=0.9, holding_time=100.0)
    rig = Rig(config)
    rig.values[0] = [9.0, 9.0, 900.0]  # AP1: a very bad score
    rig.run_until(1.0)
    rig.mute(1)
    rig.mute(2)
    rig.run_until(1.2)
    assert rig.arb.state.alive == (True, False, False, False)
    assert rig.arb.state.selected == 0
    assert rig.arb.decisions[-1].reason.endswith("AP1 is the only one alive")


def test_none_alive_selects_the_preferred_one() -> None:
    rig = started()
    for autopilot in range(3):
        rig.mute(autopilot)
    rig.run_until(1.5)
    assert rig.arb.state.alive == (False, False, False, False)
    assert rig.arb.state.selected == 0
    assert [d.reason for d in rig.arb.decisions[-5:]] == [
        "AP1 dead: arbitration variable 0 missing for 0.1 s",
        "AP2 -> AP3: AP3 0.015 < AP2 0.019 x (1 - 0)",  # relative variables dropped out
        "AP2 dead: arbitration variable 0 missing for 0.1 s",
        "AP3 dead: arbitration variable 0 missing for 0.1 s",
        "AP3 -> AP1: no autopilot alive: preferred AP1 selected",
    ]
    assert rig.arb.state.phase is ArbiterPhase.ARBITRATING


def test_relative_variables_drop_out_when_two_are_left() -> None:
    rig = started()
    rig.mute(1)
    rig.run_until(1.5)
    # Only the absolute variable counts now: 1.7 x 0.01 and 1.5 x 0.01 (as float32).
    scores = rig.arb.state.scores
    assert scores[0] == pytest.approx(0.017, rel=1e-6)
    assert scores[2] == pytest.approx(0.015, rel=1e-6)
    assert rig.arb.state.selected == 2


def test_fixed_method_keeps_tracking_alive() -> None:
    rig = Rig(ArbiterConfig(variables=SEED_VARIABLES, method=Method.FIXED_1))
    rig.run_until(1.0)
    rig.mute(1)
    rig.run_until(2.0)
    assert rig.arb.state.alive == (True, False, True, False)
    assert rig.arb.state.selected == 1


def test_variable_numbers_beyond_the_configuration_are_ignored() -> None:
    arb = Arbiter(CONFIG)
    for can_id in (8, 9, 10):
        arb.receive(can_id, READY, 0.0)
        arb.receive(can_id, variable(0, 1.0), 0.0)
        arb.receive(can_id, variable(1, 1.0), 0.0)
        arb.receive(can_id, variable(2, 1.0), 0.0)
        arb.receive(can_id, variable(7, 1.0), 0.0)
    assert arb.state.scores == {0: 0.01, 1: 0.01, 2: 0.01}


def test_maintenance_freezes_alive_and_dead() -> None:
    rig = started()
    rig.mute(0)
    rig.run_until(1.5)
    assert rig.arb.state.selected == 2  # AP1 died: relative variables out, AP3 best
    rig.arb.command_maintenance(1.52)
    rig.not_ready.add(1)
    rig.mute(2)
    rig.arb.set_fts(1.52, 1, False)
    rig.run_until(3.0)
    assert rig.arb.state.alive == (False, True, True, False)
    assert rig.arb.state.selected == 2
    assert rig.arb.state.ready == (True, False, True, False)
