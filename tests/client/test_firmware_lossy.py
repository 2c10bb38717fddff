"""A fleet firmware update finishes through a relay that drops 2 % or 10 % of the frames
(issue 41, item 6): simulated ESCs, the relay and ``veronte4x esc update`` are three
processes on two udp_multicast buses. The bootloader asks a read again when its answer
was lost (a 256-byte answer is 38 frames: at 10 % loss about one attempt in 75 gets
through), the ground tool retries its own requests and serves repeated reads alike."""

from __future__ import annotations

import subprocess
import sys
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import pytest

from veronte4x.dronecan.image_crc import crc64we

from .cli_support import HANG_GUARD, bus_args, free_port, simulator, veronte4x

RELAY = Path(__file__).with_name("lossy_relay.py")


@contextmanager
def relay(port_a: int, port_b: int, loss: float, seed: int) -> Iterator[list[str]]:
    """The relay between the two buses until the block ends; yields its last lines."""
    process = subprocess.Popen(
        [sys.executable, str(RELAY), str(port_a), str(port_b), str(loss), str(seed)],
        stderr=subprocess.PIPE,
        text=True,
    )
    lines: list[str] = []
    try:
        assert process.stderr is not None
        first = process.stderr.readline()  # written once both buses are open
        assert first.startswith("relaying"), first
        yield lines
    finally:
        process.terminate()
        _, rest = process.communicate(timeout=HANG_GUARD)
        lines += rest.splitlines()


@pytest.mark.parametrize(("loss", "seed"), [(0.02, 1), (0.10, 2)])
def test_a_fleet_update_finishes_through_a_lossy_relay(
    loss: float, seed: int, tmp_path: Path
) -> None:
    image = bytes((i * 7 + 3) & 0xFF for i in range(600))  # two full reads and a short one
    firmware = tmp_path / "esc-v3.bin"
    firmware.write_bytes(image)
    crc = f"{crc64we(image):#018x}"
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
