"""``veronte4x replay``: the arbiter model over a capture, its decisions and disagreements."""

from __future__ import annotations

import argparse
import sys
from typing import Any

from veronte4x.capture.busmap import BusMap
from veronte4x.capture.frames import Frame
from veronte4x.cli.exit_codes import EXIT_OK
from veronte4x.cli.options import add_capture_options, add_live_options, open_frame_source


def add_parser(commands: Any) -> None:
    """Register the command."""
    parser = commands.add_parser(
        "replay", help="run the arbiter model on a capture; explain switches and disagreements"
    )
    parser.add_argument("file", nargs="?", help="capture file, or - for stdin")
    parser.add_argument("--config", metavar="FILE", help="TOML arbiter configuration")
    add_capture_options(parser)
    add_live_options(parser)
    parser.set_defaults(run=run)


def run(args: argparse.Namespace, bus_map: BusMap) -> int:
    """Replay the capture through the arbiter model and print its timeline."""
    from veronte4x import arbiter
    from veronte4x.arbiter.config_file import load_config

    if args.config:
        config = load_config(args.config)
    else:
        config = arbiter.ArbiterConfig(
            autopilot_ids=bus_map.autopilot_ids,
            arbiter_id=bus_map.arbiter_id,
            extended_ids=bus_map.extended,
        )
    frames = (
        (frame.timestamp, frame.can_id, frame.data)
        for frame in open_frame_source(args)
        if isinstance(frame, Frame)
        and frame.timestamp is not None
        and not (frame.error or frame.remote or frame.fd)
        and frame.extended == config.extended_ids
    )
    result = arbiter.replay(frames, config)
    print(result.timeline())
    print(
        f"veronte4x: {len(result.decisions)} decisions, {len(result.disagreements)} "
        f"disagreements, {len(result.errors)} bad frames",
        file=sys.stderr,
    )
    return EXIT_OK
