"""``veronte4x esc allocate`` against ``veronte4x simulate esc --dynamic-node-id`` across
processes on a udp_multicast bus, as on a bench: the simulated ESCs get their node ids and
use them, and the table file holds them. Refusals are one line with their exit code.
"""

from __future__ import annotations

import json
import queue
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path
from typing import Any

import pytest

from tests.client.cli_support import (
    HANG_GUARD,
    bus_args,
    free_port,
    listening,
    simulator,
    veronte4x,
)
from veronte4x import dronecan
from veronte4x.cli import main
from veronte4x.simulator.esc import UNIQUE_ID_PREFIX


def _uid(node: int) -> str:
    return (UNIQUE_ID_PREFIX + bytes((node,))).hex()


class _Server:
    """``esc allocate TABLE --json`` in the background, its JSON lines read as they come."""

    def __init__(self, table: Path, bus: list[str]) -> None:
        self.process = subprocess.Popen(
            [sys.executable, "-m", "veronte4x", "esc", "allocate", str(table), *bus, "--json"],
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
        )
        self.lines: queue.Queue[str] = queue.Queue()
        self._reader = threading.Thread(target=self._read, daemon=True)
        self._reader.start()

    def _read(self) -> None:
        assert self.process.stdout is not None
        for line in self.process.stdout:
            self.lines.put(line)

    def allocated(self, count: int) -> list[dict[str, Any]]:
        """Wait for ``count`` allocations; return them (by node id) (a guard of `HANG_GUARD`
        s, not a timed assertion)."""
        found: list[dict[str, Any]] = []
        end = time.monotonic() + HANG_GUARD
        while len(found) < count:
            event = json.loads(self.lines.get(timeout=max(0.0, end - time.monotonic())))
            if event["event"] == "allocated":
                found.append(event)
        return sorted(found, key=lambda e: e["node_id"])

    def interrupt(self) -> tuple[int, str]:
        """Ctrl-C: its exit code and standard error."""
        self.process.send_signal(signal.SIGINT)
        _, err = self.process.communicate(timeout=HANG_GUARD)
        return self.process.returncode, err


def _statuses_from(bus: list[str], nodes: set[int]) -> None:
    """Wait until each of ``nodes`` has published a NodeStatus (a guard, not a timing)."""
    with listening(bus) as listener:
        reassembler, waiting = dronecan.Reassembler(), set(nodes)
        end = time.monotonic() + HANG_GUARD
        while waiting:
            assert time.monotonic() < end, waiting
            message = listener.recv(1.0)
            if message is None:
                continue
            transfer = reassembler.feed(message.arbitration_id, bytes(message.data), 0.0)
            if transfer is not None and isinstance(transfer.message, dronecan.NodeStatus):
                waiting.discard(transfer.source_node_id)


def test_the_server_allocates_and_keeps_its_table(tmp_path: Path) -> None:
    """One process of simulated ESCs without node ids, one server: each ESC gets the node
    id it prefers and uses it; the file holds both (the restart, the ids again, and the
    nodes with static ids are the in-process tests')."""
    port = free_port()
    bus = bus_args(port)
    table = tmp_path / "allocations.jsonl"
    with simulator(port, "--nodes", "21,22", "--dynamic-node-id"):
        server = _Server(table, bus)
        allocated = server.allocated(2)
        _statuses_from(bus, {21, 22})  # they took their node ids
        code, err = server.interrupt()
    events = [(e["node_id"], e["unique_id"], e["preferred_node_id"], e["again"]) for e in allocated]
    assert events == [(21, _uid(21), 21, False), (22, _uid(22), 22, False)]
    assert code == 130
    lines = err.splitlines()
    assert lines[0] == (
        f"veronte4x: allocation server at node 127, table {table} (0 entries); Ctrl-C stops"
    )
    assert lines[1:] == ["veronte4x: interrupted"]
    assert [json.loads(line) for line in table.read_text().splitlines()] == [
        {"format": "veronte4x-node-id-allocations/1"},
        {"node_id": 21, "unique_id": _uid(21)},
        {"node_id": 22, "unique_id": _uid(22)},
    ]


def _table_with_one_unique_id_twice(path: Path) -> str:
    path.write_text(
        '{"format": "veronte4x-node-id-allocations/1"}\n'
        f'{{"node_id": 21, "unique_id": "{_uid(21)}"}}\n'
        f'{{"node_id": 22, "unique_id": "{_uid(21)}"}}\n'
    )
    return str(path)


def test_a_table_that_binds_one_unique_id_twice_is_refused_in_one_line(tmp_path: Path) -> None:
    table = _table_with_one_unique_id_twice(tmp_path / "t.jsonl")
    result = veronte4x("esc", "allocate", table, "-i", "virtual", "-c", "test-cli-allocate")
    assert (result.returncode, result.stdout) == (2, "")
    assert result.stderr == (
        f"veronte4x: {table} line 3: unique id {_uid(21)} is bound to node 21 already, not to "
        "node 22; remove one of the two lines\n"
    )


def test_a_table_in_a_missing_directory_is_refused_before_serving(tmp_path: Path) -> None:
    table = tmp_path / "no such folder" / "t.jsonl"
    result = veronte4x("esc", "allocate", str(table), "-i", "virtual", "-c", "test-cli-allocate")
    assert (result.returncode, result.stdout) == (2, "")
    assert result.stderr == (
        f"veronte4x: {table}: the directory {table.parent} does not exist or cannot be "
        "written: give a table path in a writable directory\n"
    )


def test_a_preferred_node_id_needs_a_dynamic_one(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["simulate", "esc", "--preferred-node-id", "5", "-i", "virtual", "-c", "x"]) == 2
    assert capsys.readouterr().err == "veronte4x: --preferred-node-id needs --dynamic-node-id\n"
