"""``veronte4x decode``: a capture to one record per line, as text, JSON lines or CSV.

Numbers follow `veronte4x.numbers`: JSON lines and CSV carry the exact decoded values
(`veronte4x.capture.readable.readable_fields`), the text output shows them for people
(shortest at the field's declared width, with units); enums by name, text as text
everywhere.

Times, in every output, as ``--time`` says (`veronte4x.times`): ``timestamp`` (the default),
Unix time as ISO 8601 in UTC to the microsecond (``2025-11-21T15:00:00.010000Z``, the
tables' time) and a capture's own clock (below `veronte4x.times.EPOCH_THRESHOLD`, time since
boot) as its seconds; ``relative``, seconds since the first timestamped record, to the
microsecond; ``seconds``, the timestamp as the reader gives it (in JSON lines and CSV the
float itself, its ``repr``: the exact value where a reader holds more than microseconds).

CAN IDs as candump prints them (`veronte4x.capture.readable.can_id_text`): 3 hex digits for
an 11-bit ID, 8 for a 29-bit one, upper case; in the text output, from the first 29-bit ID
on, an 11-bit ID is indented to the width of a 29-bit one so that the columns after it line
up, as candump indents them once it has seen one (can-utils ``candump.c``).
"""

from __future__ import annotations

import argparse
import csv
import json
import sys
from collections.abc import Callable, Iterable
from typing import Any, TextIO

from veronte4x import capture
from veronte4x.capture.busmap import BusMap
from veronte4x.capture.readable import can_id_text, format_message, hex_bytes, readable_fields
from veronte4x.capture.readers.live import BusLoss
from veronte4x.capture.records import Record
from veronte4x.capture.stats import Stats
from veronte4x.cli.exit_codes import EXIT_BAD_FRAME, EXIT_INTERRUPTED, EXIT_OK
from veronte4x.cli.interrupts import Interrupts
from veronte4x.cli.notices import InputWatch, channel_hint
from veronte4x.cli.options import (
    add_capture_options,
    add_live_options,
    add_renamed_option,
    open_records,
)
from veronte4x.cli.options import live as live_bus
from veronte4x.numbers import exact
from veronte4x.times import (
    EPOCH_THRESHOLD,
    TIME_FORMS,
    TimeForm,
    format_time,
    relative_seconds,
    utc_text,
)
from veronte4x.values import name_of
from veronte4x.words import counted

HEAD_COLUMNS = ("timestamp", "channel", "can_id", "sender", "message", "error", "detail", "data")
"""The record's own columns, before the message's fields."""


def add_parser(commands: Any) -> None:
    """Register the command."""
    parser = commands.add_parser("decode", help="decode a capture, one record per line")
    parser.add_argument("file", nargs="?", default="-", help="capture file, or - for stdin")
    parser.add_argument(
        "--output",
        choices=["text", "jsonl", "csv"],
        default="text",
        help="text (default), JSON lines, or CSV with one column per field",
    )
    parser.add_argument(
        "--on-error",
        choices=["skip", "keep", "raise"],
        default="skip",
        help="bad frames: skip and count them (default), keep them as records, or stop",
    )
    parser.add_argument(
        "--time",
        choices=TIME_FORMS,
        default="timestamp",
        help="timestamp: ISO 8601 in UTC to the microsecond (the default; a clock since boot "
        "as seconds), relative: seconds since the first frame, seconds: as logged (exact)",
    )
    add_renamed_option(parser, "--relative-time", "--time relative")
    add_capture_options(parser)
    add_live_options(parser)
    parser.set_defaults(run=run)


def run(args: argparse.Namespace, bus_map: BusMap) -> int:
    """Decode the capture to standard output; the summary goes to standard error."""
    counts = Stats()
    loss = BusLoss()
    watch = InputWatch(None if live_bus(args) else args.file)
    out = sys.stdout
    bus = live_bus(args)  # written out whenever no frame is waiting, not once a record
    records = watch.records(open_records(args, bus_map, loss=loss, idle=out.flush if bus else None))
    clock = _Clock(args.time)
    if args.output == "csv":
        write, close = _csv_writer(out, clock, _csv_columns(args, bus_map))
    elif args.output == "jsonl":
        write, close = _jsonl_writer(out, clock)
    else:
        write, close = _text_writer(out, clock, _Ids())
    piped = args.file == "-" and not bus  # standard input: each record at once
    status = EXIT_OK
    try:
        with Interrupts() as interrupts:
            for record in records:
                with interrupts.whole:  # counted and written, or neither
                    counts.add(record)
                    if record.error is not None:
                        if args.on_error == "skip":
                            continue
                        if args.on_error == "raise":
                            close()
                            out.flush()
                            can_id = can_id_text(record.can_id, record.extended)
                            print(f"veronte4x: {_describe(record, clock, can_id)}", file=sys.stderr)
                            status = EXIT_BAD_FRAME
                            break
                    write(record)
                    if piped:
                        out.flush()
    except KeyboardInterrupt:
        close()
        out.flush()
        print(f"veronte4x: interrupted after {_summary(counts, loss)}", file=sys.stderr)
        return EXIT_INTERRUPTED
    if status == EXIT_OK:
        close()
    note = watch.note()
    print(
        f"veronte4x: {_summary(counts, loss)} ({args.on_error})" + (f"; {note}" if note else ""),
        file=sys.stderr,
    )
    hint = channel_hint(watch.path, args.only_channel, watch.frames)
    if hint is not None:
        print(f"veronte4x: {hint}", file=sys.stderr)
    return status


def _summary(counts: Stats, loss: BusLoss) -> str:
    errors = sum(counts.errors.values())
    unknown = sum(counts.unknown.values())
    lost = loss.text()
    text = f"{counted(counts.records, 'record')}, {unknown} undecoded, {errors} bad"
    return text + (f", {lost}" if lost else "")


class _Clock:
    """Timestamps as written, in the form ``--time`` names (the module docstring)."""

    def __init__(self, form: TimeForm) -> None:
        self.form = form
        self.start: float | None = None

    def value(self, stamp: float | None) -> str | float | None:
        """The timestamp for JSON and CSV: ISO 8601 text, or seconds."""
        if stamp is None:
            return None
        if self.form == "seconds":
            return exact(stamp)
        if self.form == "relative":
            if self.start is None:
                self.start = stamp
            return relative_seconds(stamp, self.start)
        if stamp >= EPOCH_THRESHOLD:
            try:
                return utc_text(stamp)
            except OverflowError:  # past the year 9999: no ISO 8601 form, so seconds
                pass
        return exact(stamp)

    def text(self, stamp: float | None) -> str:
        """The timestamp for text: ISO 8601, or seconds."""
        if stamp is None:
            return "-"
        if self.form == "seconds":
            return f"{stamp:.6f}"
        if self.form == "relative" and self.start is None:
            self.start = stamp
        return format_time(stamp, self.start if self.form == "relative" else None)


class _Ids:
    """CAN IDs for the text output, as candump prints them (the module docstring)."""

    def __init__(self) -> None:
        self.width = 3

    def text(self, record: Record) -> str:
        """The record's CAN ID, right-aligned in the column."""
        wide = record.extended
        if wide:
            self.width = 8
        return f"{can_id_text(record.can_id, wide):>{self.width}}"


def _describe(record: Record, clock: _Clock, can_id: str) -> str:
    """A bad record in one line: time, channel, CAN ID (``can_id``), error and detail."""
    stamp = clock.text(record.timestamp)
    return f"{stamp} {record.channel} {can_id} {record.error}: {record.detail}"


Writer = tuple[Callable[[Record], None], Callable[[], None]]
"""Write one record; close (write what is kept, once)."""


def _nothing() -> None:
    pass


def _text_writer(out: TextIO, clock: _Clock, ids: _Ids) -> Writer:
    def write(record: Record) -> None:
        if record.error is not None:
            out.write(f"{_describe(record, clock, ids.text(record))} {hex_bytes(record.data)}\n")
            return
        stamp = clock.text(record.timestamp)
        head = f"{stamp} {record.channel} {ids.text(record)} {record.sender:<9}"
        if record.message is None:
            out.write(f"{head} unknown: {record.detail} {hex_bytes(record.data)}\n")
        else:
            out.write(f"{head} {format_message(record.message)}\n")

    return write, _nothing


def _row(record: Record, clock: _Clock) -> dict[str, Any]:
    row: dict[str, Any] = {
        "timestamp": clock.value(record.timestamp),
        "channel": record.channel,
        "can_id": record.can_id,
        "sender": record.sender,
    }
    if record.message is not None:
        owner = type(record.message)
        named = getattr(owner, "_NAMED_FIELDS_", None)  # selected_name beside selected
        row["message"] = owner.__name__
        for name, value in readable_fields(record.message).items():
            row[f"message.{name}" if name in HEAD_COLUMNS else name] = value
            if named and name in named and (text := name_of(owner, name, value)) is not None:
                row[f"{name}_name"] = text
    else:
        row["message"] = None
        if record.error is not None:
            row["error"] = record.error
        row["detail"] = record.detail
        row["data"] = record.data.hex()
    return row


def _jsonl_writer(out: TextIO, clock: _Clock) -> Writer:
    def write(record: Record) -> None:  # no NaN reaches json: `exact` makes it "NaN"
        out.write(json.dumps(_row(record, clock), allow_nan=False) + "\n")

    return write, _nothing


def _csv_columns(args: argparse.Namespace, bus_map: BusMap) -> Iterable[str] | None:
    """The field columns of a file, from a first pass over it; None for standard input,
    whose rows are kept until it ends."""
    if args.file == "-":
        return None
    columns: dict[str, None] = {}
    for record in capture.read(args.file, bus_map, args.only_channel, args.dbc):
        if record.message is not None:
            columns.update(dict.fromkeys(_row(record, _Clock("seconds"))))
    return columns


def _csv_writer(out: TextIO, clock: _Clock, fields: Iterable[str] | None) -> Writer:
    """One column per field: the record's columns, then every field the capture has.

    From a file the columns are known from a first pass and rows stream out. From standard
    input they are not known until it ends: rows are kept and written on close.
    """
    if fields is not None:
        columns = [*HEAD_COLUMNS, *(name for name in fields if name not in HEAD_COLUMNS)]
        writer = csv.DictWriter(out, columns, lineterminator="\n")
        writer.writeheader()
        return (lambda record: writer.writerow(_row(record, clock))), _nothing
    rows: list[dict[str, Any]] = []

    def close() -> None:
        names = dict.fromkeys(HEAD_COLUMNS)
        for row in rows:
            names.update(dict.fromkeys(row))
        kept = csv.DictWriter(out, list(names), lineterminator="\n")
        kept.writeheader()
        kept.writerows(rows)
        rows.clear()

    return (lambda record: rows.append(_row(record, clock))), close
