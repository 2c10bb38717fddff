"""Replay a capture through the model: every decision, and where the real arbiter disagrees.

The autopilots' frames drive an `Arbiter`; the real arbiter's Status and Score frames in
the capture (on ``config.arbiter_id``) are compared with the model at their timestamps.

The model's time only goes forward; a capture's does not always. A frame up to
``max_step_back`` earlier than the latest one (lines swapped by a logger, two interfaces'
clocks merged) is taken at the latest time and counted as late; a larger step back (two
logs joined one after the other) starts the model again, as at boot, and is shown on the
timeline. A capture that steps back more often than that is not in time order at all: it
raises `DisorderedError`.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable
from dataclasses import dataclass

from veronte4x import codec
from veronte4x.arbiter.config import ArbiterConfig, autopilot_name
from veronte4x.arbiter.errors import InputError
from veronte4x.arbiter.machine import ArbiterPhase
from veronte4x.arbiter.model import Arbiter
from veronte4x.arbiter.state import ArbiterState, Decision, SystemChecks
from veronte4x.errors import DecodeError
from veronte4x.numbers import shortest
from veronte4x.words import counted

#: One captured frame: (timestamp in s, CAN ID, data bytes).
CapturedFrame = tuple[float, int, bytes]
FieldValue = bool | int | float | str | None
"""The value of a compared field, as recorded or as modelled."""

_FLAG_FIELDS = ("alive", "ready")


@dataclass(frozen=True, slots=True)
class Disagreement:
    """A run of the real arbiter's frames that disagree with the model on one field.

    Attributes:
        start: Time of the first disagreeing frame, s.
        end: Time of the last one of the run, s.
        field: What disagrees: "mode", "selected", "arbitrating", "alive AP2",
            "ready AP1", "score AP3".
        recorded: What the real arbiter sent.
        modelled: What the model holds.
        frames: How many frames of the capture the run spans.
    """

    start: float
    end: float
    field: str
    recorded: FieldValue
    modelled: FieldValue
    frames: int

    def __str__(self) -> str:
        span = f"{self.start:.3f}-{self.end:.3f} s, {self.frames} frame(s)"
        return f"{self.start:10.3f} s  {self._what()} ({span})"

    def body(self, when: Callable[[float], str]) -> str:
        """The disagreement without its start time; ``when`` formats its end time."""
        return f"{self._what()} (until {when(self.end)}, {self.frames} frame(s))"

    def _what(self) -> str:
        recorded, modelled = _show(self.field, self.recorded), _show(self.field, self.modelled)
        return f"DISAGREES   {self.field}: recorded {recorded}, model {modelled}"


@dataclass(frozen=True, slots=True)
class FrameError:
    """A captured frame that does not decode.

    Attributes:
        time: Its timestamp, s.
        can_id: Its CAN ID.
        data: Its bytes.
        error: The decode error's message.
    """

    time: float
    can_id: int
    data: bytes
    error: str

    def __str__(self) -> str:
        return f"{self.time:10.3f} s  {self.body()}"

    def body(self) -> str:
        """The bad frame without its time."""
        return f"BAD FRAME   id {self.can_id}: {self.error}"


@dataclass(frozen=True, slots=True)
class Restart:
    """Where the capture's time steps back further than ``max_step_back``: the model starts
    again there, as at boot (two logs joined one after the other, a recorder's clock reset).

    Attributes:
        time: The time of the first frame after the step back, s.
        previous: The latest time before it, s.
        firsts: The index in the result's ``decisions``, ``disagreements`` and ``errors``
            of the first item after the restart.
    """

    time: float
    previous: float
    firsts: tuple[int, int, int] = (0, 0, 0)

    def __str__(self) -> str:
        return f"{self.time:10.3f} s  {self.body()}"

    def body(self, when: Callable[[float], str] | None = None) -> str:
        """The restart without its time; ``when`` formats the time before the step."""
        previous = f"{self.previous:.3f} s" if when is None else when(self.previous)
        return (
            f"RESTART     the capture's time steps back {self.previous - self.time:.6f} s "
            f"(from {previous}): the model starts again, as at boot"
        )


class DisorderedError(InputError):
    """A capture whose timestamps step back too often to be replayed: it is not in time
    order (shuffled lines, or many logs joined). Sort it by time first.

    Attributes:
        steps: The steps back met so far.
        frames: The frames read so far.
    """

    def __init__(self, steps: int, frames: int) -> None:
        super().__init__(
            "timestamps",
            f"{counted(steps, 'step')} back in {counted(frames, 'frame')}",
            "a capture in time order",
        )
        self.steps = steps
        self.frames = frames


@dataclass(frozen=True, slots=True)
class ReplayResult:
    """What a replay found.

    Attributes:
        decisions: Every decision of the model, in time order.
        disagreements: Every run of real-arbiter frames disagreeing with the model.
        errors: Frames that did not decode (they are otherwise skipped).
        state: The model's state after the last frame.
        late: Frames up to ``max_step_back`` earlier than the one before, taken at the
            latest time.
        restarts: Where the time steps back further, and the model starts again.
    """

    decisions: tuple[Decision, ...]
    disagreements: tuple[Disagreement, ...]
    errors: tuple[FrameError, ...]
    state: ArbiterState
    late: int = 0
    restarts: tuple[Restart, ...] = ()

    def timeline(self, when: Callable[[float], str] | None = None) -> str:
        """Decisions, disagreements and bad frames as text, one a line, in time order.

        Args:
            when: Formats a time, such as `veronte4x.times.format_time` (ISO 8601 for Unix
                time); by default seconds with milliseconds, ``12.345 s``.
        """
        if when is None:
            entries: list[tuple[float, int, str]] = [
                (item.time, 0, str(item)) for item in self.decisions
            ]
            entries += [(item.start, 1, str(item)) for item in self.disagreements]
            entries += [(item.time, 2, str(item)) for item in self.errors]
            entries += [(item.time, -1, str(item)) for item in self.restarts]
        else:
            entries = [
                (item.time, 0, f"{when(item.time)}  {item.body()}") for item in self.decisions
            ]
            entries += [
                (item.start, 1, f"{when(item.start)}  {item.body(when)}")
                for item in self.disagreements
            ]
            entries += [(item.time, 2, f"{when(item.time)}  {item.body()}") for item in self.errors]
            entries += [
                (item.time, -1, f"{when(item.time)}  {item.body(when)}") for item in self.restarts
            ]
        # Time starts again at each restart: in time order within each stretch between them.
        stretch = [0] * len(self.decisions) + [0] * len(self.disagreements)
        stretch += [0] * len(self.errors)
        offsets = (0, len(self.decisions), len(self.decisions) + len(self.disagreements))
        for number, restart in enumerate(self.restarts, 1):
            for offset, first, end in zip(
                offsets, restart.firsts, (*offsets[1:], len(stretch)), strict=True
            ):
                stretch[offset + first : end] = [number] * (end - offset - first)
        stretch += range(1, len(self.restarts) + 1)
        order = sorted(range(len(entries)), key=lambda i: (stretch[i], *entries[i][:2]))
        return "\n".join(entries[i][2] for i in order)


def _show(field: str, value: FieldValue) -> str:
    if field == "selected" and isinstance(value, int):
        return autopilot_name(value)
    if isinstance(value, float):
        return repr(shortest(value, 32))
    return str(value)


def _same_score(recorded: float, modelled: float, tolerance: float) -> bool:
    if math.isnan(recorded) or math.isnan(modelled):
        return math.isnan(recorded) and math.isnan(modelled)
    if recorded == modelled:
        return True
    return abs(recorded - modelled) <= tolerance * max(abs(recorded), abs(modelled))


@dataclass(slots=True)
class _Run:
    start: float
    end: float
    recorded: FieldValue
    modelled: FieldValue
    frames: int = 1


class _Comparer:
    """Collects disagreements, merging a field's consecutive identical ones into runs."""

    def __init__(self, tolerance: float) -> None:
        self.tolerance = tolerance
        self._open: dict[str, _Run] = {}
        self._closed: list[Disagreement] = []

    def check(self, time: float, field: str, recorded: FieldValue, modelled: FieldValue) -> None:
        """Compare one field of one recorded frame with the model."""
        if isinstance(recorded, float) and isinstance(modelled, float):
            same = _same_score(recorded, modelled, self.tolerance)
        else:
            same = recorded == modelled
        run = self._open.get(field)
        if run is not None and (same or (run.recorded, run.modelled) != (recorded, modelled)):
            self._close(field)
            run = None
        if same:
            return
        if run is None:
            self._open[field] = _Run(time, time, recorded, modelled)
        else:
            run.end = time
            run.frames += 1

    def _close(self, field: str) -> None:
        run = self._open.pop(field)
        self._closed.append(
            Disagreement(run.start, run.end, field, run.recorded, run.modelled, run.frames)
        )

    def finish(self) -> tuple[Disagreement, ...]:
        """Every disagreement, runs still open included, by start time."""
        for field in list(self._open):
            self._close(field)
        return tuple(sorted(self._closed, key=lambda d: (d.start, d.field)))


def _compare_status(compare: _Comparer, time: float, arb: Arbiter, status: codec.Status) -> None:
    state = arb.state
    if state.phase is ArbiterPhase.IDLE:
        compare.check(time, "mode", "Status sent", "Idle, no Status")
        return
    if status.normal_mode is not None:
        recorded = "Normal" if status.normal_mode else "Maintenance"
        compare.check(time, "mode", recorded, state.mode.value)
    compare.check(time, "selected", status.selected, state.selected)
    compare.check(time, "arbitrating", status.arbitrating, state.arbitrating)
    for name in _FLAG_FIELDS:
        recorded_flags, modelled_flags = getattr(status, name), getattr(state, name)
        for autopilot in range(4):
            compare.check(
                time,
                f"{name} {autopilot_name(autopilot)}",
                recorded_flags[autopilot],
                modelled_flags[autopilot],
            )


MAX_STEP_BACK = 0.01
"""How far back, in seconds, a frame's time may step and still be taken as late: a tenth of
the default message timeout (0.1 s), so that moving it to the latest time changes no
timeout the model keeps."""

_DISORDER = 10
"""A capture steps back more than this many times, and in more than one frame in this many,
is not in time order."""


def replay(
    frames: Iterable[CapturedFrame],
    config: ArbiterConfig,
    *,
    checks: SystemChecks | None = None,
    score_tolerance: float = 1e-5,
    max_step_back: float = MAX_STEP_BACK,
) -> ReplayResult:
    """Run a capture through the model and compare it with the real arbiter's frames.

    Args:
        frames: (timestamp, CAN ID, data) in time order. Frames from the autopilots drive
            the model; Status and Score frames on ``config.arbiter_id`` are compared with
            it; other IDs are skipped.
        config: The configuration of the arbiter that was captured.
        checks: The arbiter's system checks at boot (default: all OK).
        score_tolerance: Relative difference up to which a recorded score equals the
            model's: the float32 rounding of the arbiter's own arithmetic.
        max_step_back: A frame up to this many seconds earlier than the latest one is taken
            at the latest time (counted in ``late``); further back, the model starts again
            (a `Restart`).

    Returns:
        The model's decisions, the disagreements, the frames that did not decode, and the
        final state. The flags of Status bytes 4-5 are not compared: the model takes them
        as inputs.

    Raises:
        DisorderedError: The time steps back more than 10 times, in more than one frame in
            10: the capture is not in time order.
        InputError: A timestamp is not a finite number.
    """
    arb = Arbiter(config, checks=checks)
    compare = _Comparer(score_tolerance)
    decisions: list[Decision] = []
    disagreements: list[Disagreement] = []
    errors: list[FrameError] = []
    restarts: list[Restart] = []
    late = count = 0
    latest = -math.inf
    for time, can_id, data in frames:
        count += 1
        if time < latest:
            if latest - time <= max_step_back:
                late += 1
                time = latest
            else:
                if len(restarts) + late >= _DISORDER and (len(restarts) + late) * _DISORDER > count:
                    raise DisorderedError(len(restarts) + late + 1, count)
                decisions += arb.decisions
                disagreements += compare.finish()
                firsts = (len(decisions), len(disagreements), len(errors))
                restarts.append(Restart(time, latest, firsts))
                arb, compare = Arbiter(config, checks=checks), _Comparer(score_tolerance)
        latest = time
        try:
            if can_id != config.arbiter_id:
                arb.receive(can_id, data, time)
                continue
            arb.advance(time)
            message = codec.decode(data, sender=codec.Sender.ARBITER)
        except DecodeError as error:
            errors.append(FrameError(time, can_id, bytes(data), str(error)))
            continue
        if isinstance(message, codec.Status):
            _compare_status(compare, time, arb, message)
        elif isinstance(message, codec.Score):
            scores = arb.state.scores
            field = f"score {autopilot_name(message.autopilot)}"
            compare.check(time, field, message.score, scores.get(message.autopilot))
    decisions += arb.decisions
    disagreements += compare.finish()
    return ReplayResult(
        tuple(decisions), tuple(disagreements), tuple(errors), arb.state, late, tuple(restarts)
    )
