"""``veronte4x stats``: counts per message type, sender and error kind."""

from __future__ import annotations

import argparse
from typing import Any

from veronte4x import capture
from veronte4x.capture.busmap import BusMap
from veronte4x.cli import rates
from veronte4x.cli.exit_codes import EXIT_OK
from veronte4x.cli.notices import tell_truncation
from veronte4x.cli.options import add_capture_options, add_live_options, open_records


def add_parser(commands: Any) -> None:
    """Register the command."""
    parser = commands.add_parser("stats", help="count frames and transfers per type and sender")
    parser.add_argument("file", nargs="?", help="capture file, or - for stdin")
    add_capture_options(parser)
    add_live_options(parser)
    rates.add_options(parser)
    parser.set_defaults(run=run)


def run(args: argparse.Namespace, bus_map: BusMap) -> int:
    """Print the counts of the capture."""
    tracker = rates.tracker(args, bus_map)
    if tracker is None:
        records = tell_truncation(open_records(args, bus_map))
    else:
        records = tell_truncation(rates.records(args, bus_map, tracker))
    print(capture.stats(records).report())
    if tracker is not None:
        print(rates.report(tracker))
    return EXIT_OK
