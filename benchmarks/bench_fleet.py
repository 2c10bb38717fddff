"""Benchmark: fleet work on simulated ESCs, every node at once against node by node.

Simulated Vertiq ESCs (`veronte4x.simulator`) serve python-can's ``virtual`` bus from a
thread on the real clock; the ground client runs in the main thread. Two jobs, each done
both ways in the same run with the same client:

- read every parameter of N ESCs (a GetSet walk per node): ``list_params`` node after
  node, as one ``veronte4x esc params NODE`` per node does, against ``run_all`` of the
  walks (what ``veronte4x esc params 21-28`` does);
- update M ESCs with one image (``update_firmware`` node after node against ``run_all``,
  what ``veronte4x esc update 21-24 FILE`` does).

The virtual bus has no bit rate: the gain measured is that of overlapping the nodes'
round trips, the part a real bus also has; a real 1 Mbit/s bus adds transmission time to
both ways alike. Timings only, never a test.

Each job runs with nodes that answer at once and with nodes that take ``--node-delay``
seconds to answer a request or to write a received chunk (`SimulatedEsc`'s
``response_delay``), as real modules take time to act.

Run: ``.venv/bin/python benchmarks/bench_fleet.py [--escs 8] [--updates 4] [--image-kb 200]
[--node-delay 0 0.002]``
"""

from __future__ import annotations

import argparse
import functools
import os
import platform
import socket
import subprocess
import sys
import threading
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any

import can

from veronte4x.client import operations
from veronte4x.client.bus import BusClient
from veronte4x.simulator import SimulatedEsc
from veronte4x.simulator.can_node import EscBus


@contextmanager
def bench_bus(escs: int, delay: float) -> Iterator[BusClient]:
    """``escs`` simulated ESCs (nodes 21...) served from a thread, and a client for them."""
    channel = f"bench-fleet-{os.getpid()}-{time.monotonic_ns()}"
    with (
        can.Bus(interface="virtual", channel=channel) as esc_bus,
        can.Bus(interface="virtual", channel=channel) as client_bus,
    ):
        simulated = [
            SimulatedEsc(21 + i, i, telem_frequency=0, response_delay=delay) for i in range(escs)
        ]
        stop = threading.Event()
        thread = threading.Thread(target=EscBus(esc_bus, simulated, max_wait).run, args=(stop,))
        thread.start()
        try:
            yield BusClient(client_bus, timeout=2.0)
        finally:
            stop.set()
            thread.join()


@contextmanager
def process_bus(escs: int) -> Iterator[BusClient]:
    """``escs`` simulated ESCs in another process (``veronte4x simulate esc``) on a
    udp_multicast bus, and a client for them: no interpreter shared between the two sides."""
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as sock:
        sock.bind(("", 0))
        port = sock.getsockname()[1]
    options = ["--interface", "udp_multicast", "--channel", "239.74.163.2"]
    simulator = subprocess.Popen(
        [sys.executable, "-m", "veronte4x", "simulate", "esc", "--nodes", f"21-{20 + escs}",
         "--telem-frequency", "0", *options, "--bus-option", f"port={port}"],
        stderr=subprocess.PIPE,
        text=True,
    )  # fmt: skip
    try:
        assert simulator.stderr is not None
        simulator.stderr.readline()  # written once its bus is open
        with can.Bus(interface="udp_multicast", channel="239.74.163.2", port=port) as bus:
            yield BusClient(bus, timeout=2.0)
    finally:
        simulator.terminate()
        simulator.wait(timeout=10)


def max_wait() -> float:
    """The simulators' clock (the real one)."""
    return time.monotonic()


def timed(job: Callable[[], object]) -> float:
    """Seconds ``job`` takes."""
    start = time.perf_counter()
    job()
    return time.perf_counter() - start


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--escs", type=int, default=8, help="ESCs whose parameters are read")
    parser.add_argument("--updates", type=int, default=4, help="ESCs updated")
    parser.add_argument("--image-kb", type=int, default=200, help="image size, kB")
    parser.add_argument(
        "--processes",
        action="store_true",
        help="also with the ESCs in another process on udp_multicast (needs msgpack)",
    )
    parser.add_argument(
        "--node-delay",
        type=float,
        default=(0.0, 0.002),
        nargs="+",
        metavar="S",
        help="seconds each simulated node takes to answer or write a chunk (0 and 0.002)",
    )
    args = parser.parse_args()
    nodes = [21 + i for i in range(args.escs)]
    updated = nodes[: args.updates]
    image = bytes((i * 7 + i // 256) & 0xFF for i in range(args.image_kb * 1000))
    print(f"Python {sys.version.split()[0]} on {platform.machine()}, {os.cpu_count()} CPUs")
    print(f"{'job':<62}  {'node by node':>12}  {'all at once':>11}  {'ratio':>6}")
    jobs = {
        f"read every parameter of {len(nodes)} ESCs": (
            lambda client: [client.list_params(n) for n in nodes],
            lambda client: client.run_all([operations.list_params(n) for n in nodes]),
        ),
        f"update {len(updated)} ESCs with a {args.image_kb} kB image": (
            lambda client: [client.update_firmware(n, image) for n in updated],
            lambda client: [
                t.result()
                for t in client.run_all(
                    [operations.update_firmware(client.protocol, n, image) for n in updated]
                )
            ],
        ),
    }
    setups: list[tuple[str, Callable[[], Any]]] = [
        (
            f"in-process, nodes answer in {delay * 1000:g} ms",
            functools.partial(bench_bus, len(nodes), delay),
        )
        for delay in args.node_delay
    ]
    if args.processes:
        setups.append(("ESCs in another process", functools.partial(process_bus, len(nodes))))
    for setup, make_bus in setups:
        for job, ways in jobs.items():
            seconds = []
            for way in ways:
                with make_bus() as client:  # fresh ESCs for each way
                    client.discover(1.1)  # every node heard once
                    seconds.append(timed(functools.partial(way, client)))
            one_by_one, at_once = seconds
            row = f"{job}, {setup}"
            print(
                f"{row:<62}  {one_by_one:>10.3f} s  {at_once:>9.3f} s  "
                f"{one_by_one / at_once:>5.2f}x"
            )
    return 0


if __name__ == "__main__":
    sys.exit(main())
