"""The status-management state machines, as explicit transition tables.

Source: the 4x Software Manual, section 4 ("Status management"): boot into Idle, Normal when
the checks pass, Maintenance when errors persist 30 s or on the maintenance command,
arbitration once every autopilot is Ready, Alive to Dead for good. The model looks every
transition up here, and the docs draw their state diagrams from these same tables.
"""

from __future__ import annotations

import enum


class ArbiterPhase(enum.Enum):
    """Where the arbiter is in its status management (`AutopilotPhase`: where one autopilot
    is; `veronte4x.client.Phase`: where a firmware update is)."""

    IDLE = "Idle"
    NORMAL = "Normal, waiting for Ready"
    ARBITRATING = "Normal, arbitrating"
    MAINTENANCE = "Maintenance"


class ArbiterEvent(enum.Enum):
    """What moves the arbiter from one phase to another (`AutopilotEvent`: one autopilot;
    `veronte4x.client.Event`: what the DroneCAN client reports)."""

    CHECKS_PASS = "boot checks pass"
    CHECKS_FAIL_30S = "errors persist 30 s after boot"
    ALL_READY = "Ready from every autopilot"
    MAINTENANCE_COMMAND = "maintenance command"


#: (phase, event) -> next phase; an event not listed for a phase leaves it unchanged.
TRANSITIONS: dict[tuple[ArbiterPhase, ArbiterEvent], ArbiterPhase] = {
    (ArbiterPhase.IDLE, ArbiterEvent.CHECKS_PASS): ArbiterPhase.NORMAL,
    (ArbiterPhase.IDLE, ArbiterEvent.CHECKS_FAIL_30S): ArbiterPhase.MAINTENANCE,
    (ArbiterPhase.IDLE, ArbiterEvent.MAINTENANCE_COMMAND): ArbiterPhase.MAINTENANCE,
    (ArbiterPhase.NORMAL, ArbiterEvent.ALL_READY): ArbiterPhase.ARBITRATING,
    (ArbiterPhase.NORMAL, ArbiterEvent.MAINTENANCE_COMMAND): ArbiterPhase.MAINTENANCE,
    (ArbiterPhase.ARBITRATING, ArbiterEvent.MAINTENANCE_COMMAND): ArbiterPhase.MAINTENANCE,
}


class AutopilotPhase(enum.Enum):
    """Where one autopilot is, as the arbiter sees it."""

    WAITING = "not Ready"
    READY = "Ready"
    ALIVE = "Alive"
    DEAD = "Dead"


class AutopilotEvent(enum.Enum):
    """What moves one autopilot from one phase to another."""

    READY = "Ready received"
    NOT_READY = "Not Ready received"
    ARBITRATION_STARTS = "arbitration starts"
    MESSAGE_MISSING = "arbitration message missing 0.1 s"
    FTS_BAD = "FTS input bad (system not OK)"
    WATCHDOG_BAD = "watchdog input bad"


#: (phase, event) -> next phase; an event not listed for a phase leaves it unchanged.
#: Nothing leaves DEAD: "The Dead status is not reversible" (4x Software Manual, section 4).
AUTOPILOT_TRANSITIONS: dict[tuple[AutopilotPhase, AutopilotEvent], AutopilotPhase] = {
    (AutopilotPhase.WAITING, AutopilotEvent.READY): AutopilotPhase.READY,
    (AutopilotPhase.READY, AutopilotEvent.NOT_READY): AutopilotPhase.WAITING,
    (AutopilotPhase.READY, AutopilotEvent.ARBITRATION_STARTS): AutopilotPhase.ALIVE,
    (AutopilotPhase.ALIVE, AutopilotEvent.NOT_READY): AutopilotPhase.DEAD,
    (AutopilotPhase.ALIVE, AutopilotEvent.MESSAGE_MISSING): AutopilotPhase.DEAD,
    (AutopilotPhase.ALIVE, AutopilotEvent.FTS_BAD): AutopilotPhase.DEAD,
    (AutopilotPhase.ALIVE, AutopilotEvent.WATCHDOG_BAD): AutopilotPhase.DEAD,
}


def next_phase(phase: ArbiterPhase, event: ArbiterEvent) -> ArbiterPhase | None:
    """The phase ``event`` leads to from ``phase``, or ``None`` when it changes nothing."""
    return TRANSITIONS.get((phase, event))


def next_autopilot_phase(phase: AutopilotPhase, event: AutopilotEvent) -> AutopilotPhase | None:
    """The autopilot phase ``event`` leads to, or ``None`` when it changes nothing."""
    return AUTOPILOT_TRANSITIONS.get((phase, event))
