"""Peak memory of `read_tables` on large captures, against its bound (2x tables + 300 MB).

Run: python benchmarks/bench_mf4_memory.py [--mf4-mb 100 1000] [--candump-mb 100 1000]
     [--layouts plain deflate buses] [--frames N]

MF4 files are written with asammdf in python-can's MF4 bus-logging record layout
(``CAN_DataFrame`` records of 64 data bytes, 84 bytes a record with its time) from the
example flight's frames (`examples/make_capture.py`), repeated with shifted timestamps; a
file of ``--mf4-mb`` megabytes holds as many frames as that size uncompressed. Layouts:

- ``plain``: one ``CAN_DataFrame`` group for the bus, uncompressed data blocks (DT);
- ``deflate``: the same, compressed as python-can's MF4Writer compresses by default
  (asammdf's level 2: transposed, deflated data blocks, DZ);
- ``buses``: two buses, one ``CAN_DataFrame`` group each (the Veronte frames on bus 1, the
  DroneCAN ones on bus 2), uncompressed.

candump files (``--candump-mb``) are the same flight as text. ``--frames N`` writes one
plain MF4 file of N frames instead of the sizes (a quick run). Each file is written once
into a temporary directory and deleted after its measurement; each measurement runs in a
fresh process and reports the kernel's high-water mark of its resident set (``VmHWM``),
the bytes of the tables returned and the time taken. MB here are 2**20 bytes.
"""

from __future__ import annotations

import argparse
import datetime
import runpy
import tempfile
from pathlib import Path

import numpy as np
from bench_capture import flight_lines, make_file
from bench_columnar import read_in_process

from veronte4x.capture.columnar.frames import FrameColumns
from veronte4x.capture.columnar.sources import read_frames

ROOT = Path(__file__).resolve().parent.parent
BLOCK = 200_000
RECORD = 84
"""Bytes of one record of python-can's layout, its time included."""
MB = 2**20
LAYOUTS = {
    "plain": "one bus group, uncompressed (DT)",
    "deflate": "one bus group, transposed deflate (DZ)",
    "buses": "two bus groups (Veronte, DroneCAN), uncompressed (DT)",
}


def flight_frames() -> FrameColumns:
    """The example flight's data frames, as columns."""
    with tempfile.TemporaryDirectory() as tmp:
        flight = Path(tmp) / "flight.log"
        runpy.run_path(str(ROOT / "examples" / "make_capture.py"))["generate"](2.0, 60.0, 4).write(
            flight
        )
        source = read_frames(flight)
    return source.take(np.flatnonzero(~source.error & ~source.remote))


def write_mf4(path: Path, frames: int, layout: str, flight: FrameColumns | None = None) -> None:
    """An MF4 bus log of ``frames`` frames of the example flight, written with asammdf."""
    from asammdf import MDF, Signal
    from asammdf.blocks.source_utils import Source
    from can.io.mf4 import STD_DTYPE

    source = flight if flight is not None else flight_frames()
    stamps_all = source.timestamp
    start = float(stamps_all[0])
    span = float(stamps_all[-1]) - start + 0.001
    buses = 2 if layout == "buses" else 1
    mdf = MDF(version="4.10")
    mdf.header.start_time = datetime.datetime.fromtimestamp(start, datetime.timezone.utc)
    for bus in range(buses):
        name = f"CAN{bus + 1}"
        mdf.append(
            Signal(
                name="CAN_DataFrame",
                samples=np.array([], dtype=STD_DTYPE),
                timestamps=np.array([], dtype="<f8"),
                source=Source(name, name, "", Source.SOURCE_BUS, Source.BUS_TYPE_CAN),
            )
        )
    n = len(stamps_all)
    for first in range(0, frames, BLOCK):
        rows = np.arange(first, min(first + BLOCK, frames))
        for bus in range(buses):
            mine = rows[source.extended[rows % n] == bool(bus)] if buses > 1 else rows
            which, lap = mine % n, mine // n
            records = np.zeros(len(mine), dtype=STD_DTYPE)
            records["CAN_DataFrame.BusChannel"] = bus + 1
            records["CAN_DataFrame.ID"] = source.can_id[which] | (
                source.extended[which].astype(np.uint32) << 31
            )
            records["CAN_DataFrame.IDE"] = source.extended[which]
            records["CAN_DataFrame.DLC"] = source.length[which]
            records["CAN_DataFrame.DataLength"] = source.length[which]
            records["CAN_DataFrame.DataBytes"][:, :8] = source.data[which]
            stamps = stamps_all[which] - start + lap * span
            mdf.extend(bus, [(stamps, None), (records, None)])
    mdf.save(path, overwrite=True, compression=2 if layout == "deflate" else 0)
    mdf.close()


def report(name: str, path: Path) -> None:
    """Measure ``path`` and print its row: peak against the bound."""
    file_size = path.stat().st_size
    rows, size_mb, seconds, peak_mb = read_in_process(path)
    bound_mb = 2 * size_mb + 300
    print(
        f"{name}, {file_size / MB:,.0f} MB: read_tables {seconds:.1f} s, tables "
        f"{size_mb:,.0f} MB ({rows:,} rows), peak RSS {peak_mb:,.0f} MB, bound "
        f"{bound_mb:,.0f} MB, peak / bound = {peak_mb / bound_mb:.2f}",
        flush=True,
    )


def main() -> None:
    """Write each file, measure read_tables on it in a fresh process, delete it."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--mf4-mb", type=float, nargs="*", default=[100, 1000])
    parser.add_argument("--candump-mb", type=float, nargs="*", default=[100, 1000])
    parser.add_argument("--layouts", nargs="*", choices=list(LAYOUTS), default=list(LAYOUTS))
    parser.add_argument("--frames", type=int, help="one plain MF4 file of this many frames")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "large.mf4"
        if args.frames:
            write_mf4(path, args.frames, "plain")
            report(f"MF4 file: {args.frames} frames, {LAYOUTS['plain']}", path)
            return
        flight = flight_frames() if args.mf4_mb else None
        for size in args.mf4_mb:
            frames = int(size * MB / RECORD)
            for layout in args.layouts:
                write_mf4(path, frames, layout, flight)
                report(f"MF4 file: {frames:,} frames, {LAYOUTS[layout]}", path)
                path.unlink()
        texts = flight_lines(None) if args.candump_mb else []
        for size in args.candump_mb:
            log = Path(tmp) / "large.log"
            frames = make_file(log, max(1, int(size * MB / 43)), texts)  # ~43 B a line
            report(f"candump file: {frames:,} frames", log)
            log.unlink()


if __name__ == "__main__":
    main()
