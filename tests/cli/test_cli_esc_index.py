"""``veronte4x esc`` reads every node's ``esc_index`` before a motor moves or an index is
given (issue 41, items 4 and 6), as subprocesses on a udp_multicast bus with simulated ESCs
in other processes; a recorder in this process hears every RawCommand and esc.Status."""

from __future__ import annotations

import json
import threading
import time
from collections.abc import Iterator
from contextlib import ExitStack, contextmanager
from pathlib import Path

import can

from tests.client.cli_support import GROUP, HANG_GUARD, bus_args, free_port, simulator, veronte4x
from veronte4x import dronecan
from veronte4x.dronecan import EscStatus, RawCommand


class Recorder:
    """Every RawCommand and every esc.Status's rpm on the bus, from a thread."""

    def __init__(self, port: int) -> None:
        self.commands: list[tuple[int, ...]] = []
        self.rpm: dict[int, list[int]] = {}
        self._lock = threading.Lock()
        self._stop = threading.Event()
        self._bus = can.Bus(interface="udp_multicast", channel=GROUP, port=port)
        self._thread = threading.Thread(target=self._run, daemon=True)
        self._thread.start()

    def _run(self) -> None:
        reassembler = dronecan.Reassembler()
        while not self._stop.is_set():
            message = self._bus.recv(0.1)
            if message is None or not message.is_extended_id:
                continue
            transfer = reassembler.feed(message.arbitration_id, bytes(message.data), 0.0)
            if transfer is None:
                continue
            with self._lock:
                if isinstance(transfer.message, RawCommand):
                    self.commands.append(transfer.message.cmd)
                elif (
                    isinstance(transfer.message, EscStatus) and transfer.source_node_id is not None
                ):
                    self.rpm.setdefault(transfer.source_node_id, []).append(transfer.message.rpm)

    def statuses(self, node: int) -> list[int]:
        with self._lock:
            return list(self.rpm.get(node, []))

    def more_statuses(self, node: int, count: int) -> list[int]:
        """Wait until ``node`` sent ``count`` more esc.Status (a guard, not a timing); its
        rpm in every esc.Status so far."""
        wanted = len(self.statuses(node)) + count
        end = time.monotonic() + HANG_GUARD
        while len(self.statuses(node)) < wanted:
            assert time.monotonic() < end, f"node {node} sent no esc.Status"
            time.sleep(0.05)
        return self.statuses(node)

    def close(self) -> None:
        self._stop.set()
        self._thread.join()
        self._bus.shutdown()


@contextmanager
def _bus(*simulators: str) -> Iterator[tuple[list[str], Recorder]]:
    """Simulators (one process per ``--nodes`` list given), a recorder, the bus options."""
    port = free_port()
    with ExitStack() as stack:
        for nodes in simulators:
            stack.enter_context(simulator(port, "--nodes", nodes))
        recorder = Recorder(port)
        stack.callback(recorder.close)
        yield bus_args(port), recorder


def test_spin_refuses_a_node_whose_motor_would_turn_too() -> None:
    with _bus("21", "22") as (bus, recorder):  # one process each: both at esc_index 0
        recorder.more_statuses(22, 1)
        result = veronte4x("esc", "spin", "21", "--throttle", "0.5", "--duration", "5",
                           "--yes", *bus)  # fmt: skip
        assert (result.returncode, result.stdout) == (2, "")
        assert result.stderr == (
            "veronte4x: node 22 has esc_index 0 too: RawCommand would turn it with node 21; "
            "name it as well to spin both, or give it an esc_index of its own; nothing was "
            "sent\n"
        )
        assert set(recorder.more_statuses(22, 5)) == {0}  # node 22's motor never turned
        assert set(recorder.statuses(21)) == {0}
        assert recorder.commands == []  # no RawCommand at all
        # both named: both turn, as asked (and the recorder hears them)
        both = veronte4x("esc", "spin", "21", "22", "--throttle", "0.5", "--duration", "1",
                         "--yes", *bus)  # fmt: skip
        assert both.returncode == 0, both.stderr
        assert any(any(cmd) for cmd in recorder.commands)
        assert max(recorder.statuses(22)) > 0


def test_nodes_lists_a_node_at_the_tools_id_and_spin_refuses_it() -> None:
    with _bus("21,127") as (bus, recorder):  # esc_index 0 and 1
        listed = veronte4x("esc", "nodes", *bus, "--timeout", "2.1", "--json")
        assert listed.returncode == 0, listed.stderr
        assert [(n["node_id"], n["name"], n["conflict"]) for n in json.loads(listed.stdout)] == [
            (21, "iq_motion.esc", None),
            (127, None, "uses this tool's node id"),
        ]
        advice = "give this tool another --node-id, one that esc nodes does not list"
        own = (
            "node 127 uses this tool's own node id, so nothing it sends can be told from "
            "this tool's own frames"
        )
        assert listed.stderr == f"veronte4x: {own}; {advice}\n"
        text = veronte4x("esc", "nodes", *bus, "--timeout", "2.1")
        rows = text.stdout.splitlines()
        assert [row.split()[0] for row in rows[1:]] == ["21", "127"]
        assert rows[2].endswith("  conflict: uses this tool's node id")
        assert "conflict" not in rows[1]
        apart = veronte4x("esc", "nodes", *bus, "--timeout", "2.1", "--node-id", "120")
        assert (apart.returncode, apart.stderr) == (0, "")
        assert "conflict" not in apart.stdout
        spin = veronte4x("esc", "spin", "21", "--throttle", "0.5", "--duration", "5", "--yes",
                         *bus)  # fmt: skip
        assert (spin.returncode, spin.stderr) == (
            2,
            f"veronte4x: node 127's esc_index cannot be read, so it may turn too ({own[9:]}); "
            f"{advice}; add --allow-unknown-index 127 if it drives no motor; nothing was "
            "sent\n",
        )
        every = veronte4x("esc", "get", "all", "esc_index", *bus)
        assert (every.returncode, every.stderr) == (
            2,
            f"veronte4x: {own}; {advice}; nothing was sent\n",
        )
        assert recorder.commands == []
        assert set(recorder.more_statuses(127, 3)) == {0}


def test_set_refuses_an_index_another_node_has() -> None:
    with _bus("21,22") as (bus, recorder):  # esc_index 0 and 1
        refused = veronte4x("esc", "set", "21", "esc_index", "1", *bus)
        assert (refused.returncode, refused.stdout) == (2, "")
        assert refused.stderr == (
            "veronte4x: node 22 has esc_index 1 already: giving it to node 21 too would make "
            "RawCommand turn both; add --allow-shared-index to give it anyway; nothing was "
            "sent\n"
        )
        by_index = veronte4x("esc", "set", "21", "2", "1", "--by-index", *bus)
        assert (by_index.returncode, by_index.stderr) == (2, refused.stderr)
        kept = veronte4x("esc", "get", "21", "esc_index", *bus)
        assert kept.stdout == "esc_index = 0 (default 0, range 0..19)\n"
        other = veronte4x("esc", "set", "21", "esc_index", "5", *bus)
        assert (other.returncode, other.stdout) == (0, "esc_index = 5 (default 0, range 0..19)\n")
        shared = veronte4x("esc", "set", "21", "esc_index", "1", "--allow-shared-index", *bus)
        assert (shared.returncode, shared.stdout) == (0, "esc_index = 1 (default 0, range 0..19)\n")
        assert recorder.commands == []


def test_apply_refuses_an_index_another_node_has(tmp_path: Path) -> None:
    with _bus("21,22") as (bus, _):  # esc_index 0 and 1
        saved = tmp_path / "vehicle.toml"
        result = veronte4x("esc", "params", "21,22", *bus, "--save", str(saved))
        assert result.returncode == 0, result.stderr
        text = saved.read_text(encoding="utf-8")
        one = tmp_path / "one.toml"
        one.write_text(text.replace("value = 0, default = 0, min = 0, max = 19",
                                    "value = 1, default = 0, min = 0, max = 19"))  # fmt: skip
        refused = veronte4x("esc", "apply", str(one), "21", *bus, "--dry-run")
        assert refused.returncode == 2
        assert refused.stdout == "node 21: esc_index 0 -> 1\n"
        assert refused.stderr == (
            "veronte4x: node 22 has esc_index 1 already: giving it to node 21 too would make "
            "RawCommand turn both; add --allow-shared-index to give it anyway; nothing was "
            "sent\n"
        )
        swap = tmp_path / "swap.toml"
        swap.write_text(text.replace("value = 0, default = 0", "value = 9, default = 0")
                        .replace("value = 1, default = 1", "value = 0, default = 1")
                        .replace("value = 9, default = 0", "value = 1, default = 0"))  # fmt: skip
        swapped = veronte4x("esc", "apply", str(swap), "21,22", *bus)
        assert swapped.returncode == 0, swapped.stderr
        got = veronte4x("esc", "get", "21,22", "esc_index", *bus, "--json")
        assert [n["value"] for n in json.loads(got.stdout)["nodes"]] == [1, 0]
        twice = tmp_path / "twice.toml"
        twice.write_text(text + text[text.index("[[node]]") :])
        dup = veronte4x("esc", "apply", str(twice), "all", *bus)
        assert (dup.returncode, dup.stdout) == (2, "")
        lines = [
            n for n, line in enumerate(twice.read_text().splitlines(), 1) if line == "[[node]]"
        ]
        assert dup.stderr == (
            f"veronte4x: {twice}: node_id 21 is given twice (lines {lines[0]} and "
            f"{lines[2]}): one would be ignored; keep one table per node\n"
        )
