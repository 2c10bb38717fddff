"""The Arbiter: a sans-IO model of the Veronte 4x arbiter.

Frames and inputs come in with their timestamps; the model never reads a clock. Status
management follows the 4x Software Manual, section 4 (through the tables of
`veronte4x.arbiter.machine`), scores the 4x PDI Builder manual, Arbitration
(`veronte4x.arbiter.scores`), selection its
Config menu (`veronte4x.arbiter.selection`). Frames are decoded and encoded by
`veronte4x.codec`.
"""

from __future__ import annotations

import math
import struct
from collections.abc import Sequence

from veronte4x import codec
from veronte4x.arbiter.config import ArbiterConfig, Method, RelativeMean, autopilot_name
from veronte4x.arbiter.errors import InputError
from veronte4x.arbiter.machine import (
    ArbiterEvent,
    ArbiterPhase,
    AutopilotEvent,
    AutopilotPhase,
    next_autopilot_phase,
    next_phase,
)
from veronte4x.arbiter.periodic import Periodic
from veronte4x.arbiter.scores import MIN_AUTOPILOTS_FOR_RELATIVE, compute_scores
from veronte4x.arbiter.selection import Choice, choose
from veronte4x.arbiter.state import (
    MODE_OF_PHASE,
    ArbiterState,
    Decision,
    DecisionKind,
    SystemChecks,
)
from veronte4x.errors import (
    BytesLike,
    argument_type_error,
    boolean,
    check_seconds,
    check_types,
    int_argument,
)

SentFrame = tuple[int, bytes]
"""A frame the model sends: its CAN ID and data (`Arbiter.poll`)."""

_AUTOPILOTS = range(4)
_FLOAT32 = struct.Struct("<f")
_DEATH_CAUSES = {
    AutopilotEvent.FTS_BAD: "FTS input bad (system not OK)",
    AutopilotEvent.WATCHDOG_BAD: "watchdog input bad",
    AutopilotEvent.NOT_READY: "Not Ready received",
}


def _within_float32(value: float) -> float:
    """``value``, or an infinity of its sign past the float32 range, as a float32 sum
    overflows on the arbiter."""
    try:
        _FLOAT32.pack(value)
    except OverflowError:
        return math.copysign(math.inf, value)
    return value


class Arbiter:
    """The 4x arbiter as a state machine driven by time-stamped frames and inputs.

    Timestamps are seconds, never decreasing. The first timestamp seen is the boot; the
    boot checks pass then unless ``checks`` says otherwise.

    Args:
        config: The arbiter configuration.
        checks: The system checks at boot (default: all OK).
    """

    def __init__(self, config: ArbiterConfig, *, checks: SystemChecks | None = None) -> None:
        if not isinstance(config, ArbiterConfig):
            raise argument_type_error("Arbiter", "config", "an ArbiterConfig", config)
        if checks is not None and not isinstance(checks, SystemChecks):
            raise argument_type_error("Arbiter", "checks", "a SystemChecks or None", checks)
        self.config = config
        self._checks = SystemChecks() if checks is None else checks
        self._phase = ArbiterPhase.IDLE
        self._time: float | None = None
        self._boot: float | None = None
        self._start: float | None = None
        self._autopilot = [AutopilotPhase.WAITING] * 4
        self._ready = [False] * 4
        self._fts_ok = [True] * 4
        self._watchdog_ok = [True] * 4
        count = len(config.variables)
        self._values: list[list[float | None]] = [[None] * count for _ in _AUTOPILOTS]
        # Last receipt of each arbitration message: variables 0..count-1, then Ready.
        self._seen: list[list[float | None]] = [[None] * (count + 1) for _ in _AUTOPILOTS]
        self._scores: dict[int, float] = {}
        fixed = config.method.fixed_autopilot
        self._selected = config.preferred if fixed is None else fixed
        self._last_switch: float | None = None
        self._retry_at: float | None = None
        self._held: int | None = None  # the switch waiting for the holding time to end
        # No timed event falls due before this time (a lower bound: receipts only push
        # deadlines later); anything that brings one earlier lowers it.
        self._quiet_until = -math.inf
        self._status: Periodic | None = None
        self._score: Periodic | None = None
        self._decisions: list[Decision] = []
        self._sources = {config.autopilot_ids[ap]: ap for ap in config.participants}

    # ----------------------------------------------------------------- inputs

    def receive(self, can_id: int, data: BytesLike, timestamp: float) -> codec.Message | None:
        """Take one frame sent to the arbiter.

        Frames on an ID other than a taking-part autopilot's are ignored (``None``).
        Ready and Not Ready, arbitration variables and the maintenance command act on the
        model; other messages are returned and ignored.

        Raises:
            DecodeError: the frame is not a valid Veronte message.
            InputError: ``timestamp`` is earlier than the previous one.
            TypeError: An argument of the wrong type.
        """
        if can_id.__class__ is not int or data.__class__ is not bytes:
            can_id = int_argument("receive", "can_id", can_id)
            check_types("receive", ("data", data, (bytes, bytearray, memoryview), "bytes-like"))
        timestamp = check_seconds("receive", "timestamp", timestamp)
        self.advance(timestamp)
        autopilot = self._sources.get(can_id)
        if autopilot is None:
            return None
        message = codec.decode(data, sender=codec.Sender.AUTOPILOT)
        if isinstance(message, codec.Ready):
            self._on_ready(autopilot, message.ready, timestamp)
        elif isinstance(message, codec.ArbitrationVariable):
            self._on_variable(autopilot, message.number, message.value, timestamp)
        elif isinstance(message, codec.MaintenanceCommand):
            source = f"maintenance command from {autopilot_name(autopilot)}"
            self._enter(ArbiterEvent.MAINTENANCE_COMMAND, timestamp, source)
        return message

    def set_checks(self, timestamp: float, checks: SystemChecks) -> None:
        """Report the arbiter's system checks; in Idle, all OK means Normal mode."""
        timestamp = check_seconds("set_checks", "timestamp", timestamp)
        if not isinstance(checks, SystemChecks):
            raise argument_type_error("set_checks", "checks", "a SystemChecks", checks)
        self.advance(timestamp)
        self._checks = checks
        if self._phase is ArbiterPhase.IDLE and checks.all_ok:
            self._checks_pass(timestamp)

    def set_fts(self, timestamp: float, autopilot: int, ok: bool) -> None:
        """Report an autopilot's FTS signal: not OK means "System Not OK" (4x Software Manual,
        section 4)."""
        timestamp, autopilot, ok = _check_signal("set_fts", timestamp, autopilot, ok)
        self._set_signal(self._fts_ok, AutopilotEvent.FTS_BAD, timestamp, autopilot, ok)

    def set_watchdog(self, timestamp: float, autopilot: int, ok: bool) -> None:
        """Report an autopilot's watchdog signal (4x Software Manual, section 4: "The watchdog
        signal ... is
        not ok" kills it)."""
        timestamp, autopilot, ok = _check_signal("set_watchdog", timestamp, autopilot, ok)
        self._set_signal(self._watchdog_ok, AutopilotEvent.WATCHDOG_BAD, timestamp, autopilot, ok)

    def command_maintenance(self, timestamp: float) -> None:
        """The maintenance command (t_cmd_maint), from wherever it comes."""
        timestamp = check_seconds("command_maintenance", "timestamp", timestamp)
        self.advance(timestamp)
        self._enter(ArbiterEvent.MAINTENANCE_COMMAND, timestamp, "maintenance command")

    def advance(self, timestamp: float) -> None:
        """Bring the model to ``timestamp``: boot, timeouts, holding time, round robin.

        Each timed event is recorded at the time it falls due, in time order.

        Raises:
            InputError: ``timestamp`` is earlier than the previous one.
            TypeError: ``timestamp`` is not a number.
        """
        timestamp = check_seconds("advance", "timestamp", timestamp)
        if not math.isfinite(timestamp):
            raise InputError("timestamp", timestamp, "a finite number of seconds")
        if self._time is not None and timestamp < self._time:
            raise InputError("timestamp", timestamp, f">= the previous one, {self._time}")
        if self._boot is None:
            self._boot = timestamp
            self._record(timestamp, DecisionKind.MODE, None, "boot: Idle, checking the system")
            if self._checks.all_ok:
                self._checks_pass(timestamp)
        while timestamp >= self._quiet_until and self._run_next_timer(timestamp):
            pass
        self._time = timestamp

    # ----------------------------------------------------------------- outputs

    def poll(self, timestamp: float) -> list[SentFrame]:
        """The frames the arbiter sends at ``timestamp``: (CAN ID, bytes).

        Status every ``status_period`` in Normal mode when ``send_status`` is set, and
        always in Maintenance; one Score per taking-part autopilot with a score every
        ``score_period`` in Normal mode when ``send_score`` is set; nothing while Idle
        (4x Software Manual, section 4, "Status message"). A late poll sends each message once.
        """
        timestamp = check_seconds("poll", "timestamp", timestamp)
        self.advance(timestamp)
        frames: list[SentFrame] = []
        arbiter_id = self.config.arbiter_id
        status_due = self._status is not None and self._status.take(timestamp)
        if status_due and (self._phase is ArbiterPhase.MAINTENANCE or self.config.send_status):
            frames.append((arbiter_id, codec.encode(self.status_message())))
        score_due = self._score is not None and self._score.take(timestamp)
        normal = self._phase in (ArbiterPhase.NORMAL, ArbiterPhase.ARBITRATING)
        if score_due and normal and self.config.send_score:
            for autopilot, score in sorted(self._scores.items()):
                message = codec.Score(autopilot, _within_float32(score))
                frames.append((arbiter_id, codec.encode(message)))
        return frames

    def status_message(self) -> codec.Status:
        """The Status message for the current state, in its 6-byte 4x form.

        Bytes 4-5 come from the system checks; CBIT also fails when arbitration runs with
        no autopilot alive (4x Software Manual, section 2.1: "There is not any autopilot alive.").
        """
        checks = self._checks
        alive = self._flags(AutopilotPhase.ALIVE)
        arbitrating = self._phase is ArbiterPhase.ARBITRATING
        no_one_alive = arbitrating and not any(alive)
        return codec.Status(
            selected=self._selected,
            arbitrating=arbitrating and self.config.method.fixed_autopilot is None,
            alive=alive,
            ready=(self._ready[0], self._ready[1], self._ready[2], self._ready[3]),
            cbit_ok=checks.all_ok and not no_one_alive,
            pbit_ok=checks.pbit_ok,
            pdi_ok=checks.pdi_ok,
            memory_ok=checks.memory_ok,
            can_a_ok=checks.can_a_ok,
            can_b_ok=checks.can_b_ok,
            cio_low_ok=checks.cio_low_ok,
            cio_high_ok=checks.cio_high_ok,
            power_ok=checks.power_ok,
            bus_a_voltage_ok=checks.bus_a_voltage_ok,
            bus_b_voltage_ok=checks.bus_b_voltage_ok,
            arbiter_voltage_ok=checks.arbiter_voltage_ok,
            ap1_voltage_ok=checks.ap1_voltage_ok,
            ap2_voltage_ok=checks.ap2_voltage_ok,
            ap3_voltage_ok=checks.ap3_voltage_ok,
            normal_mode=self._phase in (ArbiterPhase.NORMAL, ArbiterPhase.ARBITRATING),
        )

    @property
    def state(self) -> ArbiterState:
        """A snapshot of the model as of the last input."""
        status = self.status_message()
        return ArbiterState(
            time=self._time,
            mode=MODE_OF_PHASE[self._phase],
            phase=self._phase,
            arbitrating=status.arbitrating,
            ready=status.ready,
            alive=status.alive,
            dead=self._flags(AutopilotPhase.DEAD),
            scores=dict(self._scores),
            selected=self._selected,
            checks=self._checks,
            last_decision=self._decisions[-1] if self._decisions else None,
        )

    @property
    def decisions(self) -> Sequence[Decision]:
        """Every decision so far, in time order."""
        return tuple(self._decisions)

    # ------------------------------------------------------------ status management

    def _record(self, time: float, kind: DecisionKind, autopilot: int | None, why: str) -> None:
        self._decisions.append(Decision(time, kind, autopilot, why))

    def _flags(self, phase: AutopilotPhase) -> tuple[bool, bool, bool, bool]:
        flags = self._autopilot
        return (flags[0] is phase, flags[1] is phase, flags[2] is phase, flags[3] is phase)

    def _enter(self, event: ArbiterEvent, time: float, why: str) -> bool:
        phase = next_phase(self._phase, event)
        if phase is None:
            return False
        if self._phase is ArbiterPhase.IDLE:
            self._status = Periodic(time, self.config.status_period)
        self._phase = phase
        self._retry_at = None
        self._quiet_until = -math.inf
        self._record(time, DecisionKind.MODE, None, f"{phase.value}: {why}")
        return True

    def _checks_pass(self, time: float) -> None:
        if self._enter(ArbiterEvent.CHECKS_PASS, time, "boot checks pass"):
            self._score = Periodic(time, self.config.score_period)
            self._start_if_all_ready(time)

    def _start_if_all_ready(self, time: float) -> None:
        participants = self.config.participants
        if self._phase is not ArbiterPhase.NORMAL or not all(
            self._ready[ap] for ap in participants
        ):
            return
        names = ", ".join(autopilot_name(ap) for ap in participants)
        self._enter(ArbiterEvent.ALL_READY, time, f"Ready from {names}")
        self._start = time
        self._record(time, DecisionKind.ARBITRATION, None, f"arbitration starts: {names} alive")
        for autopilot in participants:
            self._move(autopilot, AutopilotEvent.ARBITRATION_STARTS)
        for autopilot in participants:
            for signal, event in (
                (self._fts_ok, AutopilotEvent.FTS_BAD),
                (self._watchdog_ok, AutopilotEvent.WATCHDOG_BAD),
            ):
                if not signal[autopilot]:
                    self._kill(autopilot, event, time, _DEATH_CAUSES[event])
        self._update_scores()
        self._arbitrate(time)

    def _move(self, autopilot: int, event: AutopilotEvent) -> bool:
        phase = next_autopilot_phase(self._autopilot[autopilot], event)
        if phase is None:
            return False
        self._autopilot[autopilot] = phase
        return True

    def _kill(self, autopilot: int, event: AutopilotEvent, time: float, cause: str) -> None:
        # Deaths belong to arbitration; Maintenance freezes alive and dead as they were.
        if self._phase is ArbiterPhase.ARBITRATING and self._move(autopilot, event):
            why = f"{autopilot_name(autopilot)} dead: {cause}"
            self._record(time, DecisionKind.DEAD, autopilot, why)
            self._update_scores()
            self._arbitrate(time)

    def _set_signal(
        self, signal: list[bool], event: AutopilotEvent, time: float, autopilot: int, ok: bool
    ) -> None:
        if autopilot not in _AUTOPILOTS:
            raise InputError("autopilot", autopilot, "0..3 (AP1, AP2, AP3, external)")
        self.advance(time)
        signal[autopilot] = ok
        if not ok:
            self._kill(autopilot, event, time, _DEATH_CAUSES[event])

    def _on_ready(self, autopilot: int, ready: bool, time: float) -> None:
        self._seen[autopilot][-1] = time
        if self._ready[autopilot] != ready:
            self._ready[autopilot] = ready
            word = "Ready" if ready else "Not Ready"
            why = f"{autopilot_name(autopilot)} {word}"
            self._record(time, DecisionKind.READY, autopilot, why)
        if ready:
            self._move(autopilot, AutopilotEvent.READY)
            self._start_if_all_ready(time)
        elif self._autopilot[autopilot] is AutopilotPhase.ALIVE:
            event = AutopilotEvent.NOT_READY
            self._kill(autopilot, event, time, _DEATH_CAUSES[event])
        else:
            self._move(autopilot, AutopilotEvent.NOT_READY)

    def _on_variable(self, autopilot: int, number: int, value: float, time: float) -> None:
        if number >= len(self.config.variables):
            return
        self._seen[autopilot][number] = time
        self._values[autopilot][number] = value
        self._update_scores()
        self._arbitrate(time)

    # ----------------------------------------------------------------- arbitration

    def _alive(self) -> list[int]:
        alive = AutopilotPhase.ALIVE
        return [ap for ap in self.config.participants if self._autopilot[ap] is alive]

    def _update_scores(self) -> None:
        config = self.config
        complete = {
            ap: [value for value in self._values[ap] if value is not None]
            for ap in config.participants
            if None not in self._values[ap]
        }
        # Before arbitration starts no one is dead: every taking-part autopilot counts.
        alive = self._alive() if self._start is not None else list(config.participants)
        if config.relative_mean is RelativeMean.ALIVE:
            mean_of = [ap for ap in alive if ap in complete]
        else:
            mean_of = list(complete)
        self._scores = compute_scores(
            complete,
            config.variables,
            mean_of=mean_of,
            relative=len(alive) >= MIN_AUTOPILOTS_FOR_RELATIVE,
            max_error_mode=config.max_error_mode,
        )

    def _holding_reference(self) -> float | None:
        if self._last_switch is not None:
            return self._last_switch
        return self._start if self.config.method is Method.ROUND_ROBIN else None

    def _arbitrate(self, time: float) -> None:
        if self._phase is not ArbiterPhase.ARBITRATING:
            return
        self._retry_at = None
        choice = choose(self.config, self._selected, self._alive(), self._scores)
        held = None
        reference = self._holding_reference()
        if choice is not None and not choice.forced and reference is not None:
            allowed = reference + self.config.holding_time
            if time < allowed:
                self._retry_at = allowed
                self._quiet_until = min(self._quiet_until, allowed)
                held = choice.autopilot
                if held != self._held and self.config.method is not Method.ROUND_ROBIN:
                    move = f"{autopilot_name(self._selected)} -> {autopilot_name(held)}"
                    why = f"{move} held until {allowed:.3f} s (holding time): {choice.reason}"
                    self._record(time, DecisionKind.HOLD, held, why)
        self._held = held
        if choice is not None and held is None:
            self._switch(choice, time)

    def _switch(self, choice: Choice, time: float) -> None:
        old = autopilot_name(self._selected)
        self._selected = choice.autopilot
        self._last_switch = time
        why = f"{old} -> {autopilot_name(choice.autopilot)}: {choice.reason}"
        self._record(time, DecisionKind.SWITCH, choice.autopilot, why)
        self._arbitrate(time)

    # ---------------------------------------------------------------------- timers

    def _deadline(self, autopilot: int) -> tuple[float, str]:
        """When the first of ``autopilot``'s arbitration messages goes missing, and which."""
        start = self._start if self._start is not None else 0.0
        timeout = self.config.message_timeout
        # The clock of a message runs from its last receipt, or from the start of
        # arbitration when that is later (see the decisions page).
        since = [start if last is None or last < start else last for last in self._seen[autopilot]]
        number = min(range(len(since)), key=since.__getitem__)
        what = "Ready" if number == len(since) - 1 else f"arbitration variable {number}"
        last = self._seen[autopilot][number]
        if last is None or last < start:
            cause = f"{what} not received within {timeout:g} s of arbitration start"
        else:
            cause = f"{what} missing for {timeout:g} s"
        return since[number] + timeout, cause

    def _run_next_timer(self, now: float) -> bool:
        """Run the earliest timed event due at or before ``now``; False when none is due."""
        due: list[tuple[float, int, int, str]] = []
        if self._phase is ArbiterPhase.IDLE and self._boot is not None:
            due.append((self._boot + self.config.boot_timeout, 0, -1, ""))
        if self._phase is ArbiterPhase.ARBITRATING:
            for autopilot in self._alive():
                deadline, cause = self._deadline(autopilot)
                due.append((deadline, 1, autopilot, cause))
            if self._retry_at is not None:
                due.append((self._retry_at, 2, -1, ""))
        if not due:
            self._quiet_until = math.inf
            return False
        time, kind, autopilot, cause = min(due)
        if time > now:
            self._quiet_until = time
            return False
        if kind == 0:
            failing = ", ".join(self._checks.failing())
            why = f"errors persist {self.config.boot_timeout:g} s after boot ({failing})"
            self._enter(ArbiterEvent.CHECKS_FAIL_30S, time, why)
        elif kind == 1:
            self._kill(autopilot, AutopilotEvent.MESSAGE_MISSING, time, cause)
        else:
            self._arbitrate(time)
        return True


def _check_signal(
    function: str, timestamp: object, autopilot: object, ok: object
) -> tuple[float, int, bool]:
    """The arguments of a signal report as Python values (NumPy scalars taken, see
    `veronte4x.errors.integer`), or the `TypeError` of the library's policy."""
    seconds = check_seconds(function, "timestamp", timestamp)
    number = int_argument(function, "autopilot", autopilot)
    flag = boolean(ok)
    if flag is None:
        raise argument_type_error(function, "ok", "a bool", ok)
    return seconds, number, flag
