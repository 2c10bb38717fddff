"""The ``veronte4x`` command line: a filter over captures, like cantools' ``decode``.

Data goes to standard output; summaries and errors go to standard error, an error as one line
naming what was wrong and what to do, never a traceback. Exit codes (`exit_codes`): 0 on
success (bad frames skipped or kept are not failures), 1 when the capture failed a check
(``--on-error raise`` met a bad frame, ``replay`` found disagreements), 2 for a usage error or
an input that cannot be read (missing file, directory, unknown format, bad bus map, a
``--dsdl`` directory that cannot be used, missing extra, a CAN bus that cannot be opened), 3
when a DroneCAN node did not answer and 4 when it refused (``esc``), 130 when interrupted by
Ctrl-C.

Each command lives in its own module with an ``add_parser`` function that registers it.
"""

from __future__ import annotations

import argparse
import contextlib
import importlib
import os
import sys
import warnings
from collections.abc import Callable, Sequence
from typing import Any, TextIO, cast

from veronte4x.capture.busmap import BusMap, BusMapError
from veronte4x.cli.buses import require_bus_packages
from veronte4x.cli.exit_codes import EXIT_INTERRUPTED, EXIT_OK, EXIT_USAGE
from veronte4x.cli.options import (
    UsageError,
    bus_settings,
    check_bus_spelling,
    live,
    with_dbc_options,
    with_transfer_rules,
)
from veronte4x.dronecan import DsdlError, load_dsdl
from veronte4x.dronecan.dsdl_cache import DsdlCacheWarning
from veronte4x.dronecan.typeset import DsdlOverrideWarning
from veronte4x.errors import SourceError

COMMANDS = (
    "decode",
    "stats",
    "replay",
    "monitor",
    "plot",
    "list",
    "esc",
    "simulate",
    "convert",
    "export",
    "play",
    "record",
)
"""The commands, in the order ``--help`` lists them: each the module of its name in this
package, with an ``add_parser`` function. A command line that names one imports that one
only (``esc`` alone loads the ESC client), any other all of them."""


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; return its exit code."""
    stdout = sys.stdout
    sys.stdout = cast(TextIO, _StandardOutput(stdout))
    shown = warnings.showwarning
    warnings.showwarning = _notes(shown)
    try:
        return _run(argv)
    finally:
        sys.stdout = stdout
        warnings.showwarning = shown


def _notes(shown: Callable[..., None]) -> Callable[..., None]:
    """A `warnings.showwarning` that shows a replaced DSDL definition, and a DSDL cache
    that cannot be written, as one line on standard error, and any other warning with
    ``shown``."""

    def note(message: Warning | str, category: type[Warning], *args: Any, **kwargs: Any) -> None:
        if issubclass(category, DsdlOverrideWarning):
            print(f"veronte4x: note: {message}", file=sys.stderr)
        elif issubclass(category, DsdlCacheWarning):
            print(f"veronte4x: warning: {message}", file=sys.stderr)
        else:
            shown(message, category, *args, **kwargs)

    return note


def _run(argv: Sequence[str] | None) -> int:
    try:
        parser = _parser(sys.argv[1:] if argv is None else argv)
        args = parser.parse_args(argv)
        check_bus_spelling(args)
        if hasattr(args, "interface") and live(args):
            # before the command shows anything: a live source opens its bus in the thread
            # that reads it, once the command has started (the monitor's table among them)
            require_bus_packages(bus_settings(args), "a live CAN bus")
        bus_map = BusMap.from_toml(args.bus_map) if args.bus_map else BusMap()
        if getattr(args, "dsdl", None):
            bus_map = bus_map.with_types(load_dsdl(*args.dsdl))
        bus_map = with_transfer_rules(args, with_dbc_options(args, bus_map))
        result: int = args.run(args, bus_map)
        return result
    except KeyboardInterrupt:
        return _fail("interrupted", EXIT_INTERRUPTED)
    except BrokenPipeError:
        # The reader (`| head`) is gone: stop quietly, and keep Python's exit-time flush
        # of standard output from failing again.
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return EXIT_OK
    except OSError as error:
        return _fail(_os_error(error), EXIT_USAGE)
    except _usage_errors() as error:
        return _fail(str(error), EXIT_USAGE)


def _usage_errors() -> tuple[type[Exception], ...]:
    """The errors a command line's user fixes (exit 2, one line), with the arbiter's
    `ConfigError` where a command loaded the arbiter (none is raised before): a command
    without it does not import it to name the error."""
    found = (SourceError, UsageError, BusMapError, DsdlError, ImportError)
    arbiter = sys.modules.get("veronte4x.arbiter.errors")
    return found if arbiter is None else (*found, arbiter.ConfigError)


def _fail(message: str, code: int) -> int:
    """Print one error line on standard error after the output so far; return the code."""
    with contextlib.suppress(OSError):
        sys.stdout.flush()
    print(f"veronte4x: {message}", file=sys.stderr)
    return code


def _os_error(error: OSError) -> str:
    """``path: reason`` rather than Python's ``[Errno 2] ...: 'path'``."""
    if error.filename is not None and error.strerror:
        return f"{error.filename}: {error.strerror}"
    return str(error)


class _StandardOutput:
    """``sys.stdout`` while a command runs: a write or flush that fails raises the error
    naming ``standard output`` (a failed write names no file: ``> /dev/full`` said only
    "[Errno 28] No space left on device"); everything else is the stream's."""

    def __init__(self, stream: TextIO) -> None:
        self._stream = stream

    def __getattr__(self, name: str) -> Any:
        return getattr(self._stream, name)

    def write(self, text: str) -> int:
        try:
            return self._stream.write(text)
        except OSError as error:
            raise type(error)(error.errno, error.strerror, "standard output") from None

    def flush(self) -> None:
        try:
            self._stream.flush()
        except OSError as error:
            raise type(error)(error.errno, error.strerror, "standard output") from None


def _parser(argv: Sequence[str] = ()) -> argparse.ArgumentParser:
    """The parser of a command line: every command's, or the one ``argv`` starts with."""
    parser = argparse.ArgumentParser(
        prog="veronte4x",
        description="Decode Veronte 4x and Vertiq DroneCAN traffic from CAN captures.",
    )
    parser.add_argument("--version", action=_Version, help="show the version and exit")
    commands = parser.add_subparsers(required=True, metavar="COMMAND")
    named = [argv[0]] if argv and argv[0] in COMMANDS else COMMANDS
    for command in named:
        importlib.import_module(f"veronte4x.cli.{command}").add_parser(commands)
    return parser


class _Version(argparse.Action):
    """``--version``, which looks the version up only when asked (it reads package metadata)."""

    def __init__(self, option_strings: Sequence[str], dest: str, help: str | None = None) -> None:
        super().__init__(option_strings, dest, nargs=0, help=help)

    def __call__(self, parser: argparse.ArgumentParser, *_: object) -> None:
        from veronte4x import __version__

        print(f"veronte4x {__version__}")
        parser.exit()
