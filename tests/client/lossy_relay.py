"""A relay between two udp_multicast buses that drops a share of the frames it passes on,
or all of them for a while: a bus cut.

Run as ``python lossy_relay.py PORT_A PORT_B LOSS SEED [CUT_AFTER CUT_FOR]``: every frame
heard on one bus is sent on the other, except a share ``LOSS`` (0..1) drawn from a random
generator seeded with ``SEED`` (one per direction). With ``CUT_AFTER``, the relay passes
nothing either way once it has passed that many file.Read requests from bus A (the nodes
pulling a firmware image: the cut falls in mid-update), until the nodes have sent
``CUT_FOR`` more (each one a node asking again, an event rather than a time), or for
good with ``CUT_FOR`` -1. A frame the relay sent comes back to it (udp_multicast loops
frames back to the sender) and is not passed on again. Writes one line to standard error
once both buses are open, one when the cut starts and one when it ends, and the counts
when SIGTERM ends it.
"""

from __future__ import annotations

import collections
import random
import signal
import sys
import threading

import can

GROUP = "239.74.163.2"

FILE_READ = 48
"""The data type id of uavcan.protocol.file.Read (DSDL ``48.Read.uavcan``)."""


def ends_a_read_request(message: can.Message) -> bool:
    """Whether a frame is the last of a file.Read request (CAN ID: service, request,
    type 48; tail byte: end of transfer; DroneCAN specification, "CAN bus transport
    layer")."""
    can_id = message.arbitration_id
    return (
        bool(can_id & 0x80 and can_id & 0x8000)
        and (can_id >> 16) & 0xFF == FILE_READ
        and bool(message.data)
        and bool(message.data[-1] & 0x40)
    )


class Cut:
    """When the relay passes nothing: after ``after`` read requests passed, until ``lasting``
    more came (never with -1); None ``after``: never cut."""

    def __init__(self, after: int | None, lasting: int) -> None:
        self.after = after
        self.lasting = lasting
        self.passed = 0
        self.dropped = 0
        self.state = "before" if after is not None else "never"

    def drops(self, source: int, message: can.Message) -> bool:
        """Whether the cut drops this frame (from bus ``source``), counting the reads."""
        read = source == 0 and ends_a_read_request(message)
        if self.state == "before":
            self.passed += read
            if self.passed == self.after:
                self.state = "cut"
                print(f"cut after {self.passed} reads", file=sys.stderr, flush=True)
            return False
        if self.state != "cut":
            return False
        self.dropped += read
        if self.dropped == self.lasting:
            self.state = "restored"
            print(f"restored after {self.dropped} reads lost", file=sys.stderr, flush=True)
        return True


class Relay:
    """Both directions between ``a`` and ``b``, each dropping ``loss`` of the frames."""

    def __init__(
        self, a: can.BusABC, b: can.BusABC, loss: float, seed: int, cut: Cut | None = None
    ) -> None:
        self.buses = (a, b)
        self.loss = loss
        self.seed = seed
        self.cut = cut or Cut(None, -1)
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
                if self.cut.drops(source, message):
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
    cut = Cut(int(sys.argv[5]), int(sys.argv[6])) if len(sys.argv) > 5 else None
    with (
        can.Bus(interface="udp_multicast", channel=GROUP, port=port_a) as a,
        can.Bus(interface="udp_multicast", channel=GROUP, port=port_b) as b,
    ):
        relay = Relay(a, b, loss, seed, cut)
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
