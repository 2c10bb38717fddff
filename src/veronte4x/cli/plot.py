"""``veronte4x plot``: a capture's arbitration timeline or ESC telemetry, to a PNG or a window."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Any

from veronte4x.capture.busmap import BusMap
from veronte4x.cli.exit_codes import EXIT_OK, EXIT_USAGE
from veronte4x.cli.notices import InputWatch, channel_hint
from veronte4x.cli.options import add_capture_options, add_renamed_option, open_records
from veronte4x.errors import SourceError
from veronte4x.extras import require


def add_parser(commands: Any) -> None:
    """Register the command."""
    parser = commands.add_parser(
        "plot", help="plot a capture: arbitration timeline or ESC telemetry (PNG or window)"
    )
    parser.add_argument("file", help="capture file, or - for stdin")
    parser.add_argument(
        "--kind",
        choices=["arbitration", "esc"],
        default="arbitration",
        help="arbitration: scores, selection, dead and maintenance periods (default); "
        "esc: speed, current, voltage and temperatures of each DroneCAN ESC",
    )
    parser.add_argument(
        "--output",
        metavar="FILE",
        help="write an image (.png, .svg, .pdf...; no suffix: .png) instead of a window",
    )
    add_capture_options(parser)
    add_renamed_option(parser, "--channel", "--only-channel")
    parser.set_defaults(run=run, interface=None, can_config=None)


def run(args: argparse.Namespace, bus_map: BusMap) -> int:
    """Draw the figure and save or show it; with nothing to draw, say so and draw nothing."""
    matplotlib = require("matplotlib", "plot", "veronte4x plot")
    output = _output_path(args.output, matplotlib) if args.output else None
    if output:
        matplotlib.use("Agg")
    watch = InputWatch(args.file)
    records = watch.records(open_records(args, bus_map))
    name = "standard input" if args.file == "-" else args.file
    if args.kind == "esc":
        from veronte4x.capture.esc_plot import draw_esc_telemetry, esc_series

        nodes = esc_series(records)
        if not nodes:
            return _nothing(
                watch, name, "no ESC status or temperature of a DroneCAN node", args.only_channel
            )
        figure = draw_esc_telemetry(nodes)
    else:
        from veronte4x.capture.plot import draw_timeline, timeline

        data = timeline(records)
        if data.empty:
            return _nothing(
                watch, name, "no Score or Status frame of the arbiter", args.only_channel
            )
        figure = draw_timeline(data)
    if output:
        figure.savefig(output)
        print(f"veronte4x: wrote {output}", file=sys.stderr)
        return EXIT_OK
    import matplotlib.pyplot as plt
    from matplotlib.backends.registry import BackendFilter, backend_registry

    batch = backend_registry.list_builtin(BackendFilter.NON_INTERACTIVE)  # type: ignore[no-untyped-call]
    if plt.get_backend().lower() in batch:
        print("veronte4x: no display for a window; give --output FILE.png", file=sys.stderr)
        return EXIT_USAGE
    plt.figure(figure)
    plt.show()
    return EXIT_OK


def _output_path(name: str, matplotlib: Any) -> str:
    """The file ``--output`` writes: ``name``, or ``name.png`` with no suffix (matplotlib's
    ``savefig.format``), checked before any frame is read.

    Raises:
        SourceError: A suffix matplotlib writes no image as, or a directory that is not there.
    """
    from matplotlib.backend_bases import FigureCanvasBase

    path = Path(name)
    kind = path.suffix.removeprefix(".").lower()
    if not kind:
        path = path.with_name(f"{path.name}.{matplotlib.rcParams['savefig.format']}")
    elif kind not in FigureCanvasBase.get_supported_filetypes():
        known = ", ".join(f".{k}" for k in sorted(FigureCanvasBase.get_supported_filetypes()))
        raise SourceError(
            f"--output {name}: matplotlib writes no .{kind} image; give one of {known}"
        )
    if not path.parent.is_dir():
        raise SourceError(f"--output {name}: no directory {path.parent}")
    return str(path)


def _nothing(watch: InputWatch, name: str, what: str, channel: str | None) -> int:
    """Say there is nothing to plot, and why; return the exit code."""
    hint = channel_hint(watch.path, channel, watch.frames)
    if hint is not None:
        reason = hint
    elif not watch.frames:
        reason = f"{name} holds no CAN frame"
    else:
        other = "arbitration" if what.startswith("no ESC") else "esc"
        reason = f"{name} has {what}; try --kind {other}, or another --only-channel"
    print(f"veronte4x: nothing to plot: {reason}", file=sys.stderr)
    return EXIT_USAGE
