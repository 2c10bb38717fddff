"""Scores: the seed's worked example, relative and absolute variables, the options."""

from __future__ import annotations

import pytest
from arbiter_support import SEED_VALUES, SEED_VARIABLES

from veronte4x import arbiter
from veronte4x.arbiter import (
    ConfigError,
    InputError,
    MaxErrorMode,
    VariableConfig,
    compute_scores,
    explain_scores,
)


def test_seed_example_to_the_table_precision() -> None:
    # seed 003, "Arbitration Example": totals 0.058, 0.026, 0.054; AP2 is the best.
    scores = compute_scores(SEED_VALUES, SEED_VARIABLES)
    table = {0: 0.058, 1: 0.026, 2: 0.054}
    # The table truncates the means to 0.096 and 0.283 and sums terms rounded to 3
    # decimals: three terms, each within 0.0007 of the exact one.
    for autopilot, total in table.items():
        assert scores[autopilot] == pytest.approx(total, abs=0.0015)
    assert min(scores, key=scores.__getitem__) == 1


def test_seed_example_exact_values() -> None:
    roll_mean = (0.12 + 0.10 + 0.07) / 3
    pitch_mean = (0.30 + 0.28 + 0.27) / 3
    scores = compute_scores(SEED_VALUES, SEED_VARIABLES)
    assert scores == {
        0: pytest.approx(abs(0.12 - roll_mean) + abs(0.30 - pitch_mean) + 1.7 * 0.01, rel=1e-12),
        1: pytest.approx(abs(0.10 - roll_mean) + abs(0.28 - pitch_mean) + 1.9 * 0.01, rel=1e-12),
        2: pytest.approx(abs(0.07 - roll_mean) + abs(0.27 - pitch_mean) + 1.5 * 0.01, rel=1e-12),
    }


def test_seed_example_rows_match_the_table_columns() -> None:
    rows = explain_scores(SEED_VALUES, SEED_VARIABLES)
    assert [(row.autopilot, row.number) for row in rows] == [
        (ap, n) for ap in range(3) for n in range(3)
    ]
    # Means as the table prints them (truncated to 3 decimals): 0.096 and 0.283.
    assert int(rows[0].mean * 1000) / 1000 == 0.096  # type: ignore[operator]
    assert int(rows[1].mean * 1000) / 1000 == 0.283  # type: ignore[operator]
    assert rows[2].mean is None
    # Absolute contributions: 0.017, 0.019, 0.015 exactly as in the table.
    assert [round(rows[i].contribution, 6) for i in (2, 5, 8)] == [0.017, 0.019, 0.015]
    # Relative deviations to the table's precision: 0.024 0.017 / 0.004 0.003 / 0.026 0.013.
    table = [0.024, 0.017, 0.004, 0.003, 0.026, 0.013]
    relative = [row.contribution for row in rows if row.mean is not None]
    assert relative == [pytest.approx(value, abs=0.0007) for value in table]


def test_api_example_of_the_issue() -> None:
    variables = [
        arbiter.VariableConfig(weight=1.0, absolute=False),
        arbiter.VariableConfig(weight=1.0, absolute=False),
        arbiter.VariableConfig(weight=0.01, absolute=True),
    ]
    scores = arbiter.compute_scores(
        {0: [0.12, 0.30, 1.7], 1: [0.10, 0.28, 1.9], 2: [0.07, 0.27, 1.5]}, variables
    )
    assert {ap: round(score, 3) for ap, score in scores.items()} == {0: 0.057, 1: 0.026, 2: 0.055}


def test_weight_scales_a_relative_deviation() -> None:
    variables = [VariableConfig(weight=2.0)]
    scores = compute_scores({0: [1.0], 1: [2.0], 2: [6.0]}, variables)
    assert scores == {0: 4.0, 1: 2.0, 2: 6.0}  # mean 3, deviations 2, 1, 3, times 2


def test_relative_variables_drop_out_with_two_or_fewer() -> None:
    variables = [VariableConfig(weight=1.0), VariableConfig(weight=0.5, absolute=True)]
    values = {0: [1.0, 2.0], 1: [5.0, 4.0]}
    assert compute_scores(values, variables) == {0: 1.0, 1: 2.0}
    rows = explain_scores(values, variables)
    assert [row.enabled for row in rows] == [False, True, False, True]


def test_mean_over_chosen_autopilots_and_forced_relative() -> None:
    variables = [VariableConfig()]
    values = {0: [1.0], 1: [3.0], 2: [5.0], 3: [100.0]}
    scores = compute_scores(values, variables, mean_of=[0, 1, 2])
    assert scores == {0: 2.0, 1: 0.0, 2: 2.0, 3: 97.0}
    assert compute_scores(values, variables, mean_of=[0, 1], relative=True)[2] == 3.0


def test_max_error_clamps_only_when_asked() -> None:
    variables = [VariableConfig(max_error=1.0), VariableConfig(absolute=True, max_error=0.5)]
    values = {0: [0.0, 2.0], 1: [0.0, 0.1], 2: [6.0, 0.1]}
    assert compute_scores(values, variables) == {0: 4.0, 1: 2.1, 2: pytest.approx(4.1)}
    clamped = compute_scores(values, variables, max_error_mode=MaxErrorMode.CLAMP)
    assert clamped == {0: 1.5, 1: 1.1, 2: pytest.approx(1.1)}


def test_bad_inputs_raise_input_error() -> None:
    with pytest.raises(InputError, match=r"values\[1\] = 1: expected 2 values"):
        compute_scores({0: [1.0, 2.0], 1: [1.0]}, [VariableConfig(), VariableConfig()])
    with pytest.raises(InputError, match="mean_of = 5"):
        compute_scores({0: [1.0]}, [VariableConfig()], mean_of=[5])
    with pytest.raises(InputError) as one:
        compute_scores({0: [1.0, 2.0]}, [VariableConfig()])
    assert str(one.value) == "values[0] = 2: expected 1 value, one per variable"


@pytest.mark.parametrize(
    ("kwargs", "field"),
    [
        ({"variables": [VariableConfig()] * 33}, "variables"),
        ({"variables": [VariableConfig(weight=float("nan"))]}, "variables[0].weight"),
        ({"variables": [VariableConfig(max_error=-1.0)]}, "variables[0].max_error"),
        ({"preferred": 3}, "preferred"),
        ({"hysteresis": 1.5}, "hysteresis"),
        ({"holding_time": -1.0}, "holding_time"),
        ({"status_period": 0.0}, "status_period"),
        ({"method": arbiter.Method.ROUND_ROBIN}, "holding_time"),
        ({"arbiter_id": 0x800}, "autopilot_ids/arbiter_id"),
        ({"arbiter_id": 8}, "autopilot_ids/arbiter_id"),
        ({"autopilot_ids": (1, 2, 3)}, "autopilot_ids"),
    ],
)
def test_config_rejects_what_the_seeds_do_not_allow(kwargs: dict[str, object], field: str) -> None:
    with pytest.raises(ConfigError) as caught:
        arbiter.ArbiterConfig(**kwargs)  # type: ignore[arg-type]
    assert caught.value.field == field
    assert isinstance(caught.value, ValueError)


def test_config_defaults_follow_the_templates() -> None:
    config = arbiter.ArbiterConfig()
    assert config.autopilot_ids == (8, 9, 10, 11)
    assert config.arbiter_id == 255
    assert not config.extended_ids
    assert (config.send_status, config.status_period) == (True, 0.25)
    assert (config.send_score, config.score_period) == (True, 3.0)
    assert config.message_timeout == 0.1
    assert config.participants == (0, 1, 2)
    assert arbiter.ArbiterConfig(external_enabled=True, preferred=3).participants == (0, 1, 2, 3)
    assert arbiter.ArbiterConfig(extended_ids=True, arbiter_id=0x1FFFFFFF).arbiter_id == 0x1FFFFFFF
    assert arbiter.ArbiterConfig(variables=[VariableConfig()]).variables == (VariableConfig(),)


def test_explain_scores_follows_its_relative_argument() -> None:
    """Three autopilots count relative variables unless told not to; two only when told."""

    def enabled(**options: object) -> list[tuple[int, int, bool]]:
        rows = explain_scores(SEED_VALUES, SEED_VARIABLES, **options)  # type: ignore[arg-type]
        return [(row.autopilot, row.number, row.enabled) for row in rows if row.autopilot == 0]

    assert enabled() == [(0, 0, True), (0, 1, True), (0, 2, True)]
    assert enabled(relative=False) == [(0, 0, False), (0, 1, False), (0, 2, True)]
    assert enabled(mean_of=[0, 1]) == [(0, 0, False), (0, 1, False), (0, 2, True)]
    assert enabled(mean_of=[0, 1], relative=True) == [(0, 0, True), (0, 1, True), (0, 2, True)]
    off = explain_scores(SEED_VALUES, SEED_VARIABLES, relative=False)
    assert [row.contribution for row in off if not row.enabled] == [0.0] * 6
