"""Cold start: whole processes, from the command to the answer, as a user in a shell sees it.

Run: python benchmarks/bench_cold.py [--runs 5] [--lines 100 5000] [--quick]
[--sections user-dsdl ...] [--against OTHER/src]

Every figure is one fresh Python process, timed from its start to its exit by the parent
(wall time), the median of ``--runs`` runs; the commands of a section take turns (one run
of each per round) so that all see the same machine load, and each section prints the load
average (1 minute) before and after it. The sections:
- ``import``: ``python -c "import M"`` for each public module, against a bare interpreter,
  the `dronecan` package (which parses all of its DSDL at import), python-can and cantools;
- ``decode``: the first ``--lines`` lines of the ArduPilot-style vehicle bus
  (``examples/make_vehicle_bus.py``) and of the example flight (``examples/make_capture.py``)
  by ``veronte4x decode FILE`` (text to /dev/null), by a script calling
  ``capture.read_tables``, by a pydronecan script (the file's lines parsed, the 29-bit
  frames fed to ``TransferManager.receive_frame``, each complete transfer decoded by
  ``Transfer.from_frames``, one short line printed per transfer), and by python-can's
  candump reader with cantools decoding the Veronte frames with an equivalent DBC (cantools
  cannot reassemble DroneCAN transfers: on the vehicle bus it only reads);
- ``DSDL``: ``load_dsdl`` of every vendor root namespace shipped under
  ``src/veronte4x/dronecan/dsdl/`` (each alone, then all at once) and of the `dronecan`
  package's own ``ardupilot`` tree as a user's namespace, against ``import dronecan``;
- ``user DSDL``: a copy of the shipped ``ardupilot`` tree (14 types) as a user's root,
  loaded into the standard set by ``TypeSet.with_dsdl``, then each type's fast paths used
  once (each compiled on its first use): the first run (an empty cache directory each
  time; then one that has seen another tree, so holds the parsed shipped definitions), the
  next (read from the disk cache, `veronte4x.dronecan.dsdl_cache`) and without the cache
  (``VERONTE4X_CACHE_DIR=off``), against the `dronecan` package parsing the same tree; the
  time in the process after the import to the loaded set (what the cache saves; the ratio
  to the `dronecan` package is of this), then with every type used once, and the whole
  process;
- ``first transfer``: in a fresh process, one transfer of each type of the default set
  decoded by ``decode_frames``, each the first use of its type; each type's median over the
  processes, the median type and the slowest, and the slowest of any one run;
- ``monitor``: ``veronte4x monitor FILE --speed 1`` on the vehicle bus (played back at the
  capture's pace): the wall time from the start to the first table that lists every stream
  of the run, and how far that table's capture time (its header) lags the wall clock.

``--quick`` runs each command once on 100 lines (the test suite's run: no figure is checked).
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import runpy
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SHIPPED_DSDL = ROOT / "src" / "veronte4x" / "dronecan" / "dsdl"
PUBLIC_MODULES = (
    "veronte4x",
    "veronte4x.codec",
    "veronte4x.dronecan",
    "veronte4x.capture",
    "veronte4x.client",
    "veronte4x.arbiter",
    "veronte4x.node",
    "veronte4x.simulator",
    "veronte4x.variables",
    "veronte4x.cli",
)
OTHERS = ("dronecan", "can", "cantools")
VERONTE_IDS = (8, 9, 10, 11, 255)  # the arbiter's and the autopilots' 11-bit IDs
SECTIONS = ("import", "decode", "dsdl", "user-dsdl", "first-transfer", "monitor")
"""The sections, in the order they run (``--sections`` picks some)."""

Command = list[str]


# --- the child processes' work (``bench_cold.py --child NAME FILE``) ---------------------


def child_read_tables(path: str) -> int:
    """Decode the file with `capture.read_tables`; the rows of all tables."""
    from veronte4x import capture

    return sum(table.num_rows for table in capture.read_tables(path).values())


def child_pydronecan(path: str) -> int:
    """Decode the file's DroneCAN frames with the `dronecan` package; the transfers."""
    import dronecan
    from dronecan import transport

    manager = transport.TransferManager()
    transfers = 0
    out = sys.stdout
    with open(path) as lines:
        for line in lines:
            stamp, _, frame = line.split()
            can_id, _, data = frame.partition("#")
            if len(can_id) != 8:  # an 11-bit ID: not DroneCAN
                continue
            received = transport.Frame(
                int(can_id, 16),
                bytearray.fromhex(data),
                ts_monotonic=float(stamp[1:-1]),
            )
            complete = manager.receive_frame(received)
            if complete:
                transfer = transport.Transfer()
                transfer.from_frames(complete)
                name = dronecan.get_dronecan_data_type(transfer.payload).full_name
                out.write(f"{stamp} {transfer.source_node_id} {name}\n")
                transfers += 1
    return transfers


def child_cantools(path: str) -> int:
    """Read the file with python-can, decode its Veronte frames with cantools; the frames."""
    import can
    import cantools.database as cdb
    from cantools.database.can import Message, Signal
    from cantools.database.conversion import BaseConversion

    signals = [
        Signal("cmd", 0, 8),
        Signal("sub", 8, 8),
        Signal("value", 16, 32, conversion=BaseConversion.factory(1, 0, None, True)),
    ]
    db = cdb.can.Database([Message(i, f"m{i}", 6, signals) for i in VERONTE_IDS])
    frames = 0
    for message in can.CanutilsLogReader(path):
        if not message.is_extended_id and message.arbitration_id in VERONTE_IDS:
            db.decode_message(message.arbitration_id, message.data, allow_truncated=True)
        frames += 1
    return frames


def child_load_dsdl(*roots: str) -> int:
    """Load DSDL root namespaces with `veronte4x.dronecan.load_dsdl`; the types outside
    the standard ``uavcan`` namespace."""
    from veronte4x.dronecan import load_dsdl

    names = load_dsdl(*roots).definitions
    return sum(not name.startswith("uavcan.") for name in names)


def child_user_dsdl(root: str) -> str:
    """Load a user root into the standard set (the cache of ``VERONTE4X_CACHE_DIR``) and
    use each of its types' fast paths once; the milliseconds after the import to the loaded
    set and to the last type used, and the types."""
    from veronte4x.dronecan import TypeSet

    start = time.perf_counter()
    types = TypeSet.standard().with_dsdl(root)
    loaded = time.perf_counter()
    mine = [c for c in types.codecs if c.data_type.full_name.startswith(Path(root).name + ".")]
    for codec in mine:
        assert codec.fast is not None
    used = time.perf_counter()
    return f"{(loaded - start) * 1e3:.1f} {(used - start) * 1e3:.1f} {len(mine)}"


def child_dronecan_parse(root: str) -> str:
    """Parse a root with the `dronecan` package's parser (after ``import dronecan``, which
    parses its own DSDL); the milliseconds of the parse, and the types."""
    import dronecan

    standard = Path(dronecan.__file__).parent / "dsdl_specs" / "uavcan"
    start = time.perf_counter()
    found = dronecan.dsdl.parse_namespaces([root], [str(standard)])
    return f"{(time.perf_counter() - start) * 1e3:.1f} {len(found)}"


def child_import_dronecan() -> int:
    """Import the `dronecan` package (it parses its DSDL); the types outside ``uavcan``."""
    import dronecan

    names = {data_type.full_name for data_type in dronecan.DATATYPES.values()}
    return sum(not name.startswith("uavcan.") for name in names)


def child_first_transfers() -> str:
    """Decode one transfer of each type of the default set, each the type's first use after
    import (its frames made by the generic serializer, which leaves the fast paths
    untouched); the seconds of each type, as JSON."""
    from veronte4x import dronecan
    from veronte4x.dronecan.compiled import can_id_base
    from veronte4x.dronecan.crc import crc16
    from veronte4x.dronecan.tail import SINGLE_FRAME_MAX, split_payload

    timings = []
    for codec in dronecan.default_types().codecs:
        data_type = codec.data_type
        payload = codec.generic.encode(data_type.schema.cls())
        can_id = 16 << 24 | can_id_base(data_type) | 10
        if data_type.kind is not dronecan.TransferKind.MESSAGE:
            can_id |= 20 << 8
        if len(payload) <= SINGLE_FRAME_MAX:
            frames = [(can_id, payload + b"\xc0")]
        else:
            chunks = split_payload(payload, crc16(payload, codec.crc_seed), 0)
            frames = [(can_id, data) for data in chunks]
        start = time.perf_counter()
        dronecan.decode_frames(frames)
        timings.append(
            (f"{data_type.full_name} {data_type.kind.name}", time.perf_counter() - start)
        )
    return json.dumps(dict(timings))


CHILDREN: dict[str, Callable[..., object]] = {
    "read_tables": child_read_tables,
    "pydronecan": child_pydronecan,
    "cantools": child_cantools,
    "load_dsdl": child_load_dsdl,
    "import_dronecan": child_import_dronecan,
    "user_dsdl": child_user_dsdl,
    "dronecan_parse": child_dronecan_parse,
    "first_transfers": child_first_transfers,
}


def child(name: str, *args: str) -> Command:
    """The command running ``CHILDREN[name](*args)`` in a fresh process."""
    return [sys.executable, str(Path(__file__).resolve()), "--child", name, *args]


# --- timing -----------------------------------------------------------------------------


def load() -> str:
    """The 1-minute load average."""
    return f"{os.getloadavg()[0]:.1f}"


def wall(command: Command) -> float:
    """Seconds from the start of ``command`` to its exit (its output to /dev/null; it
    succeeded once in `output`)."""
    start = time.perf_counter()
    subprocess.run(
        command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True, cwd=ROOT
    )
    return time.perf_counter() - start


def medians(commands: dict[str, Command], runs: int) -> dict[str, float]:
    """Each command's median wall time of ``runs`` runs, the commands taking turns."""
    times: dict[str, list[float]] = {name: [] for name in commands}
    for _ in range(runs):
        for name, command in commands.items():
            times[name].append(wall(command))
    return {name: statistics.median(seconds) for name, seconds in times.items()}


def output(command: Command) -> str:
    """What ``command`` prints (it must succeed)."""
    done = subprocess.run(command, capture_output=True, text=True, cwd=ROOT)
    if done.returncode != 0:
        raise SystemExit(f"{' '.join(command)} failed:\n{done.stderr[-2000:]}")
    return done.stdout


# --- the sections -----------------------------------------------------------------------


def imports(runs: int) -> None:
    """Import each public module, and the other tools, in fresh processes."""
    commands = {"python -c pass": [sys.executable, "-c", "pass"]}
    for module in (*PUBLIC_MODULES, *OTHERS):
        commands[f"import {module}"] = [sys.executable, "-c", f"import {module}"]
    before = load()
    times = medians(commands, runs)
    print(f"\n## import (median of {runs}, load {before} -> {load()})\n")
    bare = times["python -c pass"]
    reference = times["import dronecan"]
    print("| command | ms | ms above python | import dronecan / this |")
    print("|---|---:|---:|---:|")
    for name, seconds in times.items():
        print(
            f"| {name} | {seconds * 1e3:.0f} | {(seconds - bare) * 1e3:.0f}"
            f" | {reference / seconds:.2f}x |"
        )


def vehicle_lines(lines: int) -> list[str]:
    """The first ``lines`` candump lines of the vehicle bus."""
    make = runpy.run_path(str(ROOT / "examples" / "make_vehicle_bus.py"))
    texts: list[str] = make["vehicle_lines"](lines)
    return texts


def flight_lines(lines: int) -> list[str]:
    """The first ``lines`` candump lines of the example flight, in time order."""
    make = runpy.run_path(str(ROOT / "examples" / "make_capture.py"))
    minutes = 2.0 * max(1.0, lines / 100_000)
    texts: list[str] = make["generate"](minutes, 60.0, 4).lines()
    return texts[:lines]


def decoding(folder: Path, sizes: list[int], runs: int) -> None:
    """Decode each file with each tool, in fresh processes."""
    print(f"\n## decode (median of {runs})\n")
    print("| file | lines | command | items | s | load | pydronecan script / this |")
    print("|---|---:|---|---:|---:|---:|---:|")
    for bus, make in (("vehicle bus", vehicle_lines), ("flight", flight_lines)):
        for size in sizes:
            path = folder / f"{bus.replace(' ', '_')}_{size}.log"
            texts = make(size)
            path.write_text("".join(text + "\n" for text in texts))
            commands = {
                "veronte4x decode": [sys.executable, "-m", "veronte4x", "decode", str(path)],
                "read_tables": child("read_tables", str(path)),
                "pydronecan script": child("pydronecan", str(path)),
                "python-can + cantools": child("cantools", str(path)),
            }
            items = {
                "veronte4x decode": len(output(commands["veronte4x decode"]).splitlines()),
                "read_tables": int(output(commands["read_tables"])),
                "pydronecan script": int(output(commands["pydronecan script"]).split()[-1]),
                "python-can + cantools": int(output(commands["python-can + cantools"])),
            }
            before = load()
            times = medians(commands, runs)
            after = load()
            reference = times["pydronecan script"]
            for name, seconds in times.items():
                print(
                    f"| {bus} | {len(texts)} | {name} | {items[name]} | {seconds:.2f}"
                    f" | {before}-{after} | {reference / seconds:.2f}x |"
                )


def dsdl(runs: int) -> None:
    """Load each shipped vendor namespace, and a user one, against ``import dronecan``."""
    import dronecan  # only to find its DSDL tree

    vendors = sorted(
        path for path in SHIPPED_DSDL.iterdir() if path.is_dir() and path.name != "uavcan"
    )
    commands = {"import dronecan (parses all its DSDL)": child("import_dronecan")}
    for root in vendors:
        commands[f"load_dsdl shipped {root.name}"] = child("load_dsdl", str(root))
    if len(vendors) > 1:
        commands["load_dsdl every shipped vendor"] = child(
            "load_dsdl", *(str(root) for root in vendors)
        )
    user = Path(dronecan.__file__).parent / "dsdl_specs" / "ardupilot"
    commands["load_dsdl user ardupilot (the dronecan package's tree)"] = child(
        "load_dsdl", str(user)
    )
    types = {name: int(output(command)) for name, command in commands.items()}
    before = load()
    times = medians(commands, runs)
    print(f"\n## DSDL (median of {runs}, load {before} -> {load()})\n")
    if not vendors:
        print("(no vendor namespace shipped yet under src/veronte4x/dronecan/dsdl/)\n")
    reference = times["import dronecan (parses all its DSDL)"]
    print("| command | types | s | import dronecan / this |")
    print("|---|---:|---:|---:|")
    for name, seconds in times.items():
        print(f"| {name} | {types[name]} | {seconds:.2f} | {reference / seconds:.2f}x |")


def user_dsdl(folder: Path, runs: int, against: str | None = None) -> None:
    """A user's root loaded the first time, from the cache and without it, against the
    `dronecan` package's parser on the same tree, in fresh processes taking turns; with
    ``against`` (another veronte4x's ``src`` directory), each veronte4x run of that tree too."""
    import shutil

    root = str(shutil.copytree(SHIPPED_DSDL / "ardupilot", folder / "user" / "ardupilot"))
    load_it = child("user_dsdl", root)
    other = child("user_dsdl", str(ROOT / "examples" / "dsdl" / "com"))
    # Each tree: the suffix of its rows and its environment (this one's, or PYTHONPATH=against).
    trees = {"": dict(os.environ)}
    if against is not None:
        trees[f" [{against}]"] = {**os.environ, "PYTHONPATH": against}
    # Each run: the command, its environment and its VERONTE4X_CACHE_DIR (a new empty one
    # for a first run).
    runs_of: dict[str, tuple[Command, dict[str, str], Callable[[int], str]]] = {}
    for number, (suffix, environ) in enumerate(trees.items()):
        warm = str(folder / f"cache-warm-{number}")
        warmed = {**environ, "VERONTE4X_CACHE_DIR": warm}
        subprocess.run(load_it, env=warmed, check=True, capture_output=True)
        seeded = folder / f"seeded-{number}"  # a cache that has only seen another tree
        seeding = {**environ, "VERONTE4X_CACHE_DIR": str(seeded)}
        subprocess.run(other, env=seeding, check=True, capture_output=True)

        def cold(n: int, number: int = number) -> str:
            return str(folder / f"cold-{number}-{n}")

        def seeded_copy(n: int, seeded: Path = seeded) -> str:
            return str(shutil.copytree(seeded, seeded.with_name(f"{seeded.name}-{n}")))

        runs_of |= {
            f"veronte4x, first run (empty cache){suffix}": (load_it, environ, cold),
            f"veronte4x, first run of this tree (the cache has seen another){suffix}": (
                load_it,
                environ,
                seeded_copy,
            ),
            f"veronte4x, from the cache{suffix}": (load_it, environ, lambda n, w=warm: w),
            f"veronte4x, no cache (VERONTE4X_CACHE_DIR=off){suffix}": (
                load_it,
                environ,
                lambda n: "off",
            ),
        }
    runs_of["dronecan package: parse the tree (after import dronecan)"] = (
        child("dronecan_parse", root),
        dict(os.environ),
        lambda n: "off",
    )
    rows: dict[str, list[tuple[float, float, float]]] = {name: [] for name in runs_of}
    types: dict[str, str] = {}
    before = load()
    for run in range(runs):
        for name, (command, environ, cache) in runs_of.items():
            env = {**environ, "VERONTE4X_CACHE_DIR": cache(run)}
            start = time.perf_counter()
            done = subprocess.run(command, env=env, check=True, capture_output=True, text=True)
            whole = time.perf_counter() - start
            *ms, types[name] = done.stdout.split()
            rows[name].append((float(ms[0]), float(ms[-1]), whole))
    print(f"\n## user DSDL (median of {runs}, load {before} -> {load()})\n")
    reference = statistics.median(t for t, _, _ in rows[list(rows)[-1]])
    print(
        "| run | types | ms to the set | ms per type | ms, each type used once"
        " | whole process s | dronecan / this |"
    )
    print("|---|---:|---:|---:|---:|---:|---:|")
    for name, found in rows.items():
        inside = statistics.median(t for t, _, _ in found)
        used = statistics.median(u for _, u, _ in found)
        whole = statistics.median(w for _, _, w in found)
        print(
            f"| {name} | {types[name]} | {inside:.1f} | {inside / int(types[name]):.2f}"
            f" | {used:.1f} | {whole:.2f} | {reference / inside:.2f}x |"
        )


def first_transfers(runs: int) -> None:
    """The first transfer of each type of the default set after import, in fresh processes:
    each type's median over the processes (a single run's slowest is mostly the scheduler
    on a busy machine: a time slice is 4 ms), and the slowest of any run."""
    before = load()
    found: list[dict[str, float]] = [
        json.loads(
            subprocess.run(
                child("first_transfers"), capture_output=True, text=True, check=True, cwd=ROOT
            ).stdout
        )
        for _ in range(runs)
    ]
    print(f"\n## first transfer of each type ({runs} processes, load {before} -> {load()})\n")
    per_type = {name: statistics.median(run[name] for run in found) for name in found[0]}
    slowest = max(per_type, key=per_type.__getitem__)
    worst = max((seconds, name) for run in found for name, seconds in run.items())
    print("| types | median ms | slowest type's median ms | slowest type | slowest of any run |")
    print("|---:|---:|---:|---|---|")
    print(
        f"| {len(per_type)} | {statistics.median(per_type.values()) * 1e3:.2f}"
        f" | {per_type[slowest] * 1e3:.2f} | {slowest} | {worst[0] * 1e3:.2f} ms ({worst[1]}) |"
    )


def monitor_run(path: Path) -> list[tuple[float, float, int]]:
    """Each table of one ``monitor --speed 1`` run: (wall s since start, capture s, rows)."""
    start = time.perf_counter()
    process = subprocess.Popen(
        [sys.executable, "-m", "veronte4x", "monitor", str(path), "--speed", "1"],
        stdout=subprocess.PIPE,
        stderr=subprocess.DEVNULL,
        text=True,
        cwd=ROOT,
    )
    assert process.stdout is not None
    tables: list[tuple[float, float, int]] = []
    for line in process.stdout:
        words = line.split()
        if len(words) == 6 and words[1] == "records," and words[5] == "s":
            tables.append((time.perf_counter() - start, float(words[4]), 0))
        elif tables and words and words[0] not in ("sender", "arbiter:"):
            seen, stamp, rows = tables[-1]
            tables[-1] = (seen, stamp, rows + 1)
    if process.wait() != 0:
        raise SystemExit(f"veronte4x monitor {path} failed")
    return tables


def monitoring(folder: Path, lines: int, runs: int) -> None:
    """The monitor's delay to its first full table."""
    path = folder / "monitor.log"
    path.write_text("".join(text + "\n" for text in vehicle_lines(lines)))
    before = load()
    firsts: list[tuple[float, float]] = []
    for _ in range(runs):
        tables = monitor_run(path)
        full = max(rows for _, _, rows in tables)
        firsts.append(next((seen, stamp) for seen, stamp, rows in tables if rows == full))
    seen = statistics.median(first[0] for first in firsts)
    lag = statistics.median(first[0] - first[1] for first in firsts)
    print(f"\n## monitor (median of {runs}, load {before} -> {load()})\n")
    print("| command | lines | first full table after | its lag behind the bus |")
    print("|---|---:|---:|---:|")
    print(f"| veronte4x monitor --speed 1, vehicle bus | {lines} | {seen:.2f} s | {lag:.2f} s |")


def main() -> None:
    """Parse the arguments; run a child's work, or every section."""
    if len(sys.argv) > 2 and sys.argv[1] == "--child":
        print(CHILDREN[sys.argv[2]](*sys.argv[3:]))
        return
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=5, help="runs of each command; the median")
    parser.add_argument(
        "--lines", type=int, nargs="+", default=[100, 5000], help="lines of each decoded file"
    )
    parser.add_argument("--quick", action="store_true", help="one run of each on 100 lines")
    parser.add_argument(
        "--sections", nargs="+", choices=SECTIONS, default=SECTIONS, help="the sections to run"
    )
    parser.add_argument(
        "--against",
        metavar="SRC",
        help="another veronte4x's src directory (a checkout of main, say): the user-dsdl"
        " section times its runs too, taking turns with this tree's",
    )
    args = parser.parse_args()
    runs, sizes = (1, [100]) if args.quick else (args.runs, args.lines)
    print(f"Python {platform.python_version()}, {os.cpu_count()} CPUs, wall time per process")
    with tempfile.TemporaryDirectory() as folder:
        sections: dict[str, Callable[[], None]] = {
            "import": lambda: imports(runs),
            "decode": lambda: decoding(Path(folder), sizes, runs),
            "dsdl": lambda: dsdl(runs),
            "user-dsdl": lambda: user_dsdl(Path(folder), runs, args.against),
            "first-transfer": lambda: first_transfers(runs),
            "monitor": lambda: monitoring(Path(folder), max(sizes), runs),
        }
        for name in SECTIONS:
            if name in args.sections:
                sections[name]()


if __name__ == "__main__":
    main()
