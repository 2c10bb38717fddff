"""``veronte4x simulate esc``: simulated Vertiq ESCs on any python-can bus, until Ctrl-C."""

from __future__ import annotations

import argparse
import signal
import sys
import threading
from typing import Any

from veronte4x.capture.busmap import BusMap
from veronte4x.cli.exit_codes import EXIT_OK, EXIT_USAGE
from veronte4x.cli.fleet import node_list
from veronte4x.cli.options import add_bus_options, bus_settings
from veronte4x.simulator.esc import COMMAND_TIMEOUT, FILE_REQUEST_TIMEOUT


def _node_list(text: str) -> list[int]:
    """Node ids and ranges, e.g. ``21,22`` or ``21-28`` (not ``all``: nothing to discover)."""
    nodes = node_list(text)
    if nodes.every:
        raise argparse.ArgumentTypeError("name the simulated nodes, e.g. 21,22 or 21-28")
    return list(nodes.ids)


def _not_negative(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None
    if not value >= 0 or value == float("inf"):
        raise argparse.ArgumentTypeError(f"{text} must be a finite number, 0 or above")
    return value


_OPTIONS = {
    "telem_frequency": "--telem-frequency",
    "command_timeout": "--command-timeout",
    "file_timeout": "--file-timeout",
    "node_id": "--nodes",
    "esc_index": "--nodes (esc_index)",
    "preferred_node_id": "--preferred-node-id",
}
"""The option of each `SimulatedEsc` argument, for error lines in the user's words."""


def add_parser(commands: Any) -> None:
    """Register the command."""
    parser = commands.add_parser("simulate", help="run simulated devices on a bus")
    devices = parser.add_subparsers(required=True, metavar="DEVICE")
    esc = devices.add_parser(
        "esc",
        help="simulated Vertiq ESCs (DroneCAN), until Ctrl-C",
        description="Simulated Vertiq ESCs: NodeStatus, telemetry, parameters, RawCommand, "
        "restart and firmware update, on any python-can bus.",
    )
    esc.add_argument(
        "--nodes",
        type=_node_list,
        default=[21],
        help="node ids, e.g. 21,22 or 21-28 (esc_index 0, 1...)",
    )
    esc.add_argument("--telem-frequency", type=int, default=10, metavar="HZ")
    esc.add_argument(
        "--no-firmware-update",
        action="store_true",
        help="answer BeginFirmwareUpdate with INVALID_MODE, like the Vertiq 81-08",
    )
    esc.add_argument(
        "--stall-update-at",
        type=int,
        metavar="BYTES",
        help="fault: hang during a firmware update after reading BYTES",
    )
    esc.add_argument(
        "--command-timeout",
        type=_not_negative,
        default=COMMAND_TIMEOUT,
        metavar="S",
        help="a RawCommand setpoint holds S seconds without a new one, then zero throttle "
        f"({COMMAND_TIMEOUT:g}; 0: never, to test a tool against an ESC without one)",
    )
    esc.add_argument(
        "--response-delay",
        type=_not_negative,
        default=0.0,
        metavar="S",
        help="seconds a module takes to answer a request and, during a firmware update, to "
        "write each chunk before reading the next (0), as real modules take to write flash",
    )
    esc.add_argument(
        "--file-timeout",
        type=float,
        default=FILE_REQUEST_TIMEOUT,
        metavar="S",
        help="seconds a firmware update's file request waits for its answer before it is "
        f"sent again ({FILE_REQUEST_TIMEOUT:g})",
    )
    esc.add_argument(
        "--dynamic-node-id",
        action="store_true",
        help="start without a node id and ask an allocation server for one (DroneCAN dynamic "
        "node ID allocation); the --nodes ids name the unique ids and are the ids preferred",
    )
    esc.add_argument(
        "--preferred-node-id",
        type=int,
        metavar="N",
        help="with --dynamic-node-id: ask for N (0: any) rather than each --nodes id",
    )
    esc.add_argument("--duration", type=float, metavar="S", help="stop after S seconds")
    add_bus_options(esc)
    esc.set_defaults(run=run, bus_map=None)


def run(args: argparse.Namespace, bus_map: BusMap | None) -> int:
    """Serve the bus until Ctrl-C (exit code 130), SIGTERM or the duration (0)."""
    from veronte4x.cli.buses import open_bus, require_bus_packages

    require_bus_packages(bus_settings(args), "veronte4x simulate")
    from veronte4x.errors import EncodeError
    from veronte4x.simulator import SimulatedEsc
    from veronte4x.simulator.can_node import EscBus

    if args.preferred_node_id is not None and not args.dynamic_node_id:
        print("veronte4x: --preferred-node-id needs --dynamic-node-id", file=sys.stderr)
        return EXIT_USAGE
    try:
        escs = [
            SimulatedEsc(
                node,
                index,
                telem_frequency=args.telem_frequency,
                supports_firmware_update=not args.no_firmware_update,
                update_stall_offset=args.stall_update_at,
                command_timeout=args.command_timeout or None,
                response_delay=args.response_delay,
                file_timeout=args.file_timeout,
                dynamic_node_id=args.dynamic_node_id,
                preferred_node_id=args.preferred_node_id,
            )
            for index, node in enumerate(args.nodes)
        ]
    except EncodeError as error:
        option = _OPTIONS.get(error.field, error.field)
        print(f"veronte4x: {option} {error.value!r} is refused: {error.allowed}", file=sys.stderr)
        return EXIT_USAGE
    import can

    bus = open_bus(**bus_settings(args))
    stop = threading.Event()
    try:  # from here on the bus is shut down whatever ends the run, Ctrl-C included
        signal.signal(signal.SIGTERM, lambda *_: stop.set())
        if args.duration is not None:
            timer = threading.Timer(args.duration, stop.set)
            timer.daemon = True  # a Ctrl-C before the duration does not wait for it
            timer.start()
        node = EscBus(bus, escs)
        start = node.clock()
        for esc in escs:
            esc.power_cycle(start)
        names = ", ".join(f"{n} (esc_index {i})" for i, n in enumerate(args.nodes))
        if args.dynamic_node_id:
            names += " without node ids, asking an allocation server for them"
        print(f"veronte4x: simulating Vertiq ESC nodes {names}; Ctrl-C stops", file=sys.stderr)
        node.run(stop)  # Ctrl-C goes through: exit code 130, as every command
    except can.CanError as error:
        print(f"veronte4x: the CAN bus failed: {error}", file=sys.stderr)
        return EXIT_USAGE
    finally:
        stop.set()
        bus.shutdown()
    return EXIT_OK
