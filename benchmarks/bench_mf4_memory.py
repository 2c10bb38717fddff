"""Peak memory of `read_tables` on a large MF4 file: MF4 input is read in chunks.

Run: python benchmarks/bench_mf4_memory.py [--frames 3000000]

The file is written with asammdf in python-can's MF4 bus-logging layout (one
``CAN_DataFrame`` group, 64 data bytes a record, no compression) from the example flight's
frames (`examples/make_capture.py`), repeated with shifted timestamps up to ``--frames``.
Each measurement runs in a fresh process and reports its peak resident set size (RSS),
the size of the tables returned and the time taken.
"""

from __future__ import annotations

import argparse
import datetime
import resource
import runpy
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
BLOCK = 200_000


def write_mf4(path: Path, frames: int) -> None:
    """An MF4 bus log of ``frames`` frames of the example flight, written with asammdf."""
    from asammdf import MDF, Signal
    from asammdf.blocks.source_utils import Source
    from can.io.mf4 import STD_DTYPE

    from veronte4x.capture.columnar.sources import read_frames

    with tempfile.TemporaryDirectory() as tmp:
        flight = Path(tmp) / "flight.log"
        runpy.run_path(str(ROOT / "examples" / "make_capture.py"))["generate"](2.0, 60.0, 4).write(
            flight
        )
        source = read_frames(flight)
    source_rows = source.take(np.flatnonzero(~source.error & ~source.remote))
    start = float(source_rows.timestamp[0])
    span = float(source_rows.timestamp[-1]) - start + 0.001
    mdf = MDF(version="4.10")
    mdf.header.start_time = datetime.datetime.fromtimestamp(start, datetime.timezone.utc)
    bus = Source("CAN", "CAN", "", Source.SOURCE_BUS, Source.BUS_TYPE_CAN)
    mdf.append(
        Signal(
            name="CAN_DataFrame",
            samples=np.array([], dtype=STD_DTYPE),
            timestamps=np.array([], dtype="<f8"),
            source=bus,
        )
    )
    n = len(source_rows)
    for first in range(0, frames, BLOCK):
        rows = np.arange(first, min(first + BLOCK, frames))
        which, lap = rows % n, rows // n
        records = np.zeros(len(rows), dtype=STD_DTYPE)
        records["CAN_DataFrame.BusChannel"] = 1
        records["CAN_DataFrame.ID"] = source_rows.can_id[which] | (
            source_rows.extended[which].astype(np.uint32) << 31
        )
        records["CAN_DataFrame.IDE"] = source_rows.extended[which]
        records["CAN_DataFrame.DLC"] = source_rows.length[which]
        records["CAN_DataFrame.DataLength"] = source_rows.length[which]
        records["CAN_DataFrame.DataBytes"][:, :8] = source_rows.data[which]
        stamps = source_rows.timestamp[which] - start + lap * span
        mdf.extend(0, [(stamps, None), (records, None)])
    mdf.save(path, overwrite=True, compression=0)
    mdf.close()


def measure(path: Path) -> None:
    """Decode ``path`` with read_tables and print peak RSS, table bytes and seconds."""
    from veronte4x import capture

    began = time.perf_counter()
    tables = capture.read_tables(path)
    seconds = time.perf_counter() - began
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
    size = sum(table.nbytes for table in tables.values())
    rows = sum(table.num_rows for table in tables.values())
    print(f"{peak} {size} {rows} {seconds:.2f}")


def main() -> None:
    """Write the file, then measure read_tables on it in a fresh process."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--frames", type=int, default=3_000_000, help="frames in the file")
    parser.add_argument("--measure", type=Path, help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.measure:
        measure(args.measure)
        return
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "large.mf4"
        write_mf4(path, args.frames)
        file_size = path.stat().st_size
        done = subprocess.run(
            [sys.executable, __file__, "--measure", str(path)],
            capture_output=True,
            text=True,
            check=True,
        )
    peak, size, rows, seconds = done.stdout.split()
    mb = 1e6
    print(f"MF4 file: {args.frames} frames, {file_size / mb:.0f} MB")
    print(
        f"read_tables: peak RSS {int(peak) / mb:.0f} MB, tables {int(size) / mb:.0f} MB "
        f"({rows} rows), {seconds} s; peak / (2 x tables + 300 MB) = "
        f"{int(peak) / (2 * int(size) + 300 * mb):.2f}"
    )


if __name__ == "__main__":
    main()
