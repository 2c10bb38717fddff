"""Spinning motors: its arguments, which motors it may drive, when to stop it, what it saw
(sans-IO).

`spin_plan` checks what a spin is asked to do before anything is sent. RawCommand turns
every node whose ``esc_index`` is commanded, so `spin_indices` then checks, from an
`IndexSurvey` of the whole bus, that no node outside those named shares a named node's
index or has one that cannot be read. A tool that drives motors then listens to the nodes it
drives: a node that stops publishing esc.Status and NodeStatus may have lost power, the bus
or its firmware, and an ESC that reports too hot or too much current is a rig to stop.
`SpinMonitor` takes the transfers seen and the time, and says why to stop; the tool then
sends zero throttle to every ESC. `Spin` is one spin under way, from the plan and the
survey to its `SpinResult`; ``BusClient.spin`` and ``AsyncBusClient.spin`` run it with a
command stream, reading the clock for it.
"""

from __future__ import annotations

import math
from collections.abc import Collection, Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import Literal

from veronte4x.client.errors import ClientError, InvalidRequestError
from veronte4x.client.indices import EscIndexError, IndexSurvey, nodes_text, reason
from veronte4x.client.protocol import Event, Received
from veronte4x.dronecan.messages import EscStatus, NodeStatus
from veronte4x.dronecan.transfer import Transfer
from veronte4x.errors import EncodeError, check_seconds

DEFAULT_SILENCE = 1.5
"""Seconds without esc.Status or NodeStatus after which a spun node counts as gone: above
NodeStatus' 1 s broadcast period (DSDL ``MAX_BROADCASTING_PERIOD_MS``) with margin, so that
a node publishing no telemetry is not taken for gone; half the 3 s a node table waits
(``OFFLINE_TIMEOUT_MS``), since a motor may be turning."""

KELVIN = 273.15
"""0 °C in kelvin: esc.Status reports its temperature in kelvin (DSDL esc.Status)."""


def spin_indices(
    nodes: Sequence[int], survey: IndexSurvey, allow_unknown: Collection[int] = ()
) -> dict[int, int]:
    """The ``esc_index`` of each node to spin, when spinning them turns no other motor.

    Args:
        nodes: The nodes to spin.
        survey: Every node's ``esc_index`` (`veronte4x.client.indices.survey` with
            ``also=nodes``).
        allow_unknown: Nodes whose ``esc_index`` cannot be read that are known to drive no
            motor (a node that is no ESC); any other such node refuses the spin.

    Raises:
        ClientError: A node to spin whose ``esc_index`` cannot be read (its own error:
            `NoResponseError`, `ParameterError`, `InvalidRequestError`).
        EscIndexError: A node not named shares a named node's ``esc_index``, or has one that
            cannot be read and is not in ``allow_unknown``.

    Examples:
        >>> spin_indices([21], IndexSurvey({21: 0, 22: 1}, {}))
        {21: 0}
        >>> spin_indices([21], IndexSurvey({21: 0, 22: 0}, {}))
        Traceback (most recent call last):
        ...
        veronte4x.client.indices.EscIndexError: node 22 has esc_index 0 too: RawCommand \
would turn it with node 21; name it as well to spin both, or give it an esc_index of its \
own; nothing was sent
    """
    for node in nodes:
        if node in survey.unread:
            raise survey.unread[node]
    indices = {node: survey.indices[node] for node in nodes}
    problems = []
    for other in survey.nodes():
        if other in indices:
            continue
        if other in survey.indices:
            index = survey.indices[other]
            with_it = sorted(n for n, i in indices.items() if i == index)
            if with_it:
                problems.append(
                    f"node {other} has esc_index {index} too: RawCommand would turn it with "
                    f"{nodes_text(with_it)}; name it as well to spin both, or give it an "
                    "esc_index of its own"
                )
    shared = bool(problems)
    unread = [n for n in survey.unread if n not in indices and n not in allow_unknown]
    for other in unread:
        problems.append(
            f"node {other}'s esc_index cannot be read, so it may turn too "
            f"({reason(other, survey.unread[other])})"
        )
    if problems:
        raise EscIndexError(problems, unread, shared, survey.own_id(unread))
    return indices


def _positive(name: str, value: float | None) -> float | None:
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise EncodeError("SpinMonitor", name, value, "a finite number")
    return float(value)


class SpinMonitor:
    """Watch the nodes being spun; `check` says why to stop, or None.

    Args:
        nodes: The node ids being spun.
        now: When the spin starts: each node's silence is counted from here.
        silence: Seconds without esc.Status or NodeStatus from a node that stop the spin.
        max_temperature: Stop when an esc.Status temperature exceeds this, °C (None: no
            limit).
        max_current: Stop when an esc.Status current exceeds this, A (None: no limit).

    Raises:
        EncodeError: A silence that is not a number above 0, or a limit that is not finite.

    Examples:
        >>> from veronte4x import dronecan
        >>> monitor = SpinMonitor([21, 22], now=0.0, silence=1.0, max_current=20.0)
        >>> status = dronecan.EscStatus(0, 25.0, 3.0, 300.0, 2000, 20, 0)
        >>> monitor.observe(dronecan.Transfer(
        ...     status, 21, None, 16, 0, 0.5, dronecan.TransferKind.MESSAGE, 1034))
        >>> monitor.check(0.9) is None
        True
        >>> monitor.check(1.2)
        'node 22 fell silent: no esc.Status or NodeStatus for 1 s'
    """

    def __init__(
        self,
        nodes: Iterable[int],
        now: float,
        *,
        silence: float = DEFAULT_SILENCE,
        max_temperature: float | None = None,
        max_current: float | None = None,
    ) -> None:
        check_seconds("SpinMonitor", "now", now)
        if _positive("silence", silence) is None or not silence > 0:
            raise EncodeError("SpinMonitor", "silence", silence, "seconds above 0")
        self.silence = float(silence)
        self.max_temperature = _positive("max_temperature", max_temperature)
        self.max_current = _positive("max_current", max_current)
        self.last_heard = dict.fromkeys(nodes, float(now))
        """When each node was last heard (the start for a node not heard yet)."""
        self._tripped: str | None = None

    def observe(self, transfer: Transfer) -> None:
        """Take a transfer seen on the bus (its timestamp counts)."""
        node = transfer.source_node_id
        if node not in self.last_heard:
            return
        message = transfer.message
        if not isinstance(message, (EscStatus, NodeStatus)):
            return
        self.last_heard[node] = max(self.last_heard[node], transfer.timestamp)
        if isinstance(message, EscStatus) and self._tripped is None:
            self._tripped = self._limit(node, message)

    def _limit(self, node: int, status: EscStatus) -> str | None:
        celsius = status.temperature - KELVIN
        if self.max_temperature is not None and celsius > self.max_temperature:
            return (
                f"node {node} reported {celsius:.1f} °C, above the limit of "
                f"{self.max_temperature:g} °C"
            )
        if self.max_current is not None and status.current > self.max_current:
            return (
                f"node {node} reported {status.current:.1f} A, above the limit of "
                f"{self.max_current:g} A"
            )
        return None

    @property
    def over_limit(self) -> bool:
        """Whether a limit tripped (rather than a node falling silent)."""
        return self._tripped is not None

    def check(self, now: float) -> str | None:
        """Why to stop at ``now``, one line: a limit tripped or a node fell silent; else None."""
        check_seconds("check", "now", now)
        if self._tripped is not None:
            return self._tripped
        for node, heard in self.last_heard.items():
            if now - heard > self.silence:
                return (
                    f"node {node} fell silent: no esc.Status or NodeStatus for {self.silence:g} s"
                )
        return None


SETTLE = 0.2
"""Seconds a spin that ran its course goes on reading the bus after its zero throttle, so that
the zero throttle reaches the ESCs' telemetry before the tool lets go of the bus."""

STEP = 0.02
"""Longest wait for frames between two refreshes of a spin's setpoint, in seconds."""

AllowUnknown = Collection[int] | Literal["all"]
"""Nodes whose ``esc_index`` may be unreadable without refusing a spin, or ``"all"``."""


class SpinArgumentError(InvalidRequestError):
    """A spin argument out of its range, refused before anything is sent.

    Attributes:
        argument: The argument's name (``throttle``, ``max_current``, ...).
        value: What was given.
        need: What it must be, as the end of a sentence (``is outside -1..1``).
    """

    def __init__(self, argument: str, value: object, need: str) -> None:
        self.argument = argument
        self.value = value
        self.need = need
        super().__init__(self.line(argument))

    def line(self, name: str) -> str:
        """The error with the argument called ``name`` (a command line says ``--throttle``)."""
        shown = f"{self.value:g}" if _real(self.value) else repr(self.value)
        return f"{name} {shown} {self.need}"


class SpinStoppedError(ClientError):
    """A spin stopped before its end: a node fell silent or reported over a limit. Every
    motor got zero throttle first.

    Attributes:
        reason: Why, one line (`SpinMonitor.check`).
        over_limit: Whether a limit tripped (rather than a node falling silent).
        result: What the spin saw until then.
    """

    def __init__(self, reason: str, over_limit: bool, result: SpinResult) -> None:
        self.reason = reason
        self.over_limit = over_limit
        self.result = result
        super().__init__(f"{reason}; every motor stopped: zero throttle sent")


def _real(value: object) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def _check(argument: str, value: object, low: float, high: float, need: str) -> float:
    """``value`` as a float when ``low < value < high`` (both ends excluded)."""
    if not _real(value):
        raise SpinArgumentError(argument, value, "is not a number")
    number = float(value)  # type: ignore[arg-type]
    if not low < number < high:
        raise SpinArgumentError(argument, value, need)
    return number


@dataclass(frozen=True, slots=True)
class SpinPlan:
    """A spin's arguments, checked (`spin_plan` makes one).

    Attributes:
        nodes: The nodes to spin, each once, in the order given.
        throttle: The throttle fraction, -1..1.
        duration: Seconds to spin.
        rate: RawCommand per second.
        watchdog: Seconds after which the command stream zeroes a setpoint not refreshed.
        silence: Seconds without esc.Status or NodeStatus from a spun node that stop it.
        max_temperature: The temperature that stops it, °C (None: no limit).
        max_current: The current that stops it, A (None: no limit).
        allow_unknown: Nodes whose ``esc_index`` may be unreadable (``"all"``: any).
    """

    nodes: tuple[int, ...]
    throttle: float
    duration: float
    rate: float
    watchdog: float
    silence: float
    max_temperature: float | None
    max_current: float | None
    allow_unknown: tuple[int, ...] | Literal["all"]

    def start(self, survey: IndexSurvey, now: float) -> Spin:
        """The spin, starting at ``now``, when the ``survey`` of the bus allows it.

        Raises:
            EscIndexError: Spinning the nodes would turn another motor (`spin_indices`).
            ClientError: A node to spin whose ``esc_index`` cannot be read.
        """
        allow = list(survey.unread) if self.allow_unknown == "all" else self.allow_unknown
        return Spin(self, spin_indices(self.nodes, survey, allow), now)


def spin_plan(
    nodes: Iterable[int],
    throttle: float,
    duration: float,
    *,
    rate: float,
    watchdog: float,
    silence: float = DEFAULT_SILENCE,
    max_temperature: float | None = None,
    max_current: float | None = None,
    allow_unknown: AllowUnknown = (),
) -> SpinPlan:
    """Check a spin's arguments, in this order, before anything is sent.

    Raises:
        SpinArgumentError: A throttle outside -1..1, a duration, silence, rate or watchdog
            that is not a finite number above 0, or a limit that is not finite.
        InvalidRequestError: No node, or one that is no node id (1..127).

    Examples:
        >>> spin_plan([21, 22, 21], 0.5, 2, rate=50, watchdog=0.5).nodes
        (21, 22)
        >>> spin_plan([21], 1.5, 2, rate=50, watchdog=0.5)
        Traceback (most recent call last):
        ...
        veronte4x.client.spin.SpinArgumentError: throttle 1.5 is outside -1..1
    """
    if not _real(throttle):
        raise SpinArgumentError("throttle", throttle, "is not a number")
    if not -1.0 <= throttle <= 1.0:
        raise SpinArgumentError("throttle", throttle, "is outside -1..1")
    seconds = _check(
        "duration", duration, 0, math.inf, "must be a finite number of seconds above 0"
    )
    above = {
        name: _check(name, value, 0, math.inf, "must be above 0")
        for name, value in (("silence", silence), ("rate", rate), ("watchdog", watchdog))
    }
    limits = [
        None if value is None else _check(name, value, -math.inf, math.inf, "must be finite")
        for name, value in (("max_temperature", max_temperature), ("max_current", max_current))
    ]
    ids: list[int] = []
    for node in nodes:
        if not isinstance(node, int) or isinstance(node, bool) or not 1 <= node <= 127:
            raise InvalidRequestError(f"{node!r} is no node id (1..127); nothing was sent")
        if node not in ids:
            ids.append(node)
    if not ids:
        raise InvalidRequestError("a spin needs the nodes named: none was given")
    allowed = allow_unknown if allow_unknown == "all" else tuple(allow_unknown)
    return SpinPlan(
        tuple(ids),
        float(throttle),
        seconds,
        above["rate"],
        above["watchdog"],
        above["silence"],
        limits[0],
        limits[1],
        allowed,
    )


@dataclass(frozen=True, slots=True)
class SpunNode:
    """What one node did during a spin.

    Attributes:
        node_id: The node.
        esc_index: Its ``esc_index``: the RawCommand entry that drove it.
        peak_rpm: The esc.Status rpm farthest from zero it reported (None: none came).
        telemetry: The esc.Status it reported.
    """

    node_id: int
    esc_index: int
    peak_rpm: int | None
    telemetry: int


@dataclass(frozen=True, slots=True)
class SpinResult:
    """A spin that ended, every motor at zero throttle.

    Attributes:
        throttle: The throttle fraction it ran at.
        duration: The seconds it was asked to run.
        nodes: What each node did, in the order given.
    """

    throttle: float
    duration: float
    nodes: tuple[SpunNode, ...]


class Spin:
    """One spin under way: the setpoint to keep sending, the telemetry, when to stop.

    The client refreshes its command stream with `setpoint` while `going` says so, and
    gives `observe` the events of each wait on the bus with the time; once the stream has
    stopped, `result` says what happened.

    Args:
        plan: The spin's arguments.
        escs: Each node's ``esc_index`` (`spin_indices`).
        now: When it starts.

    Examples:
        >>> plan = spin_plan([21], 0.25, 1.0, rate=50, watchdog=0.5)
        >>> spin = plan.start(IndexSurvey({21: 3}, {}), now=10.0)
        >>> spin.setpoint
        {3: 0.25}
        >>> spin.going(10.5), spin.going(11.0)
        (True, False)
        >>> spin.result().nodes
        (SpunNode(node_id=21, esc_index=3, peak_rpm=None, telemetry=0),)
    """

    def __init__(self, plan: SpinPlan, escs: Mapping[int, int], now: float) -> None:
        self.plan = plan
        self.escs = dict(escs)
        self.setpoint = {index: plan.throttle for index in escs.values()}
        """The throttle by ESC index to send."""
        self.monitor = SpinMonitor(
            plan.nodes,
            now,
            silence=plan.silence,
            max_temperature=plan.max_temperature,
            max_current=plan.max_current,
        )
        self.end = now + plan.duration
        self.reason: str | None = None
        """Why it stops before its end, or None."""
        self._rpm: dict[int, list[int]] = {node: [] for node in plan.nodes}

    def going(self, now: float) -> bool:
        """Whether to keep sending the setpoint at ``now``."""
        return self.reason is None and now < self.end

    def observe(self, events: Iterable[Event], now: float) -> None:
        """Take the events of a wait on the bus, then check the limits at ``now``."""
        for event in events:
            if isinstance(event, Received):
                transfer = event.transfer
                self.monitor.observe(transfer)
                node = transfer.source_node_id
                if isinstance(transfer.message, EscStatus) and node in self._rpm:
                    self._rpm[node].append(transfer.message.rpm)
        self.reason = self.monitor.check(now)

    def result(self) -> SpinResult:
        """What the spin did.

        Raises:
            SpinStoppedError: It stopped before its end (with what it did until then).
        """
        result = SpinResult(
            self.plan.throttle,
            self.plan.duration,
            tuple(
                SpunNode(node, self.escs[node], max(rpm, key=abs, default=None), len(rpm))
                for node, rpm in self._rpm.items()
            ),
        )
        if self.reason is not None:
            raise SpinStoppedError(self.reason, self.monitor.over_limit, result)
        return result
