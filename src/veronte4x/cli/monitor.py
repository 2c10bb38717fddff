"""``veronte4x monitor``: a live table of the bus, one row per message type and sender.

On a terminal it is a refreshing table (the ``monitor`` extra, rich) with the arbiter's
state on top and keys to pause (``p``), filter (``f``, then text and Enter; Esc clears) and
quit (``q``). When standard output is not a terminal it prints the table as plain text,
every ``--interval`` seconds for a live bus, once at the end for a capture.
"""

from __future__ import annotations

import argparse
import contextlib
import os
import select
import sys
import threading
import time
from collections.abc import Iterator
from typing import Any

from veronte4x.capture.busmap import BusMap
from veronte4x.capture.monitor import MonitorState, Row, can_id_text, rate_text, render_text
from veronte4x.cli import play, rates
from veronte4x.cli.exit_codes import EXIT_OK
from veronte4x.cli.options import add_capture_options, add_live_options, live, open_records
from veronte4x.extras import require

KEYS_HELP = "p pause · f filter · c clear filter · q quit"


def add_parser(commands: Any) -> None:
    """Register the command."""
    parser = commands.add_parser(
        "monitor", help="live table of a bus or a capture: latest fields, rates, errors"
    )
    parser.add_argument("file", nargs="?", help="capture file (or a live bus: --interface)")
    parser.add_argument("--filter", default="", help="show only senders or types containing it")
    parser.add_argument(
        "--interval",
        type=float,
        default=1.0,
        metavar="S",
        help="plain output of a live bus: seconds between tables (1)",
    )
    add_capture_options(parser)
    add_live_options(parser)
    rates.add_options(parser)
    parser.add_argument(
        "--speed",
        type=play.speed,
        metavar="X",
        help="a capture: show it as if live, at its own pace times X (2: twice as fast)",
    )
    parser.set_defaults(run=run)


class _Reader:
    """Feeds the records of the source into the state from a thread."""

    def __init__(self, args: argparse.Namespace, bus_map: BusMap, state: MonitorState) -> None:
        self.state = state
        self.lock = threading.Lock()
        self.stop = threading.Event()
        self.done = threading.Event()
        self.failure: BaseException | None = None
        self.rates = rates.tracker(args, bus_map)
        if self.rates is None:
            self._records = open_records(args, bus_map, self.stop)
        else:
            self._records = rates.records(args, bus_map, self.rates, self.stop)
        if args.speed is not None and not live(args):
            self._records = play.paced(self._records, args.speed, self.stop)
        self._thread = threading.Thread(target=self._run, name="veronte4x-monitor", daemon=True)

    def _run(self) -> None:
        try:
            for record in self._records:
                with self.lock:
                    self.state.add(record)
                if self.stop.is_set():
                    break
        except BaseException as error:
            self.failure = error
        finally:
            self.done.set()

    def start(self) -> None:
        self._thread.start()

    def finish(self) -> None:
        """Stop reading; re-raise what stopped the reader, if anything did."""
        self.stop.set()
        self._thread.join()
        if self.failure is not None:
            raise self.failure

    def text(self, text_filter: str) -> str:
        with self.lock:
            return render_text(self.state, text_filter)


def run(args: argparse.Namespace, bus_map: BusMap) -> int:
    """Show the table until the source ends, the duration passes or the user quits."""
    if sys.stdout.isatty():
        require("rich", "monitor", "veronte4x monitor on a terminal")
    state = MonitorState()
    reader = _Reader(args, bus_map, state)
    reader.start()
    try:
        if not live(args) and args.speed is None:
            reader.done.wait()
        elif sys.stdout.isatty() and sys.stdin.isatty():
            _interactive(reader, args.filter)
        else:
            while not reader.done.wait(args.interval):
                print(reader.text(args.filter), flush=True)
    except KeyboardInterrupt:
        pass
    reader.finish()
    if sys.stdout.isatty():
        _print_rich(reader, args.filter)
    else:
        print(reader.text(args.filter), end="", flush=True)
    if reader.rates is not None:
        print(rates.report(reader.rates), flush=True)
    print(f"veronte4x: {state.summary()}", file=sys.stderr)
    return EXIT_OK


Snapshot = tuple[str, str, list[Row]]
"""The arbiter line, the summary line and every row, taken under the reader's lock."""


def _snapshot(reader: _Reader) -> Snapshot:
    with reader.lock:
        state = reader.state
        return state.arbiter.describe(), state.summary(), state.rows()


def _table(snapshot: Snapshot, text_filter: str, status: str = "") -> Any:
    from rich.console import Group
    from rich.table import Table
    from rich.text import Text

    header, summary, rows = snapshot
    wanted = text_filter.lower()
    table = Table(expand=True, show_edge=False, pad_edge=False)
    for name, justify in (
        ("sender", "left"),
        ("type", "left"),
        ("id", "right"),
        ("count", "right"),
        ("rate/s", "right"),
        ("errors", "right"),
    ):
        table.add_column(name, justify=justify, no_wrap=True)  # type: ignore[arg-type]
    table.add_column("fields", ratio=1, overflow="fold")
    for r in rows:
        if wanted and wanted not in r.sender.lower() and wanted not in r.kind.lower():
            continue
        table.add_row(
            r.sender,
            r.kind,
            can_id_text(r.can_id),
            str(r.count),
            rate_text(r.rate),
            Text(str(r.errors), style="bold red" if r.errors else ""),
            r.fields,
        )
    top = Text(header, style="bold")
    line = Text(f"{summary}   {status}".rstrip())
    return Group(top, line, table)


def _print_rich(reader: _Reader, text_filter: str) -> None:
    from rich.console import Console

    Console().print(_table(_snapshot(reader), text_filter))


@contextlib.contextmanager
def _keys() -> Iterator[Any]:
    """Standard input in cbreak mode: keys arrive one by one, without echo."""
    import termios
    import tty

    fd = sys.stdin.fileno()
    saved = termios.tcgetattr(fd)
    tty.setcbreak(fd)
    try:
        yield fd
    finally:
        termios.tcsetattr(fd, termios.TCSADRAIN, saved)


def _read_key(fd: int, timeout: float) -> str | None:
    ready, _, _ = select.select([fd], [], [], timeout)
    if not ready:
        return None
    return os.read(fd, 1).decode("utf-8", "replace")


def _interactive(reader: _Reader, text_filter: str) -> None:
    from rich.console import Console
    from rich.live import Live

    paused = False
    editing = False
    console = Console()

    def status() -> str:
        parts = ["PAUSED" if paused else ""]
        if editing:
            parts.append(f"filter: {text_filter}_")
        elif text_filter:
            parts.append(f"filter: {text_filter}")
        parts.append(KEYS_HELP)
        return "   ".join(p for p in parts if p)

    frozen = _snapshot(reader)
    with (
        _keys() as fd,
        Live(
            _table(frozen, text_filter, status()),
            console=console,
            screen=True,
            auto_refresh=False,
        ) as view,
    ):
        next_draw = 0.0
        while not reader.done.is_set():
            key = _read_key(fd, 0.1)
            changed = key is not None
            if key is None:
                pass
            elif editing:
                if key in ("\r", "\n"):
                    editing = False
                elif key == "\x1b":
                    editing, text_filter = False, ""
                elif key in ("\x7f", "\x08"):
                    text_filter = text_filter[:-1]
                elif key.isprintable():
                    text_filter += key
            elif key in ("q", "Q"):
                return
            elif key in ("p", "P", " "):
                paused = not paused
                frozen = _snapshot(reader)
            elif key in ("f", "F", "/"):
                editing = True
            elif key in ("c", "C"):
                text_filter = ""
            now = time.monotonic()
            if changed or (not paused and now >= next_draw):
                if not paused:
                    frozen = _snapshot(reader)
                view.update(_table(frozen, text_filter, status()), refresh=True)
                next_draw = now + 0.25
