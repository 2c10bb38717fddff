"""Driving a terminal program in tmux, as a person would: read the screen, wait for it."""

from __future__ import annotations

import subprocess
import time
from collections.abc import Callable

WAIT = 120.0
"""Seconds to wait for a screen: a hang guard, not a timing (the suite runs under load)."""


def screen(tmux: list[str], target: str = "monitor") -> str:
    """What the pane ``target`` of the tmux server ``tmux`` shows now."""
    return subprocess.run(
        [*tmux, "capture-pane", "-p", "-t", target], capture_output=True, text=True, check=True
    ).stdout


def wait_for(tmux: list[str], condition: Callable[[str], bool], target: str = "monitor") -> str:
    """The first screen ``condition`` accepts; AssertionError with the last one after `WAIT`."""
    end = time.monotonic() + WAIT
    shown = ""
    while time.monotonic() < end:
        shown = screen(tmux, target)
        if condition(shown):
            return shown
        time.sleep(0.1)
    raise AssertionError(f"screen never matched:\n{shown}")
