"""Anonymous transfers (spec 4.1 "ID field", anonymous message frames): source node id 0,
a 14-bit discriminator and the type id's low 2 bits; a node without a node id sends its
``uavcan.protocol.dynamic_node_id.Allocation`` requests so. Decoded in every path with
``source_node_id`` None, checked against the ``dronecan`` package on kocherga's frames
(tests/dronecan/kocherga_frames.py)."""

from __future__ import annotations

from pathlib import Path

import pytest
from kocherga_frames import ANSWERS, REQUESTS
from tests.capture.columnar_support import assert_same_tables

import dronecan as pydronecan
from veronte4x import capture
from veronte4x.capture.columnar.engine import tables_from_records
from veronte4x.dronecan import Allocation, Problem, Reassembler, TransferKind, decode_frames


def _reference(can_id: int, data: bytes) -> tuple[int, int, bool, bytes, int]:
    """What the ``dronecan`` package decodes from one frame: source node id, and the
    allocation's node id, first-part flag, unique id bytes and transfer id."""
    transfer = pydronecan.transport.Transfer()
    transfer.from_frames([pydronecan.transport.Frame(can_id, data)])
    m = transfer.payload
    return (
        transfer.source_node_id,
        m.node_id,
        bool(m.first_part_of_unique_id),
        bytes(m.unique_id),
        transfer.transfer_id,
    )


@pytest.mark.parametrize(("can_id", "data"), REQUESTS)
def test_an_allocation_request_decodes_as_the_dronecan_package_does(
    can_id: int, data: bytes
) -> None:
    transfer = decode_frames([(can_id, data)], 2.0)
    assert isinstance(transfer.message, Allocation)
    assert (transfer.source_node_id, transfer.destination_node_id) == (None, None)
    assert (transfer.kind, transfer.data_type_id, transfer.priority) == (
        TransferKind.MESSAGE,
        1,
        30,
    )
    m = transfer.message
    source, *fields = _reference(can_id, data)
    assert source == 0
    assert [m.node_id, m.first_part_of_unique_id, m.unique_id, transfer.transfer_id] == fields
    assert Reassembler().push(can_id, data, 2.0) == transfer


def test_the_reassembler_delivers_every_request() -> None:
    reassembler = Reassembler()
    out = [reassembler.push(c, d, 1.0 + i) for i, (c, d) in enumerate(REQUESTS)]
    assert [t.transfer_id for t in out] == [0, 1, 2, 3, 4]  # type: ignore[union-attr]
    assert [t.message.first_part_of_unique_id for t in out] == [True, True, False, True, False]  # type: ignore[union-attr]
    assert reassembler.reported == 0


def test_a_multi_frame_anonymous_frame_is_malformed() -> None:
    reassembler = Reassembler()
    assert reassembler.push(0x1E64B500, bytes.fromhex("0135ffd5055059a0"), 1.0) is not None
    assert [r.problem for r in reassembler.problems] == [Problem.MALFORMED_FRAME]


def test_columns_and_records_agree_on_anonymous_transfers(tmp_path: Path) -> None:
    frames = [*REQUESTS[:3], *ANSWERS, *REQUESTS[3:]]
    log = tmp_path / "allocation.log"
    log.write_text("".join(f"({10.0 + i * 0.01:.6f}) can0 {c:08X}#{d.hex().upper()}\n"
                           for i, (c, d) in enumerate(frames)))  # fmt: skip
    tables = capture.read_tables(log)
    assert_same_tables(tables, tables_from_records(capture.read(log)))
    allocation = tables["Allocation"].to_pylist()
    assert [(r["node_id"], r["sender"]) for r in allocation] == [
        *[(None, "dronecan")] * 3,
        (127, "node 127"),
        (127, "node 127"),
        (127, "node 127"),
        *[(None, "dronecan")] * 2,
    ]
    assert [r["message.node_id"] for r in allocation] == [0, 0, 0, 0, 0, 125, 0, 0]
