"""``veronte4x convert --to csv FILE --every 10ms``: captures as one flat, time-aligned CSV."""

from __future__ import annotations

import argparse
import sys
from typing import Any

from veronte4x import capture
from veronte4x.capture.align import DIRECTIONS, AlignError, write_csv
from veronte4x.capture.busmap import BusMap
from veronte4x.cli.exit_codes import EXIT_OK, EXIT_USAGE
from veronte4x.errors import NotACaptureError
from veronte4x.words import counted


def add_options(parser: argparse.ArgumentParser) -> None:
    """The options of the CSV output (`veronte4x.capture.align`'s arguments)."""
    parser.add_argument(
        "--every",
        metavar="PERIOD",
        help="csv: one row per PERIOD (10ms, 0.5s, 250us), each stream's last value",
    )
    parser.add_argument(
        "--on", metavar="TABLE", help="csv: one row per time of this message type (EscStatus)"
    )
    parser.add_argument(
        "--tolerance",
        metavar="PERIOD",
        help="csv: leave a cell empty when its value is older than this (default: no limit)",
    )
    parser.add_argument(
        "--direction",
        choices=DIRECTIONS,
        default="backward",
        help="csv: take the row before (default), after or nearest each row's time",
    )


def run_csv(args: argparse.Namespace, bus_map: BusMap, out: str) -> int:
    """Decode the captures, align their tables and write the CSV."""
    if (args.every is None) == (args.on is None):
        return _usage("--to csv needs one of --every PERIOD (10ms) or --on TABLE")
    tables = capture.read_tables(args.files, bus_map, args.only_channel, args.time, dbc=args.dbc)
    _refuse_no_frame(tables, ", ".join(args.files))
    try:
        aligned = capture.align(
            tables, on=args.on, every=args.every, tolerance=args.tolerance, direction=args.direction
        )
    except AlignError as error:
        return _usage(str(error))
    columns = write_csv(aligned, out)
    rows = counted(aligned.num_rows, "row")
    print(f"veronte4x: {rows}, {counted(columns, 'column')}, in {out}", file=sys.stderr)
    return EXIT_OK


def _refuse_no_frame(tables: dict[str, Any], name: str) -> None:
    """Refuse captures whose lines are all bad, as every command does.

    Raises:
        NotACaptureError: Not one line of them is a CAN frame.
    """
    errors = tables.get("errors")
    if errors is None or any(t.num_rows for kind, t in tables.items() if kind != "errors"):
        return
    kinds = errors["error"].cast("string").to_pylist()
    bad = kinds.count("bad line")
    if bad and all(kind in ("bad line", "truncated") for kind in kinds):
        raise NotACaptureError(name, bad)


def _usage(message: str) -> int:
    print(f"veronte4x: {message}", file=sys.stderr)
    return EXIT_USAGE
