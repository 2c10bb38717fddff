"""Vertiq helpers (seed 004) and the plain-data conversions."""

from __future__ import annotations

import math

import pytest

from veronte4x import dronecan
from veronte4x.dronecan import vertiq


def _request_frames(request: dronecan.GetSetRequest) -> list[bytes]:
    frames = dronecan.encode(request, source_node_id=1, destination_node_id=20, transfer_id=5)
    return [f.data for f in frames]


def test_parameter_names_and_values() -> None:
    assert [p.value for p in vertiq.Parameter] == [
        "uavcan_node_id",
        "bit_rate",
        "esc_index",
        "zero_behavior",
        "telem_frequency",
    ]
    assert [(z.name, z.value) for z in vertiq.ZeroBehavior] == [
        ("COAST", 0),
        ("BRAKE", 1),
        ("NORMAL_CONTROLLER", 2),
    ]
    assert vertiq.NODE_NAME == "iq_motion.esc"


def test_set_esc_index_by_name() -> None:
    request = vertiq.set_parameter(vertiq.Parameter.ESC_INDEX, 3)
    assert request == dronecan.GetSetRequest(0, dronecan.IntegerValue(3), b"esc_index")
    # index 0 (13 bits) + tag 1 (3 bits), int64 3, then the name without a length prefix.
    payload = b"\x00\x01" + (3).to_bytes(8, "little") + b"esc_index"
    decoded = dronecan.decode_frames(
        dronecan.encode(request, source_node_id=1, destination_node_id=20, transfer_id=5)
    )
    assert decoded.message == request
    from veronte4x.dronecan.codec import BY_CLASS

    assert BY_CLASS[dronecan.GetSetRequest].encode(request, False) == payload


def test_get_and_discovery_requests() -> None:
    assert vertiq.get_parameter("zero_behavior") == dronecan.GetSetRequest(
        0, dronecan.Empty(), b"zero_behavior"
    )
    assert _request_frames(vertiq.get_parameter_by_index(7)) == [bytes.fromhex("0700c5")]
    assert vertiq.set_parameter("x", vertiq.ZeroBehavior.BRAKE).value == dronecan.IntegerValue(1)
    assert vertiq.set_parameter("x", 2.5).value == dronecan.RealValue(2.5)
    assert vertiq.set_parameter("x", True).value == dronecan.BooleanValue(1)
    assert vertiq.set_parameter("x", "on").value == dronecan.StringValue(b"on")


def test_discovery_walk_stops_at_the_empty_reply() -> None:
    replies = [
        dronecan.GetSetResponse(dronecan.IntegerValue(42), name=b"uavcan_node_id"),
        dronecan.GetSetResponse(dronecan.IntegerValue(0), name=b"esc_index"),
        dronecan.GetSetResponse(),
        dronecan.GetSetResponse(dronecan.IntegerValue(9), name=b"never_reached"),
    ]
    assert vertiq.is_end_of_parameters(replies[2])
    assert vertiq.discovered_parameters(replies) == {
        "uavcan_node_id": dronecan.IntegerValue(42),
        "esc_index": dronecan.IntegerValue(0),
    }


def test_restart_magic_numbers() -> None:
    assert vertiq.restart() == dronecan.RestartNodeRequest(0xACCE551B1E)
    assert vertiq.restart(bootloader=True) == dronecan.RestartNodeRequest(0xBEEFCAFE)
    assert vertiq.RESTART_MAGIC == dronecan.RestartNodeRequest.MAGIC_NUMBER


def test_throttle_helpers() -> None:
    assert vertiq.throttle_to_raw(1.0) == 8191
    assert vertiq.throttle_to_raw(-1.0) == -8192
    assert vertiq.throttle_to_raw(0.0) == 0
    assert vertiq.throttle_to_raw(0.5) == 4096  # 4095.5 rounds away from zero
    assert vertiq.throttle_to_raw(-0.5) == -4096
    assert vertiq.raw_to_throttle(8191) == 1.0
    assert vertiq.raw_to_throttle(-8192) == -1.0
    command = vertiq.raw_command({0: 1.0, 3: -0.25})
    assert command == dronecan.RawCommand((8191, 0, 0, -2048))
    assert vertiq.throttles(command) == (1.0, 0.0, 0.0, -0.25)
    assert vertiq.raw_command([0.0] * 20).cmd == (0,) * 20


@pytest.mark.parametrize("bad", [1.01, -1.5, math.nan, math.inf])
def test_throttle_out_of_range(bad: float) -> None:
    with pytest.raises(dronecan.EncodeError):
        vertiq.throttle_to_raw(bad)


def test_raw_command_limits() -> None:
    with pytest.raises(dronecan.EncodeError):
        vertiq.raw_command([0.0] * 21)
    with pytest.raises(dronecan.EncodeError):
        vertiq.raw_command({20: 0.5})


def test_to_builtin_and_back() -> None:
    response = dronecan.GetNodeInfoResponse(
        status=dronecan.NodeStatus(5, dronecan.Health.WARNING, dronecan.Mode.MAINTENANCE, 1, 2),
        software_version=dronecan.SoftwareVersion(1, 2, 3, 0xDEADBEEF, 2**64 - 1),
        hardware_version=dronecan.HardwareVersion(4, 5, bytes(range(16)), b"coa"),
        name=vertiq.NODE_NAME.encode(),
    )
    plain = dronecan.to_builtin(response)
    assert plain == {
        "status": {
            "uptime_sec": 5,
            "health": 1,
            "mode": 2,
            "sub_mode": 1,
            "vendor_specific_status_code": 2,
        },
        "software_version": {
            "major": 1,
            "minor": 2,
            "optional_field_flags": 3,
            "vcs_commit": 0xDEADBEEF,
            "image_crc": 2**64 - 1,
        },
        "hardware_version": {
            "major": 4,
            "minor": 5,
            "unique_id": list(range(16)),
            "certificate_of_authenticity": list(b"coa"),
        },
        "name": list(b"iq_motion.esc"),
    }
    assert dronecan.from_builtin(dronecan.GetNodeInfoResponse, plain) == response
    get_set = dronecan.GetSetResponse(
        dronecan.StringValue(b"ab"), dronecan.Empty(), dronecan.RealValue(1.5)
    )
    assert dronecan.to_builtin(get_set) == {
        "value": {"string_value": [97, 98]},
        "default_value": {"empty": {}},
        "max_value": {"real_value": 1.5},
        "min_value": {"empty": {}},
        "name": [],
    }
    assert dronecan.to_builtin(dronecan.IntegerValue(5)) == {"integer_value": 5}
    assert dronecan.to_builtin(dronecan.Mode.OFFLINE) == 7


def test_reserved_modes_and_unknown_errors_decode_as_ints() -> None:
    status = dronecan.NodeStatus(0, dronecan.Health.OK, 5, 0, 0)
    frames = dronecan.encode(status, source_node_id=1, transfer_id=0)
    mode = dronecan.decode_frames(frames).message.mode
    assert mode == 5
    assert not isinstance(mode, dronecan.Mode)
    response = dronecan.BeginFirmwareUpdateResponse(7, b"")
    frames = dronecan.encode(response, source_node_id=1, destination_node_id=2, transfer_id=0)
    assert dronecan.decode_frames(frames).message.error == 7
    response = dronecan.BeginFirmwareUpdateResponse(dronecan.FirmwareUpdateError.INVALID_MODE)
    frames = dronecan.encode(response, source_node_id=1, destination_node_id=2, transfer_id=0)
    error = dronecan.decode_frames(frames).message.error
    assert error is dronecan.FirmwareUpdateError.INVALID_MODE


def test_decoded_objects_are_ordinary_frozen_instances() -> None:
    status = dronecan.NodeStatus(1, dronecan.Health.OK, dronecan.Mode.OPERATIONAL, 0, 0)
    decoded = dronecan.decode_frames(dronecan.encode(status, source_node_id=1, transfer_id=0))
    assert type(decoded.message) is dronecan.NodeStatus
    assert decoded.message == status
    assert hash(decoded.message) == hash(status)
    with pytest.raises(AttributeError):
        decoded.message.uptime_sec = 2  # type: ignore[misc]


@pytest.mark.parametrize(
    ("message", "field"),
    [
        (dronecan.NodeStatus(-1, dronecan.Health.OK, 0, 0, 0), "uptime_sec"),
        (dronecan.NodeStatus(0, 4, 0, 0, 0), "health"),  # type: ignore[arg-type]
        (dronecan.EscStatus(0, 1.0, 1.0, 1.0, 2**17, 0, 0), "rpm"),
        (dronecan.EscStatus(0, "1", 1.0, 1.0, 0, 0, 0), "voltage"),  # type: ignore[arg-type]
        (dronecan.RawCommand((8192,)), "cmd[0]"),
        (dronecan.RawCommand((0,) * 21), "cmd"),
        (dronecan.RawCommand((1.0,)), "cmd[0]"),  # type: ignore[arg-type]
        (dronecan.Temperature(0, 1.0, 256), "error_flags"),
    ],
)
def test_encode_errors_name_the_field(message: object, field: str) -> None:
    with pytest.raises(dronecan.EncodeError) as info:
        dronecan.encode(message, source_node_id=1, transfer_id=0)
    assert info.value.field == field
    assert field.split("[")[0] in str(info.value)


def test_saturation_is_opt_in() -> None:
    status = dronecan.EscStatus(2**33, 1.0, 1.0, 1.0, -(2**20), 200, 40)
    frames = dronecan.encode(status, source_node_id=1, transfer_id=0, saturate=True)
    assert dronecan.decode_frames(frames).message == dronecan.EscStatus(
        2**32 - 1, 1.0, 1.0, 1.0, -(2**17), 127, 31
    )


@pytest.mark.parametrize("index", [-1, 20])
def test_raw_command_refuses_an_esc_index_out_of_range(index: int) -> None:
    with pytest.raises(dronecan.EncodeError) as error:
        vertiq.raw_command({index: 0.5})
    assert str(error.value) == f"RawCommand.cmd = {index!r}: expected ESC indices 0..19"


@pytest.mark.parametrize("build", [vertiq.get_parameter, lambda n: vertiq.set_parameter(n, 1)])
def test_an_empty_parameter_name_is_refused(build: object) -> None:
    # With index 0, an empty name addresses the first parameter (DSDL param.GetSet): a
    # set_parameter("") would change whatever parameter a module keeps there.
    with pytest.raises(dronecan.EncodeError, match="empty name would address index 0"):
        build("")  # type: ignore[operator]
