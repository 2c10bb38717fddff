"""Which autopilot to select: the methods of the 4x PDI Builder manual
(Arbitration) and the alive rules of the 4x Software Manual, section 4.

4x PDI Builder manual, Arbitration, Config menu: "Preferred. The preferred autopilot will be chosen
in case of a
score draw."; the methods Always best, Change if worst, Round robin, Fixed 0/1/2, Fixed while
ok; "Hysteresis ... the difference between them needs to be bigger than this proportional
value ... proportional to the score of the selected autopilot". 4x Software Manual, section 4: "A
Dead autopilot
can never be selected again", "If only one autopilot is Alive, it will be selected no matter
the score.", "If all autopilots are Dead, the Preferred autopilot will be selected."
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

from veronte4x.arbiter.config import ArbiterConfig, Failover, Method, autopilot_name


@dataclass(frozen=True, slots=True)
class Choice:
    """A switch the rules ask for.

    Attributes:
        autopilot: The autopilot to select.
        reason: Why, in words.
        forced: True when the switch cannot wait (dead selected autopilot, one or none
            alive, fixed method); False when it is the method's own choice, which waits for
            the holding time.
    """

    autopilot: int
    reason: str
    forced: bool


def _fmt(score: float) -> str:
    return f"{score:.3g}"


def rank(score: float) -> float:
    """A score as it ranks: NaN (from a NaN variable) ranks as the worst."""
    return math.inf if math.isnan(score) else score


def beats(offered: float, current: float, hysteresis: float) -> bool:
    """Whether ``offered`` is lower than ``current`` by more than ``hysteresis x |current|``.

    For the manual's non-negative scores this is ``offered < current x (1 - hysteresis)``.
    """
    offered, current = rank(offered), rank(current)
    if math.isinf(current):
        return offered < current
    return offered < current - hysteresis * abs(current)


def best(scores: Mapping[int, float], candidates: Sequence[int], preferred: int) -> int | None:
    """The candidate with the lowest score; the preferred one wins a draw, then the lowest
    number. ``None`` when no candidate has a score."""
    scored = [ap for ap in candidates if ap in scores]
    if not scored:
        return None
    return min(scored, key=lambda ap: (rank(scores[ap]), ap != preferred, ap))


def next_alive(selected: int, alive: Sequence[int], order: Sequence[int]) -> int:
    """The first alive autopilot after ``selected`` in ``order``, wrapping round."""
    start = order.index(selected) + 1 if selected in order else 0
    return next(ap for ap in (*order[start:], *order[:start]) if ap in alive)


def _failover(
    config: ArbiterConfig, selected: int, alive: Sequence[int], scores: Mapping[int, float]
) -> tuple[int, str]:
    order = config.participants
    method = config.method
    if method is Method.FIXED_WHILE_OK and config.failover is Failover.LOWEST:
        return min(alive), "lowest-numbered alive"
    if method is Method.ROUND_ROBIN or (
        method is Method.FIXED_WHILE_OK and config.failover is Failover.NEXT
    ):
        return next_alive(selected, alive, order), "next alive"
    chosen = best(scores, alive, config.preferred)
    if chosen is None:
        return next_alive(selected, alive, order), "next alive, no scores yet"
    return chosen, f"best score {_fmt(scores[chosen])}"


def choose(
    config: ArbiterConfig,
    selected: int,
    alive: Sequence[int],
    scores: Mapping[int, float],
) -> Choice | None:
    """The switch the rules ask for now, or ``None`` to keep ``selected``.

    Args:
        config: The arbiter configuration (method, preferred, hysteresis).
        selected: The selected autopilot.
        alive: The alive taking-part autopilots, in number order.
        scores: The scores known so far.
    """
    fixed = config.method.fixed_autopilot
    if fixed is not None:
        if selected == fixed:
            return None
        return Choice(fixed, f"method {config.method.value}", forced=True)
    name = autopilot_name
    if not alive:
        if selected == config.preferred:
            return None
        reason = f"no autopilot alive: preferred {name(config.preferred)} selected"
        return Choice(config.preferred, reason, forced=True)
    if len(alive) == 1:
        only = alive[0]
        if selected == only:
            return None
        return Choice(only, f"{name(only)} is the only one alive", forced=True)
    if selected not in alive:
        chosen, how = _failover(config, selected, alive, scores)
        return Choice(chosen, f"{name(selected)} is dead: {name(chosen)} ({how})", forced=True)
    return _method_choice(config, selected, alive, scores)


def _method_choice(
    config: ArbiterConfig, selected: int, alive: Sequence[int], scores: Mapping[int, float]
) -> Choice | None:
    method = config.method
    if method is Method.FIXED_WHILE_OK:
        return None
    if method is Method.ROUND_ROBIN:
        chosen = next_alive(selected, alive, config.participants)
        reason = f"round robin: {autopilot_name(chosen)} after {autopilot_name(selected)}"
        return Choice(chosen, reason, forced=False)
    if any(ap not in scores for ap in alive):
        return None  # an alive autopilot without a score yet cannot be ranked
    candidate = best(scores, alive, config.preferred)
    if candidate is None or candidate == selected:
        return None
    current, offered = scores[selected], scores[candidate]
    if method is Method.CHANGE_IF_WORST and any(rank(scores[ap]) > rank(current) for ap in alive):
        return None
    if not beats(offered, current, config.hysteresis):
        return None
    reason = (
        f"{autopilot_name(candidate)} {_fmt(offered)} < {autopilot_name(selected)} "
        f"{_fmt(current)} x (1 - {config.hysteresis:g})"
    )
    if method is Method.CHANGE_IF_WORST:
        reason = f"{autopilot_name(selected)} has the worst score; {reason}"
    return Choice(candidate, reason, forced=False)
