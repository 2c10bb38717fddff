"""Arbiter configurations from TOML."""

from pathlib import Path

import pytest

from veronte4x import arbiter
from veronte4x.arbiter.config_file import config_from_dict, load_config


def test_every_kind_of_key(tmp_path: Path) -> None:
    path = tmp_path / "arbiter.toml"
    path.write_text(
        """
[arbiter]
method = "change if worst"
preferred = 1
holding_time = 2.0
hysteresis = 0.5
failover = "best score"
autopilot_ids = [0x101, 0x102, 0x103, 0x104]

[[arbiter.variables]]
weight = 1.0

[[arbiter.variables]]
weight = 0.01
absolute = true
max_error = 3.0
"""
    )
    config = load_config(str(path))
    assert config.method is arbiter.Method.CHANGE_IF_WORST
    assert config.preferred == 1
    assert config.hysteresis == 0.5
    assert config.failover is arbiter.Failover.BEST_SCORE
    assert config.autopilot_ids == (0x101, 0x102, 0x103, 0x104)
    assert config.variables == (
        arbiter.VariableConfig(weight=1.0),
        arbiter.VariableConfig(weight=0.01, absolute=True, max_error=3.0),
    )


@pytest.mark.parametrize(
    ("document", "message"),
    [
        ({"arbiter": {"method": "best"}}, "ArbiterConfig.method = 'best': expected one of"),
        ({"arbiter": {"speed": 1}}, "ArbiterConfig.speed = 1: expected a field of ArbiterConfig"),
        ({"arbiter": {"preferred": 5}}, "ArbiterConfig.preferred = 5: expected 0..2"),
        ({"arbiter": {"variables": [{"wait": 1}]}}, "ArbiterConfig.variables[0] = ['wait']"),
        ({"bus": {}}, "expected only an [arbiter] table"),
    ],
)
def test_bad_configurations(document: dict, message: str) -> None:  # type: ignore[type-arg]
    with pytest.raises(arbiter.ConfigError) as error:
        config_from_dict(document)
    assert message in str(error.value)
