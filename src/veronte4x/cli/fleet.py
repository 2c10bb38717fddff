"""Node lists for ``veronte4x esc`` (``21``, ``21,22``, ``21-28``, ``all``) and one action
run on many nodes at once, with one summary line per node and a total."""

from __future__ import annotations

import argparse
import json
import sys
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from veronte4x.cli.exit_codes import EXIT_NO_ANSWER, EXIT_OK, EXIT_REFUSED, EXIT_USAGE
from veronte4x.client.errors import (
    ClientError,
    FirmwareUpdateFailedError,
    InvalidRequestError,
    NoResponseError,
)
from veronte4x.client.indices import OwnNodeIdError
from veronte4x.client.operations import Operation
from veronte4x.errors import EncodeError
from veronte4x.words import counted

if TYPE_CHECKING:
    from veronte4x.client.bus import BusClient

DISCOVERY = 1.1
"""Seconds ``all`` listens for NodeStatus: every node sends one at least once a second."""


@dataclass(frozen=True, slots=True)
class NodeList:
    """Nodes named on the command line.

    Attributes:
        ids: The node ids, in the order given, each once (empty for ``all``).
        every: ``all``: every node that answers discovery.
        single: One node id, given alone: the output is that of a single node.
    """

    ids: tuple[int, ...]
    every: bool = False
    single: bool = False


def node_list(text: str) -> NodeList:
    """``21``, ``21,22``, ``21-28``, ``21-24,30`` or ``all`` (an argparse type).

    Raises:
        argparse.ArgumentTypeError: Not a node list, or a node id outside 1..127.
    """
    if text.strip().lower() == "all":
        return NodeList((), every=True)
    ids: list[int] = []
    for part in text.split(","):
        first, dash, last = part.strip().partition("-")
        try:
            low = int(first)
            high = int(last) if dash else low
        except ValueError:
            raise argparse.ArgumentTypeError(
                f"{text!r} is not a node list: give ids and ranges such as 21,22 or 21-28, or all"
            ) from None
        for value in (low, high):
            if not 1 <= value <= 127:
                raise argparse.ArgumentTypeError(f"node id {value} is out of range: 1..127")
        if high < low:
            raise argparse.ArgumentTypeError(f"{part.strip()!r}: a range goes up, e.g. 21-28")
        ids += [n for n in range(low, high + 1) if n not in ids]
    return NodeList(tuple(ids), single=text.strip().isdigit())


def resolve(client: BusClient, nodes: NodeList) -> list[int]:
    """The node ids to act on: those given, or for ``all`` those heard in `DISCOVERY` s.

    Raises:
        NoNodeError: ``all`` heard no node.
        InvalidRequestError: ``all`` heard a node that uses this tool's node id.
    """
    if not nodes.every:
        return list(nodes.ids)
    found = [e.node_id for e in client.discover(DISCOVERY)]
    if not found:
        raise NoNodeError(DISCOVERY)
    if client.protocol.node_id in found:
        raise InvalidRequestError(
            f"{OwnNodeIdError(client.protocol.node_id)}; {OWN_ID_ADVICE}; nothing was sent"
        )
    return found


OWN_ID_ADVICE = "give this tool another --node-id, one that esc nodes does not list"
"""What to do when a node uses the tool's node id."""


class NoNodeError(ClientError):
    """``all`` heard no node on the bus."""

    def __init__(self, seconds: float) -> None:
        super().__init__(
            f"no node on the bus within {seconds:g} s; check --interface, --channel and --bitrate"
        )


def exit_code(error: Exception) -> int:
    """The documented exit code of a failed node or request.

    Raises:
        Exception: ``error`` itself when it is none of the client's.
    """
    if isinstance(error, (NoResponseError, NoNodeError)):
        return EXIT_NO_ANSWER
    if isinstance(error, FirmwareUpdateFailedError):
        return EXIT_NO_ANSWER if error.timed_out else EXIT_REFUSED
    if isinstance(error, (InvalidRequestError, EncodeError)):
        return EXIT_USAGE
    if isinstance(error, ClientError):
        return EXIT_REFUSED
    raise error


def each(
    client: BusClient,
    args: argparse.Namespace,
    make: Callable[[int], Operation[Any]],
    text: Callable[[int, Any], str],
    data: Callable[[int, Any], Any],
    nodes: list[int] | None = None,
) -> int:
    """Run ``make(node)`` on every node of ``args.nodes`` (or of ``nodes``, resolved
    already) at once; print per node and a total.

    One node given alone prints ``text`` (or ``data`` as JSON) and lets its error reach the
    caller. Several print ``text`` per node that succeeded and ``node N: error`` per node
    that failed, then a total line; ``--json`` prints ``{"nodes": [...], "total": ...}``.

    Returns:
        0 when every node succeeded, else the exit code of the first node that failed.
    """
    if nodes is None:
        nodes = resolve(client, args.nodes)
    if args.nodes.single:
        result = client.run(make(nodes[0]))
        if args.json:
            print(json.dumps(data(nodes[0], result)))
        else:
            print(text(nodes[0], result))
        return EXIT_OK
    tasks = client.run_all([make(node) for node in nodes])
    rows = []
    code = EXIT_OK
    for node, task in zip(nodes, tasks, strict=True):
        if task.error is None:
            rows.append({"node_id": node, "ok": True, **data(node, task.result())})
            if not args.json:
                print(text(node, task.result()))
        else:
            failed = exit_code(task.error)
            code = code or failed
            rows.append({"node_id": node, "ok": False, "error": str(task.error)})
            if not args.json:
                print(f"node {node}: failed: {error_text(node, task.error)}")
    failed_ids = [row["node_id"] for row in rows if not row["ok"]]
    if args.json:
        print(json.dumps({"nodes": rows, "total": len(rows), "failed": failed_ids}))
    else:
        print(total(len(rows), failed_ids))
    if failed_ids:
        print(f"veronte4x: {total(len(rows), failed_ids)}", file=sys.stderr)
    return code


def error_text(node: int, error: BaseException) -> str:
    """What went wrong with ``node``, to follow ``node N:`` in a line: the error's text
    without its own leading ``node N`` (``stopped reading the image at byte 512 ...``)."""
    return str(error).removeprefix(f"node {node} ")


def total(count: int, failed: list[int]) -> str:
    """The total line: how many nodes, how many failed and which."""
    nodes = counted(count, "node")
    if not failed:
        return f"{nodes}: succeeded" if count == 1 else f"{nodes}: all succeeded"
    if count == 1:
        return f"{nodes}: failed ({failed[0]})"
    return (
        f"{nodes}: {count - len(failed)} succeeded, {len(failed)} failed "
        f"({', '.join(map(str, failed))})"
    )
