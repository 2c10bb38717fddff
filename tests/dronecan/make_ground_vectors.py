"""Make the golden vectors of the ground-station types with the ``dronecan`` package.

Run from the repository root (the ``dev`` extra installed) to rewrite
``tests/dronecan/data/dronecan_ground.jsonl``::

    python tests/dronecan/make_ground_vectors.py

Every vector is built by the reference implementation alone: its fields are set on a
``dronecan`` object, which makes the frames.
"""

from __future__ import annotations

import json
import random
from pathlib import Path
from typing import Any

from dronecan_oracle import reference_builtin, reference_frames, reference_object

from veronte4x import dronecan as v4

OUT = Path(__file__).parent / "data" / "dronecan_ground.jsonl"

REQ = v4.TransferKind.REQUEST
RESP = v4.TransferKind.RESPONSE

IDS = {
    "uavcan.protocol.param.ExecuteOpcode": 10,
    "uavcan.protocol.file.GetInfo": 45,
    "uavcan.protocol.file.Read": 48,
}


def _path(text: bytes) -> dict[str, Any]:
    return {"path": list(text)}


def _cases(rng: random.Random) -> list[tuple[str, v4.TransferKind, dict[str, Any]]]:
    image = bytes(rng.randrange(256) for _ in range(256))
    return [
        ("uavcan.protocol.param.ExecuteOpcode", REQ, {"opcode": 0, "argument": 0}),
        ("uavcan.protocol.param.ExecuteOpcode", REQ, {"opcode": 1, "argument": 0}),
        ("uavcan.protocol.param.ExecuteOpcode", REQ, {"opcode": 255, "argument": -(2**47)}),
        ("uavcan.protocol.param.ExecuteOpcode", REQ, {"opcode": 7, "argument": 2**47 - 1}),
        ("uavcan.protocol.param.ExecuteOpcode", RESP, {"argument": 0, "ok": True}),
        ("uavcan.protocol.param.ExecuteOpcode", RESP, {"argument": -1, "ok": False}),
        ("uavcan.protocol.param.ExecuteOpcode", RESP, {"argument": 123456789, "ok": True}),
        ("uavcan.protocol.file.GetInfo", REQ, {"path": _path(b"")}),
        ("uavcan.protocol.file.GetInfo", REQ, {"path": _path(b"fw.bin")}),
        ("uavcan.protocol.file.GetInfo", REQ, {"path": _path(b"/images/" + b"a" * 192)}),
        (
            "uavcan.protocol.file.GetInfo",
            RESP,
            {"size": 0, "error": {"value": 2}, "entry_type": {"flags": 0}},
        ),
        (
            "uavcan.protocol.file.GetInfo",
            RESP,
            {"size": 2**40 - 1, "error": {"value": 0}, "entry_type": {"flags": 9}},
        ),
        (
            "uavcan.protocol.file.GetInfo",
            RESP,
            {"size": 4096, "error": {"value": -32768}, "entry_type": {"flags": 255}},
        ),
        ("uavcan.protocol.file.Read", REQ, {"offset": 0, "path": _path(b"fw.bin")}),
        ("uavcan.protocol.file.Read", REQ, {"offset": 2**40 - 1, "path": _path(b"")}),
        ("uavcan.protocol.file.Read", REQ, {"offset": 768, "path": _path(b"x" * 200)}),
        ("uavcan.protocol.file.Read", RESP, {"error": {"value": 0}, "data": []}),
        ("uavcan.protocol.file.Read", RESP, {"error": {"value": 32767}, "data": [1, 2, 3]}),
        ("uavcan.protocol.file.Read", RESP, {"error": {"value": 0}, "data": list(image)}),
        ("uavcan.protocol.file.Read", RESP, {"error": {"value": 5}, "data": list(image[:100])}),
    ]


def main() -> None:
    rng = random.Random(12)
    lines = []
    for number, (name, kind, fields) in enumerate(_cases(rng)):
        obj = reference_object(name, kind, fields)
        source, destination = rng.randrange(1, 128), rng.randrange(1, 128)
        transfer_id, priority = rng.randrange(32), rng.randrange(32)
        frames = reference_frames(obj, source, destination, transfer_id, priority, kind)
        vector = {
            "id": number,
            "type": name,
            "kind": kind.name.lower(),
            "data_type_id": IDS[name],
            "priority": priority,
            "source_node_id": source,
            "dest_node_id": destination,
            "transfer_id": transfer_id,
            "fields": reference_builtin(obj),
            "can_id": frames[0][0],
            "frames": [data.hex() for _, data in frames],
        }
        lines.append(json.dumps(vector))
    OUT.write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
