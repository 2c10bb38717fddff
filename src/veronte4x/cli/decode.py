"""``veronte4x decode``: a capture to one record per line, as text, JSON lines or CSV."""

from __future__ import annotations

import argparse
import csv
import json
import math
import sys
from collections.abc import Callable
from typing import Any, TextIO

from veronte4x import capture
from veronte4x.capture.busmap import BusMap
from veronte4x.capture.records import Record
from veronte4x.capture.stats import Stats
from veronte4x.cli.exit_codes import EXIT_BAD_FRAME, EXIT_OK
from veronte4x.cli.options import add_capture_options, add_live_options, live, open_records


def add_parser(commands: Any) -> None:
    """Register the command."""
    parser = commands.add_parser("decode", help="decode a capture, one record per line")
    parser.add_argument("file", nargs="?", default="-", help="capture file, or - for stdin")
    parser.add_argument("--output", choices=["text", "jsonl", "csv"], default="text")
    parser.add_argument(
        "--on-error",
        choices=["skip", "keep", "raise"],
        default="skip",
        help="bad frames: skip and count them (default), keep them as records, or stop",
    )
    add_capture_options(parser)
    add_live_options(parser)
    parser.set_defaults(run=run)


def run(args: argparse.Namespace, bus_map: BusMap) -> int:
    """Decode the capture to standard output; the summary goes to standard error."""
    counts = Stats()
    records = counts.counted(open_records(args, bus_map))
    out = sys.stdout
    write = {"text": _text_writer, "jsonl": _jsonl_writer, "csv": _csv_writer}[args.output](out)
    flush = args.file == "-" or live(args)
    status = EXIT_OK
    for record in records:
        if record.error is not None:
            if args.on_error == "skip":
                continue
            if args.on_error == "raise":
                print(f"veronte4x: {_describe(record)}", file=sys.stderr)
                status = EXIT_BAD_FRAME
                break
        write(record)
        if flush:
            out.flush()
    errors = sum(counts.errors.values())
    print(f"veronte4x: {counts.records} records, {errors} bad ({args.on_error})", file=sys.stderr)
    return status


def _describe(record: Record) -> str:
    stamp = "-" if record.timestamp is None else f"{record.timestamp:.6f}"
    return f"{stamp} {record.channel} {record.can_id:03X} {record.error}: {record.detail}"


def _text_writer(out: TextIO) -> Callable[[Record], None]:
    def write(record: Record) -> None:
        if record.error is not None:
            out.write(f"{_describe(record)} [{record.data.hex(' ')}]\n")
            return
        stamp = "-" if record.timestamp is None else f"{record.timestamp:.6f}"
        out.write(
            f"{stamp} {record.channel} {record.can_id:03X} {record.sender:<9} {record.message}\n"
        )

    return write


def _row(record: Record) -> dict[str, Any]:
    row: dict[str, Any] = {
        "timestamp": record.timestamp,
        "channel": record.channel,
        "can_id": record.can_id,
        "sender": record.sender,
    }
    if record.error is None:
        row["message"] = type(record.message).__name__
        row.update({k: _plain(v) for k, v in capture.fields(record.message).items()})
    else:
        row.update(message=None, error=record.error, detail=record.detail)
        row["data"] = record.data.hex()
    return row


def _plain(value: Any) -> Any:
    """JSON-safe: bytes as hex, non-finite floats as strings."""
    if isinstance(value, (bytes, bytearray)):
        return value.hex()
    if isinstance(value, float) and not math.isfinite(value):
        return str(value)
    return value


def _jsonl_writer(out: TextIO) -> Callable[[Record], None]:
    def write(record: Record) -> None:
        out.write(json.dumps(_row(record)) + "\n")

    return write


CSV_COLUMNS = ("timestamp", "channel", "can_id", "sender", "message", "error", "detail", "fields")


def _csv_writer(out: TextIO) -> Callable[[Record], None]:
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(CSV_COLUMNS)

    def write(record: Record) -> None:
        row = _row(record)
        fields = {k: v for k, v in row.items() if k not in CSV_COLUMNS and k != "data"}
        if record.error is not None:
            fields = {"data": record.data.hex()}
        writer.writerow(
            [
                row["timestamp"],
                row["channel"],
                row["can_id"],
                row["sender"],
                row.get("message") or "",
                row.get("error") or "",
                row.get("detail") or "",
                json.dumps(fields),
            ]
        )

    return write
