"""``veronte4x export dbc``: the Veronte frames of a bus map as a DBC file."""

from __future__ import annotations

import argparse
import sys
from typing import Any

from veronte4x.capture.busmap import BusMap
from veronte4x.capture.dbc import export_dbc
from veronte4x.cli.exit_codes import EXIT_OK


def add_parser(commands: Any) -> None:
    """Register the command."""
    parser = commands.add_parser(
        "export", help="write the bus map's Veronte frames for other tools (DBC)"
    )
    parser.add_argument("format", choices=["dbc"], help="what to write: dbc")
    parser.add_argument("--bus-map", metavar="FILE", help="TOML file of CAN IDs and choices")
    parser.add_argument(
        "-o", "--output", metavar="FILE", help="file to write (default: standard output)"
    )
    parser.set_defaults(run=run)


def run(args: argparse.Namespace, bus_map: BusMap) -> int:
    """Write the DBC text."""
    text = export_dbc(bus_map)
    if args.output is None:
        sys.stdout.write(text)
    else:
        with open(args.output, "w", encoding="ascii", newline="\n") as file:
            file.write(text)
    return EXIT_OK
