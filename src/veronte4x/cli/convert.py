"""``veronte4x convert``: captures into a Parquet dataset, on this machine or a Dask cluster."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Any

from veronte4x import capture
from veronte4x.capture.busmap import TEXT_FORMS, BusMap
from veronte4x.cli import aligned, pydronecan_out
from veronte4x.cli.exit_codes import EXIT_OK, EXIT_USAGE
from veronte4x.cli.notices import tell
from veronte4x.cli.options import add_capture_options, add_renamed_option
from veronte4x.errors import SourceError
from veronte4x.extras import require
from veronte4x.times import TIME_FORMS

FORMATS = ("parquet", "csv", "pydronecan")
"""What ``--to`` writes."""


def add_parser(commands: Any) -> None:
    """Register the command."""
    parser = commands.add_parser(
        "convert",
        help="convert captures into a Parquet dataset: one directory per capture, a file per "
        "message type in it",
    )
    parser.add_argument("files", nargs="+", metavar="IN", help="capture files")
    parser.add_argument(
        "--to",
        nargs=2,
        required=True,
        metavar=("FORMAT", "OUT_DIR"),
        help="the format and where: parquet and the dataset's directory, csv and a file "
        "(with --every or --on), or pydronecan and a file (the frames, as pydronecan's "
        "fileout: driver writes them)",
    )
    parser.add_argument(
        "--scheduler",
        metavar="ADDRESS",
        help="convert on the workers of this Dask scheduler (tcp://host:8786; "
        "needs veronte4x[dask]); OUT_DIR must be a directory every worker sees",
    )
    parser.add_argument(
        "--time",
        choices=TIME_FORMS,
        default="timestamp",
        help="the time column: timestamp (UTC to the microsecond, the default; ISO 8601 in "
        "a CSV), relative (seconds from the first frame) or seconds (as logged)",
    )
    parser.add_argument(
        "--text",
        choices=TEXT_FORMS,
        help="DroneCAN text fields (names, paths, log text): string (bytes that are not "
        "UTF-8 give a null and a 'bad text' error row holding them) or binary (every uint8 "
        "array as its exact bytes); default: the bus map's text, string unless it says",
    )
    add_capture_options(parser)
    add_renamed_option(parser, "--channel", "--only-channel")
    aligned.add_options(parser)
    parser.set_defaults(run=run)


def run(args: argparse.Namespace, bus_map: BusMap) -> int:
    """Convert the captures; progress and a one-line summary go to standard error."""
    format_, out_dir = args.to
    bus_map = bus_map.with_text(args.text)
    if format_ not in FORMATS:
        print(
            f"veronte4x: cannot convert to {format_!r}: the formats are {', '.join(FORMATS)}",
            file=sys.stderr,
        )
        return EXIT_USAGE
    if format_ in ("csv", "pydronecan") and not Path(out_dir).resolve().parent.is_dir():
        # before any capture is read: the file is written last (a temporary file beside it)
        parent = Path(out_dir).parent
        raise SourceError(f"--to {format_} {out_dir}: no directory {parent}; create it first")
    if format_ == "csv":
        return aligned.run_csv(args, bus_map, out_dir)
    if format_ == "pydronecan":
        return pydronecan_out.run(args, out_dir)
    client = None
    if args.scheduler:
        distributed = require("distributed", "dask", "--scheduler")
        client = distributed.Client(args.scheduler, timeout="10s")
    try:
        summary = capture.to_parquet(
            args.files,
            out_dir,
            bus_map,
            client,
            None,
            args.only_channel,
            dbc=args.dbc,
            time=args.time,
        )
    finally:
        if client is not None:
            client.close()
    for detail in summary.truncated:
        tell(detail)
    print(f"veronte4x: {summary.line()}, dataset in {out_dir}", file=sys.stderr)
    return EXIT_OK
