"""Benchmark: fleet work on simulated ESCs, every node at once against node by node.

Simulated Vertiq ESCs (`veronte4x.simulator`) serve python-can's ``virtual`` bus from a
thread on the real clock; the ground client runs in the main thread. Two jobs, each done
both ways in the same run with the same client:

- read every parameter of N ESCs (a GetSet walk per node): ``list_params`` node after
  node, as one ``veronte4x esc params NODE`` per node does, against ``run_all`` of the
  walks (what ``veronte4x esc params 21-28`` does);
- update 4 ESCs (``--updates``: more counts) with one image (``update_firmware`` node after
  node against ``run_all``, what ``veronte4x esc update 21-24 FILE`` does).

The virtual bus has no bit rate: the gain measured is that of overlapping the nodes'
round trips, the part a real bus also has; a real 1 Mbit/s bus adds transmission time to
both ways alike. Timings only, never a test.

Each job runs with nodes that answer at once and with nodes that take ``--node-delay``
seconds to answer a request or to write a received chunk (`SimulatedEsc`'s
``response_delay``), as real modules take time to write flash. Each way reports its wall
time, the CPU time of the client's thread (the ground tool's work) and of the whole
process and of the simulator's process (both sides' work), the time both sides' threads
were ready to run but waited for a CPU (Linux's schedstat: the machine's load), and the
load (``uptime``) before and after: on a loaded machine a process waits for a CPU, and the
wall times show it. Each way runs ``--repeat`` times, the two ways in turn, and its fastest
run is shown.

Run: ``nice -n 10 .venv/bin/python benchmarks/bench_fleet.py [--escs 8] [--updates 4 8]
[--image-kb 200] [--node-delay 0 0.002 0.005] [--repeat 1] [--processes]``
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
from dataclasses import dataclass
from typing import Any

import can

from veronte4x.canbus import open_bus
from veronte4x.client import operations
from veronte4x.client.bus import BusClient
from veronte4x.simulator import SimulatedEsc
from veronte4x.simulator.can_node import EscBus


@contextmanager
def bench_bus(escs: int, delay: float) -> Iterator[tuple[BusClient, list[int]]]:
    """``escs`` simulated ESCs (nodes 21...) served from a thread, and a client for them
    (with no other process: the ESCs' work is this process's)."""
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
            yield BusClient(client_bus, timeout=2.0), []
        finally:
            stop.set()
            thread.join()


@contextmanager
def process_bus(escs: int, delay: float) -> Iterator[tuple[BusClient, list[int]]]:
    """``escs`` simulated ESCs in another process (``veronte4x simulate esc``) on a
    udp_multicast bus, a client for them, and that process's id: no interpreter shared
    between the two sides."""
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as sock:
        sock.bind(("", 0))
        port = sock.getsockname()[1]
    options = ["--interface", "udp_multicast", "--channel", "239.74.163.2"]
    simulator = subprocess.Popen(
        [sys.executable, "-m", "veronte4x", "simulate", "esc", "--nodes", f"21-{20 + escs}",
         "--telem-frequency", "0", "--response-delay", str(delay), *options,
         "--bus-option", f"port={port}"],
        stderr=subprocess.PIPE,
        text=True,
    )  # fmt: skip
    try:
        assert simulator.stderr is not None
        simulator.stderr.readline()  # written once its bus is open
        with open_bus("udp_multicast", "239.74.163.2", options={"port": port}) as bus:
            yield BusClient(bus, timeout=2.0), [simulator.pid]
    finally:
        simulator.terminate()
        simulator.wait(timeout=10)


def max_wait() -> float:
    """The simulators' clock (the real one)."""
    return time.monotonic()


@dataclass(frozen=True)
class Measure:
    """What one way of doing a job took."""

    wall: float
    """Seconds of wall-clock time."""
    client_cpu: float
    """CPU seconds of the client's thread (the ground tool's own work)."""
    cpu: float
    """CPU seconds of both sides: the benchmark's process (in-process, the simulated ESCs'
    thread too) and the simulator's process, if any."""
    queued: float | None
    """Seconds the threads of both sides were ready to run but waiting for a CPU, summed
    (Linux's ``/proc/PID/task/TID/schedstat``; None elsewhere): the machine's load."""


def scheduled(pids: list[int]) -> tuple[float, float] | None:
    """CPU seconds and seconds waiting for a CPU of every thread of ``pids``, summed, from
    Linux's ``schedstat``; None where it cannot be read."""
    ran = waited = 0
    try:
        for pid in pids:
            for task in os.listdir(f"/proc/{pid}/task"):
                with open(f"/proc/{pid}/task/{task}/schedstat") as stats:
                    run, wait, _ = stats.read().split()
                ran, waited = ran + int(run), waited + int(wait)
    except (OSError, ValueError):
        return None
    return ran / 1e9, waited / 1e9


def measured(job: Callable[[], object], others: list[int]) -> Measure:
    """Run ``job``; its wall time, the CPU time of this thread and of both sides (this
    process and the processes ``others``), and the time both sides waited for a CPU."""
    sides = [os.getpid()], others
    before = [scheduled(pids) for pids in sides]
    wall, thread, process = time.perf_counter(), time.thread_time(), time.process_time()
    job()
    wall, thread = time.perf_counter() - wall, time.thread_time() - thread
    process = time.process_time() - process
    after = [scheduled(pids) for pids in sides]
    mine, theirs = (
        None if start is None or end is None else (end[0] - start[0], end[1] - start[1])
        for start, end in zip(before, after, strict=True)
    )
    if mine is None or theirs is None:
        return Measure(wall, thread, process, None)
    return Measure(wall, thread, process + theirs[0], mine[1] + theirs[1])


def uptime() -> str:
    """The load averages (``uptime``), to print beside the figures."""
    try:
        return subprocess.run(["uptime"], capture_output=True, text=True).stdout.strip()
    except OSError:
        return f"load average {os.getloadavg()}"


def udp_drops() -> int | None:
    """UDP datagrams the whole machine dropped for a full receive buffer so far (Linux's
    ``/proc/net/snmp``, ``RcvbufErrors``), or None where it cannot be read."""
    try:
        with open("/proc/net/snmp") as snmp:
            names, values = (line.split() for line in snmp if line.startswith("Udp:"))
        return int(values[names.index("RcvbufErrors")])
    except (OSError, ValueError):
        return None


def columns(measure: Measure) -> str:
    """One way's figures in a row of the table."""
    queued = "-" if measure.queued is None else f"{measure.queued:.2f}s"
    return f"{measure.wall:>6.2f}s {measure.client_cpu:>5.2f}s {measure.cpu:>6.2f}s {queued:>7}"


def update_one_by_one(client: BusClient, nodes: list[int], image: bytes) -> None:
    """What one ``veronte4x esc update NODE FILE`` per node does."""
    for node in nodes:
        client.update_firmware(node, image, progress=False)


def update_at_once(client: BusClient, nodes: list[int], image: bytes) -> None:
    """What ``veronte4x esc update NODES FILE`` does: every node at once."""
    for task in client.run_all(
        [operations.update_firmware(client.protocol, n, image) for n in nodes]
    ):
        task.result()


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--escs", type=int, default=8, help="ESCs whose parameters are read")
    parser.add_argument(
        "--updates",
        type=int,
        default=(4,),
        nargs="+",
        metavar="N",
        help="numbers of ESCs updated (4, as the issue asks; e.g. 4 8)",
    )
    parser.add_argument("--image-kb", type=int, default=200, help="image size, kB")
    parser.add_argument(
        "--processes",
        action="store_true",
        help="also with the ESCs in another process on udp_multicast (needs msgpack), as "
        "separate modules are: no interpreter shared with the client",
    )
    parser.add_argument(
        "--node-delay",
        type=float,
        default=(0.0, 0.002, 0.005),
        nargs="+",
        metavar="S",
        help="seconds each simulated node takes to answer or write a chunk (0, 0.002, 0.005)",
    )
    parser.add_argument(
        "--repeat",
        type=int,
        default=1,
        metavar="N",
        help="runs of each way, taken in turn; the fastest is shown (1)",
    )
    args = parser.parse_args()
    nodes = [21 + i for i in range(args.escs)]
    image = bytes((i * 7 + i // 256) & 0xFF for i in range(args.image_kb * 1000))
    print(f"Python {sys.version.split()[0]} on {platform.machine()}, {os.cpu_count()} CPUs")
    print(f"before: {uptime()}")
    drops = udp_drops()
    print(
        "Each way: wall time; CPU time of the client's thread; CPU time of both sides (the\n"
        "simulated ESCs' too); time both sides were ready to run but waited for a CPU (load)."
    )
    print(
        f"{'job':<68}  {'node by node':>30}  {'all at once':>30}  {'ratio':>6}\n"
        f"{'':<68}  {'wall':>7} {'client':>6} {'CPU':>7} {'queued':>7}  {'wall':>7} "
        f"{'client':>6} {'CPU':>7} {'queued':>7}  {'wall':>6}"
    )
    jobs: dict[str, tuple[int, Callable[[BusClient], object], Callable[[BusClient], object]]]
    jobs = {
        f"read every parameter of {len(nodes)} ESCs": (
            len(nodes),
            lambda client: [client.list_params(n) for n in nodes],
            lambda client: client.run_all([operations.list_params(n) for n in nodes]),
        ),
    }
    for count in args.updates:
        updated = [21 + i for i in range(count)]
        jobs[f"update {count} ESCs with a {args.image_kb} kB image"] = (
            count,
            functools.partial(update_one_by_one, nodes=updated, image=image),
            functools.partial(update_at_once, nodes=updated, image=image),
        )
    setups: list[tuple[str, Callable[[int], Any]]] = [
        (
            f"ESCs in a thread, {delay * 1000:g} ms per request",
            functools.partial(bench_bus, delay=delay),
        )
        for delay in args.node_delay
    ]
    if args.processes:
        setups += [
            (
                f"ESCs in a process, {delay * 1000:g} ms per request",
                functools.partial(process_bus, delay=delay),
            )
            for delay in args.node_delay
        ]
    for setup, make_bus in setups:
        for job, (escs, *ways) in jobs.items():
            runs: list[list[Measure]] = [[], []]
            for _ in range(args.repeat):  # the ways in turn, so that both see the same load
                for way, measures in zip(ways, runs, strict=True):
                    with make_bus(escs) as (client, others):  # fresh ESCs for each run
                        client.discover(1.1)  # every node heard once
                        measures.append(measured(functools.partial(way, client), others))
            one, all_ = (min(measures, key=lambda m: m.wall) for measures in runs)
            print(
                f"{f'{job}, {setup}':<68}  {columns(one)}  {columns(all_)}  "
                f"{one.wall / all_.wall:>5.2f}x",
                flush=True,
            )
    print(f"after: {uptime()}")
    dropped = udp_drops()
    if dropped is not None and drops is not None:
        print(f"UDP datagrams dropped for a full receive buffer (whole machine): {dropped - drops}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
