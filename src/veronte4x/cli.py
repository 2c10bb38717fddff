"""The ``veronte4x`` command line: a filter over captures, like cantools' ``decode``.

Data goes to standard output; summaries and errors go to standard error. Exit codes: 0 on
success (bad frames skipped or kept are not failures), 1 when ``--on-error raise`` met a bad
frame, 2 for a usage error or an input that cannot be opened (missing file, bad bus map).
"""

from __future__ import annotations

import argparse
import csv
import json
import math
import os
import sys
from collections.abc import Callable, Sequence
from typing import Any, TextIO

from veronte4x import __version__, capture
from veronte4x.arbiter.errors import ConfigError
from veronte4x.busmap import BusMap, BusMapError
from veronte4x.frames import Frame
from veronte4x.readers.open import open_frames
from veronte4x.records import Record
from veronte4x.stats import Stats

EXIT_OK, EXIT_BAD_FRAME, EXIT_USAGE = 0, 1, 2


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; return its exit code."""
    parser = _parser()
    args = parser.parse_args(argv)
    try:
        bus_map = BusMap.from_toml(args.bus_map) if args.bus_map else BusMap()
        result: int = args.run(args, bus_map)
        return result
    except BrokenPipeError:
        # The reader (`| head`) is gone: stop quietly, and keep Python's exit-time flush
        # of standard output from failing again.
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return EXIT_OK
    except (OSError, BusMapError, ConfigError, ImportError) as error:
        print(f"veronte4x: {error}", file=sys.stderr)
        return EXIT_USAGE


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="veronte4x",
        description="Decode Veronte 4x and Vertiq DroneCAN traffic from CAN captures.",
    )
    parser.add_argument("--version", action="version", version=f"veronte4x {__version__}")
    commands = parser.add_subparsers(required=True, metavar="COMMAND")

    decode = commands.add_parser("decode", help="decode a capture, one record per line")
    decode.add_argument("file", nargs="?", default="-", help="capture file, or - for stdin")
    decode.add_argument("--output", choices=["text", "jsonl", "csv"], default="text")
    decode.add_argument(
        "--on-error",
        choices=["skip", "keep", "raise"],
        default="skip",
        help="bad frames: skip and count them (default), keep them as records, or stop",
    )
    decode.set_defaults(run=_decode)

    stats = commands.add_parser("stats", help="count frames and transfers per type and sender")
    stats.add_argument("file", help="capture file, or - for stdin")
    stats.set_defaults(run=_stats)

    replay = commands.add_parser(
        "replay", help="run the arbiter model on a capture; explain switches and disagreements"
    )
    replay.add_argument("file", help="capture file, or - for stdin")
    replay.add_argument("--config", metavar="FILE", help="TOML arbiter configuration")
    replay.set_defaults(run=_replay)

    for sub in (decode, stats, replay):
        sub.add_argument("--bus-map", metavar="FILE", help="TOML file of CAN IDs and choices")
        sub.add_argument("--channel", help="keep only this interface's frames")
    return parser


def _decode(args: argparse.Namespace, bus_map: BusMap) -> int:
    counts = Stats()
    records = counts.counted(capture.read(args.file, bus_map, args.channel))
    out = sys.stdout
    write = {"text": _text_writer, "jsonl": _jsonl_writer, "csv": _csv_writer}[args.output](out)
    live = args.file == "-"
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
        if live:
            out.flush()
    errors = sum(counts.errors.values())
    print(f"veronte4x: {counts.records} records, {errors} bad ({args.on_error})", file=sys.stderr)
    return status


def _stats(args: argparse.Namespace, bus_map: BusMap) -> int:
    print(capture.stats(capture.read(args.file, bus_map, args.channel)).report())
    return EXIT_OK


def _replay(args: argparse.Namespace, bus_map: BusMap) -> int:
    from veronte4x import arbiter
    from veronte4x.arbiter.config_file import load_config

    if args.config:
        config = load_config(args.config)
    else:
        config = arbiter.ArbiterConfig(
            autopilot_ids=bus_map.autopilot_ids,
            arbiter_id=bus_map.arbiter_id,
            extended_ids=bus_map.extended,
        )
    frames = (
        (frame.timestamp, frame.can_id, frame.data)
        for frame in open_frames(args.file, args.channel)
        if isinstance(frame, Frame)
        and frame.timestamp is not None
        and not (frame.error or frame.remote or frame.fd)
        and frame.extended == config.extended_ids
    )
    result = arbiter.replay(frames, config)
    print(result.timeline())
    print(
        f"veronte4x: {len(result.decisions)} decisions, {len(result.disagreements)} "
        f"disagreements, {len(result.errors)} bad frames",
        file=sys.stderr,
    )
    return EXIT_OK


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
