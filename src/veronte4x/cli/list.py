"""``veronte4x list``: the message types with their CAN IDs, commands and layouts, and the
DroneCAN types with their data type ids and signatures."""

from __future__ import annotations

import argparse
import json
from typing import Any

from veronte4x.capture.busmap import AUTOPILOT_NAMES, BusMap
from veronte4x.cli.exit_codes import EXIT_OK
from veronte4x.codec.compiler import FrameLayout
from veronte4x.codec.routes import RouteTable, sender_names
from veronte4x.dronecan.definitions import DATA_TYPES


def add_parser(commands: Any) -> None:
    """Register the command."""
    parser = commands.add_parser(
        "list", help="list message types: Veronte CAN IDs, commands, layouts; DroneCAN types"
    )
    parser.add_argument("--bus-map", metavar="FILE", help="TOML file of CAN IDs and choices")
    parser.add_argument("--json", action="store_true", help="JSON on standard output")
    parser.set_defaults(run=run)


def _routes(bus_map: BusMap) -> list[tuple[int | None, str, FrameLayout]]:
    """Each layout of the route table with its command byte (None for several) and who
    sends it; a declared layout replaces the opaque one."""
    table = RouteTable(bus_map.pwm_packing, bus_map.layouts)
    commands = table.layout_commands()
    found: dict[FrameLayout, tuple[int | None, str, FrameLayout]] = {}
    for route in table.routes:
        if route.frame not in found:
            routed = commands[route.frame]
            command = routed[0] if len(routed) == 1 else None
            found[route.frame] = (command, sender_names(route), route.frame)
    return list(found.values())


def _veronte(bus_map: BusMap) -> dict[str, Any]:
    width = 8 if bus_map.extended else 3
    ids = {"arbiter": f"{bus_map.arbiter_id:0{width}X}"}
    ids.update(
        {
            name: f"{can_id:0{width}X}"
            for name, can_id in zip(AUTOPILOT_NAMES, bus_map.autopilot_ids, strict=True)
        }
    )
    messages = []
    for command, sender, layout in _routes(bus_map):
        size = layout.fixed_size
        high = size + (layout.tail.bits // 8 if layout.tail is not None else 0)
        messages.append(
            {
                "message": layout.title or layout.name,
                "command": command,
                "from": sender,
                "bytes": str(size) if high == size else f"{size}..{high}",
                "fields": [p.field.label for p in layout.placed]
                + ([layout.tail.label] if layout.tail is not None else []),
                "source": layout.source,
            }
        )
    return {"extended_ids": bus_map.extended, "ids": ids, "messages": messages}


def _dronecan() -> list[dict[str, Any]]:
    return [
        {
            "type": t.full_name,
            "kind": t.kind.name.lower(),
            "data_type_id": t.data_type_id,
            "signature": f"{t.signature:#018x}",
            "max_payload": t.max_payload,
            "class": t.schema.cls.__name__,
        }
        for t in DATA_TYPES
    ]


def run(args: argparse.Namespace, bus_map: BusMap) -> int:
    """Print the lists."""
    veronte, dronecan = _veronte(bus_map), _dronecan()
    if args.json:
        print(json.dumps({"veronte": veronte, "dronecan": dronecan}))
        return EXIT_OK
    ids = ", ".join(f"{name} {can_id}" for name, can_id in veronte["ids"].items())
    bits = 29 if veronte["extended_ids"] else 11
    print(f"Veronte 4x ({bits}-bit CAN IDs: {ids})")
    width = max(len(m["message"]) for m in veronte["messages"])
    print(f"  {'message':<{width}}  {'cmd':>3}  {'from':<14}  {'bytes':<6}  fields")
    for m in veronte["messages"]:
        command = "-" if m["command"] is None else m["command"]
        print(
            f"  {m['message']:<{width}}  {command:>3}  {m['from']:<14}  {m['bytes']:<6}  "
            + ", ".join(m["fields"])
        )
    print("\nDroneCAN (29-bit CAN IDs)")
    width = max(len(t["type"]) for t in dronecan)
    print(f"  {'type':<{width}}  {'kind':<8}  {'id':>4}  {'signature':<18}  max bytes")
    for t in dronecan:
        print(
            f"  {t['type']:<{width}}  {t['kind']:<8}  {t['data_type_id']:>4}  "
            f"{t['signature']}  {t['max_payload']}"
        )
    return EXIT_OK
