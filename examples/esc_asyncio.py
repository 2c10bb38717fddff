"""A vehicle's ESCs from an asyncio program: read them all at once, update two of them.

Usage: python examples/esc_asyncio.py  (needs the ``can`` extra)

Four simulated Vertiq ESCs (nodes 21-24) serve python-can's virtual bus from a thread; the
asyncio client (`veronte4x.client.aio.AsyncBusClient`) finds them, reads every node's
``esc_index`` concurrently, updates nodes 21 and 22 with one image side by side, and skips
a node that already runs it.
"""

from __future__ import annotations

import asyncio
import threading

import can

from veronte4x.client import operations
from veronte4x.client.aio import AsyncBusClient
from veronte4x.simulator import SimulatedEsc
from veronte4x.simulator.can_node import EscBus

IMAGE = bytes((i * 73 + 11) & 0xFF for i in range(3000))


async def maintain(bus: can.BusABC) -> int:
    """The ground-station side; returns the exit status."""
    async with AsyncBusClient(bus) as client:
        nodes = [entry.node_id for entry in await client.discover()]
        print("nodes:", nodes)
        reads = await client.run_all([operations.get_param(n, "esc_index") for n in nodes])
        print(
            "esc_index:",
            {n: t.result().as_dict()["value"] for n, t in zip(nodes, reads, strict=True)},
        )
        updates = await client.run_all(
            [operations.update_unless_current(client.protocol, n, IMAGE) for n in (21, 22)]
        )
        for node, task in zip((21, 22), updates, strict=True):
            updated, info = task.result()
            print(
                f"node {node}: updated {updated}, image CRC {info.software_version.image_crc:#018x}"
            )
        (again,) = await client.run_all(
            [operations.update_unless_current(client.protocol, 21, IMAGE)]
        )
        print("node 21 again: updated", again.result()[0])
        return 0


def main(channel: str = "esc-asyncio") -> int:
    """Serve four ESCs from a thread and run the asyncio client against them."""
    with (
        can.Bus(interface="virtual", channel=channel) as esc_bus,
        can.Bus(interface="virtual", channel=channel) as client_bus,
    ):
        escs = EscBus(esc_bus, [SimulatedEsc(21 + i, i) for i in range(4)])
        stop = threading.Event()
        thread = threading.Thread(target=escs.run, args=(stop,))
        thread.start()
        try:
            return asyncio.run(maintain(client_bus))
        finally:
            stop.set()
            thread.join()


if __name__ == "__main__":
    raise SystemExit(main())
