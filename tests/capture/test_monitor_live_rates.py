"""``veronte4x monitor --rates`` as a person sees it in a terminal (tmux): each row's period,
jitter and longest gap live in the table, the bus load in the summary line, and a node
whose NodeStatus falls silent flagged STOPPED while the others run on."""

from __future__ import annotations

from pathlib import Path

from tests.tmux_support import keys, needs_tmux, terminal, wait_for

START = 1_763_737_000.0


def capture(path: Path) -> Path:
    """AP2's Ready at 20 Hz and node 21's NodeStatus at 10 Hz for 60 s; node 20's
    NodeStatus at 10 Hz for its first second only."""
    lines = []
    for tick in range(1200):
        stamp = START + tick * 0.05
        lines.append((stamp, "009#00FF01"))
        if tick % 2 == 0:
            tail = 0xC0 | (tick // 2) & 0x1F
            lines.append((stamp + 0.001, f"{0x10015515:08X}#00000000000000{tail:02X}"))
            if tick < 20:
                lines.append((stamp + 0.002, f"{0x10015514:08X}#00000000000000{tail:02X}"))
    path.write_text("".join(f"({stamp:.6f}) can0 {frame}\n" for stamp, frame in sorted(lines)))
    return path


def _row(screen: str, start: str) -> str:
    return next((line for line in screen.splitlines() if line.startswith(start)), "")


def _node_20_stopped_alone(screen: str) -> bool:
    return "STOPPED" in _row(screen, "node 20") and "STOPPED" not in _row(screen, "node 21")


@needs_tmux
def test_live_rates_flag_the_node_that_falls_silent(tmp_path: Path) -> None:
    path = capture(tmp_path / "silent.log")
    args = ("monitor", str(path), "--rates", "--speed", "1")
    with terminal(*args, width=160, height=12) as tmux:
        screen = wait_for(tmux, lambda s: "node 21" in s and "period" in s)
        head = _row(screen, "sender").split()
        assert head[:12] == [
            "sender", "┃", "type", "┃", "id", "┃", "count", "┃", "rate/s", "┃", "period", "┃",
        ]  # fmt: skip
        assert "jitter" in head and "gap" in head and "state" in head
        assert "bus load can0 " in screen and " kbit/s" in screen
        screen = wait_for(tmux, _node_20_stopped_alone)
        node = [cell.strip() for cell in _row(screen, "node 20").split("│")]
        assert node[1:3] == ["NodeStatus", "10015514"]
        assert node[3] == "10"  # its count stays at its 10 records
        assert node[5] == "100 ms"  # period
        assert node[8] == "STOPPED"
        assert "STOPPED" not in _row(screen, "AP2")
        keys(tmux, "q")
        screen = wait_for(tmux, lambda s: "exit=" in s)
        assert "exit=0" in screen
