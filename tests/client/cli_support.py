"""Run the command line as a subprocess on a udp_multicast bus of its own."""

from __future__ import annotations

import socket
import subprocess
import sys
from collections.abc import Iterator
from contextlib import contextmanager

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
