"""The ``veronte4x`` command line: a filter over captures, like cantools' ``decode``.

Data goes to standard output; summaries and errors go to standard error. Exit codes: 0 on
success (bad frames skipped or kept are not failures), 1 when ``--on-error raise`` met a bad
frame, 2 for a usage error or an input that cannot be opened (missing file, bad bus map).

Each command lives in its own module with an ``add_parser`` function that registers it.
"""

from __future__ import annotations

import argparse
import os
import sys
from collections.abc import Sequence

from veronte4x import __version__
from veronte4x.arbiter.errors import ConfigError
from veronte4x.capture.busmap import BusMap, BusMapError
from veronte4x.cli import decode, esc, monitor, plot, replay, simulate, stats
from veronte4x.cli import list as list_command
from veronte4x.cli.exit_codes import EXIT_OK, EXIT_USAGE

COMMANDS = (decode, stats, replay, monitor, plot, list_command, esc, simulate)
"""The command modules, in the order ``--help`` lists them."""


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; return its exit code."""
    parser = _parser()
    args = parser.parse_args(argv)
    try:
        bus_map = BusMap.from_toml(args.bus_map) if args.bus_map else BusMap()
        result: int = args.run(args, bus_map)
        return result
    except BrokenPipeError:
        # The reader (`| head`) is gone: stop quietly, and keep Python's exit-time flush
        # of standard output from failing again.
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return EXIT_OK
    except (OSError, BusMapError, ConfigError, ImportError) as error:
        print(f"veronte4x: {error}", file=sys.stderr)
        return EXIT_USAGE


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="veronte4x",
        description="Decode Veronte 4x and Vertiq DroneCAN traffic from CAN captures.",
    )
    parser.add_argument("--version", action="version", version=f"veronte4x {__version__}")
    commands = parser.add_subparsers(required=True, metavar="COMMAND")
    for command in COMMANDS:
        command.add_parser(commands)
    return parser
