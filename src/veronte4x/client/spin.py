"""Which motors a spin may drive, and when to stop it: a node gone silent, or over a limit
(sans-IO).

RawCommand turns every node whose ``esc_index`` is commanded, so before anything is sent
`spin_indices` checks, from an `IndexSurvey` of the whole bus, that no node outside those
named shares a named node's index or has one that cannot be read. A tool that drives motors
then listens to the nodes it drives: a node that stops publishing esc.Status and NodeStatus
may have lost power, the bus or its firmware, and an ESC that reports too hot or too much
current is a rig to stop. `SpinMonitor` takes the transfers seen and the time, and says why
to stop; the tool then sends zero throttle to every ESC.
"""

from __future__ import annotations

import math
from collections.abc import Collection, Iterable, Sequence

from veronte4x.client.indices import EscIndexError, IndexSurvey, nodes_text, reason
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
        raise EscIndexError(problems, unread, shared)
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
