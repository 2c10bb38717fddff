"""Arbiter configuration: the 4x PDI Builder's Config menu and CAN setup.

Source: 4x PDI Builder manual, Arbitration ("Config menu": preferred, method, holding CAP time,
hysteresis, external
autopilot, per-variable max error, weight and absolute flag, at most 32 variables; "CAN
Setup": status and score sending and periods, status message ID, autopilot IDs, extended
flag). Defaults follow Embention's manuals and configuration templates: autopilots on IDs 8, 9, 10,
11, arbiter on 255, standard IDs, Status every 0.25 s,
Score every 3 s. Where the manuals are silent the field is an option with a documented default
(see the arbiter decisions page).
"""

from __future__ import annotations

import enum
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

from veronte4x.arbiter.errors import ConfigError
from veronte4x.codec.layouts import AUTOPILOTS
from veronte4x.errors import boolean, integer, real

#: Index of the external autopilot.
EXTERNAL = 3
#: "Currently, the maximum amount of arbitration variables supported is 32." (4x PDI Builder
#: manual, Arbitration)
MAX_VARIABLES = 32
_STANDARD_ID_MAX = 0x7FF
_EXTENDED_ID_MAX = 0x1FFF_FFFF


def autopilot_name(autopilot: int) -> str:
    """The name of an autopilot number: 0 -> "AP1", 3 -> "external AP"."""
    return AUTOPILOTS[autopilot]


class Method(enum.Enum):
    """Arbitration method (4x PDI Builder manual, Arbitration, Config menu, item 2)."""

    ALWAYS_BEST = "always best"
    CHANGE_IF_WORST = "change if worst"
    ROUND_ROBIN = "round robin"
    FIXED_0 = "fixed 0"
    FIXED_1 = "fixed 1"
    FIXED_2 = "fixed 2"
    FIXED_WHILE_OK = "fixed while ok"

    @property
    def fixed_autopilot(self) -> int | None:
        """The autopilot a Fixed method selects, or ``None`` for the other methods."""
        return _FIXED.get(self)


_FIXED = {Method.FIXED_0: 0, Method.FIXED_1: 1, Method.FIXED_2: 2}


class MaxErrorMode(enum.Enum):
    """What a variable's max error does (the 4x PDI Builder manual only says "Arbitration maximum
    error").

    Attributes:
        IGNORE: Kept as configuration, no effect on scores (default).
        CLAMP: A variable's error (its deviation from the mean, or its value for an
            absolute variable) is limited to max error before the weight applies.
    """

    IGNORE = "ignore"
    CLAMP = "clamp"


class RelativeMean(enum.Enum):
    """Which autopilots the mean of a relative variable is taken over.

    Attributes:
        ALIVE: The alive autopilots only (default).
        REPORTING: Every taking-part autopilot with a value, dead ones included.
    """

    ALIVE = "alive"
    REPORTING = "reporting"


class Failover(enum.Enum):
    """Which autopilot "fixed while ok" switches to when the selected one dies.

    Attributes:
        NEXT: The next alive one in the order AP1, AP2, AP3, external, wrapping (default).
        LOWEST: The alive one with the lowest number.
        BEST_SCORE: The alive one with the best score (the preferred one wins a draw).
    """

    NEXT = "next"
    LOWEST = "lowest"
    BEST_SCORE = "best score"


@dataclass(frozen=True, slots=True)
class VariableConfig:
    """One arbitration variable (4x PDI Builder manual, Arbitration, Config menu, items 6 to 8).

    Its number on the wire is its position in `ArbiterConfig.variables`.

    Attributes:
        weight: Arbitration weight: the value is multiplied by it.
        absolute: True: added directly to the score; False: relative, its deviation from
            the mean over the autopilots is added.
        max_error: Arbitration maximum error; what it does is `ArbiterConfig.max_error_mode`.
    """

    weight: float = 1.0
    absolute: bool = False
    max_error: float = math.inf

    def __post_init__(self) -> None:
        _as_python(self, floats=("weight", "max_error"), bools=("absolute",))


@dataclass(frozen=True, slots=True)
class ArbiterConfig:
    """Everything the arbiter model is configured with.

    Attributes:
        variables: The arbitration variables, number 0 first; at most 32.
        method: Arbitration method.
        preferred: Preferred autopilot (0..2, or 3 when the external one takes part).
        holding_time: Holding CAP time, s: no switch within this time of the last one;
            also the round-robin period.
        hysteresis: A candidate must score below ``selected x (1 - hysteresis)``.
        external_enabled: Enable arbitration of the external autopilot.
        max_error_mode: What `VariableConfig.max_error` does.
        relative_mean: Which autopilots the mean of a relative variable is taken over.
        failover: Which autopilot "fixed while ok" switches to.
        autopilot_ids: CAN IDs the arbiter receives AP1, AP2, AP3, external on.
        arbiter_id: CAN ID of the arbiter's Status and Score messages.
        extended_ids: 29-bit IDs instead of 11-bit ones (only the ID range checks use it).
        send_status: Send the Status message in Normal mode (always sent in Maintenance).
        status_period: Status period, s.
        send_score: Send the Score messages in Normal mode.
        score_period: Score period, s.
        message_timeout: An autopilot dies when one of its arbitration messages is
            missing for this long, s.
        boot_timeout: Idle for this long with failing checks means Maintenance, s.
    """

    variables: Sequence[VariableConfig] = ()
    method: Method = Method.ALWAYS_BEST
    preferred: int = 0
    holding_time: float = 0.0
    hysteresis: float = 0.0
    external_enabled: bool = False
    max_error_mode: MaxErrorMode = MaxErrorMode.IGNORE
    relative_mean: RelativeMean = RelativeMean.ALIVE
    failover: Failover = Failover.NEXT
    autopilot_ids: tuple[int, int, int, int] = (8, 9, 10, 11)
    arbiter_id: int = 255
    extended_ids: bool = False
    send_status: bool = True
    status_period: float = 0.25
    send_score: bool = True
    score_period: float = 3.0
    message_timeout: float = 0.1
    boot_timeout: float = 30.0

    def __post_init__(self) -> None:
        object.__setattr__(self, "variables", tuple(self.variables))
        ids = tuple(self.autopilot_ids)
        object.__setattr__(self, "autopilot_ids", tuple(_python(integer, i) for i in ids))
        floats = ("holding_time", "hysteresis", "status_period", "score_period")
        _as_python(
            self,
            floats=(*floats, "message_timeout", "boot_timeout"),
            ints=("preferred", "arbiter_id"),
            bools=("external_enabled", "extended_ids", "send_status", "send_score"),
        )
        self._validate()

    @property
    def participants(self) -> tuple[int, ...]:
        """The autopilots taking part: AP1..AP3, and the external one when enabled."""
        return (0, 1, 2, EXTERNAL) if self.external_enabled else (0, 1, 2)

    def _validate(self) -> None:
        if len(self.variables) > MAX_VARIABLES:
            raise ConfigError("variables", len(self.variables), "at most 32 variables")
        for number, variable in enumerate(self.variables):
            if not isinstance(variable, VariableConfig):
                raise ConfigError(f"variables[{number}]", variable, "a VariableConfig")
            if not math.isfinite(variable.weight):
                raise ConfigError(f"variables[{number}].weight", variable.weight, "a finite number")
            if not variable.max_error >= 0:
                raise ConfigError(f"variables[{number}].max_error", variable.max_error, ">= 0")
        top = EXTERNAL if self.external_enabled else 2
        if self.preferred not in range(top + 1):
            raise ConfigError("preferred", self.preferred, f"0..{top}")
        for name in ("holding_time", "message_timeout", "boot_timeout"):
            value = getattr(self, name)
            if not (math.isfinite(value) and value >= 0):
                raise ConfigError(name, value, "a finite number >= 0")
        for name in ("status_period", "score_period"):
            value = getattr(self, name)
            if not (math.isfinite(value) and value > 0):
                raise ConfigError(name, value, "a finite number > 0")
        if self.method is Method.ROUND_ROBIN and not self.holding_time > 0:
            raise ConfigError("holding_time", self.holding_time, "> 0 (the round-robin period)")
        if not (math.isfinite(self.hysteresis) and 0 <= self.hysteresis <= 1):
            raise ConfigError("hysteresis", self.hysteresis, "a fraction 0..1")
        top_id = _EXTENDED_ID_MAX if self.extended_ids else _STANDARD_ID_MAX
        ids = (*self.autopilot_ids, self.arbiter_id)
        if len(self.autopilot_ids) != 4:
            raise ConfigError("autopilot_ids", self.autopilot_ids, "four CAN IDs")
        for can_id in ids:
            if not 0 <= can_id <= top_id:
                raise ConfigError("autopilot_ids/arbiter_id", can_id, f"a CAN ID 0..{top_id:#x}")
        if len(set(ids)) != len(ids):
            raise ConfigError("autopilot_ids/arbiter_id", ids, "five different CAN IDs")


def _python(rule: Callable[[object], object], value: object) -> Any:
    """``value`` as Python's number or bool by ``rule`` (`veronte4x.errors.integer`, `real`
    or `boolean`: a NumPy scalar converts exactly), or unchanged for the checks to refuse."""
    converted = rule(value)
    return value if converted is None else converted


def _as_python(
    config: object,
    *,
    floats: tuple[str, ...] = (),
    ints: tuple[str, ...] = (),
    bools: tuple[str, ...] = (),
) -> None:
    """Store the named fields of a frozen ``config`` as Python numbers and bools."""
    for names, rule in ((floats, real), (ints, integer), (bools, boolean)):
        for name in names:
            object.__setattr__(config, name, _python(rule, getattr(config, name)))
