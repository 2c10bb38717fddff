"""Talk to a simulated Vertiq ESC on python-can's virtual bus.

Usage: python examples/esc_demo.py  (needs the ``can`` extra)

One thread runs both sides: the client's waits call the simulated node's ``step``, which
takes the client's frames from the bus and sends the ESC's replies and telemetry. The
demo reads telemetry, discovers the parameters by index, sets ``esc_index`` by name,
spins the motor with RawCommand and reboots the ESC into its bootloader.
"""

from __future__ import annotations

import time
from collections.abc import Callable

import can

from veronte4x import dronecan
from veronte4x.client import NoResponseError
from veronte4x.client.bus import BusClient
from veronte4x.dronecan import vertiq
from veronte4x.simulator import SimulatedEsc
from veronte4x.simulator.can_node import EscNode

ESC_NODE = 20
CLIENT_NODE = 10


def _esc_status(transfers: list[dronecan.Transfer]) -> list[dronecan.EscStatus]:
    return [t.message for t in transfers if isinstance(t.message, dronecan.EscStatus)]


def main(clock: Callable[[], float] = time.monotonic, channel: str = "esc-demo") -> int:
    """Run the demo; returns the exit status (0 when every step got its answer)."""
    with (
        can.Bus(interface="virtual", channel=channel) as esc_bus,
        can.Bus(interface="virtual", channel=channel) as client_bus,
    ):
        esc = SimulatedEsc(ESC_NODE, esc_index=0, telem_frequency=20, start_time=clock())
        node = EscNode(esc_bus, esc, clock=clock)
        client = BusClient(
            client_bus, CLIENT_NODE, clock=clock, timeout=0.5, while_waiting=node.step
        )

        def ask(request: object) -> object:
            try:
                return client.call(request, ESC_NODE)
            except NoResponseError as error:
                raise SystemExit(str(error)) from None

        info = ask(dronecan.GetNodeInfoRequest())
        assert isinstance(info, dronecan.GetNodeInfoResponse)
        print(f"node {ESC_NODE}: {info.name.decode()}, mode {info.status.mode.name}")

        heard = client.listen(0.5)
        counts: dict[str, int] = {}
        for transfer in heard:
            name = type(transfer.message).__name__
            counts[name] = counts.get(name, 0) + 1
        print(
            "telemetry heard in the first 0.5 s:",
            ", ".join(f"{k} x{v}" for k, v in sorted(counts.items())),
        )

        replies = []
        index = 0
        while True:
            reply = ask(vertiq.get_parameter_by_index(index))
            assert isinstance(reply, dronecan.GetSetResponse)
            if vertiq.is_end_of_parameters(reply):
                break
            replies.append(reply)
            index += 1
        for reply in replies:
            value, low, high = (
                v.value if isinstance(v, dronecan.IntegerValue) else v
                for v in (reply.value, reply.min_value, reply.max_value)
            )
            print(f"parameter {reply.name.decode()} = {value} ({low}..{high})")

        reply = ask(vertiq.set_parameter(vertiq.Parameter.ESC_INDEX, 2))
        assert isinstance(reply, dronecan.GetSetResponse)
        assert isinstance(reply.value, dronecan.IntegerValue)
        print(f"set esc_index by name -> {reply.value.value}")

        command = vertiq.raw_command({2: 0.6})
        spin: list[dronecan.EscStatus] = []
        for _ in range(10):
            client.broadcast(command)
            spin += _esc_status(client.listen(0.1))
        rpm = [s.rpm for s in spin]
        print(
            f"RawCommand 60 % at index 2: rpm {rpm[0]} -> {rpm[-1]}, esc_index {spin[-1].esc_index}"
        )

        reply = ask(vertiq.restart(bootloader=True))
        assert isinstance(reply, dronecan.RestartNodeResponse)
        print(f"reboot into bootloader: ok={reply.ok}")
        after = [t for t in client.listen(1.2) if t.source_node_id == ESC_NODE]
        print(f"frames from node {ESC_NODE} in the next 1.2 s: {len(after)}")
        return 0 if reply.ok and not after and rpm[-1] > rpm[0] else 1


if __name__ == "__main__":
    raise SystemExit(main())
