"""``veronte4x play CAPTURE --interface I --channel C``: a capture onto a CAN bus, like canplayer.

The schedule is `veronte4x.capture.playback.Player`'s; this module only opens the buses,
reads the clock, sleeps and sends.
"""

from __future__ import annotations

import argparse
import contextlib
import sys
import threading
import time
from collections.abc import Callable, Iterable, Iterator
from typing import Any

from veronte4x.capture.busmap import BusMap
from veronte4x.capture.frames import Frame
from veronte4x.capture.playback import IdFilter, Pacer, PlaybackError, Player
from veronte4x.capture.records import Record
from veronte4x.capture.source import open_frames
from veronte4x.cli.exit_codes import EXIT_OK, EXIT_USAGE
from veronte4x.cli.options import add_bus_options, bus_settings
from veronte4x.words import counted


def add_parser(commands: Any) -> None:
    """Register the command."""
    parser = commands.add_parser(
        "play", help="send a capture's frames onto a CAN bus with their original spacing"
    )
    parser.add_argument("file", metavar="CAPTURE", help="capture file (any format decode reads)")
    parser.add_argument("old_bus", nargs="?", help=argparse.SUPPRESS)  # refused: see `run`
    parser.add_argument(
        "--speed", type=speed, default=1.0, metavar="X", help="2 plays twice as fast (1)"
    )
    parser.add_argument(
        "--channel-map",
        metavar="CAPTURED=SENT",
        action="append",
        default=[],
        help="send the frames captured on CAPTURED to the bus channel SENT, e.g. can0=vcan1 "
        "(repeatable; given, other channels are not sent)",
    )
    parser.add_argument(
        "--filter",
        metavar="ID[:MASK]",
        action="append",
        default=[],
        help="send only frames whose CAN ID matches, hexadecimal as candump: 0FF, 100:700 "
        "(repeatable)",
    )
    parser.add_argument(
        "--loop",
        type=int,
        nargs="?",
        const=0,
        default=1,
        metavar="N",
        help="play N times, or for ever without N (until Ctrl-C)",
    )
    add_bus_options(parser)
    parser.set_defaults(run=run, bus_map=None)


def speed(text: str) -> float:
    """``--speed``: a positive number, else argparse's usage error."""
    try:
        value = float(text)
        Pacer(value)
    except (ValueError, PlaybackError):
        raise argparse.ArgumentTypeError(
            f"{text!r}: expected a positive number, e.g. 2 or 0.5"
        ) from None
    return value


def paced(
    records: Iterable[Record],
    speed: float,
    stop: threading.Event,
    clock: Callable[[], float] = time.monotonic,
) -> Iterator[Record]:
    """Records with their capture's spacing over ``speed``, until ``stop`` is set."""
    pacer = Pacer(speed)
    for record in records:
        wait = pacer.delay(record.timestamp, clock())
        if wait > 0 and stop.wait(wait):
            return
        yield record


def run(args: argparse.Namespace, bus_map: BusMap) -> int:
    """Play the capture; the timing goes to standard error."""
    from veronte4x.cli.buses import open_bus

    if args.old_bus is not None:
        return _usage(_old_bus_line(args.old_bus))
    settings = bus_settings(args)
    mapping: dict[str, str] | None = None
    if args.channel_map:
        mapping = {}
        for item in args.channel_map:
            captured, sep, sent = item.partition("=")
            if not sep or not captured or not sent:
                return _usage(f"--channel-map {item!r}: expected CAPTURED=SENT, e.g. can0=vcan1")
            mapping[captured] = sent
    try:
        filters = [IdFilter.parse(text) for text in args.filter]
        frames = [f for f in open_frames(args.file) if isinstance(f, Frame)]
        player = Player(frames, args.speed, args.loop or None, filters, mapping)
    except PlaybackError as error:
        return _usage(str(error))
    buses: dict[str | None, Any] = {}
    try:
        for target in sorted(set(mapping.values())) if mapping else [None]:
            buses[target] = open_bus(**{**settings, "channel": target or args.channel})
        return _play(player, buses, mapping is not None)
    finally:
        for bus in buses.values():
            bus.shutdown()


def _old_bus_line(bus: str) -> str:
    """The line refusing ``play CAPTURE INTERFACE:CHANNEL``, the spelling before the bus
    options, with the options it means."""
    interface, _, channel = bus.partition(":")
    options = " ".join(
        f"--{name} {value}"
        for name, value in (("interface", interface), ("channel", channel))
        if value
    )
    return (
        f"play takes the bus as options now: {options or '--interface I --channel C'} (not {bus})"
    )


def _play(
    player: Player,
    buses: dict[str | None, Any],
    mapped: bool,
    clock: Callable[[], float] = time.monotonic,
    sleep: Callable[[float], None] = time.sleep,
) -> int:
    """Send each frame when it is due; report how late they went."""
    import can

    began = clock()
    player.start(began)
    sent = 0
    try:
        while (due := player.due()) is not None:
            wait = due - clock()
            if wait > 0:
                sleep(wait)
            for frame in player.take(clock()):
                message = can.Message(
                    arbitration_id=frame.can_id,
                    data=frame.data,
                    is_extended_id=frame.extended,
                    is_remote_frame=frame.remote,
                    is_error_frame=frame.error,
                    is_fd=frame.fd,
                    bitrate_switch=frame.brs,
                    error_state_indicator=frame.esi,
                    dlc=frame.dlc if frame.remote else None,
                    channel=frame.channel if mapped else None,
                )
                buses[frame.channel if mapped else None].send(message)
                sent += 1
    except can.CanError as error:
        with contextlib.suppress(OSError):
            sys.stdout.flush()
        print(f"veronte4x: the CAN bus failed sending frame {sent + 1}: {error}", file=sys.stderr)
        return EXIT_USAGE
    timing = player.timing()
    print(
        f"veronte4x: sent {counted(timing.frames, 'frame')} in {clock() - began:.3f} s; late "
        f"against the schedule: {timing.mean_late * 1000:.3g} ms on average, "
        f"{timing.max_late * 1000:.3g} ms at most",
        file=sys.stderr,
    )
    return EXIT_OK


def _usage(message: str) -> int:
    print(f"veronte4x: {message}", file=sys.stderr)
    return EXIT_USAGE
