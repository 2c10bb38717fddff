"""Selection (seed 003, Config menu): each method, preferred, holding time, hysteresis,
the external autopilot."""

from __future__ import annotations

import pytest
from arbiter_support import SEED_VARIABLES, Rig

from veronte4x.arbiter import (
    ArbiterConfig,
    DecisionKind,
    Failover,
    MaxErrorMode,
    Method,
    RelativeMean,
    VariableConfig,
)
from veronte4x.arbiter.selection import best, choose

ONE_ABSOLUTE = (VariableConfig(weight=1.0, absolute=True),)


def switches(rig: Rig) -> list[tuple[float, int | None, str]]:
    return [
        (round(d.time, 6), d.autopilot, d.reason)
        for d in rig.arb.decisions
        if d.kind is DecisionKind.SWITCH
    ]


def absolute_rig(values: list[float], **options: object) -> Rig:
    config = ArbiterConfig(variables=ONE_ABSOLUTE, **options)  # type: ignore[arg-type]
    return Rig(config, {ap: [value] for ap, value in enumerate(values)})


def test_hysteresis_example_of_the_seed() -> None:
    # "hysteresis is 0.5 and score for AP 1 is 0.3, AP 2 will need a score lower than 0.15"
    config = ArbiterConfig(variables=ONE_ABSOLUTE, hysteresis=0.5)
    assert choose(config, 0, [0, 1, 2], {0: 0.3, 1: 0.15, 2: 1.0}) is None
    choice = choose(config, 0, [0, 1, 2], {0: 0.3, 1: 0.1499, 2: 1.0})
    assert choice is not None
    assert (choice.autopilot, choice.forced) == (1, False)
    assert choice.reason == "AP2 0.15 < AP1 0.3 x (1 - 0.5)"


def test_hysteresis_scenario_with_frames() -> None:
    rig = absolute_rig([0.3, 0.16, 1.0], hysteresis=0.5)
    rig.run_until(1.0)
    rig.values[1] = [0.15]  # float32(0.15) == float32(0.3) x 0.5: not lower
    rig.run_until(2.0)
    assert rig.arb.state.selected == 0
    rig.values[1] = [0.149]
    rig.run_until(3.0)
    assert switches(rig) == [(2.05, 1, "AP1 -> AP2: AP2 0.149 < AP1 0.3 x (1 - 0.5)")]


def test_always_best_switches_at_once_without_holding() -> None:
    rig = absolute_rig([0.5, 0.2, 0.9])
    rig.run_until(0.5)
    rig.values[2] = [0.1]
    rig.run_until(1.0)
    assert switches(rig) == [
        (0.0, 1, "AP1 -> AP2: AP2 0.2 < AP1 0.5 x (1 - 0)"),
        (0.55, 2, "AP2 -> AP3: AP3 0.1 < AP2 0.2 x (1 - 0)"),
    ]


def test_holding_time_delays_a_switch_to_when_it_ends() -> None:
    rig = absolute_rig([0.5, 0.2, 0.9], holding_time=2.02)
    rig.run_until(0.5)
    rig.values[2] = [0.1]
    rig.run_until(3.0)
    assert switches(rig) == [
        (0.0, 1, "AP1 -> AP2: AP2 0.2 < AP1 0.5 x (1 - 0)"),
        (2.02, 2, "AP2 -> AP3: AP3 0.1 < AP2 0.2 x (1 - 0)"),
    ]
    held = [d for d in rig.arb.decisions if d.kind is DecisionKind.HOLD]
    assert [(d.time, d.autopilot, d.reason) for d in held] == [
        (
            0.55,
            2,
            "AP2 -> AP3 held until 2.020 s (holding time): AP3 0.1 < AP2 0.2 x (1 - 0)",
        )
    ]


def test_holding_time_does_not_keep_a_dead_autopilot() -> None:
    rig = absolute_rig([0.5, 0.2, 0.9], holding_time=100.0)
    rig.run_until(0.5)
    rig.mute(1)
    rig.run_until(1.0)
    assert switches(rig)[-1] == (0.6, 0, "AP2 -> AP1: AP2 is dead: AP1 (best score 0.5)")


def test_change_if_worst_switches_only_from_the_worst() -> None:
    rig = absolute_rig([0.5, 0.2, 0.9], method=Method.CHANGE_IF_WORST)
    rig.run_until(1.0)
    assert switches(rig) == []  # AP1 is not the worst: AP3 is
    rig.values[0] = [1.0]
    rig.run_until(2.0)
    assert switches(rig) == [
        (1.05, 1, "AP1 -> AP2: AP1 has the worst score; AP2 0.2 < AP1 1 x (1 - 0)")
    ]


def test_change_if_worst_keeps_hysteresis() -> None:
    rig = absolute_rig([0.5, 0.4, 0.3], method=Method.CHANGE_IF_WORST, hysteresis=0.5)
    rig.run_until(1.0)
    assert switches(rig) == []  # worst, but 0.3 is not below 0.5 x 0.5
    rig.values[2] = [0.2]
    rig.run_until(2.0)
    assert [s[:2] for s in switches(rig)] == [(1.05, 2)]


def test_preferred_wins_a_draw() -> None:
    assert best({0: 0.2, 1: 0.1, 2: 0.1}, [0, 1, 2], preferred=2) == 2
    assert best({0: 0.1, 1: 0.1, 2: 0.1}, [0, 1, 2], preferred=1) == 1
    assert best({0: 0.2, 1: 0.1, 2: 0.1}, [0, 1, 2], preferred=0) == 1  # then the lowest
    rig = absolute_rig([0.3, 0.1, 0.3], preferred=2)
    rig.run_until(0.5)
    assert rig.arb.state.selected == 1
    rig.values[0] = rig.values[2] = [0.2]
    rig.mute(1)
    rig.run_until(1.0)
    assert switches(rig)[-1] == (0.6, 2, "AP2 -> AP3: AP2 is dead: AP3 (best score 0.2)")


def test_round_robin_cycles_every_holding_time_and_skips_the_dead() -> None:
    rig = absolute_rig([0.1, 0.5, 0.9], method=Method.ROUND_ROBIN, holding_time=1.0)
    rig.run_until(3.2)
    rig.mute(1)
    rig.run_until(5.5)
    assert [s[:2] for s in switches(rig)] == [(1.0, 1), (2.0, 2), (3.0, 0), (4.0, 2), (5.0, 0)]
    assert switches(rig)[0][2] == "AP1 -> AP2: round robin: AP2 after AP1"


def test_round_robin_leaves_a_dead_selected_one_at_once() -> None:
    rig = absolute_rig([0.1, 0.5, 0.9], method=Method.ROUND_ROBIN, holding_time=1.0)
    rig.run_until(1.2)
    rig.mute(1)
    rig.run_until(2.5)
    assert [s[:2] for s in switches(rig)] == [(1.0, 1), (1.3, 2), (2.3, 0)]
    assert switches(rig)[1][2] == "AP2 -> AP3: AP2 is dead: AP3 (next alive)"


@pytest.mark.parametrize(
    ("method", "fixed"), [(Method.FIXED_0, 0), (Method.FIXED_1, 1), (Method.FIXED_2, 2)]
)
def test_fixed_methods_stay_fixed(method: Method, fixed: int) -> None:
    rig = absolute_rig([0.5, 0.2, 0.9], method=method, holding_time=0.0)
    sent = rig.run_until(0.25)
    assert rig.arb.state.selected == fixed
    # Arbitration is disabled: byte 2 is the fixed autopilot with the arbitrating bit clear.
    assert sent[-1] == (0.25, 255, bytes([0, 0xFF, fixed, 0x77, 0xFF, 0xFF]))
    rig.values[fixed] = [100.0]
    rig.mute(fixed)
    rig.run_until(2.0)
    assert rig.arb.state.selected == fixed
    assert switches(rig) == []  # selected from the start: never a switch


@pytest.mark.parametrize(
    ("failover", "expected"),
    [(Failover.NEXT, 2), (Failover.LOWEST, 0), (Failover.BEST_SCORE, 2)],
)
def test_fixed_while_ok_ignores_scores_and_fails_over(failover: Failover, expected: int) -> None:
    rig = absolute_rig(
        [0.5, 0.9, 0.2], method=Method.FIXED_WHILE_OK, preferred=1, failover=failover
    )
    rig.run_until(1.0)
    assert rig.arb.state.selected == 1  # the preferred one, though the worst
    rig.mute(1)
    rig.run_until(2.0)
    assert rig.arb.state.selected == expected
    assert len(switches(rig)) == 1
    rig.values[0] = [0.0]
    rig.run_until(3.0)
    assert len(switches(rig)) == 1


def test_external_autopilot_takes_part_when_enabled() -> None:
    config = ArbiterConfig(variables=SEED_VARIABLES, external_enabled=True)
    rig = Rig(config)
    rig.values[3] = [0.10, 0.28, 0.1]
    sent = rig.run_until(0.0)
    assert rig.arb.state.selected == 3
    assert sent[0] == (0.0, 255, bytes.fromhex("00ff83ffffff"))
    assert [data[:2] for _, _, data in sent[1:]] == [bytes([0, ap]) for ap in range(4)]
    # Means over the four: roll 0.0975, pitch 0.2825.
    assert rig.arb.state.scores[3] == pytest.approx(0.0025 + 0.0025 + 0.001, abs=1e-7)


def test_external_autopilot_ignored_when_disabled() -> None:
    rig = Rig(ArbiterConfig(variables=SEED_VARIABLES))
    rig.values[3] = [0.10, 0.28, 0.1]
    rig.run_until(1.0)
    assert rig.arb.state.selected == 1
    assert set(rig.arb.state.scores) == {0, 1, 2}
    assert rig.arb.state.ready == (True, True, True, False)


def test_a_nan_score_ranks_worst() -> None:
    config = ArbiterConfig(variables=ONE_ABSOLUTE)
    nan = float("nan")
    assert best({0: nan, 1: 0.5, 2: 0.7}, [0, 1, 2], preferred=0) == 1
    choice = choose(config, 0, [0, 1, 2], {0: nan, 1: 0.5, 2: 0.7})
    assert choice is not None and choice.autopilot == 1
    assert choose(config, 1, [0, 1, 2], {0: nan, 1: 0.5, 2: 0.7}) is None
    rig = absolute_rig([0.5, nan, 0.7])
    rig.run_until(0.5)
    assert rig.arb.state.selected == 0


def test_hysteresis_with_negative_scores_is_relative_to_their_size() -> None:
    config = ArbiterConfig(variables=ONE_ABSOLUTE, hysteresis=0.5)
    assert choose(config, 0, [0, 1, 2], {0: -1.0, 1: -1.4, 2: 0.0}) is None
    choice = choose(config, 0, [0, 1, 2], {0: -1.0, 1: -1.6, 2: 0.0})
    assert choice is not None and choice.autopilot == 1
    draw = ArbiterConfig(variables=ONE_ABSOLUTE, preferred=1)
    assert choose(draw, 0, [0, 1, 2], {0: -1.0, 1: -1.0, 2: 0.0}) is None


def test_relative_mean_and_max_error_options_reach_the_model() -> None:
    variables = (VariableConfig(weight=1.0, max_error=0.5),)
    values = {0: [10.0], 1: [1.0], 2: [2.0], 3: [3.0]}
    scores = {}
    for mean in (RelativeMean.ALIVE, RelativeMean.REPORTING):
        for clamp in (MaxErrorMode.IGNORE, MaxErrorMode.CLAMP):
            config = ArbiterConfig(
                variables=variables,
                external_enabled=True,
                relative_mean=mean,
                max_error_mode=clamp,
            )
            rig = Rig(config, values)
            rig.run_until(0.5)
            rig.mute(0)
            rig.run_until(1.0)
            scores[mean, clamp] = rig.arb.state.scores
    # AP1 is dead: the mean of the alive ones is 2, of all four 4.
    assert scores[RelativeMean.ALIVE, MaxErrorMode.IGNORE] == {0: 8.0, 1: 1.0, 2: 0.0, 3: 1.0}
    assert scores[RelativeMean.REPORTING, MaxErrorMode.IGNORE] == {0: 6.0, 1: 3.0, 2: 2.0, 3: 1.0}
    assert scores[RelativeMean.ALIVE, MaxErrorMode.CLAMP] == {0: 0.5, 1: 0.5, 2: 0.0, 3: 0.5}
    assert scores[RelativeMean.REPORTING, MaxErrorMode.CLAMP] == {0: 0.5, 1: 0.5, 2: 0.5, 3: 0.5}
