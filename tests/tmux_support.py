"""Driving a terminal program in tmux, as a person would: start it in a pane of a given
size, press keys, read the screen, wait for it."""

from __future__ import annotations

import itertools
import os
import shlex
import shutil
import subprocess
import sys
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager

import pytest

WAIT = 120.0
"""Seconds to wait for a screen: a hang guard, not a timing (the suite runs under load)."""

needs_tmux = pytest.mark.skipif(shutil.which("tmux") is None, reason="tmux is not installed")
"""Skip a test where tmux is not installed."""

_servers = itertools.count()


@contextmanager
def terminal(*args: str, width: int = 150, height: int = 30) -> Iterator[list[str]]:
    """``veronte4x ARGS`` in a ``width`` x ``height`` pane ``monitor`` of a tmux server of
    its own (the command prefix to give `screen`, `wait_for` and `keys`); its exit code
    shows as ``exit=N`` after it. The server is killed on leaving.

    The program sees the pane's size, as in a person's terminal: ``COLUMNS`` and ``LINES``
    are unset (a pane started from pytest inherits them, at 80 and 24, whatever its size)."""
    tmux = ["tmux", "-L", f"veronte4x-{os.getpid()}-{next(_servers)}"]
    command = shlex.join(
        ["env", "-u", "COLUMNS", "-u", "LINES", sys.executable, "-m", "veronte4x", *args]
    )
    subprocess.run(
        [*tmux, "new-session", "-d", "-s", "monitor", "-x", str(width), "-y", str(height),
         f"{command}; echo exit=$?; sleep 60"],
        check=True,
    )  # fmt: skip
    try:
        yield tmux
    finally:
        subprocess.run([*tmux, "kill-server"], check=False)


def keys(tmux: list[str], *names: str, literal: bool = False, target: str = "monitor") -> None:
    """Press keys (tmux names: ``Enter``, ``C-c``, ``Down``) in ``target``; with ``literal``,
    type ``names`` as text."""
    flags = ["-l"] if literal else []
    subprocess.run([*tmux, "send-keys", "-t", target, *flags, *names], check=True)


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
