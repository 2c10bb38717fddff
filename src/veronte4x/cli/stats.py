"""``veronte4x stats``: counts per message type, sender and error kind."""

from __future__ import annotations

import argparse
from typing import Any

from veronte4x import capture
from veronte4x.capture.busmap import BusMap
from veronte4x.capture.readers.live import BusLoss
from veronte4x.cli import rates
from veronte4x.cli.exit_codes import EXIT_OK
from veronte4x.cli.notices import InputWatch, channel_hint, tell
from veronte4x.cli.options import add_capture_options, add_live_options, live, open_records


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
    watch = InputWatch(None if live(args) else args.file)
    tracker = rates.tracker(args, bus_map)
    loss = BusLoss()
    if tracker is None:
        records = open_records(args, bus_map, loss=loss)
    else:
        records = rates.records(args, bus_map, tracker, loss=loss)
    print(capture.stats(watch.records(records)).report())
    if tracker is not None:
        print(rates.report(tracker))
    hint = channel_hint(watch.path, args.only_channel, watch.frames)
    for note in (loss.text(), watch.note(), hint):
        if note:
            tell(note)
    return EXIT_OK
