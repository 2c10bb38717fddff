"""Options that every command reading a capture shares."""

from __future__ import annotations

import argparse


def add_capture_options(parser: argparse.ArgumentParser) -> None:
    """The capture argument's companions: the bus map and the channel filter."""
    parser.add_argument("--bus-map", metavar="FILE", help="TOML file of CAN IDs and choices")
    parser.add_argument("--channel", help="keep only this interface's frames")
