"""``veronte4x monitor`` as a person sees it on an 80x24 terminal (tmux), and Ctrl-C."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

from tests.client.cli_support import bus_args, free_port, simulator
from tests.inputs.support import candump
from tests.tmux_support import keys, needs_tmux, terminal, wait_for

NODES = [str(node) for node in range(20, 28)]  # 8 ESCs: 24 rows, more than the screen holds


@needs_tmux
def test_an_80x24_terminal_shows_what_does_not_fit_and_scrolls() -> None:
    port = free_port()
    with (
        simulator(port, "--nodes", ",".join(NODES)),
        terminal("monitor", *bus_args(port), width=80, height=24) as tmux,
    ):
        # Every node's three rows: NodeStatus comes once a second, the others faster.
        screen = wait_for(tmux, lambda s: _shown_and_hidden(s) == 24)
        lines = screen.rstrip("\n").split("\n")
        assert len(lines) <= 24
        rows = [i for i, line in enumerate(lines) if line.startswith("node ")]
        # The narrow layout: each row's fields on the line under it, none cut mid-line.
        assert rows and all(lines[i + 1].startswith("  ") for i in rows), screen
        assert all(len(line) <= 80 for line in lines), screen
        assert "node 20 Temperature" in screen
        assert "node 27" not in screen
        keys(tmux, *["Down"] * 30)
        screen = wait_for(tmux, lambda s: "node 27 Temperature" in s and "above (↑)" in s)
        assert "more rows" not in screen
        keys(tmux, "C-c")
        screen = wait_for(tmux, lambda s: "exit=" in s)
        assert "exit=130" in screen
        assert "veronte4x: interrupted after " in screen


def _shown_and_hidden(screen: str) -> int:
    """Rows on the screen plus those its ``+N more rows`` line says are below (0 without
    one)."""
    lines = screen.rstrip("\n").split("\n")
    more = [line for line in lines if "more rows (↓)" in line]
    if len(more) != 1:
        return 0
    return sum(line.startswith("node ") for line in lines) + int(more[0].split()[0].lstrip("+"))


def test_ctrl_c_on_a_capture_file_exits_130(tmp_path: Path) -> None:
    fifo = tmp_path / "live.log"
    os.mkfifo(fifo)
    process = subprocess.Popen(
        [sys.executable, "-m", "veronte4x", "monitor", str(fifo)],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    with fifo.open("w") as writer:  # opens once monitor has opened the capture
        writer.write(candump(500))
        writer.flush()
        time.sleep(0.5)
        process.send_signal(signal.SIGINT)
        out, err = process.communicate(timeout=60)
    assert process.returncode == 130, err
    assert err.startswith("veronte4x: interrupted after 500 records, 0 bad, ")
    assert "AP2     Ready       009      500" in out  # what was read is shown
