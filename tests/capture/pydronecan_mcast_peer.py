"""A pydronecan node on an ``mcast:`` bus, for the tests of veronte4x's mcast bus.

``python pydronecan_mcast_peer.py BUS publish``: node 42 publishes NodeStatus (pydronecan
sends it every second) until it is terminated; it writes ``ready`` once its node is up.

``python pydronecan_mcast_peer.py BUS watch NODE``: node 43 waits for an esc.Status from
NODE, asks NODE for GetNodeInfo, and prints ``esc_status <error_count> <rpm>`` and
``node_info <name>``, then exits 0; it gives up (exit 1) after 60 s.
"""

from __future__ import annotations

import signal
import sys
import time

import dronecan


def main() -> int:
    # SIGTERM exits as a normal exit does, so that multiprocessing ends pydronecan's I/O
    # process (which holds this process's output pipes) instead of leaving it running
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(0))
    bus, action = sys.argv[1], sys.argv[2]
    if action == "publish":
        node = dronecan.make_node(f"mcast:{bus}", node_id=42)
        print("ready", flush=True)
        while True:
            node.spin(1.0)
    watched = int(sys.argv[3])
    node = dronecan.make_node(f"mcast:{bus}", node_id=43)
    seen: dict[str, str] = {}

    def on_status(event: dronecan.node.TransferEvent) -> None:
        if event.transfer.source_node_id == watched and "esc_status" not in seen:
            status = event.message
            seen["esc_status"] = f"{status.error_count} {status.rpm}"
            node.request(
                dronecan.uavcan.protocol.GetNodeInfo.Request(), watched, on_info, timeout=10
            )

    def on_info(event: dronecan.node.TransferEvent | None) -> None:
        if event is None:  # no answer in 10 s: ask again after the next esc.Status
            seen.pop("esc_status")
        else:
            seen["node_info"] = event.response.name.decode()

    node.add_handler(dronecan.uavcan.equipment.esc.Status, on_status)
    end = time.monotonic() + 60.0
    while time.monotonic() < end and "node_info" not in seen:
        node.spin(0.1)
    for key, value in seen.items():
        print(key, value, flush=True)
    return 0 if "node_info" in seen else 1


if __name__ == "__main__":
    sys.exit(main())
