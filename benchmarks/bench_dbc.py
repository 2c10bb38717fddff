"""DBC in: decoding the frames a DBC knows, side by side with cantools' own decode_message.

Run: python benchmarks/bench_dbc.py [--frames 50000] [--repeat 3]

Shapes: a capture of only DBC frames (a BMS status, 8 bytes, with a value table; a
multiplexed 29-bit gimbal frame), and the example flight with those frames mixed in
(one in ten). The reference is cantools' `Database.decode_message` per frame on the same
frames already parsed (bytes in hand). Rows, in microseconds per DBC frame, best of the
turns, and the ratio veronte4x over cantools:

- ``columnar DBC pass``: the columnar engine's DBC step alone (`columnar.dbc.decode_dbc_frames`
  over the parsed frame columns, then the Arrow tables built): what decoding through the
  engine costs, the issue's 2x row;
- ``read_tables``: the whole path, parsing the file and routing included (for the mixed
  shape, what its DBC frames add to the flight alone);
- ``read``: what the DBC adds to `capture.read` (records with it minus without).

The last rows are what the DBC path costs when it has nothing to do: `read_tables` of the
flight with a DBC that knows none of its frames over none, and the engine step without a
DBC, per call.
"""

from __future__ import annotations

import argparse
import functools
import random
import runpy
import tempfile
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import cantools
import numpy as np

from veronte4x import capture
from veronte4x.capture import BusMap
from veronte4x.capture.columnar import dbc
from veronte4x.capture.columnar.frames import FrameColumns
from veronte4x.capture.columnar.schema import TableSpec, all_specs
from veronte4x.capture.columnar.sources import read_frames
from veronte4x.capture.columnar.tables import Tables

ROOT = Path(__file__).resolve().parent.parent
DBC = ROOT / "tests" / "capture" / "data" / "payload.dbc"
BUS_MAP = BusMap(dronecan=False)


def frames(count: int, seed: int = 1) -> list[tuple[int, bool, bytes]]:
    rng = random.Random(seed)
    out = []
    for _ in range(count):
        if rng.random() < 0.7:
            out.append((0x123, False, bytes(rng.randrange(256) for _ in range(8))))
        else:
            data = bytes([rng.choice([1, 2]), rng.randrange(256), rng.randrange(256), 0])
            out.append((0x18FF1234, True, data))
    return out


def lines(listed: list[tuple[int, bool, bytes]], start: float = 1.7e9) -> list[str]:
    return [
        f"({start + i / 1000:.6f}) can0 {c:{'08X' if e else '03X'}}#{d.hex()}"
        for i, (c, e, d) in enumerate(listed)
    ]


def tables_of(path: Path, dbc: list[Path]) -> object:
    return capture.read_tables(path, BUS_MAP, dbc=dbc)


def records_of(path: Path, dbc: list[Path]) -> object:
    return list(capture.read(path, BUS_MAP, dbc=dbc))


def best(function: Callable[[], Any], repeat: int) -> float:
    times = []
    for _ in range(repeat):
        began = time.perf_counter()
        function()
        times.append(time.perf_counter() - began)
    return min(times)


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--frames", type=int, default=50_000)
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    database: Any = cantools.database.load_file(str(DBC))
    listed = frames(args.frames)
    work = Path(tempfile.mkdtemp())
    only = work / "payload.log"
    only.write_text("\n".join(lines(listed)) + "\n")
    flight = work / "flight.log"
    runpy.run_path(str(ROOT / "examples" / "make_capture.py"))["generate"](
        args.frames / 60_000, 15.0, 4
    ).write(flight)
    flight_lines = flight.read_text().splitlines()
    mixed = work / "mixed.log"
    payload = lines(frames(len(flight_lines) // 10, 2))
    merged = flight_lines + payload  # time order does not matter to the decoders
    mixed.write_text("\n".join(merged) + "\n")

    def cantools_loop(chosen: list[tuple[int, bool, bytes]]) -> None:
        decode = database.decode_message
        for can_id, extended, data in chosen:
            decode(can_id, data, force_extended_id=extended)

    print(f"DBC in, {args.frames} frames, best of {args.repeat}")
    print("microseconds per DBC frame, against cantools' decode_message per frame on the")
    print("same frames, already parsed")
    print(f"{'path, shape':<44}{'veronte4x':>12}{'cantools':>12}{'ratio':>8}")
    mixed_listed = frames(len(flight_lines) // 10, 2)
    bus_map = BusMap(dronecan=False, dbc=(str(DBC),))
    for shape, path, chosen in (
        ("only DBC frames", only, listed),
        ("flight + 1/10 DBC frames", mixed, mixed_listed),
    ):
        count = len(chosen)
        reference = best(functools.partial(cantools_loop, chosen), args.repeat) / count
        parsed = read_frames(path)
        step = functools.partial(engine_pass, parsed, bus_map, all_specs(bus_map.codec()))
        whole = best(functools.partial(tables_of, path, [DBC]), args.repeat)
        if path == mixed:  # what the DBC frames add to the flight's own decoding
            whole -= best(functools.partial(tables_of, flight, []), args.repeat)
        with_records = best(functools.partial(records_of, path, [DBC]), args.repeat)
        rows = (
            ("columnar DBC pass", best(step, args.repeat)),
            ("read_tables" + (" (added)" if path == mixed else ""), whole),
            (
                "read (added)",
                with_records - best(functools.partial(records_of, path, []), args.repeat),
            ),
        )
        for label, seconds in rows:
            each = seconds / count
            print(
                f"{label + ', ' + shape:<44}{each * 1e6:>10.2f}us{reference * 1e6:>10.2f}us"
                f"{each / reference:>8.2f}"
            )
    none = work / "none.dbc"
    none.write_text('VERSION ""\nNS_ :\nBS_:\nBU_: X\nBO_ 1 Nothing: 1 X\n')
    without = best(lambda: capture.read_tables(flight, BUS_MAP), args.repeat)
    useless = best(lambda: capture.read_tables(flight, BUS_MAP, dbc=[none]), args.repeat)
    print(f"read_tables of the flight, a DBC that knows none over none: {useless / without:.2f}")
    parsed = read_frames(flight)
    done = np.zeros(len(parsed), np.bool_)
    calls = 10_000
    began = time.perf_counter()
    for _ in range(calls):
        dbc.decode_dbc_frames(parsed, BUS_MAP, done, None)  # type: ignore[arg-type]
    per_call = (time.perf_counter() - began) / calls
    print(f"the engine's DBC step without a DBC: {per_call * 1e9:.0f} ns a call")


def engine_pass(parsed: FrameColumns, bus_map: BusMap, specs: dict[str, TableSpec]) -> None:
    """The columnar engine's DBC step over parsed frames, and its tables built."""
    tables = Tables(specs, list(parsed.channels))
    dbc.decode_dbc_frames(parsed, bus_map, np.zeros(len(parsed), np.bool_), tables)
    tables.finish()


if __name__ == "__main__":
    main()
