"""A sans-IO model of the Veronte 4x arbiter: scores, selection, status management, replay.

Examples:
    >>> from veronte4x import arbiter
    >>> variables = [arbiter.VariableConfig(weight=1.0, absolute=False),
    ...              arbiter.VariableConfig(weight=1.0, absolute=False),
    ...              arbiter.VariableConfig(weight=0.01, absolute=True)]
    >>> scores = arbiter.compute_scores(
    ...     {0: [0.12, 0.30, 1.7], 1: [0.10, 0.28, 1.9], 2: [0.07, 0.27, 1.5]}, variables)
    >>> {ap: round(score, 3) for ap, score in scores.items()}
    {0: 0.057, 1: 0.026, 2: 0.055}
"""

from __future__ import annotations

from veronte4x.arbiter.config import (
    ArbiterConfig,
    Failover,
    MaxErrorMode,
    Method,
    RelativeMean,
    VariableConfig,
    autopilot_name,
)
from veronte4x.arbiter.errors import ConfigError, InputError
from veronte4x.arbiter.machine import (
    AUTOPILOT_TRANSITIONS,
    TRANSITIONS,
    ArbiterEvent,
    ArbiterPhase,
    AutopilotEvent,
    AutopilotPhase,
)
from veronte4x.arbiter.model import Arbiter
from veronte4x.arbiter.replay import (
    CapturedFrame,
    Disagreement,
    DisorderedError,
    FrameError,
    ReplayResult,
    Restart,
    replay,
)
from veronte4x.arbiter.scores import Contribution, compute_scores, explain_scores
from veronte4x.arbiter.state import ArbiterMode, ArbiterState, Decision, DecisionKind, SystemChecks

__all__ = [
    "AUTOPILOT_TRANSITIONS",
    "TRANSITIONS",
    "Arbiter",
    "ArbiterConfig",
    "ArbiterEvent",
    "ArbiterMode",
    "ArbiterPhase",
    "ArbiterState",
    "AutopilotEvent",
    "AutopilotPhase",
    "CapturedFrame",
    "ConfigError",
    "Contribution",
    "Decision",
    "DecisionKind",
    "Disagreement",
    "DisorderedError",
    "Failover",
    "FrameError",
    "InputError",
    "MaxErrorMode",
    "Method",
    "RelativeMean",
    "ReplayResult",
    "Restart",
    "SystemChecks",
    "VariableConfig",
    "autopilot_name",
    "compute_scores",
    "explain_scores",
    "replay",
]
