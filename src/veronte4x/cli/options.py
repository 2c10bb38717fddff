"""Options that commands share: the capture's, and the live bus's (python-can)."""

from __future__ import annotations

import argparse
import dataclasses
import sys
import threading
import warnings
from collections.abc import Callable, Iterator
from typing import TYPE_CHECKING, Any

from veronte4x import capture
from veronte4x.capture.busmap import BusMap
from veronte4x.capture.dbc_in import DbcWarning, decoder_of
from veronte4x.capture.decoder import CaptureDecoder
from veronte4x.capture.frames import BadLine, Frame
from veronte4x.capture.records import Record
from veronte4x.capture.source import open_frames
from veronte4x.errors import SourceError, Veronte4xError

if TYPE_CHECKING:
    from veronte4x.capture.readers.live import BusLoss


class UsageError(Veronte4xError, ValueError):
    """A command line the commands do not take, such as an old spelling; the message names
    the spelling to use."""


def add_capture_options(parser: argparse.ArgumentParser) -> None:
    """The capture argument's companions: the bus map and the channel filter."""
    parser.add_argument("--bus-map", metavar="FILE", help="TOML file of CAN IDs and choices")
    parser.add_argument(
        "--only-channel",
        metavar="CHANNEL",
        help="keep only the frames of this channel: a capture's interface name, e.g. can0",
    )
    parser.add_argument(
        "--dbc",
        metavar="FILE",
        action="append",
        default=[],
        help="decode the frames outside the bus map that this DBC knows (repeatable; "
        "needs veronte4x[dbc])",
    )
    parser.add_argument(
        "--dbc-lax",
        action="store_true",
        help="read DBC files that cantools reads only with strict=False (overlapping "
        "signals) that way, saying what the strict reading found",
    )
    parser.add_argument(
        "--dbc-first",
        action="store_true",
        help="a CAN ID a --dbc file knows is the DBC's, even a Veronte ID or a 29-bit ID "
        "DroneCAN would decode",
    )
    parser.add_argument(
        "--strict-transfers",
        action="store_true",
        help="reassemble DroneCAN transfers under veronte4x's strict rules instead of "
        "libcanard's (the default): a first frame repeating the transfer id just delivered, "
        "even a single frame, is refused within the 2 s timeout",
    )
    add_dsdl_option(parser)


def with_transfer_rules(args: argparse.Namespace, bus_map: BusMap) -> BusMap:
    """``bus_map`` with ``--strict-transfers`` if given (else the bus map's own choice)."""
    return bus_map.with_strict_transfers(True if getattr(args, "strict_transfers", False) else None)


def with_dbc_options(args: argparse.Namespace, bus_map: BusMap) -> BusMap:
    """``bus_map`` with the ``--dbc`` files and ``--dbc-lax``/``--dbc-first``; reading
    them prints each `veronte4x.capture.dbc_in.DbcWarning` once on standard error.

    Raises:
        SourceError: A DBC file that cannot be read.
    """
    changes: dict[str, Any] = {"dbc": (*bus_map.dbc, *getattr(args, "dbc", ()))}
    if getattr(args, "dbc_lax", False):
        changes["dbc_lax"] = True
    if getattr(args, "dbc_first", False):
        changes["dbc_first"] = True
    if not changes["dbc"]:
        return dataclasses.replace(bus_map, **changes)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", DbcWarning)
        bus_map = dataclasses.replace(bus_map, **changes)
    for warning in caught:
        print(f"veronte4x: warning: {warning.message}", file=sys.stderr)
    warnings.simplefilter("ignore", DbcWarning)  # reported: not again when read again
    return bus_map


def add_dsdl_option(parser: argparse.ArgumentParser) -> None:
    """``--dsdl DIR``: DroneCAN types of a vendor root namespace (`main` loads them)."""
    parser.add_argument(
        "--dsdl",
        metavar="DIR",
        action="append",
        default=[],
        help="also decode the DroneCAN types of this DSDL root namespace directory, "
        "e.g. dsdl/ardupilot (repeatable)",
    )


def add_bus_options(parser: argparse.ArgumentParser) -> None:
    """python-can's bus options, the same in every command that opens a bus: ``-i/--interface``,
    ``-c/--channel``, ``-b/--bitrate`` (python-can's own command-line names),
    ``--can-config`` and ``--bus-option``.

    Without ``--interface`` python-can reads its own configuration (``--can-config`` or its
    default files and environment). ``--channel`` is always the bus's channel; a capture's
    channel filter is ``--only-channel`` (`add_capture_options`).
    """
    group = parser.add_argument_group("bus (python-can, the 'can' extra)")
    group.add_argument(
        "-i",
        "--interface",
        help="python-can interface: socketcan, pcan, slcan, udp_multicast, ...; or mcast, the "
        "bus of pydronecan and ArduPilot SITL",
    )
    group.add_argument(
        "-c",
        "--channel",
        help="the interface's channel, e.g. can0 or 239.74.163.2; mcast: the bus number "
        "(0, the default, is pydronecan's mcast:0)",
    )
    group.add_argument("-b", "--bitrate", type=int, help="bit rate in bit/s (DroneCAN: 1000000)")
    group.add_argument(
        "--can-config", metavar="FILE", help="python-can configuration file ([default] section)"
    )
    group.add_argument(
        "--bus-option",
        metavar="KEY=VALUE",
        action="append",
        default=[],
        help="another keyword argument of the python-can bus, e.g. port=43113 (repeatable)",
    )


def add_renamed_option(parser: argparse.ArgumentParser, old: str, new: str) -> None:
    """An option spelled ``old`` before, hidden from the help, that refuses with one line
    naming ``new`` (`UsageError`, exit code 2)."""
    parser.add_argument(old, nargs="?", help=argparse.SUPPRESS, action=_Renamed, new=new)


class _Renamed(argparse.Action):
    """Refuses an old spelling, naming the new one."""

    def __init__(self, option_strings: list[str], dest: str, new: str, **kwargs: Any) -> None:
        super().__init__(option_strings, dest, **kwargs)
        self.new = new

    def __call__(
        self,
        parser: argparse.ArgumentParser,
        namespace: argparse.Namespace,
        values: Any,
        option_string: str | None = None,
    ) -> None:
        given = f" ({self.new} {values})" if isinstance(values, str) else ""
        raise UsageError(f"{option_string} is now {self.new}{given}")


def add_live_options(parser: argparse.ArgumentParser) -> None:
    """Options of a command that reads a capture and can read a live bus instead."""
    add_bus_options(parser)
    parser.add_argument(
        "--duration",
        type=float,
        metavar="S",
        help="live bus: stop after S seconds (default: until Ctrl-C)",
    )


NO_SOURCE = (
    "give a capture file, or a live bus with --interface and --channel (e.g. --interface "
    "socketcan --channel can0) or --can-config FILE"
)
"""The error line of a command that reads a capture or a bus when given neither."""


def live(args: argparse.Namespace) -> bool:
    """Whether the command reads a live bus rather than a capture."""
    return bool(args.interface or args.can_config)


def check_bus_spelling(args: argparse.Namespace) -> None:
    """Refuse ``--channel`` given with a capture and no bus: it was the capture's channel
    filter once, and is the bus's channel now.

    Raises:
        UsageError: ``--channel`` without ``--interface`` or ``--can-config`` in a command
            that reads a capture (the message names ``--only-channel``).
    """
    if not hasattr(args, "only_channel") or getattr(args, "channel", None) is None:
        return
    if not live(args):
        raise UsageError(
            f"--channel names a live bus's channel (with --interface); to keep only the "
            f"frames of channel {args.channel} of a capture, use --only-channel {args.channel}"
        )


def bus_settings(args: argparse.Namespace) -> dict[str, Any]:
    """The keyword arguments for `veronte4x.canbus.open_bus` from the bus options."""
    options: dict[str, Any] = {}
    for item in args.bus_option:
        key, sep, text = item.partition("=")
        if not sep or not key:
            raise SourceError(f"--bus-option {item!r} is not KEY=VALUE")
        options[key] = _option_value(text)
    return {
        "interface": args.interface,
        "channel": args.channel,
        "bitrate": args.bitrate,
        "config_file": args.can_config,
        "options": options,
    }


def _option_value(text: str) -> object:
    """An option's value: an int, a float, true/false, or the text."""
    lowered = text.lower()
    if lowered in ("true", "false"):
        return lowered == "true"
    for kind in (int, float):
        try:
            return kind(text)
        except ValueError:
            pass
    return text


def open_records(
    args: argparse.Namespace,
    bus_map: BusMap,
    stop: threading.Event | None = None,
    loss: BusLoss | None = None,
    idle: Callable[[], object] | None = None,
) -> Iterator[Record]:
    """The records of the command's source: the capture file, or the live bus if one is set.

    A live bus is read until its ``--duration`` ends, Ctrl-C or ``stop`` is set; ``loss``
    counts the frames its bus layer dropped meanwhile; ``idle`` is called whenever the
    records so far are all handed out and the bus has no frame waiting
    (`veronte4x.capture.readers.live.read_bus`).

    Raises:
        SourceError: Both a file and a bus, or neither.
        BusOpenError: The bus cannot be opened (`veronte4x.canbus.BusOpenError`).
    """
    if not live(args):
        if args.file is None:
            raise SourceError(NO_SOURCE)
        return capture.read(args.file, bus_map, args.only_channel, getattr(args, "dbc", ()))
    frames = open_frame_source(args, stop, loss, idle)
    return with_dbc(args, CaptureDecoder(bus_map).decode(frames))


def with_dbc(args: argparse.Namespace, records: Iterator[Record]) -> Iterator[Record]:
    """``records`` with the frames a ``--dbc`` file knows decoded (`capture.DbcDecoder`)."""
    paths = getattr(args, "dbc", ())
    return decoder_of(paths, getattr(args, "dbc_lax", False)).records(records) if paths else records


def open_frame_source(
    args: argparse.Namespace,
    stop: threading.Event | None = None,
    loss: BusLoss | None = None,
    idle: Callable[[], object] | None = None,
) -> Iterator[Frame | BadLine]:
    """The frames of the command's source: the capture file, or the live bus if one is set
    (``loss`` counting the frames its bus layer drops, ``idle`` called when it has none
    waiting).

    Raises:
        SourceError: Both a file and a bus, or neither.
    """
    if not live(args):
        if args.file is None:
            raise SourceError(NO_SOURCE)
        return open_frames(args.file, args.only_channel)
    if args.file not in (None, "-"):
        raise SourceError(f"give a capture file ({args.file}) or --interface, not both")
    return _live_frames(args, stop, loss, idle)


def _live_frames(
    args: argparse.Namespace,
    stop: threading.Event | None,
    loss: BusLoss | None,
    idle: Callable[[], object] | None,
) -> Iterator[Frame | BadLine]:
    from veronte4x.canbus import RECEIVE_BUFFER
    from veronte4x.capture.readers.live import read_bus
    from veronte4x.cli.buses import open_bus
    from veronte4x.sockets import frame_socket, receive_buffer

    bus = open_bus(**bus_settings(args))
    try:
        duplicate = frame_socket(bus) if loss is not None else None
        if duplicate is not None:
            with duplicate:
                given = receive_buffer(duplicate)
            if loss is not None and given < RECEIVE_BUFFER:  # open_bus asked for it
                loss.short_buffer = (given, RECEIVE_BUFFER)
        channel = args.channel or args.interface
        frames = read_bus(bus, channel, args.duration, stop=stop, loss=loss, idle=idle)
        only = getattr(args, "only_channel", None)
        yield from frames if only is None else (f for f in frames if f.channel == only)
    finally:
        bus.shutdown()
