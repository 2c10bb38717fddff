"""``veronte4x monitor``: a live table of the bus, one row per message type and sender.

On a terminal it is a refreshing table (the ``monitor`` extra, rich) with the arbiter's
state on top and keys to pause (``p``), filter (``f``, then text and Enter; Esc clears),
scroll (arrow keys, ``j`` and ``k``) and quit (``q``). One line per row, its fields cut with
an ellipsis at the terminal's edge; rows below the screen are counted in a last line
(``+N more rows``).

On a terminal narrower than `NARROW` columns (80x24 is the one every terminal has) the
layout is narrow, by one rule: the arbiter's line wraps between its parts (state; alive;
ready; scores), never inside one; the table has no rules, its fixed columns are as narrow as
their contents (a type name longer than `TYPE_WIDTH` is cut with ``…``, the head ``err``),
and each row's fields (after its timing, with ``--rates``) take the next line, indented, cut
with ``…`` at the edge: two lines per row.

When standard output is not a terminal it prints the table as plain
text, every ``--interval`` seconds for a live bus, once at the end for a capture. Ctrl-C
stops it with code 130, as every command; ``q`` with 0.

With ``--rates`` the table shows each row's timing live (period, jitter, longest gap, and
``STOPPED`` or ``slow``: `veronte4x.capture.monitor`), the summary line the bus load, and
the per-stream report of ``stats --rates`` follows the last table.
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
from veronte4x.capture.monitor import (
    TIMING_HEADS,
    MonitorState,
    Row,
    rate_text,
    render_text,
    timing_texts,
)
from veronte4x.capture.readable import can_id_text
from veronte4x.capture.readers.live import BusLoss
from veronte4x.capture.records import Record
from veronte4x.cli import play, rates
from veronte4x.cli.exit_codes import EXIT_INTERRUPTED, EXIT_OK
from veronte4x.cli.notices import InputWatch, channel_hint
from veronte4x.cli.options import add_capture_options, add_live_options, live, open_records
from veronte4x.extras import require

KEYS_HELP = "p pause · f filter · c clear · q quit · ↑↓ scroll"

NARROW = 100
"""Terminals narrower than this many columns get the narrow layout (module docstring)."""
TYPE_WIDTH = 20
"""Characters of a type name in the narrow layout (``GetNodeInfoResponse`` has 19)."""


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
        self.watch = InputWatch(None if live(args) else args.file)
        self.rates = rates.tracker(args, bus_map)
        self._source = (args, bus_map)
        self._pace = None if not (live(args) or args.speed) else (args.speed or 1.0)
        self._seen: tuple[float, float] | None = None  # latest timestamp, when it came
        self._thread = threading.Thread(target=self._run, name="veronte4x-monitor", daemon=True)

    def _open(self) -> Iterator[Record]:
        """The source's records: fed to the rates tracker and paced as the options say."""
        args, bus_map = self._source
        loss = self.state.loss
        if self.rates is None:
            records = open_records(args, bus_map, self.stop, loss)
        else:
            records = rates.records(args, bus_map, self.rates, self.stop, loss)
        if args.speed is not None and not live(args):
            records = play.paced(records, args.speed, self.stop)
        return records

    def _run(self) -> None:
        try:  # opened in the thread that reads it (python-can's SQLite reader must be)
            for record in self.watch.records(self._open()):
                with self.lock:
                    self.state.add(record)
                    latest = self.state.last_timestamp
                    if latest is not None and self._pace is not None:
                        self._seen = (latest, time.monotonic())
                if self.stop.is_set():
                    break
        except BaseException as error:
            self.failure = error
        finally:
            self.done.set()

    def start(self) -> None:
        self._thread.start()

    def finish(self, wait: bool = True) -> None:
        """Stop reading; re-raise what stopped the reader, if anything did.

        Without ``wait`` (after Ctrl-C) the reader is not waited for: it may be blocked
        reading a pipe that never ends, and it is a daemon thread.
        """
        self.stop.set()
        if wait:
            self._thread.join()
        if self.failure is not None:
            raise self.failure

    def now(self) -> float | None:
        """The bus time now, for the silence of streams (under the lock): a live bus's or
        a paced capture's latest timestamp plus the time since it came (times the
        speed); else None, the latest timestamp."""
        if self._seen is None or self.done.is_set():
            return None
        latest, at = self._seen
        return latest + (time.monotonic() - at) * (self._pace or 1.0)

    def summary(self) -> str:
        """The state's summary, and the bus load with ``--rates`` (under the lock)."""
        text = self.state.summary()
        if self.rates is not None:
            text += "; " + rates.load_text(self.rates)
        return text

    def text(self, text_filter: str) -> str:
        with self.lock:
            return render_text(self.state, text_filter, self.now())


def run(args: argparse.Namespace, bus_map: BusMap) -> int:
    """Show the table until the source ends, the duration passes or the user quits."""
    if sys.stdout.isatty():
        require("rich", "monitor", "veronte4x monitor on a terminal")
    state = MonitorState(rates=args.rates, loss=BusLoss())
    reader = _Reader(args, bus_map, state)
    reader.start()
    status = EXIT_OK
    try:
        if not live(args) and args.speed is None:
            reader.done.wait()
        elif sys.stdout.isatty() and sys.stdin.isatty():
            _interactive(reader, args.filter)
        else:
            while not reader.done.wait(args.interval):
                print(reader.text(args.filter), flush=True)
    except KeyboardInterrupt:
        status = EXIT_INTERRUPTED
    reader.finish(wait=status == EXIT_OK)
    if sys.stdout.isatty():
        _print_rich(reader, args.filter)
    else:
        print(reader.text(args.filter), end="", flush=True)
    if reader.rates is not None:
        print(rates.report(reader.rates), flush=True)
    interrupted = "interrupted after " if status == EXIT_INTERRUPTED else ""
    note = reader.watch.note()
    print(
        f"veronte4x: {interrupted}{state.summary()}" + (f"; {note}" if note else ""),
        file=sys.stderr,
    )
    hint = channel_hint(reader.watch.path, args.only_channel, reader.watch.frames)
    if hint is not None:
        print(f"veronte4x: {hint}", file=sys.stderr)
    return status


Snapshot = tuple[str, str, list[Row], bool]
"""The arbiter line, the summary line, every row and whether to show their timing, taken
under the reader's lock."""


def _snapshot(reader: _Reader) -> Snapshot:
    with reader.lock:
        state = reader.state
        rows = state.rows(now=reader.now())
        return state.arbiter.describe(), reader.summary(), rows, state.rates


def _table(
    snapshot: Snapshot,
    text_filter: str,
    status: str = "",
    screen: Any = None,
    skip: int = 0,
    width: int | None = None,
) -> Any:
    """The view: the arbiter line, the summary line and the table.

    On a ``screen`` (the live view's rich console), each row is one line, its fields cut
    with an ellipsis, and the rows from ``skip`` on that fit are shown, the others counted
    in a last line; without, every row is shown, its fields wrapped between words. On a
    screen or a ``width`` under `NARROW` columns, the narrow layout (module docstring).
    """
    from rich.console import Group
    from rich.text import Text

    header, summary, rows, timing = snapshot
    wanted = text_filter.lower()
    shown = filtered = [
        r for r in rows if not wanted or wanted in r.sender.lower() or wanted in r.kind.lower()
    ]
    if screen is not None:
        width = screen.size.width
    narrow = width is not None and width < NARROW
    if width is not None and narrow:
        header = "\n".join(_wrap_parts(header, width))
    top = Text(header, style="bold")
    line = Text(f"{summary}   {status}".rstrip())
    above = below = 0
    if screen is not None:
        heads = sum(len(screen.render_lines(text, screen.options)) for text in (top, line))
        room = max(1, screen.size.height - heads - (1 if narrow else _TABLE_HEAD))
        if narrow:
            room = max(1, room // 2)
        if len(shown) > room:
            room = max(1, room - 1)  # a last line counts the rows not shown
        skip = max(0, min(skip, len(shown) - room))
        above, below = skip, max(0, len(shown) - skip - room)
        shown = shown[skip : skip + room]
    several = len({r.channel for r in rows}) > 1  # a stream per channel: say which
    if width is not None and narrow:
        table = _narrow_table(shown, filtered, timing, several, width)
    else:
        table = _wide_table(shown, timing, several, screen is not None)
    parts: list[Any] = [top, line, table]
    if below or above:
        more = [f"+{below} more rows (↓)" if below else "", f"{above} above (↑)" if above else ""]
        parts.append(Text(", ".join(m for m in more if m) + "; f to filter", style="bold"))
    return Group(*parts)


def _wrap_parts(text: str, width: int) -> list[str]:
    """The arbiter's line in lines of at most ``width`` characters, broken between its
    ``; ``-separated parts (a part longer than the width is a line of its own)."""
    lines: list[str] = []
    for part in text.split("; "):
        if lines and len(lines[-1]) + 2 + len(part) <= width:
            lines[-1] += "; " + part
        else:
            lines.append(part)
    return lines


def _wide_table(rows: list[Row], timing: bool, several: bool, one_line: bool) -> Any:
    """The table of a wide terminal (or of the last table printed): a row per line."""
    from rich.table import Table
    from rich.text import Text

    table = Table(expand=True, show_edge=False, pad_edge=False)
    for name, justify in (
        ("sender", "left"),
        ("type", "left"),
        ("id", "right"),
        ("count", "right"),
        ("rate/s", "right"),
        *((head, "right") for head in (TIMING_HEADS if timing else ())),
        ("errors", "right"),
    ):
        table.add_column(name, justify=justify, no_wrap=True)  # type: ignore[arg-type]
    table.add_column("fields", ratio=1, no_wrap=one_line, overflow="ellipsis")
    for r in rows:
        table.add_row(
            f"{r.sender} {r.channel}" if several else r.sender,
            r.kind,
            can_id_text(r.can_id, r.extended),
            str(r.count),
            rate_text(r.rate),
            *(_timing_cells(r) if timing else ()),
            Text(str(r.errors), style="bold red" if r.errors else ""),
            r.fields,
        )
    return table


def _narrow_table(
    rows: list[Row], every: list[Row], timing: bool, several: bool, width: int
) -> Any:
    """The table of a narrow terminal: a head line, then per row its columns on one line
    and its timing and fields on the next, indented, cut with an ellipsis at ``width``.
    The columns are as wide as those of ``every`` row, shown or not: they stay put while
    the rows scroll."""
    from rich.console import Group
    from rich.text import Text

    def texts_of(r: Row) -> tuple[str, ...]:
        return (
            f"{r.sender} {r.channel}" if several else r.sender,
            r.kind if len(r.kind) <= TYPE_WIDTH else r.kind[: TYPE_WIDTH - 1] + "…",
            can_id_text(r.can_id, r.extended),
            str(r.count),
            rate_text(r.rate),
            str(r.errors),
        )

    cells = [texts_of(r) for r in rows]
    heads = ("sender", "type", "id", "count", "rate/s", "err")
    columns = [texts_of(r) for r in every]
    widths = [max([len(head), *(len(c[i]) for c in columns)]) for i, head in enumerate(heads)]

    def line(texts: tuple[str, ...]) -> str:
        left = [f"{t:<{w}}" for t, w in zip(texts[:2], widths[:2], strict=True)]
        right = [f"{t:>{w}}" for t, w in zip(texts[2:], widths[2:], strict=False)]
        return " ".join(left + right)

    lines = [Text(line(heads), style="bold", no_wrap=True, overflow="ellipsis")]
    for r, texts in zip(rows, cells, strict=True):
        head = Text(line(texts[:-1]) + " ", no_wrap=True, overflow="ellipsis")
        head.append(f"{texts[-1]:>{widths[-1]}}", style="bold red" if r.errors else "")
        below = Text("  ", no_wrap=True, overflow="ellipsis")
        if timing:
            for cell in _timing_cells(r):
                below.append_text(cell if isinstance(cell, Text) else Text(cell))
                below.append(" ")
        below.append(r.fields)
        below.truncate(width, overflow="ellipsis")
        lines += [head, below]
    return Group(*lines)


def _timing_cells(row: Row) -> list[Any]:
    from rich.text import Text

    period, jitter, gap, flags = timing_texts(row)
    style = "bold red" if "stopped" in row.flags else "yellow" if row.flags else ""
    return [period, jitter, gap, Text(flags, style=style)]


_TABLE_HEAD = 2
"""Lines of the table that are not rows: its head and the rule under it."""


def _print_rich(reader: _Reader, text_filter: str) -> None:
    from rich.console import Console

    console = Console()
    console.print(_table(_snapshot(reader), text_filter, width=console.width))


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


def _arrow(fd: int) -> int:
    """The rows an arrow key's escape sequence scrolls by (after its Esc): down 1, up -1,
    Page Down 10, Page Up -10; 0 for another key."""
    sequence = ""
    while len(sequence) < 3:
        key = _read_key(fd, 0.05)
        if key is None:
            break
        sequence += key
        if key.isalpha() or key == "~":
            break
    return {"[B": 1, "[A": -1, "[6~": 10, "[5~": -10}.get(sequence, 0)


def _interactive(reader: _Reader, text_filter: str) -> None:
    from rich.console import Console
    from rich.live import Live

    paused = False
    editing = False
    skip = 0
    console = Console()

    def view_of(snapshot: Snapshot) -> Any:
        return _table(snapshot, text_filter, status(), console, skip)

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
            view_of(frozen),
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
            elif key in ("j", "k", "\x1b"):
                step = _arrow(fd) if key == "\x1b" else 1 if key == "j" else -1
                skip = max(0, skip + step)
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
                rows = len(frozen[2])
                skip = min(skip, max(0, rows - 1))
                view.update(view_of(frozen), refresh=True)
                next_draw = now + 0.25
