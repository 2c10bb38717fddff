"""``python -m veronte4x`` and the ``veronte4x`` script: the command line as a process.

A Ctrl-C (SIGINT) at any moment of the process ends it with one line and exit code 130
(`veronte4x.cli.exit_codes.EXIT_INTERRUPTED`), never a traceback: while the command runs it
is the command's to handle (it stops between records and says how far it got); while the
modules load, and once the command has returned, the process ends at once, its output
flushed. This module imports little, so that the handler is in place before the command
line's modules load.
"""

from __future__ import annotations

import atexit
import contextlib
import os
import signal
import sys
from types import FrameType
from typing import NoReturn

EXIT_INTERRUPTED = 130
"""`veronte4x.cli.exit_codes.EXIT_INTERRUPTED`, which this module does not import (it would
load the whole command line before the handler is in place)."""


class _Process:
    """Whether a Ctrl-C is the command's (raised in it) or the process's (ends it), and the
    command's exit code once it has returned."""

    command_running = False
    code: int | None = None


def script() -> NoReturn:
    """Run the command line on ``sys.argv`` and exit with its code."""
    signal.signal(signal.SIGINT, _on_sigint)
    atexit.register(_exit_now)  # registered first: runs after every other exit function
    from veronte4x.cli import main

    try:
        _Process.command_running = True
        code = main()
        _Process.command_running = False
    except KeyboardInterrupt:  # between the command's return and the line above
        _Process.command_running = False
        _interrupted()
    finally:
        _Process.command_running = False  # argparse's exit (--help, a usage error)
    _Process.code = code
    sys.exit(code)


def _on_sigint(signum: int, frame: FrameType | None) -> None:
    if _Process.command_running:
        raise KeyboardInterrupt
    _interrupted()


def _exit_now() -> None:
    """End the process with the command's code once threads are joined and exit functions
    run, without unloading the modules: that takes a while (pyarrow's), and SIGINT is back
    to its default action by then, which would end the process without a word."""
    if _Process.code is not None:
        _flush()
        _save_coverage()
        os._exit(_Process.code)


def _interrupted() -> NoReturn:
    """Flush the output so far, say so in one line, end the process with code 130."""
    _flush()
    with contextlib.suppress(OSError):
        os.write(sys.stderr.fileno(), b"veronte4x: interrupted\n")
    _save_coverage()
    os._exit(EXIT_INTERRUPTED)


def _save_coverage() -> None:
    """Save coverage.py's data when it measures this process (``make coverage`` follows the
    command lines the tests start): its exit function, registered before this module's,
    would never run after ``os._exit``."""
    coverage = sys.modules.get("coverage")
    current = None if coverage is None else coverage.Coverage.current()
    if current is not None:
        current.stop()
        current.save()


def _flush() -> None:
    for stream in (sys.stdout, sys.stderr):
        with contextlib.suppress(Exception):  # a closed pipe, a flush already under way
            stream.flush()


if __name__ == "__main__":
    script()
