"""ExecuteOpcode, file.GetInfo and file.Read against golden vectors of the ``dronecan`` package.

The vectors (``data/dronecan_ground.jsonl``) come from ``make_ground_vectors.py``; here they
are checked both ways. Random messages of these types are compared with the reference in
test_dronecan_differential.py.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest
from dronecan_oracle import CLASS_OF, KINDS

from veronte4x import dronecan

VECTORS = [
    json.loads(line) for line in (Path(__file__).parent / "data" / "dronecan_ground.jsonl").open()
]


def _ids(vector: dict[str, Any]) -> str:
    return f"{vector['id']}-{vector['type'].split('.')[-1]}-{vector['kind']}"


def _frames(vector: dict[str, Any]) -> list[tuple[int, bytes]]:
    return [(vector["can_id"], bytes.fromhex(h)) for h in vector["frames"]]


@pytest.mark.parametrize("vector", VECTORS, ids=_ids)
def test_golden_frames_decode(vector: dict[str, Any]) -> None:
    reassembler = dronecan.Reassembler()
    results = [reassembler.feed(can_id, data, 2.0) for can_id, data in _frames(vector)]
    transfer = results[-1]
    assert results[:-1] == [None] * (len(results) - 1)
    assert transfer is not None
    assert type(transfer.message) is CLASS_OF[(vector["type"], KINDS[vector["kind"]])]
    assert dronecan.to_builtin(transfer.message) == vector["fields"]
    assert transfer.source_node_id == vector["source_node_id"]
    assert transfer.destination_node_id == vector["dest_node_id"]
    assert transfer.transfer_id == vector["transfer_id"]
    assert transfer.priority == vector["priority"]
    assert transfer.data_type_id == vector["data_type_id"]


@pytest.mark.parametrize("vector", VECTORS, ids=_ids)
def test_golden_frames_encode(vector: dict[str, Any]) -> None:
    cls = CLASS_OF[(vector["type"], KINDS[vector["kind"]])]
    message: Any = dronecan.from_builtin(cls, vector["fields"])
    frames = dronecan.encode(
        message,
        source_node_id=vector["source_node_id"],
        destination_node_id=vector["dest_node_id"],
        transfer_id=vector["transfer_id"],
        priority=vector["priority"],
    )
    assert [(f.can_id, f.data) for f in frames] == _frames(vector)


def test_enums_and_nested_classes() -> None:
    request = dronecan.decode_frames([(0x000A8F8F, bytes.fromhex("01000000000000d6"))]).message
    assert request == dronecan.ExecuteOpcodeRequest(dronecan.Opcode.ERASE, 0)
    assert request.opcode is dronecan.Opcode.ERASE
    assert dronecan.FileErrorCode(2).value == dronecan.FileError.NOT_FOUND
    assert dronecan.EntryTypeFlag.FILE | dronecan.EntryTypeFlag.READABLE == 9
