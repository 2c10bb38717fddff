"""``veronte4x monitor`` in a terminal (tmux), the keys a person presses: the filter edited
(Backspace, a control key, Esc), cleared with ``c``, keys that scroll nothing (Esc alone, a
function key), a paced capture that ends by itself, and ``--rates`` over a capture whose
bit rate cannot be told from its timestamps.

Not asserted: ``cli/monitor.py:110``, the reader thread stopping between two records once
``q`` is pressed; whether a record comes between ``q`` and the end of the source is a race
that no key sequence decides, and either way the command exits with 0 and the last table.
"""

from __future__ import annotations

from pathlib import Path

from tests.client.cli_support import bus_args, free_port, simulator
from tests.tmux_support import keys, needs_tmux, terminal, wait_for

CAPTURE = Path(__file__).resolve().parents[2] / "examples" / "capture.log"

pytestmark = needs_tmux


def test_the_filter_edited_and_cleared_with_keys() -> None:
    port = free_port()
    with simulator(port, "--nodes", "21,22"), terminal("monitor", *bus_args(port)) as tmux:
        wait_for(tmux, lambda s: "node 22" in s and "Temperature" in s)
        keys(tmux, "f")
        keys(tmux, "nodexy", literal=True)
        keys(tmux, "BSpace")
        wait_for(tmux, lambda s: "filter: nodex_" in s)
        keys(tmux, "Escape")  # while editing: the filter is dropped
        wait_for(tmux, lambda s: "filter:" not in s and "EscStatus" in s)
        keys(tmux, "f")
        keys(tmux, "status", literal=True)
        keys(tmux, "C-a")  # a control key is not text: ignored
        keys(tmux, "Enter")
        wait_for(
            tmux,
            lambda s: "filter: status " in s and "NodeStatus" in s and "Temperature" not in s,
        )
        keys(tmux, "c")
        wait_for(tmux, lambda s: "filter:" not in s and "Temperature" in s)
        # Esc alone, then a function key: neither scrolls. Whether the Esc is read alone
        # (cli/monitor.py:308, no byte within 0.05 s) or with the next key's bytes depends on
        # when tmux delivers them: both leave the table where it is, which is all asserted.
        keys(tmux, "Escape")
        keys(tmux, "F5")
        keys(tmux, "j")
        keys(tmux, "k")
        keys(tmux, "q")
        screen = wait_for(tmux, lambda s: "exit=0" in s)
    assert "node 21" in screen and "node 22" in screen  # the last table, every row


def test_a_paced_capture_ends_by_itself() -> None:
    with terminal("monitor", str(CAPTURE), "--speed", "5") as tmux:
        screen = wait_for(tmux, lambda s: "exit=" in s)
    assert "exit=0" in screen
    assert "veronte4x: 39 records, 1 bad, 0.501 s" in screen
    # The last row of the last table, whole on one line of the 150-column pane.
    assert "│ number=2, value=2.0\n" in screen


def test_rates_of_frames_too_close_for_any_bit_rate(tmp_path: Path) -> None:
    capture = tmp_path / "fast.log"
    capture.write_text(
        "(1.000000) can0 123#0102030405060708\n"
        "(1.000001) can0 123#0102030405060708\n"  # 1 µs apart: faster than 1 Mbit/s
        "(1.001001) can0 123#0102030405060708\n",
        encoding="utf-8",
    )
    with terminal("monitor", str(capture), "--rates") as tmux:
        screen = wait_for(tmux, lambda s: "exit=" in s)
    assert "exit=0" in screen
    assert "3 records, 0 bad, 0.001 s; bus load can0 ? (give --bitrate)" in screen
    assert (
        "  can0: 3 frames, bit rate unknown: frames 1 µs apart: faster than any standard bit "
        "rate; give --bitrate"
    ) in screen
