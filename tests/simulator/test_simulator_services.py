"""Service requests: GetNodeInfo, GetSet, RestartNode, BeginFirmwareUpdate; RawCommand."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from veronte4x import dronecan
from veronte4x.dronecan import vertiq
from veronte4x.dronecan.vertiq import ZeroBehavior
from veronte4x.errors import EncodeError
from veronte4x.simulator import (
    DEFAULT_MODEL,
    NO_PARAMETER,
    SOFTWARE_VERSION,
    UNIQUE_ID_PREFIX,
    SimulatedEsc,
)

from .support import ESC, ask, decode, feed, names

Int = dronecan.IntegerValue


def test_get_node_info_bytes_and_fields() -> None:
    esc = SimulatedEsc(ESC)
    esc.poll(0.0)
    feed(esc, dronecan.GetNodeInfoRequest(), 3.7, transfer_id=7, priority=30)
    frames = esc.poll(3.7)
    expected = dronecan.GetNodeInfoResponse(
        status=dronecan.NodeStatus(3, dronecan.Health.OK, dronecan.Mode.OPERATIONAL, 0, 0),
        software_version=SOFTWARE_VERSION,
        hardware_version=dronecan.HardwareVersion(1, 0, UNIQUE_ID_PREFIX + b"\x14"),
        name=b"iq_motion.esc",
    )
    reply = dronecan.encode(
        expected, source_node_id=ESC, destination_node_id=1, transfer_id=7, priority=30
    )
    assert frames[: len(reply)] == reply
    assert names(frames[len(reply) :]) == ["NodeStatus", "EscStatus", "Temperature"]
    (response, *_) = decode(frames)
    assert response.message == expected
    assert (response.priority, response.transfer_id, response.destination_node_id) == (30, 7, 1)


@pytest.mark.parametrize(
    ("name", "value", "minimum", "maximum"),
    [
        ("uavcan_node_id", 20, 1, 127),
        ("bit_rate", 250000, 10000, 1000000),
        ("esc_index", 3, 0, 19),
        ("zero_behavior", 1, 0, 2),
        ("telem_frequency", 25, 0, 1000),
    ],
)
def test_get_each_parameter_by_name(name: str, value: int, minimum: int, maximum: int) -> None:
    esc = SimulatedEsc(
        ESC, 3, telem_frequency=25, zero_behavior=ZeroBehavior.BRAKE, bit_rate=250000
    )
    response = ask(esc, vertiq.get_parameter(name), 0.0, transfer_id=4)
    assert response.transfer_id == 4
    assert response.message == dronecan.GetSetResponse(
        Int(value), Int(value), Int(maximum), Int(minimum), name.encode()
    )


def test_discovery_by_index_ends_with_the_empty_reply() -> None:
    esc = SimulatedEsc(ESC, 1)
    replies = [ask(esc, vertiq.get_parameter_by_index(i), 0.0).message for i in range(7)]
    assert replies[5] == replies[6] == NO_PARAMETER
    assert vertiq.is_end_of_parameters(replies[5])
    assert vertiq.discovered_parameters(replies) == {
        "uavcan_node_id": Int(20),
        "bit_rate": Int(500000),
        "esc_index": Int(1),
        "zero_behavior": Int(0),
        "telem_frequency": Int(10),
    }
    # The empty reply: void padding and empty union tags (4 bytes), no name, the tail.
    feed(esc, vertiq.get_parameter_by_index(5), 0.5, transfer_id=3)
    assert esc.poll(0.5)[0] == dronecan.TransferFrame(0x100B0194, bytes.fromhex("00000000c3"))


def test_unknown_name_gets_the_empty_reply() -> None:
    esc = SimulatedEsc(ESC)
    assert ask(esc, vertiq.get_parameter("rpm_max"), 0.0).message == NO_PARAMETER
    assert ask(esc, vertiq.set_parameter("rpm_max", 5), 0.0).message == NO_PARAMETER


def test_name_wins_over_index() -> None:
    esc = SimulatedEsc(ESC)
    request = dronecan.GetSetRequest(index=0, value=dronecan.Empty(), name=b"esc_index")
    assert ask(esc, request, 0.0).message.name == b"esc_index"


def test_set_esc_index_takes_effect_at_once() -> None:
    esc = SimulatedEsc(ESC, 0)
    response = ask(esc, vertiq.set_parameter(vertiq.Parameter.ESC_INDEX, 2), 1.0)
    assert response.message == dronecan.GetSetResponse(
        Int(2), Int(0), Int(19), Int(0), b"esc_index"
    )
    assert esc.esc_index == 2
    assert esc.state.parameters["esc_index"] == 2
    feed(esc, vertiq.raw_command([0.1, 0.2]), 1.0)
    assert esc.state.throttle == 0.0  # no entry at index 2
    feed(esc, vertiq.raw_command([0.1, 0.2, 0.5]), 1.0)
    assert esc.state.throttle == vertiq.raw_to_throttle(4096)
    status, temperature = (t.message for t in decode(esc.poll(1.1)))
    assert (status.esc_index, status.power_rating_pct) == (2, 50)
    assert temperature.device_id == 2


@pytest.mark.parametrize(
    "value",
    [
        Int(20),
        Int(-1),
        dronecan.RealValue(2.0),
        dronecan.BooleanValue(1),
        dronecan.StringValue(b"2"),
    ],
)
def test_set_out_of_range_or_not_integer_changes_nothing(value: dronecan.Value) -> None:
    esc = SimulatedEsc(ESC, 1)
    response = ask(esc, vertiq.set_parameter("esc_index", value), 0.0)
    assert response.message.value == Int(1)
    assert esc.esc_index == 1


def test_set_telem_frequency_restarts_the_schedule() -> None:
    esc = SimulatedEsc(ESC, telem_frequency=10)
    esc.poll(0.0)
    esc.poll(0.9)
    response = ask(esc, vertiq.set_parameter("telem_frequency", 20), 0.93)
    assert response.message.value == Int(20)
    assert esc.next_time() == 0.93 + 0.05
    assert names(esc.poll(0.98)) == ["EscStatus", "Temperature"]
    assert names(esc.poll(1.0)) == ["NodeStatus"]
    assert names(esc.poll(1.03)) == ["EscStatus", "Temperature"]
    ask(esc, vertiq.set_parameter("telem_frequency", 0), 1.04)
    assert [names(esc.poll(t / 10)) for t in range(11, 20)] == [[]] * 9
    assert names(esc.poll(2.0)) == ["NodeStatus"]


def test_set_zero_behavior_and_bit_rate() -> None:
    esc = SimulatedEsc(ESC)
    ask(esc, vertiq.set_parameter("zero_behavior", ZeroBehavior.NORMAL_CONTROLLER), 0.0)
    ask(esc, vertiq.set_parameter("bit_rate", 1_000_000), 0.0)
    assert esc.state.parameters == {
        "uavcan_node_id": 20,
        "bit_rate": 1_000_000,
        "esc_index": 0,
        "zero_behavior": 2,
        "telem_frequency": 10,
    }
    feed(esc, vertiq.raw_command([0.0]), 0.0)
    assert esc.motor.driven  # the normal controller keeps running at 0 %
    esc.poll(1.0)
    assert esc.state.current == DEFAULT_MODEL.idle_current


def test_node_id_changes_after_a_normal_restart() -> None:
    esc = SimulatedEsc(ESC)
    esc.poll(0.0)
    response = ask(esc, vertiq.set_parameter("uavcan_node_id", 42), 2.5)
    assert response.message.value == Int(42)
    assert esc.node_id == 20
    assert response.source_node_id == 20
    feed(esc, dronecan.GetNodeInfoRequest(), 2.6, destination=42)
    assert names(esc.poll(2.6)) == ["EscStatus", "Temperature"]  # no reply: still node 20
    feed(esc, vertiq.raw_command([0.5]), 2.6)
    feed(esc, vertiq.restart(), 3.25, transfer_id=9, priority=5)
    restart, *transfers = decode(esc.poll(3.25))
    assert restart.message == dronecan.RestartNodeResponse(True)
    assert (restart.source_node_id, restart.transfer_id, restart.priority) == (20, 9, 5)
    assert esc.node_id == 42
    assert esc.state.throttle == 0.0 and not esc.motor.driven
    assert [(t.source_node_id, t.transfer_id) for t in transfers] == [(42, 0)] * 3
    assert transfers[0].message.uptime_sec == 0
    assert decode(esc.poll(5.25))[0].message.uptime_sec == 2
    assert ask(esc, vertiq.get_parameter("uavcan_node_id"), 5.3, destination=42).message.value == (
        Int(42)
    )


def test_restart_frames_are_byte_exact() -> None:
    esc = SimulatedEsc(ESC)
    feed(esc, vertiq.restart(), 1.0, transfer_id=3)
    # RestartNode response (service 5), priority 16, to node 1 from 20: ok bit set.
    assert esc.poll(1.0)[0] == dronecan.TransferFrame(0x10050194, bytes.fromhex("80c3"))


def test_bootloader_restart_goes_silent_until_power_cycle() -> None:
    esc = SimulatedEsc(ESC)
    esc.poll(0.0)
    feed(esc, vertiq.raw_command([1.0]), 0.0)
    response = ask(esc, vertiq.restart(bootloader=True), 0.5, transfer_id=1)
    assert response.message == dronecan.RestartNodeResponse(True)
    assert esc.state.in_bootloader
    assert not esc.motor.driven
    feed(esc, dronecan.GetNodeInfoRequest(), 0.6)
    assert [esc.poll(t) for t in (0.6, 1.0, 5.0)] == [[], [], []]
    assert esc.next_time() is None
    esc.power_cycle(6.0)
    assert not esc.state.in_bootloader
    assert names(esc.poll(6.0)) == ["NodeStatus", "EscStatus", "Temperature"]


@pytest.mark.parametrize("magic", [0, 0xACCE551B1F, 0xBEEFCAFF, 0xFFFFFFFFFF])
def test_other_magic_numbers_are_refused(magic: int) -> None:
    esc = SimulatedEsc(ESC)
    esc.poll(0.0)
    response = ask(esc, dronecan.RestartNodeRequest(magic), 2.5)
    assert response.message == dronecan.RestartNodeResponse(False)
    assert esc.state.uptime_sec == 2
    assert not esc.state.in_bootloader


def _firmware(source: int = 0) -> dronecan.BeginFirmwareUpdateRequest:
    return dronecan.BeginFirmwareUpdateRequest(source, dronecan.Path(b"fw/esc.bin"))


def test_begin_firmware_update_enters_software_update_mode() -> None:
    esc = SimulatedEsc(ESC)
    feed(esc, vertiq.raw_command([0.5]), 0.0)
    response = ask(esc, _firmware(), 0.2, transfer_id=6)
    assert response.message == dronecan.BeginFirmwareUpdateResponse(dronecan.FirmwareUpdateError.OK)
    assert esc.state.mode is dronecan.Mode.SOFTWARE_UPDATE
    assert esc.state.firmware_source == (1, b"fw/esc.bin")
    assert not esc.motor.driven
    feed(esc, vertiq.raw_command([0.5]), 0.3)
    assert esc.state.throttle == 0.0  # commands are ignored during an update
    sent = decode(esc.poll(1.0))
    # It asks the file server (node 1, the caller) about the image, then keeps reporting.
    assert sent[0].message == dronecan.FileGetInfoRequest(dronecan.Path(b"fw/esc.bin"))
    assert sent[0].destination_node_id == 1
    statuses = [t.message for t in sent if isinstance(t.message, dronecan.NodeStatus)]
    assert statuses[0].mode == dronecan.Mode.SOFTWARE_UPDATE
    again = ask(esc, _firmware(7), 1.1)
    assert again.message.error == dronecan.FirmwareUpdateError.IN_PROGRESS
    ask(esc, vertiq.restart(), 1.2)
    assert esc.state.mode is dronecan.Mode.OPERATIONAL
    assert esc.state.firmware_source is None


def test_begin_firmware_update_unsupported_is_invalid_mode() -> None:
    esc = SimulatedEsc(ESC, supports_firmware_update=False)
    response = ask(esc, _firmware(5), 0.0)
    assert response.message == dronecan.BeginFirmwareUpdateResponse(
        dronecan.FirmwareUpdateError.INVALID_MODE
    )
    assert esc.state.mode is dronecan.Mode.OPERATIONAL
    # error 1, empty message: one payload byte and the tail.
    feed(esc, _firmware(5), 0.0, transfer_id=2)
    assert esc.poll(0.0)[0] == dronecan.TransferFrame(0x10280194, bytes.fromhex("01c2"))


def test_requests_to_other_nodes_and_responses_are_ignored() -> None:
    esc = SimulatedEsc(ESC)
    feed(esc, dronecan.GetNodeInfoRequest(), 0.0, destination=21)
    feed(esc, dronecan.RestartNodeResponse(True), 0.0, destination=ESC)
    assert names(esc.poll(0.0)) == ["NodeStatus", "EscStatus", "Temperature"]


def test_raw_command_at_its_index() -> None:
    esc = SimulatedEsc(ESC, 3, command_timeout=None)
    feed(esc, vertiq.raw_command({3: -1.0}), 0.0)
    assert esc.state.throttle == -1.0
    esc.poll(DEFAULT_MODEL.drive_time_constant)
    assert esc.state.rpm == -DEFAULT_MODEL.max_rpm * -math.expm1(-1.0)
    assert esc.state.power_rating_pct == 100
    feed(esc, vertiq.raw_command({0: 1.0, 3: 0.0}), 0.3)  # entry 3 is 0: the zero behaviour, coast
    assert esc.state.throttle == 0.0 and not esc.motor.driven


def test_frames_before_start_time_are_ignored() -> None:
    esc = SimulatedEsc(ESC, start_time=10.0)
    feed(esc, vertiq.raw_command([1.0]), 9.0)
    feed(esc, dronecan.GetNodeInfoRequest(), 9.0)
    assert esc.state.throttle == 0.0
    assert names(esc.poll(10.0)) == ["NodeStatus", "EscStatus", "Temperature"]


@pytest.mark.parametrize(
    ("argument", "value"),
    [
        ("node_id", 0),
        ("node_id", 128),
        ("esc_index", 20),
        ("telem_frequency", 2.5),
        ("telem_frequency", -1),
        ("telem_frequency", math.nan),
        ("zero_behavior", 3),
        ("bit_rate", 5000),
        ("priority", 32),
        ("node_id", True),
        ("esc_index", "1"),
    ],
)
def test_bad_constructor_arguments(argument: str, value: object) -> None:
    kwargs: dict[str, object] = {"node_id": 20, argument: value}
    with pytest.raises(dronecan.EncodeError) as error:
        SimulatedEsc(**kwargs)  # type: ignore[arg-type]
    assert error.value.field == argument
    assert error.value.message_type == "SimulatedEsc"
    assert error.value.value is value or math.isnan(error.value.value)  # type: ignore[arg-type]


@settings(max_examples=300)
@given(
    st.lists(
        st.tuples(st.integers(0, 0x1FFFFFFF), st.binary(min_size=0, max_size=9)),
        max_size=30,
    )
)
def test_bad_frames_never_raise(frames: list[tuple[int, bytes]]) -> None:
    esc = SimulatedEsc(ESC)
    for i, (can_id, data) in enumerate(frames):
        esc.receive(can_id, data, i * 0.01)
        esc.poll(i * 0.01)


def test_a_response_delay_holds_each_answer_and_each_read() -> None:
    esc = SimulatedEsc(ESC, telem_frequency=0, response_delay=0.002)
    esc.poll(0.0)
    feed(esc, vertiq.get_parameter("esc_index"), 0.5)
    assert esc.poll(0.501) == [] and esc.next_time() == pytest.approx(0.502)
    (reply,) = decode(esc.poll(0.502))
    assert reply.message.name == b"esc_index"
    for bad in (-0.1, float("nan"), True):
        with pytest.raises(EncodeError) as refused:
            SimulatedEsc(ESC, response_delay=bad)
        assert str(refused.value) == (
            f"SimulatedEsc.response_delay = {bad!r}: expected seconds, 0 or above"
        )


def test_an_opcode_other_than_save_and_erase_is_refused_with_argument_zero() -> None:
    """A mutation survivor: the refusal's ``argument`` made -1."""
    esc = SimulatedEsc(ESC, telem_frequency=0)
    esc.poll(0.0)
    reply = ask(esc, dronecan.ExecuteOpcodeRequest(opcode=7), 0.5)
    assert reply.message == dronecan.ExecuteOpcodeResponse(0, False)


def test_a_power_cycle_drops_the_answers_still_held_by_the_response_delay() -> None:
    """A mutation survivor: `power_cycle` kept the delayed answers of before the cycle."""
    esc = SimulatedEsc(ESC, telem_frequency=0, response_delay=0.002)
    esc.poll(0.0)
    feed(esc, vertiq.get_parameter("esc_index"), 0.5)
    esc.power_cycle(0.501)
    assert names(esc.poll(0.501)) == ["NodeStatus"]
    assert esc.poll(0.502) == [] and esc.poll(0.6) == []
    assert esc.next_time() == pytest.approx(1.501)
