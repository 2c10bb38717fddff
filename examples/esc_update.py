"""Update the firmware of a simulated Vertiq ESC with the ground-station client.

Usage: python examples/esc_update.py  (needs the ``can`` extra)

The ESC and the client share python-can's virtual bus and one thread: the client's waits
step the simulated node. The client finds the node, asks it to begin the update, serves
the image as the node reads it with file.Read, waits for the node to run the new image and
checks the CRC-64-WE the node reports.
"""

from __future__ import annotations

import time
from collections.abc import Callable

import can

from veronte4x.client import FirmwareUpdateFailedError, Phase, UpdateProgress
from veronte4x.client.bus import BusClient
from veronte4x.dronecan.image_crc import crc64we
from veronte4x.simulator import SimulatedEsc
from veronte4x.simulator.can_node import EscBus

ESC_NODE = 21
IMAGE = bytes((i * 73 + 11) & 0xFF for i in range(3000))


def main(clock: Callable[[], float] = time.monotonic, channel: str = "esc-update") -> int:
    """Run the update; returns the exit status (0 when the node reports the image's CRC)."""
    with (
        can.Bus(interface="virtual", channel=channel) as esc_bus,
        can.Bus(interface="virtual", channel=channel) as client_bus,
    ):
        node = EscBus(esc_bus, [SimulatedEsc(ESC_NODE, start_time=clock())], clock=clock)
        client = BusClient(client_bus, clock=clock, while_waiting=node.step)
        print("nodes:", [entry.node_id for entry in client.discover()])
        before = client.node_info(ESC_NODE).software_version

        def progress(p: UpdateProgress) -> None:
            if p.phase is not Phase.READING or p.sent % 1024 == 0:
                print(f"  {p.phase.value}: {p.sent} of {p.size} bytes")

        try:
            info = client.update_firmware(ESC_NODE, IMAGE, "esc.bin", progress=progress)
        except FirmwareUpdateFailedError as error:
            print(error)
            return 1
        after = info.software_version
        print(f"image CRC before: {before.image_crc:#018x}, after: {after.image_crc:#018x}")
        print(f"the image's CRC-64-WE: {crc64we(IMAGE):#018x}")
        return 0 if after.image_crc == crc64we(IMAGE) else 1


if __name__ == "__main__":
    raise SystemExit(main())
