"""One rule for transfer length: as many frames as the type's largest payload needs.

libcanard keeps a received payload's length in a ``uint16_t`` and the ``dronecan`` package
cuts and joins any number of frames; neither counts frames. So `encode`, `decode_frames`,
the `Reassembler` and the columnar path take a transfer of any frame count whose payload
decodes as its type, and refuse a longer one with their own error. The type:
``ardupilot.equipment.power.BatteryInfoAux`` (tests/dronecan/data/dsdl_ardupilot), 255
cells in 76 frames, 211 cells (the first past 63 frames) in 64.
"""

from __future__ import annotations

from pathlib import Path

import pytest

import dronecan as pydronecan
from veronte4x import capture
from veronte4x.dronecan import Reassembler, TypeSet, decode_frames, encode
from veronte4x.dronecan.crc import crc16
from veronte4x.dronecan.tail import frame_count, split_payload
from veronte4x.errors import DecodeError

TYPES = TypeSet.standard().with_dsdl(
    Path(__file__).parent / "data" / "dsdl_ardupilot" / "ardupilot"
)
AUX = next(c for c in TYPES.codecs if c.data_type.full_name.endswith("BatteryInfoAux"))
CELLS = pytest.mark.parametrize("cells", [210, 211, 255])


def _reference(cells: int) -> list[tuple[int, bytes]]:
    """The frames the ``dronecan`` package sends for ``cells`` cells, transfer id 3."""
    message = pydronecan.ardupilot.equipment.power.BatteryInfoAux(
        voltage_cell=[0.5 * (i % 9) for i in range(cells)], cycle_count=9, battery_id=3
    )
    transfer = pydronecan.transport.Transfer(
        transfer_id=3, source_node_id=5, payload=message, transfer_priority=16
    )
    return [(frame.message_id, bytes(frame.bytes)) for frame in transfer.to_frames()]


@CELLS
def test_every_path_takes_a_transfer_past_63_frames(cells: int, tmp_path: Path) -> None:
    frames = _reference(cells)
    assert len(frames) == frame_count(len(b"".join(d[:-1] for _, d in frames)) - 2)
    transfer = decode_frames(frames, 1.0, types=TYPES)
    assert len(transfer.message.voltage_cell) == cells
    assert transfer.message.voltage_cell[:3] == (0.0, 0.5, 1.0)
    assert (transfer.source_node_id, transfer.transfer_id) == (5, 3)
    sent = encode(transfer.message, source_node_id=5, transfer_id=3, priority=16, types=TYPES)
    assert [tuple(f) for f in sent] == frames
    reassembler = Reassembler(types=TYPES)
    out = [
        reassembler.push(can_id, data, 1.0 + i * 1e-4) for i, (can_id, data) in enumerate(frames)
    ]
    assert out[:-1] == [None] * (len(frames) - 1)
    assert out[-1] == transfer._replace(timestamp=1.0)
    log = tmp_path / "aux.log"
    log.write_text("".join(f"({1.0 + i * 1e-4:.6f}) can0 {c:08X}#{d.hex().upper()}\n"
                           for i, (c, d) in enumerate(frames)))  # fmt: skip
    tables = capture.read_tables(log, types=TYPES, time="seconds")
    assert set(tables) == {"BatteryInfoAux"}
    row = tables["BatteryInfoAux"].to_pylist()[0]
    assert row["voltage_cell"] == list(transfer.message.voltage_cell)
    assert row["node_id"] == 5
    records = list(capture.read(log, types=TYPES))
    assert [r.message for r in records] == [transfer.message]


def test_a_payload_longer_than_the_type_is_refused_everywhere() -> None:
    frames = _reference(255)
    # One more frame: the payload has 7 bytes past the type's largest (CRC fixed up).
    payload = b"".join(d[:-1] for _, d in frames)[2:] + bytes(7)
    can_id = frames[0][0]
    longer = [(can_id, d) for d in split_payload(payload, crc16(payload, AUX.crc_seed), 3)]
    assert len(longer) == 77
    with pytest.raises(DecodeError, match="left after the last field"):
        decode_frames(longer, types=TYPES)
    reassembler = Reassembler(types=TYPES)
    for c, d in longer:
        reassembler.push(c, d, 1.0)
    assert [r.problem.name for r in reassembler.problems] == ["PAYLOAD_TOO_LONG"]
    assert reassembler.transfers == 0
