"""CAN IDs, tail bytes, transfer CRC, v0 bit order and framing."""

from __future__ import annotations

import dataclasses
from typing import Any

import pytest

from veronte4x import dronecan
from veronte4x.dronecan.codec import BY_CLASS
from veronte4x.dronecan.crc import crc16, signature_seed
from veronte4x.dronecan.definitions import DATA_TYPES
from veronte4x.dronecan.scalar_code import bit_runs
from veronte4x.dronecan.tail import split_payload, tail_byte

K = dronecan.TransferKind


def test_crc_check_value_and_seeds() -> None:
    assert crc16(b"123456789") == 0x29B1
    seeds = {t.full_name: signature_seed(t.signature) for t in DATA_TYPES}
    assert {name: seeds[name] for name in list(seeds)[:11]} == {
        "uavcan.protocol.NodeStatus": 0xBE5F,
        "uavcan.equipment.esc.Status": 0x1591,
        "uavcan.equipment.device.Temperature": 0x5D7E,
        "uavcan.equipment.esc.RawCommand": 0xE4B8,
        "uavcan.protocol.GetNodeInfo": 0xD9A7,
        "uavcan.protocol.param.GetSet": 0xFB10,
        "uavcan.protocol.RestartNode": 0x1F7F,
        "uavcan.protocol.file.BeginFirmwareUpdate": 0x729E,
        "uavcan.protocol.param.ExecuteOpcode": 0xD7D4,
        "uavcan.protocol.file.GetInfo": 0x14B9,
        "uavcan.protocol.file.Read": 0x2F12,
    }


def test_message_can_id() -> None:
    can_id = dronecan.message_can_id(priority=16, data_type_id=341, source_node_id=42)
    assert can_id == 16 << 24 | 341 << 8 | 42
    assert dronecan.parse_can_id(can_id) == dronecan.CanId(16, K.MESSAGE, 341, 42, None, None)


def test_service_can_id() -> None:
    request = dronecan.service_can_id(30, 11, True, source_node_id=5, destination_node_id=100)
    assert request == 30 << 24 | 11 << 16 | 1 << 15 | 100 << 8 | 1 << 7 | 5
    assert dronecan.parse_can_id(request) == dronecan.CanId(30, K.REQUEST, 11, 5, 100, None)
    response = dronecan.service_can_id(30, 11, False, source_node_id=100, destination_node_id=5)
    assert dronecan.parse_can_id(response) == dronecan.CanId(30, K.RESPONSE, 11, 100, 5, None)


def test_anonymous_can_id() -> None:
    can_id = dronecan.anonymous_can_id(priority=31, data_type_id=1, discriminator=0x2ABC)
    assert can_id == 31 << 24 | 0x2ABC << 10 | 1 << 8
    assert dronecan.parse_can_id(can_id) == dronecan.CanId(31, K.MESSAGE, 1, 0, None, 0x2ABC)


@pytest.mark.parametrize(
    ("function", "args"),
    [
        (dronecan.message_can_id, (32, 341, 1)),
        (dronecan.message_can_id, (0, 65536, 1)),
        (dronecan.message_can_id, (0, 341, 0)),
        (dronecan.message_can_id, (0, 341, 128)),
        (dronecan.anonymous_can_id, (0, 4, 0)),
        (dronecan.anonymous_can_id, (0, 1, 1 << 14)),
        (dronecan.service_can_id, (0, 256, True, 1, 2)),
        (dronecan.service_can_id, (0, 1, True, 1, 0)),
    ],
)
def test_can_id_ranges(function: object, args: tuple[object, ...]) -> None:
    with pytest.raises(dronecan.EncodeError):
        function(*args)  # type: ignore[operator]


@pytest.mark.parametrize("can_id", [-1, 1 << 29])
def test_parse_rejects_non_29_bit_ids(can_id: int) -> None:
    with pytest.raises(dronecan.DecodeError):
        dronecan.parse_can_id(can_id)


@pytest.mark.parametrize("can_id", ["x", 1.0, True, None])
def test_parse_refuses_a_can_id_that_is_not_an_int(can_id: object) -> None:
    with pytest.raises(TypeError, match=r"^parse_can_id\(\): can_id must be an int, not "):
        dronecan.parse_can_id(can_id)  # type: ignore[arg-type]


def test_tail_byte() -> None:
    assert tail_byte(True, True, False, 3) == 0xC3
    assert tail_byte(True, False, False, 31) == 0x9F
    assert tail_byte(False, False, True, 0) == 0x20
    assert tail_byte(False, True, False, 7) == 0x47


def test_split_payload_prefixes_crc_and_alternates_toggle() -> None:
    frames = split_payload(bytes(range(14)), 0xB7E4, 0)
    assert frames == [
        bytes.fromhex("e4b7000102030480"),
        bytes.fromhex("05060708090a0b20"),
        bytes.fromhex("0c0d40"),
    ]


def test_v0_bit_order_examples() -> None:
    # notes/dronecan-wire.md "Serialization rules".
    request = dronecan.GetSetRequest(index=5, value=dronecan.StringValue(b""), name=b"")
    frames = dronecan.encode(request, source_node_id=1, destination_node_id=2, transfer_id=0)
    assert frames[0].data[:2] == bytes.fromhex("0504")
    command = dronecan.RawCommand((1, -1, 8191, -8192, 100))
    payload = dronecan.decode_frames(
        dronecan.encode(command, source_node_id=1, transfer_id=0)
    ).message
    assert payload == command
    from veronte4x.dronecan.codec import BY_CLASS

    assert BY_CLASS[dronecan.RawCommand].encode(command, False) == bytes.fromhex(
        "0103fffff7c0206400"
    )
    status = dronecan.EscStatus(0, 0.0, 0.0, 0.0, 0x12345, 0, 0)
    assert BY_CLASS[dronecan.EscStatus].encode(status, False)[10:] == bytes.fromhex("45234000")


def test_restart_node_magic_numbers_on_the_wire() -> None:
    for magic, data in ((0xACCE551B1E, "1e1b55ceac"), (0xBEEFCAFE, "fecaefbe00")):
        frames = dronecan.encode(
            dronecan.RestartNodeRequest(magic),
            source_node_id=1,
            destination_node_id=2,
            transfer_id=4,
        )
        assert frames[0].data == bytes.fromhex(data + "c4")
    ok = dronecan.encode(
        dronecan.RestartNodeResponse(True), source_node_id=2, destination_node_id=1, transfer_id=4
    )
    assert ok[0].data == bytes.fromhex("80c4")


def test_frame_counts() -> None:
    def count(message: object, **kwargs: Any) -> int:
        return len(dronecan.encode(message, source_node_id=1, transfer_id=0, **kwargs))

    assert count(dronecan.RawCommand((0,) * 4)) == 1
    assert count(dronecan.RawCommand((0,) * 5)) == 2
    assert count(dronecan.RawCommand((0,) * 20)) == 6
    assert count(dronecan.EscStatus(0, 0.0, 0.0, 0.0, 0, 0, 0)) == 3
    assert count(dronecan.GetNodeInfoRequest(), destination_node_id=2) == 1
    empty = dronecan.encode(
        dronecan.GetNodeInfoRequest(), source_node_id=1, destination_node_id=2, transfer_id=9
    )
    assert empty[0].data == b"\xc9"


@pytest.mark.parametrize(
    ("kwargs", "field"),
    [
        ({"source_node_id": 0, "transfer_id": 0}, "source_node_id"),
        ({"source_node_id": 128, "transfer_id": 0}, "source_node_id"),
        ({"source_node_id": 1, "transfer_id": 32}, "transfer_id"),
        ({"source_node_id": 1, "transfer_id": -1}, "transfer_id"),
        ({"source_node_id": 1, "transfer_id": 0, "priority": 32}, "priority"),
        ({"source_node_id": 1, "transfer_id": 0, "destination_node_id": 5}, "destination_node_id"),
    ],
)
def test_encode_checks_transport_fields(kwargs: dict[str, Any], field: str) -> None:
    status = dronecan.NodeStatus(0, dronecan.Health.OK, dronecan.Mode.OPERATIONAL, 0, 0)
    with pytest.raises(dronecan.EncodeError) as info:
        dronecan.encode(status, **kwargs)
    assert info.value.field == field


def test_services_need_a_destination() -> None:
    with pytest.raises(dronecan.EncodeError) as info:
        dronecan.encode(dronecan.RestartNodeResponse(True), source_node_id=1, transfer_id=0)
    assert info.value.field == "destination_node_id"


# Each CAN ID builder, arguments in range, and (name, low, high) of its int arguments.
_RANGES: list[tuple[Any, tuple[Any, ...], dict[int, tuple[str, int, int]]]] = [
    (
        dronecan.message_can_id,
        (0, 341, 1),
        {0: ("priority", 0, 31), 1: ("data_type_id", 0, 0xFFFF), 2: ("source_node_id", 1, 127)},
    ),
    (
        dronecan.anonymous_can_id,
        (0, 1, 0),
        {0: ("priority", 0, 31), 1: ("data_type_id", 0, 3), 2: ("discriminator", 0, 0x3FFF)},
    ),
    (
        dronecan.service_can_id,
        (0, 1, True, 1, 2),
        {
            0: ("priority", 0, 31),
            1: ("data_type_id", 0, 0xFF),
            3: ("source_node_id", 1, 127),
            4: ("destination_node_id", 1, 127),
        },
    ),
]
_RANGE_CASES = [
    (function, args, position, *limits)
    for function, args, ranges in _RANGES
    for position, limits in ranges.items()
]


@pytest.mark.parametrize(
    ("function", "args", "position", "name", "low", "high"),
    _RANGE_CASES,
    ids=[f"{case[0].__name__}-{case[3]}" for case in _RANGE_CASES],
)
def test_can_id_builders_take_each_range_edge_and_refuse_one_beyond(
    function: Any, args: tuple[Any, ...], position: int, name: str, low: int, high: int
) -> None:
    for value in (low, high):
        changed = (*args[:position], value, *args[position + 1 :])
        assert getattr(dronecan.parse_can_id(function(*changed)), name) == value
    for value in (low - 1, high + 1):
        changed = (*args[:position], value, *args[position + 1 :])
        with pytest.raises(dronecan.EncodeError) as error:
            function(*changed)
        assert str(error.value) == f"CanId.{name} = {value}: expected an int in {low}..{high}"


def test_bit_runs_are_as_long_as_the_bit_order_allows() -> None:
    """One shift and mask per run in the generated code: consecutive bits merge."""
    assert bit_runs(0, 18) == [(0, 16, 0), (16, 2, 22)]
    assert bit_runs(3, 18) == [(0, 3, 13), (3, 5, 0), (8, 3, 21), (11, 5, 8), (16, 2, 19)]


def test_a_trailing_array_takes_no_length_in_the_largest_payload() -> None:
    """Tail array optimization: RawCommand's 20 int14 are 35 bytes, with no length field."""
    classes = (dronecan.NodeStatus, dronecan.EscStatus, dronecan.RawCommand)
    assert [BY_CLASS[cls].max_payload for cls in classes] == [7, 14, 35]


def test_schemas_are_frozen() -> None:
    """The generated codecs are built from them once, at import: they must not change."""
    with pytest.raises(dataclasses.FrozenInstanceError):
        DATA_TYPES[0].schema.name = "changed"  # type: ignore[misc]
