"""Which node reads which RawCommand entry: every node's ``esc_index`` (sans-IO).

RawCommand addresses ESCs by index, not by node (DSDL ``uavcan.equipment.esc.RawCommand``):
every node whose ``esc_index`` is N turns with entry N. A tool that spins one motor, or gives
a node an index, must therefore know the index of every node on the bus. `survey` listens
for NodeStatus and reads each node's ``esc_index``; `check_changes` refuses an index that
another node holds, or may hold because its index cannot be read.

Examples:
    >>> survey = IndexSurvey({21: 0, 22: 1}, {})
    >>> check_changes({23: 1}, survey)
    Traceback (most recent call last):
    ...
    veronte4x.client.indices.EscIndexError: node 22 has esc_index 1 already: giving it to \
node 23 too would make RawCommand turn both; nothing was sent
"""

from __future__ import annotations

from collections.abc import Collection, Mapping, Sequence
from dataclasses import dataclass

from veronte4x.client.errors import ClientError, InvalidRequestError, NodeIdConflictError
from veronte4x.client.operations import Operation, discover, get_param
from veronte4x.client.params import plain
from veronte4x.client.protocol import ClientProtocol
from veronte4x.dronecan import vertiq
from veronte4x.dronecan.messages import IntegerValue

SURVEY = 2.1
"""Seconds `survey` listens for NodeStatus: two broadcast periods (DSDL NodeStatus
``MAX_BROADCASTING_PERIOD_MS``, 1 s), so that a node whose one NodeStatus was lost or late is
still heard."""

ESC_INDEX = vertiq.Parameter.ESC_INDEX.value
"""The parameter that says which RawCommand entry a Vertiq ESC reads."""


class EscIndexError(InvalidRequestError):
    """An ``esc_index`` that would be shared, or that cannot be known: refused before any
    command or set is sent.

    Attributes:
        problems: One clause per node or index at fault.
        unread: The nodes whose ``esc_index`` could not be read (a tool may accept them
            explicitly).
        shared: Whether an index would be shared (rather than only unknown).
        own: Whether a node of ``unread`` uses this tool's own node id (`OwnNodeIdError`).
    """

    def __init__(
        self, problems: Sequence[str], unread: Sequence[int], shared: bool, own: bool = False
    ) -> None:
        self.problems = tuple(problems)
        self.unread = tuple(unread)
        self.shared = shared
        self.own = own
        super().__init__(self.line())

    def line(self, *advice: str) -> str:
        """The problems and ``advice`` in one line, ending with ``nothing was sent``."""
        return "; ".join([*self.problems, *advice, "nothing was sent"])


@dataclass(frozen=True, slots=True)
class IndexSurvey:
    """Every node's ``esc_index`` as read, or why it could not be read.

    Attributes:
        indices: The ``esc_index`` of each node that reported one.
        unread: The error of each node whose ``esc_index`` could not be read (no answer, no
            such parameter, not a whole number, or this tool's own node id).
    """

    indices: Mapping[int, int]
    unread: Mapping[int, ClientError]

    def nodes(self) -> list[int]:
        """Every node surveyed, by id."""
        return sorted({*self.indices, *self.unread})

    def own_id(self, nodes: Collection[int]) -> bool:
        """Whether one of ``nodes`` was not asked because it uses the tool's own node id."""
        return any(isinstance(self.unread.get(n), OwnNodeIdError) for n in nodes)


class OwnNodeIdError(InvalidRequestError):
    """A node on the bus uses this tool's node id: nothing it sends can be told from this
    tool's own frames echoed back, so it is not asked anything."""

    def __init__(self, node_id: int) -> None:
        super().__init__(
            f"node {node_id} uses this tool's own node id, so nothing it sends can be told "
            "from this tool's own frames"
        )


def read_esc_index(node_id: int) -> Operation[int]:
    """A node's ``esc_index``.

    Raises:
        InvalidRequestError: The node reports a value that is not a whole number.
        ParameterError: The node has no ``esc_index``.
        NoResponseError: It did not answer.
    """
    parameter = yield from get_param(node_id, ESC_INDEX)
    if not isinstance(parameter.value, IntegerValue):
        raise InvalidRequestError(
            f"node {node_id} reports esc_index {plain(parameter.value)!r}, not a number"
        )
    return parameter.value.value


def survey(
    protocol: ClientProtocol, also: Collection[int] = (), duration: float = SURVEY
) -> Operation[IndexSurvey]:
    """Listen for NodeStatus for ``duration`` seconds, then read the ``esc_index`` of every
    node heard and of those in ``also`` (heard or not), one after another.

    A node that uses ``protocol``'s own node id is not asked (`OwnNodeIdError`).

    Raises:
        NodeIdConflictError: Another tool sends with ``protocol``'s node id.
    """
    heard = yield from discover(protocol, duration)
    indices: dict[int, int] = {}
    unread: dict[int, ClientError] = {}
    for node in sorted({*(e.node_id for e in heard), *also}):
        if node == protocol.node_id:
            unread[node] = OwnNodeIdError(node)
            continue
        try:
            indices[node] = yield from read_esc_index(node)
        except NodeIdConflictError:
            raise  # no node's answer can be trusted: not one node's problem
        except ClientError as error:
            unread[node] = error
    return IndexSurvey(indices, unread)


def nodes_text(nodes: Sequence[int]) -> str:
    """``node 21``, ``nodes 21 and 22``, ``nodes 21, 22 and 23``."""
    ids = [str(n) for n in nodes]
    if len(ids) == 1:
        return f"node {ids[0]}"
    return f"nodes {', '.join(ids[:-1])} and {ids[-1]}"


def reason(node_id: int, error: ClientError) -> str:
    """Why a node's ``esc_index`` could not be read, without the error's leading node."""
    return str(error).removeprefix(f"node {node_id} ")


def check_changes(
    changes: Mapping[int, int],
    survey: IndexSurvey,
    *,
    allow_shared: bool = False,
    allow_unknown: Collection[int] = (),
) -> None:
    """Refuse giving nodes the ``esc_index`` of ``changes`` when another node holds it (or a
    node changed alongside is given it too), unless ``allow_shared``; and when a node other
    than those changed has an ``esc_index`` that cannot be read, unless it is in
    ``allow_unknown``.

    Raises:
        EscIndexError: Every problem found, in one line.
    """
    final = {**survey.indices, **changes}
    problems: list[str] = []
    shared = False
    if not allow_shared:
        for index in sorted(set(changes.values())):
            given = sorted(n for n, i in changes.items() if i == index)
            holders = sorted(n for n, i in final.items() if i == index and n not in changes)
            if len(given) + len(holders) < 2:
                continue
            shared = True
            turn = "both" if len(given) + len(holders) == 2 else "them all"
            if holders:
                has = "has" if len(holders) == 1 else "have"
                problems.append(
                    f"{nodes_text(holders)} {has} esc_index {index} already: giving it to "
                    f"{nodes_text(given)} too would make RawCommand turn {turn}"
                )
            else:
                problems.append(
                    f"giving esc_index {index} to {nodes_text(given)} would make RawCommand "
                    f"turn {turn}"
                )
    unread = [n for n in survey.unread if n not in changes and n not in allow_unknown]
    for node in unread:
        problems.append(
            f"node {node}'s esc_index cannot be read, so it may hold the same one "
            f"({reason(node, survey.unread[node])})"
        )
    if problems:
        raise EscIndexError(problems, unread, shared, survey.own_id(unread))
