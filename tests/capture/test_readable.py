"""Values as people read them: shortest round-trip floats, enum names, text, units, times."""

from __future__ import annotations

import struct
from pathlib import Path

from hypothesis import given
from hypothesis import strategies as st

from veronte4x import capture, codec, dronecan
from veronte4x.capture.monitor import MonitorState
from veronte4x.capture.readable import (
    format_message,
    format_time,
    hex_bytes,
    readable_fields,
)
from veronte4x.numbers import shortest
from veronte4x.units import UNIT_NAMES, UNITS

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "capture.log"


@given(st.floats(width=32))
def test_shortest_float32_round_trips_and_is_never_longer(value: float) -> None:
    short = shortest(value, 32)
    if value != value:  # nan
        assert short != short
        return
    assert struct.unpack("<f", struct.pack("<f", short))[0] == value
    assert len(repr(short)) <= len(repr(value))


@given(st.floats(width=16))
def test_shortest_float16_round_trips(value: float) -> None:
    short = shortest(value, 16)
    if value == value:
        assert struct.unpack("<e", struct.pack("<e", short))[0] == value


def test_a_value_that_is_no_float32_is_kept() -> None:
    assert shortest(0.1, 32) == 0.1
    assert shortest(1e300, 32) == 1e300


def test_readable_fields_have_the_keys_of_capture_fields() -> None:
    for record in capture.read(EXAMPLE):
        if record.message is not None:
            assert list(readable_fields(record.message)) == list(capture.fields(record.message))


def test_enums_text_and_units() -> None:
    status = dronecan.NodeStatus(7, dronecan.Health.WARNING, dronecan.Mode.MAINTENANCE, 0, 0)
    assert format_message(status) == (
        "NodeStatus(uptime_sec=7 s, health=WARNING, mode=MAINTENANCE, sub_mode=0, "
        "vendor_specific_status_code=0)"
    )
    name = dronecan.StringValue(b"caf\xc3\xa9 \xff")
    assert readable_fields(name) == {"value": "café \\xff"}
    assert format_message(codec.Score(autopilot=1, score=0.30000001192092896)) == (
        "Score(autopilot=1, score=0.3)"
    )
    assert format_message(codec.McuCommand(payload=b"\x01\xab")) == "McuCommand(payload=01ab)"


def test_units_are_known_symbols() -> None:
    assert {symbol for fields in UNITS.values() for symbol in fields.values()} <= set(UNIT_NAMES)


def test_times() -> None:
    assert format_time(None) == "-"
    assert format_time(12.5) == "12.500000"
    assert format_time(1436509052.249713) == "2015-07-10T06:17:32.249713Z"
    assert format_time(1436509052.249713, 1436509052.0) == "0.249713"


def test_undecoded_bytes_are_hex_in_brackets_in_one_place(tmp_path: Path) -> None:
    assert (hex_bytes(b""), hex_bytes(b"\x01"), hex_bytes(bytes([0, 0xC0, 0xFF]))) == (
        "[]",
        "[01]",
        "[00 c0 ff]",
    )
    log = tmp_path / "foreign.log"
    log.write_text("(1763737200.100000) can0 123#00C0FF\n", encoding="utf-8")
    state = MonitorState()
    for record in capture.read(log):
        state.add(record)
    assert [row.fields for row in state.rows()] == ["[00 c0 ff]"]


@given(st.binary(max_size=64))
def test_hex_bytes_reads_back(data: bytes) -> None:
    assert bytes.fromhex(hex_bytes(data)[1:-1]) == data
