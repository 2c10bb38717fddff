"""DroneCAN frames in a capture: one record per transfer, one per reassembly problem."""

import pytest

from veronte4x import dronecan
from veronte4x.capture import decoder
from veronte4x.capture.busmap import Role
from veronte4x.capture.decoder import CaptureDecoder
from veronte4x.capture.frames import Frame

STATUS = dronecan.EscStatus(
    error_count=1, voltage=24.0, current=3.5, temperature=300.0, rpm=1200,
    power_rating_pct=20, esc_index=2,
)  # fmt: skip


def _frames(start: float, node: int, tid: int) -> list[Frame]:
    frames = dronecan.encode(STATUS, source_node_id=node, transfer_id=tid)
    return [Frame(start + i / 1000, "can0", f.can_id, f.data, True) for i, f in enumerate(frames)]


def test_a_transfer_is_one_record_when_its_last_frame_arrives() -> None:
    frames = _frames(1.0, 22, 5)
    records = list(CaptureDecoder().decode(frames))
    assert len(records) == 1
    record = records[0]
    assert record.message == STATUS
    assert (record.role, record.node_id, record.sender) == (Role.DRONECAN, 22, "node 22")
    assert record.timestamp == 1.002
    assert record.data == frames[-1].data


def test_problems_are_records_and_the_stream_goes_on() -> None:
    missed = _frames(1.0, 22, 6)[1:]
    corrupt = _frames(2.0, 23, 7)
    corrupt[1] = corrupt[1]._replace(data=bytes([corrupt[1].data[0] ^ 1]) + corrupt[1].data[1:])
    good = _frames(3.0, 24, 8)
    records = list(CaptureDecoder().decode(missed + corrupt + good))
    assert [(r.error, r.node_id) for r in records] == [
        ("missed start", 22),  # each frame libcanard refuses is one record
        ("missed start", 22),
        ("crc mismatch", 23),
        (None, 24),
    ]
    assert records[0].detail.startswith("A frame of a transfer whose first frame was not seen.")
    assert records[-1].message == STATUS


def test_fused_candump_path_reassembles_too(monkeypatch: pytest.MonkeyPatch) -> None:
    """`decode_chunks` reads plain log-form lines itself: the exact line parser, which the
    other lines take, is never called, and the records equal `decode_candump`'s."""
    frames = _frames(1.0, 9, 1)
    lines = [f"({f.timestamp:.6f}) can0 {f.can_id:08X}#{f.data.hex()}\n" for f in frames]
    exact = list(CaptureDecoder().decode_candump(lines))
    assert [r.message for r in exact] == [STATUS]

    def not_fused(*args: object) -> None:
        raise AssertionError("a plain line left the fused path")

    monkeypatch.setattr(decoder, "parse_line", not_fused)
    monkeypatch.setattr(decoder, "parse_candump", not_fused)
    fused = list(CaptureDecoder().decode_chunks([line.encode() for line in lines]))
    assert fused == exact
