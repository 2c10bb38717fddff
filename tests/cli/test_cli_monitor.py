"""``veronte4x monitor``: plain text over a capture, and interactively in a terminal (tmux)."""

from __future__ import annotations

import time
from pathlib import Path

from tests.client.cli_support import bus_args, free_port, simulator, veronte4x, veronte4x_all
from tests.tmux_support import keys, needs_tmux, terminal, wait_for
from tests.tmux_support import screen as shown_now

CAPTURE = Path(__file__).resolve().parents[2] / "examples" / "capture.log"


def test_plain_table_over_a_capture() -> None:
    result = veronte4x("monitor", str(CAPTURE))
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    assert lines[:3] == [
        "arbiter: selected AP2, arbitration on; alive AP1 AP2 AP3 -; ready AP1 AP2 AP3 -; "
        "scores AP1 0.058 AP2 0.026 AP3 0.054",
        "39 records, 1 bad, 0.501 s",
        "sender    type                        id    count   rate/s  errors  fields",
    ]
    assert (
        "AP1       ArbitrationVariable        008        3   1000.0       0  number=2, value=1.7"
        in lines
    )
    assert result.stderr == "veronte4x: 39 records, 1 bad, 0.501 s\n"


def test_plain_filter_and_live_bus() -> None:
    port = free_port()
    with simulator(port, "--nodes", "21"):
        result = veronte4x("monitor", *bus_args(port), "--duration", "1.2", "--filter", "node")
    assert result.returncode == 0, result.stderr
    tables = result.stdout.split("arbiter: no Status yet\n")[1:]
    assert len(tables) >= 2  # one a second while live, and the last one
    rows = [line.split()[2] for line in tables[-1].splitlines()[2:]]
    assert rows == ["EscStatus", "NodeStatus", "Temperature"]


@needs_tmux
def test_interactive_in_a_terminal() -> None:
    port = free_port()
    with (
        simulator(port, "--nodes", "21,22"),
        terminal("monitor", *bus_args(port)) as tmux,
    ):
        screen = wait_for(tmux, lambda s: "node 22" in s and "Temperature" in s)
        assert "p pause · f filter · c clear · q quit" in screen
        keys(tmux, "f")
        keys(tmux, "nodestat", literal=True)
        keys(tmux, "Enter")
        wait_for(
            tmux,
            lambda s: (
                "filter: nodestat " in s
                and s.count("NodeStatus") == 2
                and "EscStatus" not in s
                and "Temperature" not in s
            ),
        )
        keys(tmux, "p")
        paused = wait_for(tmux, lambda s: "PAUSED" in s)
        time.sleep(1.2)
        assert shown_now(tmux) == paused  # frozen while paused
        keys(tmux, "q")
        screen = wait_for(tmux, lambda s: "exit=0" in s)
        assert "veronte4x: " in screen and " records, 0 bad" in screen


def test_stats_and_replay_read_a_live_bus() -> None:
    port = free_port()
    with simulator(port, "--nodes", "21"):
        stats, replay = veronte4x_all(
            ["stats", *bus_args(port), "--duration", "1.2"],
            ["replay", *bus_args(port), "--duration", "0.3"],
        )
    assert stats.returncode == 0, stats.stderr
    assert "NodeStatus" in stats.stdout and "EscStatus" in stats.stdout
    assert replay.returncode == 0, replay.stderr
    assert replay.stderr.splitlines()[-1] == (
        "veronte4x: 0 decisions, 0 disagreements, 0 bad frames"
    )


def test_live_bus_and_a_file_is_a_usage_error() -> None:
    result = veronte4x("stats", str(CAPTURE), *bus_args(free_port()))
    assert result.returncode == 2
    assert result.stderr == (
        f"veronte4x: give a capture file ({CAPTURE}) or --interface, not both\n"
    )
