"""End-to-end speed: a candump file of at least 1 M frames to decoded records.

Run: python benchmarks/bench_capture.py [--frames 1000000] [--repeat 3]

Two files, both from the example flight (`examples/make_capture.py`: the arbiter, three
autopilots, PWM sets and four Vertiq ESCs over DroneCAN), repeated with shifted timestamps
up to ``--frames`` lines:
- ``flight``: the example flight as it is, a quarter of its frames DroneCAN;
- ``third DroneCAN``: the same flight with every DroneCAN frame kept (multi-frame esc.Status,
  RawCommand, Temperature, NodeStatus, GetNodeInfo) and only enough Veronte frames, in
  order, for DroneCAN to be a third of the frames.

For each file, in one run, best of ``--repeat`` rounds (one run of each reader per round, so
that all see the same machine load), it times:
- python-can's candump reader alone (`can.CanutilsLogReader`, messages only);
- python-can's reader plus cantools decoding each Veronte frame with an equivalent DBC
  built in memory (cantools cannot reassemble DroneCAN transfers, so those frames are only
  read);
- veronte4x from the file to records (`capture.read`: Veronte decoding and DroneCAN
  reassembly and decoding included);
- veronte4x from the file to a pandas DataFrame (`capture.to_dataframe`).
"""

from __future__ import annotations

import argparse
import math
import platform
import runpy
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

import can
import cantools.database as cdb
from cantools.database.can import Message, Signal
from cantools.database.conversion import BaseConversion

from veronte4x import capture

ROOT = Path(__file__).resolve().parent.parent
HOUR_OF_TWO_BUSES = 63_000_000  # frames in one hour of two busy 1 Mbit/s buses


def flight_lines(dronecan_share: float | None) -> list[str]:
    """The example flight's lines in time order; with ``dronecan_share``, Veronte frames
    thinned, in order, until DroneCAN frames are that share of the lines."""
    make = runpy.run_path(str(ROOT / "examples" / "make_capture.py"))
    texts = make["generate"](2.0, 60.0, 4).lines()
    if dronecan_share is None:
        return texts
    kept: list[str] = []
    dronecan = veronte = 0
    for text in texts:
        if len(text.split()[2].partition("#")[0]) == 8:  # a 29-bit ID: DroneCAN
            dronecan += 1
            kept.append(text)
        elif veronte < dronecan * (1 - dronecan_share) / dronecan_share:
            veronte += 1
            kept.append(text)
    return kept


def make_file(path: Path, frames: int, texts: list[str]) -> int:
    """Write ``texts``, repeated with shifted timestamps, up to `frames` lines."""
    span = 120.0
    written = 0
    with path.open("w") as out:
        copy = 0
        while written < frames:
            shift = copy * span
            for text in texts:
                stamp, rest = text.split(" ", 1)
                out.write(f"({float(stamp[1:-1]) + shift:.6f}) {rest}\n")
                written += 1
                if written == frames:
                    break
            copy += 1
    return written


def _veronte_dbc() -> cdb.can.Database:
    signals = [
        Signal("cmd", 0, 8),
        Signal("sub", 8, 8),
        Signal("value", 16, 32, conversion=BaseConversion.factory(1, 0, None, True)),
    ]
    return cdb.can.Database([Message(i, f"m{i}", 6, signals) for i in (8, 9, 10, 11, 255)])


def python_can_reader(path: Path) -> int:
    """Read every message with python-can."""
    return sum(1 for _ in can.CanutilsLogReader(str(path)))


def python_can_and_cantools(path: Path) -> int:
    """Read with python-can, decode Veronte frames with cantools."""
    db = _veronte_dbc()
    ids = {8, 9, 10, 11, 255}
    count = 0
    for message in can.CanutilsLogReader(str(path)):
        if not message.is_extended_id and message.arbitration_id in ids:
            db.decode_message(message.arbitration_id, message.data, allow_truncated=True)
        count += 1
    return count


def veronte4x_records(path: Path) -> int:
    """Read and decode every frame into records."""
    return sum(1 for _ in capture.read(str(path)))


def veronte4x_dataframe(path: Path) -> int:
    """Read and decode into a DataFrame."""
    return len(capture.to_dataframe(capture.read(str(path))))


def _best_times(
    functions: list[tuple[str, Callable[[Path], int]]], path: Path, repeat: int
) -> dict[str, tuple[int, float]]:
    """Each function's count and best time of ``repeat`` runs, run in turns (one run of
    each per round) so that all of them see the same machine load."""
    best = {name: (0, math.inf) for name, _ in functions}
    for _ in range(repeat):
        for name, function in functions:
            start = time.perf_counter()
            count = function(path)
            seconds = time.perf_counter() - start
            best[name] = (count, min(best[name][1], seconds))
    return best


def main() -> None:
    """Build each file, time every reader, print rates and ratios."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--frames", type=int, default=1_000_000, help="lines in each file")
    parser.add_argument("--repeat", type=int, default=3, help="runs per reader; the best counts")
    args = parser.parse_args()
    print(f"Python {platform.python_version()}, best of {args.repeat} runs")
    with tempfile.TemporaryDirectory() as folder:
        for mix, share in (("flight", None), ("third DroneCAN", 1 / 3)):
            path = Path(folder) / "flight.log"
            texts = flight_lines(share)
            written = make_file(path, args.frames, texts)
            dronecan = sum(len(t.split()[2].partition("#")[0]) == 8 for t in texts) / len(texts)
            print(f"\n{mix}: {written} frames, {dronecan:.1%} DroneCAN, {path.stat().st_size} B")
            functions = [
                ("python-can reader alone", python_can_reader),
                ("python-can + cantools", python_can_and_cantools),
                ("veronte4x to records", veronte4x_records),
                ("veronte4x to DataFrame", veronte4x_dataframe),
            ]
            best = _best_times(functions, path, args.repeat)
            baseline = best["python-can reader alone"][1]
            for name, (count, seconds) in best.items():
                rate = written / seconds
                print(
                    f"{name:26} {rate:10.0f} frames/s  {baseline / seconds:5.2f}x reader"
                    f"  ({count} items, {seconds:.2f} s;"
                    f" 63 M frames: {HOUR_OF_TWO_BUSES / rate:.0f} s)"
                )


if __name__ == "__main__":
    main()
