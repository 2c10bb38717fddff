"""DBC in: decoding the frames a DBC knows, side by side with cantools' own decode_message.

Run: python benchmarks/bench_dbc.py [--frames 50000] [--repeat 3]

Shapes: a capture of only DBC frames (a BMS status, 8 bytes, with a value table; a
multiplexed 29-bit gimbal frame), and the example flight with those frames mixed in
(one in ten). Rows: seconds per frame of `capture.read_tables(..., dbc=...)` (the whole
path: parse the file, route, decode), of `capture.read(..., dbc=...)` to records, and of
cantools' `Database.decode_message` on the same frames already parsed, best of the turns;
the ratio is veronte4x over cantools. The last row is `read_tables` of the flight alone,
with a DBC that knows none of its frames over none: what the DBC path costs when it has
nothing to do.
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

from veronte4x import capture
from veronte4x.capture import BusMap

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
    print("what the DBC adds per DBC frame (time with it - time without, over its frames),")
    print("against cantools' decode_message per frame on the same frames, already parsed")
    print(f"{'path, shape':<40}{'veronte4x':>12}{'cantools':>12}{'ratio':>8}")
    mixed_listed = frames(len(flight_lines) // 10, 2)
    for shape, path, chosen in (
        ("only DBC frames", only, listed),
        ("flight + 1/10 DBC frames", mixed, mixed_listed),
    ):
        reference = best(functools.partial(cantools_loop, chosen), args.repeat) / len(chosen)
        for label, function in (("read_tables", tables_of), ("read", records_of)):
            with_dbc = best(functools.partial(function, path, [DBC]), args.repeat)
            without = best(functools.partial(function, path, []), args.repeat)
            seconds = max(with_dbc - without, 0.0) / len(chosen)
            print(
                f"{label + ', ' + shape:<40}{seconds * 1e6:>10.2f}us{reference * 1e6:>10.2f}us"
                f"{seconds / reference:>8.2f}"
            )
    none = work / "none.dbc"
    none.write_text('VERSION ""\nNS_ :\nBS_:\nBU_: X\nBO_ 1 Nothing: 1 X\n')
    without = best(lambda: capture.read_tables(flight, BUS_MAP), args.repeat)
    useless = best(lambda: capture.read_tables(flight, BUS_MAP, dbc=[none]), args.repeat)
    print(f"read_tables of the flight, a DBC that knows none over none: {useless / without:.2f}")


if __name__ == "__main__":
    main()
