"""The client against simulated Vertiq ESCs on python-can's virtual bus.

Most tests run the ESCs and the client in one thread with a clock that moves 1 ms at every
reading (the client's waits step the simulators), so they are deterministic. The command
stream's tests are in ``test_command_stream.py``.
"""

from __future__ import annotations

import itertools
from collections.abc import Iterator

import can
import pytest

from veronte4x import dronecan
from veronte4x.client import (
    FirmwareUpdateFailedError,
    InvalidRequestError,
    NoResponseError,
    ParameterError,
    Phase,
    UpdateProgress,
)
from veronte4x.client.bus import BusClient
from veronte4x.dronecan.image_crc import crc64we
from veronte4x.simulator import SimulatedEsc
from veronte4x.simulator.can_node import EscBus

from ..simulator.support import StepClock

_CHANNELS = itertools.count()
NODES = (21, 22, 23)


@pytest.fixture
def buses() -> Iterator[tuple[can.BusABC, can.BusABC]]:
    channel = f"test-client-{next(_CHANNELS)}"
    with (
        can.Bus(interface="virtual", channel=channel) as esc_bus,
        can.Bus(interface="virtual", channel=channel) as client_bus,
    ):
        yield esc_bus, client_bus


def _setup(
    buses: tuple[can.BusABC, can.BusABC], *escs: SimulatedEsc, timeout: float = 0.2
) -> tuple[EscBus, BusClient]:
    esc_bus, client_bus = buses
    clock = StepClock(0.001)
    node = EscBus(esc_bus, escs or [SimulatedEsc(n, i) for i, n in enumerate(NODES)], clock)
    client = BusClient(client_bus, clock=clock, timeout=timeout, retries=1, while_waiting=node.step)
    return node, client


def test_discovery_finds_every_node(buses: tuple[can.BusABC, can.BusABC]) -> None:
    _, client = _setup(buses)
    found = client.discover(1.1)
    assert [e.node_id for e in found] == list(NODES)
    assert {(e.health, e.mode) for e in found} == {(dronecan.Health.OK, dronecan.Mode.OPERATIONAL)}
    assert all(e.uptime_sec in (0, 1) and e.restarts == 0 for e in found)


def test_node_info(buses: tuple[can.BusABC, can.BusABC]) -> None:
    _, client = _setup(buses)
    info = client.node_info(22)
    assert info.name == b"iq_motion.esc"
    assert info.hardware_version.unique_id == b"veronte4x.sim\x00\x00\x16"
    assert info.status.mode == dronecan.Mode.OPERATIONAL


def test_every_parameter_set_saved_and_read_back(buses: tuple[can.BusABC, can.BusABC]) -> None:
    _, client = _setup(buses)
    listed = [p.as_dict() for p in client.list_params(21)]
    assert listed == [
        {"name": "uavcan_node_id", "value": 21, "default": 21, "min": 1, "max": 127, "index": 0},
        {"name": "bit_rate", "value": 500000, "default": 500000, "min": 10000, "max": 1000000,
         "index": 1},
        {"name": "esc_index", "value": 0, "default": 0, "min": 0, "max": 19, "index": 2},
        {"name": "zero_behavior", "value": 0, "default": 0, "min": 0, "max": 2, "index": 3},
        {"name": "telem_frequency", "value": 10, "default": 10, "min": 0, "max": 1000,
         "index": 4},
    ]  # fmt: skip
    after = client.set_param(21, "esc_index", "7")
    assert dronecan.to_builtin(after.value) == {"integer_value": 7}
    client.save_params(21)
    assert client.get_param(21, "esc_index").value == dronecan.IntegerValue(7)
    client.erase_params(21)
    assert client.get_param(21, "esc_index").value == dronecan.IntegerValue(0)
    by_index = client.set_param(21, None, 25, index=4)  # telem_frequency, by index
    assert (by_index.name, by_index.value, by_index.index) == (
        "telem_frequency",
        dronecan.IntegerValue(25),
        4,
    )
    assert client.get_param(21, index=4).as_dict()["value"] == 25
    with pytest.raises(ParameterError, match=r"^node 21 has no parameter at index 5$"):
        client.get_param(21, index=5)


def test_bad_parameter_name_and_value(buses: tuple[can.BusABC, can.BusABC]) -> None:
    _, client = _setup(buses)
    with pytest.raises(ParameterError, match=r"^node 21 has no parameter 'esc_idx'$"):
        client.get_param(21, "esc_idx")
    with pytest.raises(ParameterError, match=r"^node 21: 20 is out of range for esc_index: 0..19$"):
        client.set_param(21, "esc_index", 20)
    with pytest.raises(
        InvalidRequestError, match=r"^node 21: esc_index takes an integer, not 'two'$"
    ):
        client.set_param(21, "esc_index", "two")
    assert client.get_param(21, "esc_index").value == dronecan.IntegerValue(0)


def test_restart(buses: tuple[can.BusABC, can.BusABC]) -> None:
    node, client = _setup(buses)
    client.set_param(23, "uavcan_node_id", 42)
    client.discover(2.0)
    client.restart(23)
    found = [e.node_id for e in client.discover(1.1)]
    assert 42 in found
    assert node.escs[2].state.uptime_sec == 1


def test_no_node_is_a_one_line_error(buses: tuple[can.BusABC, can.BusABC]) -> None:
    _, client = _setup(buses)
    with pytest.raises(NoResponseError) as error:
        client.node_info(99)
    assert str(error.value) == (
        "node 99 did not answer uavcan.protocol.GetNodeInfo (sent 2 times, 0.2 s each); "
        "check the node id, the bus and the bit rate"
    )


def _image(size: int) -> bytes:
    return bytes((i * 7 + i // 256) & 0xFF for i in range(size))


def test_firmware_update_pulls_the_image_and_checks_its_crc(
    buses: tuple[can.BusABC, can.BusABC],
) -> None:
    node, client = _setup(buses)
    image = _image(3000)
    seen: list[UpdateProgress] = []
    info = client.update_firmware(22, image, "esc-v2.bin", progress=seen.append)
    assert info.software_version.image_crc == crc64we(image)
    assert info.software_version.optional_field_flags == dronecan.SoftwareVersionFlag.IMAGE_CRC
    assert info.status.mode == dronecan.Mode.OPERATIONAL
    phases = [p.phase for p in seen]
    assert phases[0] is Phase.WAITING and phases[-1] is Phase.DONE
    assert [p.sent for p in seen if p.phase is Phase.READING] == list(range(256, 3000, 256))
    assert node.escs[1].state.mode is dronecan.Mode.OPERATIONAL


def test_firmware_update_of_a_node_that_hangs(buses: tuple[can.BusABC, can.BusABC]) -> None:
    node, client = _setup(buses, SimulatedEsc(21, update_stall_offset=1024))
    with pytest.raises(FirmwareUpdateFailedError) as error:
        client.update_firmware(21, _image(4096), read_timeout=0.5)
    assert str(error.value) == (
        "node 21 stopped reading the image at byte 1024 of 4096 (nothing for 0.5 s)"
    )
    assert not node.escs[0].motor.driven


def test_firmware_update_refused(buses: tuple[can.BusABC, can.BusABC]) -> None:
    _, client = _setup(buses, SimulatedEsc(21, supports_firmware_update=False))
    with pytest.raises(
        FirmwareUpdateFailedError, match=r"^node 21 refused the update: INVALID_MODE"
    ):
        client.update_firmware(21, _image(10))
