"""A fleet firmware update finishes through a relay that drops 2 % or 10 % of the frames
(issue 41, item 6): simulated ESCs, the relay and ``veronte4x esc update`` are three
processes on two udp_multicast buses. The bootloader asks a read again when its answer
was lost (a 256-byte answer is 38 frames: at 10 % loss about one attempt in 75 gets
through), the ground tool retries its own requests and serves repeated reads alike."""

from __future__ import annotations

from pathlib import Path

import pytest

from veronte4x import dronecan
from veronte4x.client import FileServer, FirmwareUpdate, Phase
from veronte4x.dronecan.image_crc import crc64we
from veronte4x.simulator import SimulatedEsc
from veronte4x.simulator.esc import FILE_SERVER_SILENCE

from .cli_support import bus_args, free_port, relay, simulator, veronte4x

IMAGE = bytes((i * 7 + 3) & 0xFF for i in range(600))
"""Two full reads and a short one."""


@pytest.mark.parametrize(("loss", "seed"), [(0.02, 1), (0.10, 2)])
def test_a_fleet_update_finishes_through_a_lossy_relay(
    loss: float, seed: int, tmp_path: Path
) -> None:
    firmware = tmp_path / "esc-v3.bin"
    firmware.write_bytes(IMAGE)
    crc = f"{crc64we(IMAGE):#018x}"
    esc_port, tool_port = free_port(), free_port()
    with (
        simulator(esc_port, "--nodes", "21-24", "--file-timeout", "0.1"),
        relay(esc_port, tool_port, loss, seed) as counts,
    ):
        result = veronte4x(
            "esc", "update", "21-24", str(firmware), *bus_args(tool_port), "--retries", "15"
        )
    assert result.returncode == 0, result.stderr
    assert result.stdout.splitlines() == [
        f"node {n}: updated with esc-v3.bin (600 bytes, CRC-64-WE {crc}); the node reports "
        "the same CRC"
        for n in range(21, 25)
    ] + ["4 nodes: all succeeded"]
    [summary] = [line for line in counts if line.startswith("passed")]
    dropped = [int(word) for word in summary.replace(",", "").split()[-3::2]]
    assert all(count > 0 for count in dropped), summary  # frames were lost both ways


def _transfers(frames: list[dronecan.TransferFrame]) -> list[dronecan.Transfer]:
    reassembler = dronecan.Reassembler()
    found = [reassembler.feed(f.can_id, f.data, 0.0) for f in frames]
    return [t for t in found if t is not None]


def test_repeated_reads_are_served_alike_and_count_once() -> None:
    server = FileServer()
    server.add(b"fw.bin", IMAGE)
    request = dronecan.FileReadRequest(256, dronecan.Path(b"fw.bin"))
    assert server.read(request) == server.read(request)
    update = FirmwareUpdate(21, b"fw.bin", len(IMAGE), now=0.0)
    update.accepted(dronecan.BeginFirmwareUpdateResponse(0), 0.1)
    for now in (0.2, 0.3):  # the second: the node asked again, its answer was lost
        update.served(21, server.read(request)[1], now)
        assert (update.progress.phase, update.progress.sent) == (Phase.READING, 512)


def test_the_bootloader_asks_again_until_its_silence_limit() -> None:
    """Sans-IO, on timestamps: with nothing answering, node 21 asks for the file every
    ``file_timeout`` seconds, then after `FILE_SERVER_SILENCE` s runs its old image."""
    esc = SimulatedEsc(21, file_timeout=0.5)
    begin = dronecan.BeginFirmwareUpdateRequest(0, dronecan.Path(b"fw.bin"))
    replies = []
    for transfer_id in (0, 1):  # the second: the tool's retry, its first answer lost
        for frame in dronecan.encode(
            begin, source_node_id=127, destination_node_id=21, transfer_id=transfer_id
        ):
            esc.receive(frame.can_id, frame.data, 0.0)
        replies += [
            t.message
            for t in _transfers(esc.poll(0.0))
            if isinstance(t.message, dronecan.BeginFirmwareUpdateResponse)
        ]
    assert [r.error for r in replies] == [dronecan.FirmwareUpdateError.OK] * 2
    asked = []
    now = 0.0
    while esc.state.mode is dronecan.Mode.SOFTWARE_UPDATE:
        now = round(now + 0.1, 1)
        asked += [
            now
            for t in _transfers(esc.poll(now))
            if isinstance(t.message, dronecan.FileGetInfoRequest)
        ]
    assert asked == [round(0.5 * k, 1) for k in range(1, 120)]  # 120 attempts in all
    assert now == FILE_SERVER_SILENCE
    assert not esc.motor.driven
