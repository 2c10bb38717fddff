"""Read an `ArbiterConfig` from TOML, for ``veronte4x replay --config``.

Keys are the `ArbiterConfig` attribute names; enum options take their value strings::

    [arbiter]
    method = "always best"        # change if worst, round robin, fixed 0..2, fixed while ok
    preferred = 0
    holding_time = 2.0
    hysteresis = 0.2
    external_enabled = false
    max_error_mode = "ignore"     # or "clamp"
    relative_mean = "alive"       # or "reporting"
    failover = "next"             # or "lowest", "best score"
    autopilot_ids = [8, 9, 10, 11]
    arbiter_id = 255
    status_period = 0.25
    score_period = 3.0

    [[arbiter.variables]]         # variable 0, then 1, ...
    weight = 1.0
    absolute = false
    max_error = 0.5
"""

from __future__ import annotations

import dataclasses
import os
import sys
from collections.abc import Mapping
from typing import Any

from veronte4x.arbiter.config import (
    ArbiterConfig,
    Failover,
    MaxErrorMode,
    Method,
    RelativeMean,
    VariableConfig,
)
from veronte4x.arbiter.errors import ConfigError
from veronte4x.extras import require

_ENUMS: dict[str, type[Any]] = {
    "method": Method,
    "max_error_mode": MaxErrorMode,
    "relative_mean": RelativeMean,
    "failover": Failover,
}


def config_from_dict(document: Mapping[str, Any]) -> ArbiterConfig:
    """Build an `ArbiterConfig` from a parsed TOML document (its ``[arbiter]`` table).

    Raises:
        ConfigError: Unknown keys or values the configuration does not allow.
    """
    unknown_top = set(document) - {"arbiter"}
    if unknown_top:
        raise ConfigError("(file)", sorted(unknown_top), "only an [arbiter] table")
    table = dict(document.get("arbiter", {}))
    allowed = {f.name for f in dataclasses.fields(ArbiterConfig)}
    for key in table:
        if key not in allowed:
            raise ConfigError(key, table[key], "a field of ArbiterConfig")
    for key, kind in _ENUMS.items():
        if key in table:
            try:
                table[key] = kind(table[key])
            except ValueError:
                options = ", ".join(repr(member.value) for member in kind)
                raise ConfigError(key, table[key], f"one of {options}") from None
    variables = []
    for number, entry in enumerate(table.pop("variables", ())):
        extra = set(entry) - {"weight", "absolute", "max_error"}
        if extra:
            raise ConfigError(f"variables[{number}]", sorted(extra), "weight, absolute, max_error")
        variables.append(VariableConfig(**entry))
    try:
        return ArbiterConfig(variables=variables, **table)
    except TypeError as error:
        raise ConfigError("(file)", table, str(error)) from None


def load_config(path: str | os.PathLike[str]) -> ArbiterConfig:
    """Read an `ArbiterConfig` from a TOML file.

    Raises:
        ConfigError: Unknown keys or values the configuration does not allow.
        MissingExtraError: Python 3.10 without tomli (the ``toml`` extra).
        OSError: The file cannot be read.
    """
    if sys.version_info >= (3, 11):
        import tomllib
    else:  # pragma: no cover - Python 3.10
        tomllib = require("tomli", "toml", "reading TOML on Python 3.10")
    with open(path, "rb") as file:
        try:
            document = tomllib.load(file)
        except tomllib.TOMLDecodeError as error:
            raise ConfigError("(file)", os.fspath(path), f"valid TOML ({error})") from None
    return config_from_dict(document)
