"""Scores from arbitration variables (4x PDI Builder manual, Arbitration, "Arbitration" to
"Arbitration Example").

"After receiving the value, each variable is multiplied by their respective arbitration
weight, and then it is used to compute the score for their respective unit." Absolute
variables "are added directly to the score"; a relative variable contributes "its Deviation
from the Average of the same variable from each autopilot". Lower is better. 4x Software Manual,
section 4: "If
the number of Alive autopilots is 2 or less, relative arbitration variables are disabled".
"""

from __future__ import annotations

import math
from collections.abc import Collection, Iterator, Mapping, Sequence
from dataclasses import dataclass

from veronte4x.arbiter.config import MaxErrorMode, VariableConfig
from veronte4x.arbiter.errors import InputError
from veronte4x.words import counted

#: Relative variables need at least this many alive autopilots (4x Software Manual, section 4,
#: "Alive status").
MIN_AUTOPILOTS_FOR_RELATIVE = 3


@dataclass(frozen=True, slots=True)
class Contribution:
    """What one variable of one autopilot adds to its score.

    Attributes:
        autopilot: 0 = AP1 .. 3 = external.
        number: Variable number.
        value: The received value.
        mean: Mean of the variable over the autopilots (relative variables), else ``None``.
        error: The deviation from the mean (relative), or the value (absolute), after the
            max-error clamp when that applies; it is multiplied by the weight.
        contribution: What is added to the score (0 for a disabled relative variable).
        enabled: False for a relative variable while too few autopilots are alive.
    """

    autopilot: int
    number: int
    value: float
    mean: float | None
    error: float
    contribution: float
    enabled: bool


_Row = tuple[int, int, float, "float | None", float, float, bool]


def _rows(
    values: Mapping[int, Sequence[float]],
    variables: Sequence[VariableConfig],
    mean_of: Collection[int] | None,
    relative: bool | None,
    max_error_mode: MaxErrorMode,
) -> Iterator[_Row]:
    """The fields of every `Contribution`, as plain tuples."""
    for autopilot, row in values.items():
        if len(row) != len(variables):
            raise InputError(
                f"values[{autopilot}]",
                len(row),
                f"{counted(len(variables), 'value')}, one per variable",
            )
    pool = list(values) if mean_of is None else list(mean_of)
    for autopilot in pool:
        if autopilot not in values:
            raise InputError("mean_of", autopilot, "autopilots that have values")
    if relative is None:
        relative = len(pool) >= MIN_AUTOPILOTS_FOR_RELATIVE
    clamp = max_error_mode is MaxErrorMode.CLAMP
    # Per variable: mean (None for absolute ones), weight, max error, enabled.
    # Weighting first and taking the deviation of the weighted values, as the manual words
    # it, equals weighting the deviation: |w*v - mean(w*v)| = |w| * |v - mean(v)|.
    plan: list[tuple[float | None, float, float, bool]] = []
    for number, variable in enumerate(variables):
        limit = variable.max_error if clamp else math.inf
        if variable.absolute:
            plan.append((None, variable.weight, limit, True))
        elif pool:
            total = sum(values[autopilot][number] for autopilot in pool)
            plan.append((total / len(pool), abs(variable.weight), limit, relative))
        else:
            plan.append((None, abs(variable.weight), limit, False))
    for autopilot, row in values.items():
        for number, (value, (mean, weight, limit, on)) in enumerate(zip(row, plan, strict=True)):
            error = (value if on else 0.0) if mean is None else abs(value - mean)
            error = min(error, limit)
            yield autopilot, number, value, mean, error, error * weight if on else 0.0, on


def explain_scores(
    values: Mapping[int, Sequence[float]],
    variables: Sequence[VariableConfig],
    *,
    mean_of: Collection[int] | None = None,
    relative: bool | None = None,
    max_error_mode: MaxErrorMode = MaxErrorMode.IGNORE,
) -> list[Contribution]:
    """Every variable's contribution to every autopilot's score, autopilot by autopilot.

    Args:
        values: For each autopilot, its latest value of each variable, number 0 first.
        variables: The variables' configuration, number 0 first.
        mean_of: The autopilots a relative variable's mean is taken over (default: all
            of ``values``).
        relative: Whether relative variables count (default: when ``mean_of`` holds 3 or
            more autopilots).
        max_error_mode: What each variable's max error does.

    Raises:
        InputError: an autopilot has not one value per variable, or ``mean_of`` names an
            autopilot without values.
    """
    rows = _rows(values, variables, mean_of, relative, max_error_mode)
    return [Contribution(*row) for row in rows]


def compute_scores(
    values: Mapping[int, Sequence[float]],
    variables: Sequence[VariableConfig],
    *,
    mean_of: Collection[int] | None = None,
    relative: bool | None = None,
    max_error_mode: MaxErrorMode = MaxErrorMode.IGNORE,
) -> dict[int, float]:
    """The score of each autopilot of ``values``: the sum of its contributions.

    Takes the arguments of `explain_scores`. For the manual's example,
    ``compute_scores({0: [0.12, 0.30, 1.7], 1: [0.10, 0.28, 1.9], 2: [0.07, 0.27, 1.5]},
    variables)`` gives about ``{0: 0.057, 1: 0.026, 2: 0.055}`` (the manual rounds each term
    to 0.058, 0.026, 0.054).
    """
    scores = dict.fromkeys(values, 0.0)
    for row in _rows(values, variables, mean_of, relative, max_error_mode):
        scores[row[0]] += row[5]
    return scores
