"""A relay between two udp_multicast buses that drops a share of the frames it passes on.

Run as ``python lossy_relay.py PORT_A PORT_B LOSS SEED``: every frame heard on one bus
is sent on the other, except a share ``LOSS`` (0..1) drawn from a random generator
seeded with ``SEED`` (one per direction). A frame the relay sent comes back to it
(udp_multicast loops frames back to the sender) and is not passed on again. Writes one
line to standard error once both buses are open, and the counts when SIGTERM ends it.
"""

from __future__ import annotations

import collections
import random
import signal
import sys
import threading

import can

GROUP = "239.74.163.2"


class Relay:
    """Both directions between ``a`` and ``b``, each dropping ``loss`` of the frames."""

    def __init__(self, a: can.BusABC, b: can.BusABC, loss: float, seed: int) -> None:
        self.buses = (a, b)
        self.loss = loss
        self.seed = seed
        self.stop = threading.Event()
        self.lock = threading.Lock()
        self.echoes: tuple[collections.Counter[tuple[int, bytes]], ...] = (
            collections.Counter(),
            collections.Counter(),
        )
        self.passed = [0, 0]
        self.dropped = [0, 0]

    def run(self, source: int) -> None:
        """Pass frames from bus ``source`` (0 or 1) to the other one until `stop`."""
        target = 1 - source
        rng = random.Random(self.seed * 2 + source)
        while not self.stop.is_set():
            message = self.buses[source].recv(0.05)
            if message is None:
                continue
            key = (message.arbitration_id, bytes(message.data))
            with self.lock:
                echoes = self.echoes[source]
                if echoes[key]:  # what this relay sent there, back from the group
                    echoes[key] -= 1
                    continue
            if rng.random() < self.loss:
                self.dropped[source] += 1
                continue
            with self.lock:
                self.echoes[target][key] += 1
            self.buses[target].send(
                can.Message(
                    arbitration_id=message.arbitration_id,
                    data=message.data,
                    is_extended_id=True,
                )
            )
            self.passed[source] += 1


def main() -> None:
    port_a, port_b, loss, seed = (
        int(sys.argv[1]),
        int(sys.argv[2]),
        float(sys.argv[3]),
        int(sys.argv[4]),
    )
    with (
        can.Bus(interface="udp_multicast", channel=GROUP, port=port_a) as a,
        can.Bus(interface="udp_multicast", channel=GROUP, port=port_b) as b,
    ):
        relay = Relay(a, b, loss, seed)
        signal.signal(signal.SIGTERM, lambda *_: relay.stop.set())
        threads = [threading.Thread(target=relay.run, args=(side,)) for side in (0, 1)]
        for thread in threads:
            thread.start()
        print(f"relaying {port_a} <-> {port_b}, dropping {loss:.0%}", file=sys.stderr, flush=True)
        for thread in threads:
            thread.join()
        print(
            f"passed {relay.passed[0]} and {relay.passed[1]}, "
            f"dropped {relay.dropped[0]} and {relay.dropped[1]}",
            file=sys.stderr,
            flush=True,
        )


if __name__ == "__main__":
    main()
