"""The capture decoder: routing by bus map, every error kind as a record, both paths equal."""

from pathlib import Path

import pytest

from veronte4x import codec
from veronte4x.capture.busmap import BusMap, Role
from veronte4x.capture.decoder import CaptureDecoder
from veronte4x.capture.records import Record
from veronte4x.capture.source import open_frames

ODD = Path(__file__).with_name("data") / "odd.log"
EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "capture.log"


def _kinds(records: list[Record]) -> list[tuple[str, str]]:
    return [(r.sender, r.kind) for r in records]


def test_odd_capture_gives_one_record_per_frame_or_bad_line() -> None:
    records = list(CaptureDecoder().decode(open_frames(ODD)))
    assert _kinds(records) == [
        ("arbiter", "Status"),
        ("node 42", "unknown"),
        ("unknown", "error: remote frame"),
        ("unknown", "error: remote frame"),
        ("unknown", "unknown"),
        ("dronecan", "error: error frame"),
        ("AP1", "Ready"),
        ("unknown", "unknown"),
        ("arbiter", "Status"),
        ("AP2", "Ready"),
        ("unknown", "error: remote frame"),
        ("dronecan", "error: error frame"),
        ("AP3", "Ready"),
        ("unknown", "error: bad line"),
        ("unknown", "error: bad line"),
        ("unknown", "error: bad line"),
        ("unknown", "error: bad line"),
        ("AP1", "error: unknown command"),
    ]
    assert records[6].message == codec.Ready(ready=True)
    assert records[-1].data == b"\x04\x00"
    assert records[-1].detail == (
        "frame.command: command byte 4 is reserved or unknown (data: 04 00)"
    )
    assert records[13].detail == "line 14: expected 'interface ID [length] data': 'garbage here'"


def test_fused_candump_path_equals_the_two_stage_path() -> None:
    decoder = CaptureDecoder()
    for path in (ODD, EXAMPLE):
        with path.open() as lines:
            fused = list(decoder.decode_candump(lines))
        assert fused == list(decoder.decode(open_frames(path)))


def test_records_carry_role_autopilot_and_raw_bytes() -> None:
    records = list(CaptureDecoder().decode(open_frames(EXAMPLE)))
    ready = records[2]
    assert ready == Record(
        1763737200.01, "can0", 8, Role.AUTOPILOT, 0, None, codec.Ready(ready=True), None, "",
        b"\x00\xff\x01",
    )  # fmt: skip
    assert ready.sender == "AP1"
    assert records[3].sender == "AP2"


def test_bad_veronte_frames_are_records_not_exceptions() -> None:
    lines = [
        "(1.0) can0 0FF#00FF05",  # Status of 3 bytes
        "(2.0) can0 008#",  # empty frame
        "(3.0) can0 008#00",  # 1-byte arbitration frame
        "(4.0) can0 009#00FF0100000000",  # padded Ready: rejected unless allow_excess
    ]
    strict = list(CaptureDecoder().decode_candump(lines))
    assert [r.error for r in strict] == ["decode error"] * 4
    assert strict[1].detail == "frame: 0 bytes; a frame has 1 to 8 (data: empty)"
    lenient = list(CaptureDecoder(BusMap(allow_excess=True)).decode_candump(lines))
    assert lenient[3].message == codec.Ready(ready=True)


def test_extended_veronte_ids() -> None:
    bus = BusMap(arbiter_id=0x1ABCDEF0, autopilot_ids=(1, 2, 3, 4), extended=True)
    records = list(CaptureDecoder(bus).decode_candump(["(1.0) can0 1ABCDEF0#00FF00"]))
    assert records[0].error is not None  # 3-byte Status: decode error, routed as the arbiter
    assert records[0].role is Role.ARBITER
    records = list(CaptureDecoder(bus).decode_candump(["(1.0) can0 00000001#00FF01"]))
    assert records[0].message == codec.Ready(ready=True)
    assert records[0].sender == "AP1"


def test_foreign_traffic_is_undecoded_and_counted_apart() -> None:
    """CAN IDs outside the bus map and DroneCAN types without a codec are not errors."""
    from veronte4x.capture.stats import Stats
    from veronte4x.dronecan import can_id

    lines = [
        "(1.0) can0 123#0102",
        "(1.1) can0 01ABCDEF#",
        f"(2.0) can0 {can_id.message_can_id(16, 1234, 42):08X}#C0",
        f"(2.1) can0 {can_id.service_can_id(16, 200, True, 7, 42):08X}#C1",
        f"(2.2) can0 {can_id.anonymous_can_id(16, 2, 99):08X}#C2",
        "(3.0) can0 008#0400",
    ]
    records = list(CaptureDecoder(BusMap(dronecan=False)).decode_candump(lines[:2]))
    records += list(CaptureDecoder().decode_candump(lines[2:]))
    assert [(r.kind, r.error, r.message, r.detail, r.data) for r in records[:5]] == [
        ("unknown", None, None, "11-bit CAN ID 0x123", b"\x01\x02"),
        ("unknown", None, None, "29-bit CAN ID 0x1abcdef", b""),
        ("unknown", None, None, "DroneCAN data type 1234", b"\xc0"),
        ("unknown", None, None, "DroneCAN service type 200", b"\xc1"),
        ("unknown", None, None, "DroneCAN anonymous data type 2", b"\xc2"),
    ]
    assert records[2].node_id == 42 and records[3].node_id == 7
    counts = Stats()
    for record in records:
        counts.add(record)
    assert counts.unknown["DroneCAN data type 1234"] == 1
    assert sum(counts.unknown.values()) == 5
    assert counts.errors == {"unknown command": 1}
    assert "Record" not in counts.by_type and sum(counts.by_type.values()) == 0
    assert "records: 6, undecoded: 5, errors: 1" in counts.report()


def test_decode_chunks_takes_any_bytes_like_chunk_and_refuses_text() -> None:
    line = b"(1.0) can0 009#00FF01\n"
    expected = list(CaptureDecoder().decode_chunks([line]))
    for chunk in (bytearray(line), memoryview(line)):
        assert list(CaptureDecoder().decode_chunks([chunk])) == expected
    with pytest.raises(
        TypeError, match=r"^decode_chunks\(\): each chunk must be bytes-like, not str$"
    ):
        list(CaptureDecoder().decode_chunks([line.decode()]))  # type: ignore[list-item]
    with pytest.raises(
        TypeError, match=r"^decode_chunks\(\): channel must be a str or None, not int$"
    ):
        list(CaptureDecoder().decode_chunks([line], 0))  # type: ignore[arg-type]
