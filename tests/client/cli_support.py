"""Run the command line as a subprocess on a udp_multicast bus of its own."""

from __future__ import annotations

import socket
import subprocess
import sys
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path

import can

from veronte4x import dronecan
from veronte4x.dronecan import EscStatus

GROUP = "239.74.163.2"
"""python-can's default IPv4 multicast group; each test bus gets a port of its own."""


def free_port() -> int:
    """A UDP port nothing uses now, so that concurrent test runs do not hear each other."""
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as sock:
        sock.bind(("", 0))
        port: int = sock.getsockname()[1]
        return port


def bus_args(port: int) -> list[str]:
    """The bus options of a udp_multicast bus on ``port``."""
    return ["--interface", "udp_multicast", "--channel", GROUP, "--bus-option", f"port={port}"]


ANSWER = "10"
"""``--timeout`` (s) for a command where one node never answers and the others must: the
silent node costs all of it, and a simulated node in another process, on a loaded
two-core machine, has this long to answer (2 s was missed once, at load 4 with a test run
on both cores)."""
HANG_GUARD = 600.0
"""Seconds before a CLI subprocess counts as hung: a guard, not a timed assertion (30 s
expired on a loaded two-core machine with two test runs going)."""


def veronte4x(*args: str, timeout: float = HANG_GUARD) -> subprocess.CompletedProcess[str]:
    """Run ``python -m veronte4x ARGS`` and capture its output."""
    return subprocess.run(
        [sys.executable, "-m", "veronte4x", *args],
        capture_output=True,
        text=True,
        timeout=timeout,
        check=False,
    )


def veronte4x_all(
    *commands: list[str], timeout: float = HANG_GUARD
) -> list[subprocess.CompletedProcess[str]]:
    """Run several commands at once (each ``esc`` one should have its own ``--node-id``)."""
    processes = [
        subprocess.Popen(
            [sys.executable, "-m", "veronte4x", *args],
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
        )
        for args in commands
    ]
    results = []
    for process, args in zip(processes, commands, strict=True):
        out, err = process.communicate(timeout=timeout)
        results.append(subprocess.CompletedProcess(args, process.returncode, out, err))
    return results


@contextmanager
def simulator(port: int, *options: str) -> Iterator[subprocess.Popen[str]]:
    """``veronte4x simulate esc`` in the background until the block ends (SIGTERM)."""
    process = subprocess.Popen(
        [sys.executable, "-m", "veronte4x", "simulate", "esc", *options, *bus_args(port)],
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        assert process.stderr is not None
        first = process.stderr.readline()  # written once the bus is open
        assert first.startswith("veronte4x: simulating Vertiq ESC nodes"), first
        yield process
    finally:
        process.terminate()
        process.wait(timeout=HANG_GUARD)


RELAY = Path(__file__).with_name("lossy_relay.py")


@contextmanager
def relay(
    port_a: int, port_b: int, loss: float, seed: int, cut: tuple[int, int] | None = None
) -> Iterator[list[str]]:
    """``lossy_relay.py`` between the two buses until the block ends (``cut``: its
    CUT_AFTER and CUT_FOR); yields its lines after the first, complete once the block
    has ended."""
    process = subprocess.Popen(
        [
            sys.executable,
            str(RELAY),
            str(port_a),
            str(port_b),
            str(loss),
            str(seed),
            *(str(n) for n in cut or ()),
        ],
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


@contextmanager
def listening(bus: list[str]) -> Iterator[can.BusABC]:
    """A python-can bus on the test bus ``bus`` (`bus_args`'s options), in this process."""
    port = int(bus[bus.index("--bus-option") + 1].removeprefix("port="))
    with can.Bus(interface="udp_multicast", channel=GROUP, port=port) as listener:
        yield listener


def _statuses(listener: can.BusABC) -> Iterator[tuple[int, EscStatus]]:
    """The esc.Status transfers on the bus with their senders; fails after `HANG_GUARD` s
    of waiting, a guard for telemetry that should come, not a timed assertion."""
    reassembler = dronecan.Reassembler()
    end = time.monotonic() + HANG_GUARD
    while True:
        assert time.monotonic() < end, "no esc.Status came"
        message = listener.recv(1.0)
        if message is None:
            continue
        transfer = reassembler.feed(message.arbitration_id, bytes(message.data), 0.0)
        if (
            transfer is not None
            and transfer.source_node_id is not None
            and isinstance(transfer.message, EscStatus)
        ):
            yield transfer.source_node_id, transfer.message


def wait_for_status(
    listener: can.BusABC, nodes: set[int], done: Callable[[EscStatus], bool]
) -> None:
    """Read the bus until each of ``nodes`` has sent an esc.Status that is ``done``."""
    waiting = set(nodes)
    statuses = _statuses(listener)
    while waiting:
        node, status = next(statuses)
        if node in waiting and done(status):
            waiting.discard(node)


def stopped_for_good(bus: list[str], nodes: set[int], count: int = 3) -> None:
    """Each of ``nodes`` reports no drive (power_rating_pct 0), then ``count`` more times in
    a row: a motor that stops and stays stopped, whatever the machine's load."""
    with listening(bus) as listener:
        wait_for_status(listener, nodes, lambda status: status.power_rating_pct == 0)
        after: dict[int, list[int]] = {node: [] for node in nodes}
        statuses = _statuses(listener)
        while any(len(duties) < count for duties in after.values()):
            node, status = next(statuses)
            if node in after:
                after[node].append(status.power_rating_pct)
    assert all(set(duties) == {0} for duties in after.values()), after
