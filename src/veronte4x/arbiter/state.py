"""What the model holds and reports: system checks, decisions, state snapshots."""

from __future__ import annotations

import datetime
import enum
from collections.abc import Mapping
from dataclasses import dataclass, fields
from typing import ClassVar

from veronte4x.arbiter.machine import ArbiterPhase
from veronte4x.codec.layouts import AUTOPILOTS
from veronte4x.codec.messages import Flags4
from veronte4x.display import HtmlDisplay
from veronte4x.times import utc_datetime


class ArbiterMode(enum.Enum):
    """The arbiter's mode (4x Software Manual, section 4): Idle after boot, then Normal or
    Maintenance. Not `veronte4x.dronecan.Mode`, a DroneCAN node's mode in NodeStatus."""

    IDLE = "Idle"
    NORMAL = "Normal"
    MAINTENANCE = "Maintenance"


MODE_OF_PHASE = {
    ArbiterPhase.IDLE: ArbiterMode.IDLE,
    ArbiterPhase.NORMAL: ArbiterMode.NORMAL,
    ArbiterPhase.ARBITRATING: ArbiterMode.NORMAL,
    ArbiterPhase.MAINTENANCE: ArbiterMode.MAINTENANCE,
}


@dataclass(frozen=True, slots=True)
class SystemChecks:
    """The arbiter's own built-in checks: an input of the model, all OK by default.

    They fill bytes 4 and 5 of the Status message (4x Software Manual, section 3.1.1). The boot
    checks pass when every item is OK (4x Software Manual, section 4: "If all checks success, the
    Arbiter will
    enter Normal mode"). CBIT and "power OK" are derived, not inputs.

    Attributes:
        pbit_ok: PBIT, system boot OK.
        pdi_ok: Configuration files OK.
        memory_ok: Memory allocation OK.
        can_a_ok: CAN A OK.
        can_b_ok: CAN B OK.
        cio_low_ok: CIO low-priority task OK.
        cio_high_ok: CIO high-priority task OK.
        bus_a_voltage_ok: A bus voltage OK.
        bus_b_voltage_ok: B bus voltage OK.
        arbiter_voltage_ok: Arbiter voltage OK.
        ap1_voltage_ok: AP1 voltage OK.
        ap2_voltage_ok: AP2 voltage OK.
        ap3_voltage_ok: AP3 voltage OK.
    """

    pbit_ok: bool = True
    pdi_ok: bool = True
    memory_ok: bool = True
    can_a_ok: bool = True
    can_b_ok: bool = True
    cio_low_ok: bool = True
    cio_high_ok: bool = True
    bus_a_voltage_ok: bool = True
    bus_b_voltage_ok: bool = True
    arbiter_voltage_ok: bool = True
    ap1_voltage_ok: bool = True
    ap2_voltage_ok: bool = True
    ap3_voltage_ok: bool = True

    @property
    def power_ok(self) -> bool:
        """ "Power OK. All power indicators are OK." (4x Software Manual, section 3.1.1, byte 5 bit
        0)."""
        return (
            self.bus_a_voltage_ok
            and self.bus_b_voltage_ok
            and self.arbiter_voltage_ok
            and self.ap1_voltage_ok
            and self.ap2_voltage_ok
            and self.ap3_voltage_ok
        )

    @property
    def all_ok(self) -> bool:
        """Every check passes."""
        return all(getattr(self, item.name) for item in fields(self))

    def failing(self) -> list[str]:
        """The names of the failing checks."""
        return [item.name for item in fields(self) if not getattr(self, item.name)]


class DecisionKind(enum.Enum):
    """What a decision changed."""

    MODE = "mode"
    READY = "ready"
    ARBITRATION = "arbitration"
    DEAD = "dead"
    SWITCH = "switch"
    HOLD = "held"


@dataclass(frozen=True, slots=True)
class Decision:
    """One state change or switch of the model, with its time and reason.

    Attributes:
        time: When it happened, in the timestamps' unit (s).
        kind: What changed (``HOLD``: a switch the method asks for waits for the
            holding time).
        autopilot: The autopilot concerned (the new one for a switch), if any.
        reason: Why, in words: "AP1 dead: arbitration variable 2 missing for 0.1 s".
    """

    time: float
    kind: DecisionKind
    autopilot: int | None
    reason: str

    def __str__(self) -> str:
        return f"{self.time:10.3f} s  {self.body()}"

    @property
    def utc(self) -> datetime.datetime | None:
        """`time` as a UTC datetime where it is Unix time (a capture's own clock: None)."""
        return utc_datetime(self.time)

    def body(self) -> str:
        """The decision without its time."""
        return f"{self.kind.value:<11} {self.reason}"


@dataclass(frozen=True, slots=True)
class ArbiterState(HtmlDisplay):
    """A snapshot of the model after the last input; in Jupyter a table of its fields, the
    selected autopilot's name beside its index (``1 (AP2)``).

    Attributes:
        time: Timestamp of the last input, or ``None`` before the first one.
        mode: Idle, Normal or Maintenance.
        phase: The status-management phase (Normal splits into waiting and arbitrating).
        arbitrating: Arbitration has started (Normal mode, every autopilot was Ready).
        ready: AP1, AP2, AP3, external: the last Ready message said Ready.
        alive: AP1, AP2, AP3, external: alive (only once arbitration has started).
        dead: AP1, AP2, AP3, external: declared dead.
        scores: Score of each taking-part autopilot that has sent every variable.
        selected: The selected autopilot, 0 = AP1 .. 3 = external.
        checks: The system checks last reported.
        last_decision: The latest decision, or ``None``.
    """

    time: float | None
    mode: ArbiterMode
    phase: ArbiterPhase
    arbitrating: bool
    ready: Flags4
    alive: Flags4
    dead: Flags4
    scores: Mapping[int, float]
    selected: int
    checks: SystemChecks
    last_decision: Decision | None
    _NAMED_FIELDS_: ClassVar[Mapping[str, tuple[str, ...]]] = {"selected": AUTOPILOTS}
    """The autopilot's name beside ``selected`` (`veronte4x.values.name_of`)."""
