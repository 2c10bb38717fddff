"""The operations the fleet commands run, in-process: `read_node` (what a parameter file
keeps of a node) and `update_unless_current` (skip a node that runs the image already,
unless forced). Sans-IO: simulated ESCs behind a `Peer`, time as an argument."""

from __future__ import annotations

from typing import Any

from veronte4x import dronecan
from veronte4x.client import operations as ops
from veronte4x.client.protocol import ClientProtocol
from veronte4x.dronecan.image_crc import crc64we
from veronte4x.simulator import SimulatedEsc
from veronte4x.simulator.esc import UNIQUE_ID_PREFIX

from .peer import Peer

IMAGE = bytes(range(256)) * 2 + b"v2"


class Bench:
    """One client and its simulated nodes; operations run one after another, in one time."""

    def __init__(self, peer: Peer) -> None:
        self.peer = peer
        self.protocol = ClientProtocol()
        self.runner = ops.Runner(self.protocol, timeout=0.5, retries=0)
        self.now = 0.0

    def run(self, operation: ops.Operation[Any]) -> ops.Task[Any]:
        task = self.runner.start(operation, self.now)
        self.now = self.peer.run(self.protocol, self.runner, task, 0.01, self.now)
        return task


def _info(flags: int, crc: int, name: bytes = b"iq_motion.esc") -> dronecan.GetNodeInfoResponse:
    return dronecan.GetNodeInfoResponse(
        dronecan.NodeStatus(9, dronecan.Health.OK, dronecan.Mode.OPERATIONAL, 0, 0),
        dronecan.SoftwareVersion(2, 7, flags, 0, crc),
        dronecan.HardwareVersion(1, 0, bytes(range(16))),
        name,
    )


def _begins(peer: Peer) -> int:
    return sum(isinstance(r, dronecan.BeginFirmwareUpdateRequest) for r in peer.requests)


def test_a_node_read_for_its_parameter_file() -> None:
    peer = Peer([SimulatedEsc(21, 3)])
    node = Bench(peer).run(ops.read_node(21)).result()
    assert (node.node_id, node.name, node.unique_id, node.software_version, node.image_crc) == (
        21,
        "iq_motion.esc",
        (UNIQUE_ID_PREFIX + bytes([21])).hex(),
        "1.0",
        None,  # the simulator reports no image CRC before an update
    )
    assert [(p.name, p.value, p.index) for p in node.parameters] == [
        ("uavcan_node_id", dronecan.IntegerValue(21), 0),
        ("bit_rate", dronecan.IntegerValue(500000), 1),
        ("esc_index", dronecan.IntegerValue(3), 2),
        ("zero_behavior", dronecan.IntegerValue(0), 3),
        ("telem_frequency", dronecan.IntegerValue(10), 4),
    ]


def test_a_node_with_an_image_crc_and_a_name_that_is_no_utf8() -> None:
    info = _info(dronecan.SoftwareVersionFlag.IMAGE_CRC, 0x0123456789ABCDEF, b"esc\xff")
    peer = Peer(
        [SimulatedEsc(21)], lambda r: info if isinstance(r, dronecan.GetNodeInfoRequest) else None
    )
    node = Bench(peer).run(ops.read_node(21)).result()
    assert (node.name, node.unique_id, node.software_version, node.image_crc) == (
        "esc\ufffd",
        bytes(range(16)).hex(),
        "2.7",
        "0x0123456789abcdef",
    )


def test_a_node_that_runs_the_image_is_skipped_unless_forced() -> None:
    bench = Bench(Peer([SimulatedEsc(21)]))
    peer, protocol = bench.peer, bench.protocol
    first = bench.run(ops.update_unless_current(protocol, 21, IMAGE))
    updated, info = first.result()
    assert updated and info.software_version.image_crc == crc64we(IMAGE)
    assert _begins(peer) == 1
    again = bench.run(ops.update_unless_current(protocol, 21, IMAGE))
    assert again.result() == (False, info)  # one GetNodeInfo, no update
    assert _begins(peer) == 1 and isinstance(peer.requests[-1], dronecan.GetNodeInfoRequest)
    forced = bench.run(ops.update_unless_current(protocol, 21, IMAGE, force=True))
    assert forced.result()[0] and _begins(peer) == 2
    other = IMAGE + b"."
    newer = bench.run(ops.update_unless_current(protocol, 21, other))
    assert newer.result()[1].software_version.image_crc == crc64we(other)
    assert _begins(peer) == 3


def test_a_crc_without_its_flag_does_not_count_as_running_the_image() -> None:
    """The CRC field means nothing unless the node sets IMAGE_CRC: such a node is updated
    (and, reporting no CRC afterwards either, is taken at its word)."""
    info = _info(0, crc64we(IMAGE))
    peer = Peer(
        [SimulatedEsc(21)], lambda r: info if isinstance(r, dronecan.GetNodeInfoRequest) else None
    )
    bench = Bench(peer)
    task = bench.run(ops.update_unless_current(bench.protocol, 21, IMAGE))
    assert task.result() == (True, info)
    assert _begins(peer) == 1
    assert peer.escs[0].state.mode is dronecan.Mode.OPERATIONAL
