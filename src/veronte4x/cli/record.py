"""``veronte4x record``: a live bus's frames into a file, as pydronecan's ``fileout:`` driver
records them (`veronte4x.capture.readers.pydronecan`), which pydronecan's ``filein:`` plays,
or as ``candump -L`` text (`veronte4x.capture.readers.candump.log_line`), which can-utils,
python-can and SavvyCAN read; every command of veronte4x reads either."""

from __future__ import annotations

import argparse
import contextlib
import os
import sys
import threading
from collections.abc import Callable
from typing import Any

from veronte4x.capture.busmap import BusMap
from veronte4x.capture.frames import Frame
from veronte4x.capture.readers.candump import log_line
from veronte4x.capture.readers.live import BusLoss
from veronte4x.capture.readers.pydronecan import record
from veronte4x.cli.exit_codes import EXIT_OK
from veronte4x.cli.interrupts import Interrupts
from veronte4x.cli.options import UsageError, add_live_options, live, open_frame_source
from veronte4x.errors import SourceError
from veronte4x.words import counted


def _candump(frame: Frame) -> bytes:
    return (log_line(frame) + "\n").encode("ascii")


WRITERS: dict[str, Callable[[Frame], bytes]] = {"pydronecan": record, "candump": _candump}
"""What ``--to`` writes, and the bytes of one frame in it (`SourceError` for a frame the
format cannot hold)."""


def add_parser(commands: Any) -> None:
    """Register the command."""
    parser = commands.add_parser(
        "record",
        help="record a live bus's frames into a file (pydronecan's capture file or candump text)",
    )
    parser.add_argument(
        "--to",
        nargs=2,
        required=True,
        metavar=("FORMAT", "FILE"),
        help="pydronecan and a file (the frames as pydronecan's fileout: driver writes them) "
        "or candump and a file (candump -L text)",
    )
    parser.add_argument(
        "--count",
        type=_count,
        metavar="N",
        help="stop after N frames (default: at the end of --duration, or Ctrl-C)",
    )
    add_live_options(parser)
    parser.set_defaults(run=run, file=None, bus_map=None)


def _count(text: str) -> int:
    """A ``--count``: a whole number of frames, 1 or more."""
    try:
        count = int(text)
    except ValueError:
        count = 0
    if count < 1:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number of frames (1 or more)")
    return count


def run(args: argparse.Namespace, bus_map: BusMap) -> int:
    """Write the bus's frames into the file until ``--count``, ``--duration`` or Ctrl-C (each
    a normal end: exit code 0); the frames the format cannot hold (a pydronecan file's remote
    and error frames) are left out and counted."""
    format_, out = args.to
    if format_ not in WRITERS:
        raise UsageError(f"--to {format_}: record writes {' or '.join(WRITERS)}")
    write = WRITERS[format_]
    if not live(args):
        raise UsageError(
            "record reads a live bus: give --interface and --channel (e.g. --interface mcast "
            "--channel 0) or --can-config FILE"
        )
    loss = BusLoss()
    stop = threading.Event()
    written = left_out = 0
    existed = os.path.exists(out)
    # Appending until the bus is read: a file given by mistake keeps its bytes if the bus
    # cannot be opened; from the first frame (or a normal end) it holds this recording only.
    with open(out, "ab") as file:
        try:
            with Interrupts() as interrupts:
                for frame in open_frame_source(args, stop, loss):
                    if type(frame) is not Frame:
                        left_out += 1
                        continue
                    with interrupts.whole:  # a record is in the file whole, or not at all
                        try:
                            data = write(frame)
                        except SourceError:
                            left_out += 1
                            continue
                        if not written:
                            file.truncate(0)
                        file.write(data)
                        file.flush()
                        written += 1
                    if written == args.count:
                        stop.set()  # the bus is closed as the reading ends
        except KeyboardInterrupt:  # the way to stop a recording: as the bus reader takes it
            pass
        except Exception:
            if not written and not existed:  # the bus failed at once: no empty file
                file.close()
                with contextlib.suppress(OSError):
                    os.remove(out)
            raise
        if not written:
            file.truncate(0)
    summary = f"{counted(written, 'frame')} in {out}"
    if left_out:
        summary += f", {left_out} left out that {format_} cannot hold"
    if lost := loss.text():
        summary += f", {lost}"
    print(f"veronte4x: {summary}", file=sys.stderr)
    return EXIT_OK
