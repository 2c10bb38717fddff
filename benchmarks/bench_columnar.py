"""Whole captures to tables: the columnar engine against the tools a user would pick instead.

Run: python benchmarks/bench_columnar.py [--frames 2000000] [--small 1000000]
(``--shapes-only``: just the three shapes of capture below and their stages)

The capture is the example flight (`examples/make_capture.py`: three autopilots and the
arbiter, PWM sets, four Vertiq ESCs over DroneCAN with multi-frame esc.Status, RawCommand,
NodeStatus and GetNodeInfo services), repeated with shifted timestamps up to ``--frames``
lines, written as candump text and, for asammdf, as MF4 bus logging of the same frames. In
one run it times, best of ``--repeat`` runs each:

- python-can's candump reader (`can.CanutilsLogReader`) iterating every message;
- asammdf: `MDF.extract_bus_logging` with an equivalent DBC (the Veronte IDs multiplexed on
  the command byte: arbitration frames with a float32 value, PWM sets as four 12-bit
  signals; DroneCAN cannot be described in a DBC, so asammdf skips those frames) and
  `to_dataframe`;
- veronte4x per frame, as before the columnar engine (`to_dataframe(read(path))`), on the
  first ``--per-frame`` frames only (it is slow);
- veronte4x `read_tables` (every frame decoded, DroneCAN reassembled and CRC-checked) on
  ``--small`` and ``--frames`` frames, to show the time is linear in the file's size.

Then DroneCAN buses: ``--session-frames`` frames of 10 to 100,000 distinct sessions (time
per frame), and an ArduPilot-style vehicle bus of ``--vehicle-frames`` frames
(``examples/make_vehicle_bus.py``: 8 ESCs, two servos, GNSS, compass, barometer, airspeed,
battery, arming, lights, log messages and every node's NodeStatus) against python-can's
reader.

Then `capture.to_parquet` (a Parquet dataset, decoded in batches): time and peak memory
(each in a fresh process) on the same two files, to show the memory flat and the time
linear; and ``--files`` copies of the small file converted in one process against a Dask
`LocalCluster` of two worker processes.
"""

from __future__ import annotations

import argparse
import os
import platform
import runpy
import shutil
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from itertools import islice
from pathlib import Path
from typing import Any

import can
import numpy as np
from asammdf import MDF
from bench_capture import ROOT, flight_lines, make_file

from veronte4x import capture, dronecan
from veronte4x.capture.columnar.sources import read_frames
from veronte4x.dronecan.definitions import DATA_TYPES

VERONTE_IDS = ((255, "Arbiter"), (8, "AP1"), (9, "AP2"), (10, "AP3"), (11, "External"))
PWM_COMMANDS = (2, 3, 11, 12, 13)


def write_dbc(path: Path) -> None:
    """A DBC of the Veronte frames, multiplexed on the command byte."""
    lines = ['VERSION ""', "", "NS_ :", "", "BS_:", "", "BU_:", ""]
    value_types = []
    for can_id, name in VERONTE_IDS:
        lines += [
            f"BO_ {can_id} {name}: 8 Vector__XXX",
            ' SG_ command M : 0|8@1+ (1,0) [0|255] "" Vector__XXX',
            ' SG_ sub m0 : 8|8@1+ (1,0) [0|255] "" Vector__XXX',
            ' SG_ value m0 : 16|32@1- (1,0) [0|0] "" Vector__XXX',
        ]
        for command in PWM_COMMANDS:
            lines += [
                f" SG_ pwm{command}_{i} m{command} : {8 + 12 * i}|12@1+ (1,0) [0|4095] "
                '"" Vector__XXX'
                for i in range(4)
            ]
        lines.append("")
        value_types.append(f"SIG_VALTYPE_ {can_id} value : 1;")
    path.write_text("\n".join(lines + value_types) + "\n")


def write_mf4(log: Path, path: Path) -> None:
    """The frames of a candump log as MF4 bus logging, laid out as python-can's MF4Writer
    lays them out, but written as whole arrays (its per-message writer takes minutes)."""
    from can.io.mf4 import STD_DTYPE

    frames = read_frames(log)
    writer = can.MF4Writer(str(path))
    records = np.zeros(len(frames), dtype=STD_DTYPE)
    records["CAN_DataFrame.BusChannel"] = 0
    records["CAN_DataFrame.ID"] = frames.can_id
    records["CAN_DataFrame.IDE"] = frames.extended
    records["CAN_DataFrame.DLC"] = frames.length
    records["CAN_DataFrame.DataLength"] = frames.length
    records["CAN_DataFrame.DataBytes"][:, :8] = frames.data
    stamps = frames.timestamp - writer._start_time
    writer._mdf.extend(0, [(stamps, None), (records, None)])
    writer.stop()


def python_can_reader(path: Path) -> int:
    """Every message through python-can's candump reader."""
    return sum(1 for _ in can.CanutilsLogReader(str(path)))


def asammdf_dataframe(mf4: Path, dbc: Path) -> int:
    """asammdf's bus-logging decode into one DataFrame."""
    decoded = MDF(str(mf4)).extract_bus_logging(database_files={"CAN": [(str(dbc), 0)]})
    return len(decoded.to_dataframe())


def per_frame_dataframe(path: Path) -> int:
    """veronte4x before the columnar engine: records, then a DataFrame."""
    return len(capture.to_dataframe(capture.read(path)))


def columnar_tables(path: Path) -> int:
    """veronte4x's columnar engine: every table."""
    return sum(table.num_rows for table in capture.read_tables(path).values())


CONVERT = """
import re, sys, time
from pathlib import Path
from veronte4x import capture
import veronte4x.capture.columnar.dataset  # imported before the clock starts
start = time.perf_counter()
summary = capture.to_parquet(sys.argv[1], sys.argv[2], progress=False)
seconds = time.perf_counter() - start
peak = re.search(r"VmHWM:\\s+(\\d+) kB", Path("/proc/self/status").read_text())[1]
print(summary.frames, seconds, peak)
"""
"""Peak memory from the kernel's high-water mark of the process (ru_maxrss would count the
parent's memory at the fork)."""


def converted(path: Path, out: Path) -> tuple[int, float, float]:
    """`to_parquet` of one file in a fresh process: frames, seconds, peak memory in MB."""
    result = subprocess.run(
        [sys.executable, "-c", CONVERT, str(path), str(out)],
        capture_output=True,
        text=True,
        check=True,
    )
    frames, seconds, peak_kb = result.stdout.split()
    shutil.rmtree(out)
    return int(frames), float(seconds), int(peak_kb) / 1024


READ = """
import re, sys, time
from pathlib import Path
from veronte4x import capture
import veronte4x.capture.columnar  # imported before the clock starts
start = time.perf_counter()
tables = capture.read_tables(sys.argv[1])
seconds = time.perf_counter() - start
peak = re.search(r"VmHWM:\\s+(\\d+) kB", Path("/proc/self/status").read_text())[1]
print(sum(t.num_rows for t in tables.values()), sum(t.nbytes for t in tables.values()),
      seconds, peak)
"""


def read_in_process(path: Path) -> tuple[int, float, float, float]:
    """`read_tables` of one file in a fresh process: rows, table MB, seconds, peak MB."""
    result = subprocess.run(
        [sys.executable, "-c", READ, str(path)], capture_output=True, text=True, check=True
    )
    rows, size, seconds, peak_kb = result.stdout.split()
    return int(rows), int(size) / 2**20, float(seconds), int(peak_kb) / 1024


def memory_rows(root: Path, sizes_mb: list[float]) -> list[tuple[float, int, float, float, float]]:
    """read_tables of example flights of ``sizes_mb`` megabytes, each in a fresh process:
    (file MB, rows, table MB, seconds, peak MB); the files are deleted after."""
    rows = []
    for size in sizes_mb:
        path = root / f"flight-{size}MB.log"
        make_file(path, max(1, int(size * 1e6 / 43)), flight_lines(None))  # ~43 B a line
        file_mb = path.stat().st_size / 2**20
        rows.append((file_mb, *read_in_process(path)))
        path.unlink()
    return rows


def fleet_rows(small: Path, root: Path, files: int, repeat: int) -> list[tuple[str, int, float]]:
    """Several files converted in this process, then on a local cluster of 2 workers."""
    import dask
    from dask.distributed import Client, LocalCluster

    paths = []
    for index in range(files):
        paths.append(root / f"copy{index}.log")
        shutil.copy(small, paths[-1])
    frames = files * sum(1 for _ in small.open())

    def convert(client: Client | None) -> int:
        out = root / "fleet"
        summary = capture.to_parquet(paths, out, client=client, progress=False)
        shutil.rmtree(out)
        return summary.frames

    rows = [
        (f"to_parquet, {files} files, one process", frames, _timed(lambda: convert(None), repeat))
    ]
    for name, environ in (
        ("LocalCluster 2 workers", {}),
        ("2 workers, mmap 32 MB", {"MALLOC_MMAP_THRESHOLD_": 1 << 25}),
    ):
        with (
            dask.config.set(
                {f"distributed.nanny.pre-spawn-environ.{k}": v for k, v in environ.items()}
            ),
            LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=":0") as cluster,
            Client(cluster) as client,
        ):
            convert(client)  # the workers import veronte4x once
            rows.append(
                (
                    f"to_parquet, {files} files, {name}",
                    frames,
                    _timed(lambda: convert(client), repeat),
                )
            )
    return rows


SESSION_COUNTS = (10, 1_000, 10_000, 100_000)


def session_kinds() -> list[tuple[object, bool]]:
    """Single-frame DroneCAN kinds the column decoders take, and whether each is a service."""
    from veronte4x import dronecan

    return [
        (dronecan.GetNodeInfoRequest(), True),
        (dronecan.RestartNodeRequest(magic_number=0xACCE551B1E), True),
        (dronecan.RestartNodeResponse(ok=True), True),
        (dronecan.ExecuteOpcodeRequest(opcode=0, argument=7), True),
        (dronecan.ExecuteOpcodeResponse(argument=-3, ok=False), True),
        (
            dronecan.NodeStatus(
                uptime_sec=5,
                health=dronecan.Health.OK,
                mode=0,
                sub_mode=0,
                vendor_specific_status_code=0,
            ),
            False,
        ),
    ]


def write_sessions(path: Path, sessions: int, frames: int) -> int:
    """A DroneCAN bus of ``sessions`` distinct sessions (services between any two nodes,
    messages from any node; over two interfaces beyond one's 80,774), one after another,
    each sending its share of ``frames`` single-frame transfers 1 ms apart. Returns the
    frames written."""
    import random

    from veronte4x import dronecan

    kinds = session_kinds()
    keys = [
        (channel, kind, source, target)
        for channel in ("can0", "can1")
        for kind, (_, service) in enumerate(kinds)
        for source in range(1, 128)
        for target in (range(1, 128) if service else (None,))
    ]
    one_bus = len(keys) // 2
    picked = random.Random(sessions).sample(
        keys[:one_bus] if sessions <= one_bus else keys, sessions
    )
    each = max(1, frames // sessions)
    stamp = 1_700_000_000.0
    written = 0
    with path.open("w") as out:
        for channel, kind, source, target in picked:
            frame = dronecan.encode(
                kinds[kind][0], source_node_id=source, transfer_id=0, destination_node_id=target
            )[0]
            head, tail = frame.data[:-1].hex().upper(), frame.data[-1]
            lines = []
            for tid in range(each):
                stamp += 0.001
                lines.append(
                    f"({stamp:.6f}) {channel} {frame.can_id:08X}#{head}{tail | tid % 32:02X}\n"
                )
            out.writelines(lines)
            written += each
    return written


def many_session_lines(flight: list[str], frames: int, sessions: int = 1_500) -> list[str]:
    """A two-bus flight: the example flight on ``can0`` (``flight``: its lines, repeated
    with shifted timestamps) and, on ``can1``, a DroneCAN bus of ``sessions`` distinct
    sessions (services between node pairs and messages of many nodes, single-frame, as a
    bench with many devices has them), all open through the capture, taking turns in a
    random order; half of the ``frames`` lines each, in time order."""
    import random

    from veronte4x import dronecan

    kinds = session_kinds()
    keys = [
        (kind, source, target)
        for kind, (_, service) in enumerate(kinds)
        for source in range(1, 128)
        for target in (range(1, 128) if service else (None,))
    ]
    chooser = random.Random(sessions)
    picked = chooser.sample(keys, sessions)
    made = []
    for kind, source, target in picked:
        frame = dronecan.encode(
            kinds[kind][0], source_node_id=source, transfer_id=0, destination_node_id=target
        )[0]
        made.append((f"{frame.can_id:08X}#{frame.data[:-1].hex().upper()}", frame.data[-1]))
    half = frames // 2
    stamps = [float(line[1 : line.index(")")]) for line in flight]
    span = stamps[-1] - stamps[0] + 0.02
    can0 = []
    for copy in range(half // len(flight) + 1):
        for stamp, line in zip(stamps, flight, strict=True):
            can0.append((stamp + copy * span, line[line.index(")") + 1 :]))
    can0 = can0[:half]
    start, step = can0[0][0], (can0[-1][0] - can0[0][0]) / (frames - half)
    can1 = []
    for k in range(frames - half):
        head, tail = made[k % sessions]
        tid = (k // sessions) % 32
        can1.append((start + k * step, f" can1 {head}{tail | tid:02X}"))
    merged = sorted(can0 + can1, key=lambda item: item[0])
    return [f"({stamp:.6f}){rest}" for stamp, rest in merged]


def session_rows(root: Path, frames: int, repeat: int) -> list[tuple[int, int, float]]:
    """read_tables on buses of 10 to 100,000 distinct sessions: (sessions, frames, s)."""
    rows = []
    for sessions in SESSION_COUNTS:
        path = root / f"sessions-{sessions}.log"
        written = write_sessions(path, sessions, max(frames, sessions))
        rows.append((sessions, written, _timed(lambda p=path: columnar_tables(p), repeat)))
        path.unlink()
    return rows


def vehicle_lines(frames: int) -> list[str]:
    """The first ``frames`` candump lines of the vehicle bus of
    ``examples/make_vehicle_bus.py``."""
    make = runpy.run_path(str(ROOT / "examples" / "make_vehicle_bus.py"))
    lines: list[str] = make["vehicle_lines"](frames)
    return lines


EVERY_TYPE_NODE = 90
"""The node of `every_type_lines`' extra streams (the vehicle bus's autopilot is 10)."""


def every_type_lines(frames: int) -> list[str]:
    """The first ``frames`` lines of the vehicle bus (`vehicle_lines`) with every other
    standard DroneCAN type beside it: each message type the bus lacks once a second from
    node 90, each service's request once a second from the autopilot to node 90 and its
    response back, values zero and arrays empty (``_plain_defaults`` of the example)."""
    make = runpy.run_path(str(ROOT / "examples" / "make_vehicle_bus.py"))
    vehicle = make["vehicle_lines"](frames)
    seconds = frames / make["frames_per_second"]() + 1.0
    on_bus = {name for _, _, name, _ in make["_traffic"]()}
    timed = [(float(line[1 : line.index(")")]), line) for line in vehicle]
    for stream, data_type in enumerate(DATA_TYPES):
        if data_type.full_name in on_bus:
            continue
        service = data_type.kind is not dronecan.TransferKind.MESSAGE
        request = data_type.kind is dronecan.TransferKind.REQUEST
        source = make["AUTOPILOT"] if request else EVERY_TYPE_NODE
        target = (EVERY_TYPE_NODE if request else make["AUTOPILOT"]) if service else None
        message = make["_message"](data_type, {})
        for k in range(int(seconds)):
            t = make["START"] + k + stream * 1e-3 + (0.5e-3 if service and not request else 0)
            made = dronecan.encode(
                message, source_node_id=source, transfer_id=k % 32, destination_node_id=target
            )
            for index, f in enumerate(made):
                stamp = t + index * 1.3e-4
                timed.append((stamp, f"({stamp:.6f}) can0 {f.can_id:08X}#{f.data.hex().upper()}"))
    timed.sort(key=lambda item: item[0])
    return [line for _, line in timed[:frames]]


STAGES = (
    ("parse", "candump text to frame columns (`candump.parse_block`)"),
    ("veronte", "Veronte frames routed and decoded (`engine.decode_veronte`)"),
    ("split", "DroneCAN frames split by session, checked, carried (`stream._dronecan`)"),
    ("reassembly", "transfers joined and their CRCs checked (`dronecan.transfers`, `crc_ok`)"),
    ("payloads", "payloads decoded field by field (`engine._decode_type`)"),
    ("per frame", "irregular frames through the per-frame decoder (`Tables.add_records`)"),
    ("tables", "Arrow columns and tables built (`Tables.add_columns`, `finish_with_keys`)"),
    ("other", "reading the file, joining batches, the rest"),
)
"""The stages of `read_tables` that `stage_times` tells apart."""


def stage_times(path: Path, repeat: int) -> tuple[float, dict[str, float]]:
    """Thread CPU seconds of `read_tables` on one thread (no read-ahead), in all and per
    stage (see `STAGES`), best of ``repeat`` runs. Each stage's functions are wrapped in a
    timer that leaves out the time of the stages they call."""
    import veronte4x.capture.columnar as columnar
    from veronte4x.capture.columnar import batches, dronecan, engine, stream, tables

    spent: dict[str, float] = {}
    inside: list[float] = []

    def timer(owner: Any, name: str, stage: str) -> tuple[Any, str, Any]:
        function = getattr(owner, name, None)
        if function is None:  # a version of veronte4x before this function
            return owner, name, None

        def timed(*args: Any, **kwargs: Any) -> Any:
            start = time.thread_time()
            inside.append(0.0)
            try:
                return function(*args, **kwargs)
            finally:
                took = time.thread_time() - start
                spent[stage] = spent.get(stage, 0.0) + took - inside.pop()
                if inside:
                    inside[-1] += took

        setattr(owner, name, timed)
        return owner, name, function

    wrapped = [
        timer(batches, "parse_block", "parse"),
        timer(batches, "parse_text", "parse"),  # its name before
        timer(engine, "decode_veronte", "veronte"),
        timer(stream.StreamDecoder, "_dronecan", "split"),
        timer(dronecan, "transfers", "reassembly"),
        timer(dronecan, "crc_ok", "reassembly"),
        timer(engine, "_decode_type", "payloads"),
        timer(tables.Tables, "add_records", "per frame"),
        timer(tables.Tables, "add_columns", "tables"),
        timer(tables.Tables, "finish_with_keys", "tables"),
        timer(engine, "_add_transfers", "tables"),
        timer(columnar, "_batched", "other"),
        timer(columnar, "ahead", "other"),
    ]
    columnar.ahead = lambda batches, prepare=None: batches  # type: ignore[assignment]
    best: tuple[float, dict[str, float]] = (float("inf"), {})
    try:
        for _ in range(repeat):
            spent.clear()
            start = time.thread_time()
            capture.read_tables(path)
            total = time.thread_time() - start
            if total < best[0]:
                best = (total, dict(spent))
    finally:
        for owner, name, function in wrapped:
            if function is not None:
                setattr(owner, name, function)
    return best


def print_stages(shapes: list[tuple[str, Path, int]], repeat: int) -> None:
    """The per-stage table: nanoseconds of CPU per frame of each stage, per shape."""
    found = [(name, frames, *stage_times(path, repeat)) for name, path, frames in shapes]
    print(
        f"\n{'read_tables per stage, CPU ns/frame on one thread':52}"
        + "".join(f" {name:>16}" for name, *_ in found)
    )
    for stage, _ in STAGES:
        cells = []
        for _, frames, total, spent in found:
            took = spent.get(stage, 0.0)
            cells.append(f"{1e9 * took / frames:9.0f} ({100 * took / total:3.0f} %)")
        print(f"{stage:52}" + "".join(f" {cell:>16}" for cell in cells))
    totals = [f"{1e9 * total / frames:9.0f}" for _, frames, total, _ in found]
    print(f"{'all (one thread)':52}" + "".join(f" {cell:>16}" for cell in totals))
    for stage, meaning in STAGES:
        print(f"  {stage}: {meaning}")


def _both(function: Callable[[], int], repeat: int) -> tuple[float, float]:
    """The best wall and the best CPU seconds (every thread of this process) of
    ``repeat`` runs."""
    wall = cpu = float("inf")
    for _ in range(repeat):
        start, start_cpu = time.perf_counter(), time.process_time()
        function()
        wall = min(wall, time.perf_counter() - start)
        cpu = min(cpu, time.process_time() - start_cpu)
    return wall, cpu


def shape_rows(
    shapes: list[tuple[str, Path, int]], dbc: Path, repeat: int
) -> list[tuple[str, str, int, float, float]]:
    """python-can's reader, asammdf and `read_tables` on each shape, taking turns:
    (shape, reader, frames, wall s, CPU s)."""
    rows = []
    for name, path, frames in shapes:
        mf4 = path.with_suffix(".mf4")
        write_mf4(path, mf4)
        readers: tuple[tuple[str, Callable[[], int]], ...] = (
            ("python-can CanutilsLogReader", lambda p=path: python_can_reader(p)),
            (
                "asammdf extract_bus_logging + to_dataframe",
                lambda m=mf4: asammdf_dataframe(m, dbc),
            ),
            ("veronte4x read_tables", lambda p=path: columnar_tables(p)),
        )
        times = {reader: (float("inf"), float("inf")) for reader, _ in readers}
        for _ in range(repeat):  # one run of each per round: all see the same load
            for reader, function in readers:
                wall, cpu = _both(function, 1)
                times[reader] = (min(times[reader][0], wall), min(times[reader][1], cpu))
        rows += [(name, reader, frames, *times[reader]) for reader, _ in readers]
        mf4.unlink()
    return rows


def print_shapes(rows: list[tuple[str, str, int, float, float]]) -> None:
    """The three shapes' table: rates, and `read_tables`' ratios by wall and CPU time."""
    print(
        f"\n{'shape':14} {'reader':44} {'frames/s':>11} {'wall s':>7} {'CPU s':>7}"
        f" {'read_tables is':>15} {'(CPU)':>7}"
    )
    ours = {shape: (wall, cpu) for shape, reader, _, wall, cpu in rows if "read_tables" in reader}
    for shape, reader, frames, wall, cpu in rows:
        ratio = f"{wall / ours[shape][0]:14.2f}x {cpu / ours[shape][1]:6.2f}x"
        if "read_tables" in reader:
            ratio = ""
        print(f"{shape:14} {reader:44} {frames / wall:11,.0f} {wall:7.2f} {cpu:7.2f} {ratio}")


def _timed(function: Callable[[], int], repeat: int) -> float:
    """The best of ``repeat`` runs, in seconds."""
    best = float("inf")
    for _ in range(repeat):
        start = time.perf_counter()
        function()
        best = min(best, time.perf_counter() - start)
    return best


def _head(path: Path, frames: int, out: Path) -> None:
    with path.open() as lines, out.open("w") as head:
        head.writelines(islice(lines, frames))


def shapes_and_stages(
    root: Path, big: Path, written: int, dbc: Path, args: argparse.Namespace
) -> None:
    """The three shapes' table and the per-stage table."""
    many, vehicle = root / "many.log", root / "vehicle.log"
    many.write_text(
        "\n".join(many_session_lines(flight_lines(None), args.many_frames, args.sessions)) + "\n"
    )
    vehicle.write_text("\n".join(vehicle_lines(args.vehicle_frames)) + "\n")
    shapes = [
        ("flight", big, written),
        (f"{args.sessions:,} sessions", many, args.many_frames),
        ("vehicle bus", vehicle, args.vehicle_frames),
    ]
    print_shapes(shape_rows(shapes, dbc, args.repeat))
    print_stages(shapes, args.repeat)
    many.unlink()
    vehicle.unlink()


def print_hour(root: Path, frames: int) -> None:
    """`to_parquet` of ``frames`` frames of the flight, written to a file and converted
    whole in a fresh process (the file deleted afterwards)."""
    hour = root / "hour.log"
    written = make_file(hour, frames, flight_lines(None))
    size = hour.stat().st_size
    frames, seconds, peak = converted(hour, root / "hour-dataset")
    hour.unlink()
    print(
        f"to_parquet of {frames:,} frames ({size / 1e9:.2f} GB of candump text), fresh process:"
        f" {seconds:.1f} s, {frames / seconds:,.0f} frames/s, peak {peak:.0f} MB"
    )
    assert frames == written


def main() -> None:
    """Build the files, time every reader in one run, print rates and ratios."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--frames", type=int, default=2_000_000, help="frames of the big file")
    parser.add_argument("--small", type=int, default=1_000_000, help="frames of the small file")
    parser.add_argument("--per-frame", type=int, default=200_000, help="frames for the old path")
    parser.add_argument("--repeat", type=int, default=2, help="runs of each reader (best kept)")
    parser.add_argument("--files", type=int, default=4, help="files for the cluster rows")
    parser.add_argument(
        "--session-frames", type=int, default=200_000, help="frames of each sessions bus"
    )
    parser.add_argument(
        "--vehicle-frames", type=int, default=200_000, help="frames of the vehicle bus"
    )
    parser.add_argument(
        "--many-frames", type=int, default=1_000_000, help="frames of the many-session flight"
    )
    parser.add_argument(
        "--sessions", type=int, default=1_500, help="DroneCAN sessions of that flight's can1"
    )
    parser.add_argument(
        "--memory-mb",
        type=float,
        nargs="*",
        default=[100, 1000],
        help="sizes of the files read_tables reads in a fresh process for its peak memory",
    )
    parser.add_argument(
        "--hour-frames",
        type=int,
        default=0,
        help="also convert a file of this many frames of the flight to Parquet for real, in a"
        " fresh process (63000000: one hour of two busy buses, 2.7 GB of text); 0: skip",
    )
    parser.add_argument(
        "--shapes-only",
        action="store_true",
        help="time only the three shapes of capture and their stages",
    )
    args = parser.parse_args()
    repeat = args.repeat
    with tempfile.TemporaryDirectory() as folder:
        root = Path(folder)
        big, small, head = root / "big.log", root / "small.log", root / "head.log"
        written = make_file(big, args.frames, flight_lines(None))
        _head(big, args.small, small)
        _head(big, args.per_frame, head)
        mf4, dbc = root / "big.mf4", root / "veronte.dbc"
        write_mf4(big, mf4)
        write_dbc(dbc)
        print(
            f"Python {platform.python_version()}, {os.cpu_count()} CPUs; {written} frames, "
            f"{big.stat().st_size / 1e6:.0f} MB of candump text, {mf4.stat().st_size / 1e6:.0f}"
            " MB of MF4"
        )
        if args.hour_frames:
            print_hour(root, args.hour_frames)
        if args.shapes_only:
            shapes_and_stages(root, big, written, dbc, args)
            return
        rows = [
            (
                "python-can CanutilsLogReader",
                written,
                _timed(lambda: python_can_reader(big), repeat),
            ),
            (
                "asammdf extract_bus_logging + to_dataframe",
                written,
                _timed(lambda: asammdf_dataframe(mf4, dbc), repeat),
            ),
            (
                "veronte4x to_dataframe(read()) (per frame)",
                args.per_frame,
                _timed(lambda: per_frame_dataframe(head), repeat),
            ),
            (
                f"veronte4x read_tables, {args.small} frames",
                args.small,
                _timed(lambda: columnar_tables(small), repeat),
            ),
            (
                f"veronte4x read_tables, {written} frames",
                written,
                _timed(lambda: columnar_tables(big), repeat),
            ),
        ]
        rates = {name: frames / seconds for name, frames, seconds in rows}
        ours = rows[-1][1] / rows[-1][2]
        print(f"{'reader':48} {'frames/s':>12} {'seconds':>8} {'read_tables is':>15}")
        for name, frames, seconds in rows:
            ratio = ours / rates[name]
            print(f"{name:48} {frames / seconds:12,.0f} {seconds:8.2f} {ratio:14.2f}x")
        hour = 63_000_000 / ours
        print(f"one hour of two 1 Mbit/s buses (63 M frames) at this rate: {hour:.0f} s")

        shapes_and_stages(root, big, written, dbc, args)

        header = f"{'frames/s':>12} {'seconds':>8} {'peak MB':>8}"
        print(f"\n{'to_parquet (fresh process each)':48} {header}")
        for path in (small, big):
            frames, seconds, peak = converted(path, root / "dataset")
            name = f"to_parquet, {frames} frames"
            print(f"{name:48} {frames / seconds:12,.0f} {seconds:8.2f} {peak:8.0f}")
        hour = 63_000_000 * seconds / frames
        print(f"one hour of two buses (63 M frames) at this rate: {hour:.0f} s, same peak memory")
        python_can = rates["python-can CanutilsLogReader"]
        print(
            f"\n{'read_tables, distinct DroneCAN sessions':48} {'frames/s':>12} {'us/frame':>8}"
            f" {'x python-can (flight rate)':>27}"
        )
        for sessions, frames, seconds in session_rows(root, args.session_frames, repeat):
            name = f"{sessions:,} sessions, {frames:,} frames"
            rate = frames / seconds
            print(
                f"{name:48} {rate:12,.0f} {1e6 * seconds / frames:8.2f} {rate / python_can:26.2f}x"
            )
        print(
            f"\n{'read_tables peak memory (fresh process each)':48} {'seconds':>8} "
            f"{'tables MB':>9} {'peak MB':>8} {'peak/(2 tables+300)':>20}"
        )
        for file_mb, _, table_mb, seconds, peak in memory_rows(root, args.memory_mb):
            name = f"{file_mb:,.0f} MB candump file"
            bound = peak / (2 * table_mb + 300)
            print(f"{name:48} {seconds:8.2f} {table_mb:9.0f} {peak:8.0f} {bound:19.2f}x")
        rows = fleet_rows(small, root, args.files, repeat)
        print(f"\n{'several files':48} {'frames/s':>12} {'seconds':>8} {'speed-up':>8}")
        for name, frames, seconds in rows:
            speedup = rows[0][2] / seconds
            print(f"{name:48} {frames / seconds:12,.0f} {seconds:8.2f} {speedup:7.2f}x")


if __name__ == "__main__":
    main()
