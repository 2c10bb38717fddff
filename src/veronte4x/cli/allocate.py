"""``veronte4x esc allocate``: a dynamic node ID allocation server on a live bus.

The centralized allocator of `veronte4x.client.allocator`, its table in the JSON Lines file
the user names (`veronte4x.client.allocation_table`). Each allocation and each node
recorded is a line on standard output (a JSON object with ``--json``); what the server
refuses is one line on standard error. It serves until Ctrl-C (exit code 130) or for
``--duration`` seconds: then 0, or 1 if it refused something.
"""

from __future__ import annotations

import argparse
import json
import sys
from typing import TYPE_CHECKING, Any

from veronte4x.cli.exit_codes import EXIT_FINDINGS, EXIT_OK
from veronte4x.client import allocation_table
from veronte4x.client.allocation_table import MOCK
from veronte4x.client.allocator import (
    Allocated,
    AllocationConflict,
    AllocationEvent,
    NodeRecorded,
)
from veronte4x.words import counted

if TYPE_CHECKING:
    from veronte4x.client.bus import BusClient

HELP = "serve dynamic node ID allocations (DroneCAN), the table kept in a file"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """The action's own arguments (the bus and node options are ``esc``'s)."""
    parser.add_argument(
        "table",
        metavar="TABLE",
        help="the allocation table, a JSON Lines file (created if missing, rewritten whole "
        "at every change): unique ids and their node ids",
    )
    parser.add_argument(
        "--duration", type=float, metavar="S", help="stop after S seconds (default: Ctrl-C)"
    )


def _plain(event: AllocationEvent) -> dict[str, Any]:
    """An event as a JSON object."""
    if isinstance(event, Allocated):
        return {
            "event": "allocated",
            "node_id": event.node_id,
            "unique_id": event.unique_id.hex(),
            "preferred_node_id": event.preferred_node_id or None,
            "again": event.again,
        }
    if isinstance(event, NodeRecorded):
        return {
            "event": "recorded",
            "node_id": event.node_id,
            "unique_id": None if event.unique_id == MOCK else event.unique_id.hex(),
        }
    return {
        "event": "refused",
        "message": event.message,
        "node_id": event.node_id,
        "unique_id": None if event.unique_id is None else event.unique_id.hex(),
    }


def _text(event: Allocated | NodeRecorded) -> str:
    if isinstance(event, Allocated):
        wanted = event.preferred_node_id or "any"
        how = "again, as the table has it" if event.again else f"preferred: {wanted}"
        return f"node {event.node_id} allocated to unique id {event.unique_id.hex()} ({how})"
    if event.unique_id == MOCK:
        return (
            f"node {event.node_id} recorded without a unique id: it did not answer GetNodeInfo "
            "(the specification's mock entry keeps its node id taken)"
        )
    return f"node {event.node_id} recorded: unique id {event.unique_id.hex()} (seen on the bus)"


def run(client: BusClient, args: argparse.Namespace) -> int:
    """Serve until Ctrl-C or the duration; 1 if something was refused, else 0."""
    refused = 0

    def show(event: AllocationEvent) -> None:
        nonlocal refused
        if isinstance(event, AllocationConflict):
            refused += 1
            print(f"veronte4x: {event.message}", file=sys.stderr)
        if args.json:
            print(json.dumps(_plain(event)), flush=True)
        elif not isinstance(event, AllocationConflict):
            print(_text(event), flush=True)

    allocation_table.check_storable(args.table)  # one line before anything is sent
    entries = len(allocation_table.load(args.table))  # a bad table: one line, nothing sent
    print(
        f"veronte4x: allocation server at node {client.node_id}, table {args.table} "
        f"({counted(entries, 'entry', 'entries')}); "
        + ("Ctrl-C stops" if args.duration is None else f"for {args.duration:g} s"),
        file=sys.stderr,
        flush=True,
    )
    client.serve_allocations(args.table, duration=args.duration, on_event=show)
    return EXIT_FINDINGS if refused else EXIT_OK
