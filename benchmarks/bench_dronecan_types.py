"""DroneCAN types one by one: CPU per transfer of each type's column-wise decoding.

Run: python benchmarks/bench_dronecan_types.py [--frames 200000] [--repeat 3]
[--shape vehicle|every] [--against OLD_SRC ...]

``read_tables`` (on one thread, no read-ahead) decodes a capture of ``--frames`` frames:
``vehicle``, the ArduPilot-style bus of ``examples/make_vehicle_bus.py``, or ``every``, a
bus of every standard DroneCAN type at once (`bench_columnar.every_type_lines`). The
thread CPU of `engine._decode_type` (a type's payloads and their table columns, in one
batch) is summed per type; the table gives it per transfer, best of ``--repeat`` runs,
and the DroneCAN stages of `bench_columnar.stage_times` per frame (after one run left
out, which fills the caches).

With ``--against``, each source tree given (a ``src`` folder of another checkout of
veronte4x) and this one take turns in fresh processes (two runs each), ``--repeat``
rounds, and the table puts their figures side by side with the ratio old / new.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

HERE = Path(__file__).resolve().parent
DRONECAN_STAGES = ("split", "reassembly", "payloads", "tables")
"""The stages of `bench_columnar.STAGES` that decode DroneCAN."""


def measure(path: Path, repeat: int) -> dict[str, Any]:
    """Per type: transfers and best CPU seconds of `engine._decode_type`; and the DroneCAN
    stages' best CPU seconds per frame (of the run with the lowest total)."""
    import bench_columnar

    from veronte4x import capture
    from veronte4x.capture.columnar import engine

    decode_type = engine._decode_type
    spent: dict[str, float] = {}
    counts: dict[str, int] = {}

    def timed(frames: Any, found: Any, codec: Any, which: Any, *rest: Any) -> Any:
        start = time.thread_time()
        try:
            return decode_type(frames, found, codec, which, *rest)
        finally:
            name = str(codec.data_type.full_name)
            spent[name] = spent.get(name, 0.0) + time.thread_time() - start
            counts[name] = counts.get(name, 0) + len(which)

    best: dict[str, float] = {}
    frames = sum(1 for _ in path.open())
    setattr(engine, "_decode_type", timed)  # noqa: B010
    import veronte4x.capture.columnar as columnar

    ahead = columnar.ahead
    columnar.ahead = lambda batches, prepare=None: batches  # type: ignore[assignment]
    try:
        capture.read_tables(path)  # caches filled, pyarrow's first arrays made
        for _ in range(repeat):
            spent.clear()
            counts.clear()
            capture.read_tables(path)
            for name, seconds in spent.items():
                best[name] = min(best.get(name, float("inf")), seconds)
    finally:
        setattr(engine, "_decode_type", decode_type)  # noqa: B010
        columnar.ahead = ahead  # type: ignore[assignment]
    _, stages = bench_columnar.stage_times(path, repeat)
    return {
        "types": {name: (counts[name], best[name]) for name in best},
        "stages": {stage: stages.get(stage, 0.0) / frames for stage in DRONECAN_STAGES},
    }


def write_shape(path: Path, shape: str, frames: int) -> None:
    """The capture of ``shape``, ``frames`` lines."""
    import bench_columnar

    make = bench_columnar.vehicle_lines if shape == "vehicle" else bench_columnar.every_type_lines
    path.write_text("\n".join(make(frames)) + "\n")


def run(src: Path, path: Path, repeat: int) -> dict[str, Any]:
    """`measure` in a fresh process importing veronte4x from ``src``."""
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(src), str(HERE)])}
    out = subprocess.run(
        [sys.executable, __file__, "--measure", str(path), "--repeat", str(repeat)],
        env=env,
        check=True,
        capture_output=True,
        text=True,
    ).stdout
    result: dict[str, Any] = json.loads(out.splitlines()[-1])
    return result


def _best(results: list[dict[str, Any]]) -> dict[str, Any]:
    types: dict[str, list[float]] = {}
    for result in results:
        for name, (count, seconds) in result["types"].items():
            now = types.get(name, [count, float("inf")])
            types[name] = [count, min(now[1], seconds)]
    stages = {s: min(r["stages"][s] for r in results) for s in DRONECAN_STAGES}
    return {"types": types, "stages": stages}


def main() -> None:
    """Write the capture, measure each tree in turn, print the per-type table."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--frames", type=int, default=200_000, help="frames of the capture")
    parser.add_argument("--repeat", type=int, default=3, help="runs (rounds with --against)")
    parser.add_argument("--shape", choices=("vehicle", "every"), default="vehicle")
    parser.add_argument("--against", nargs="*", type=Path, default=[], help="old src trees")
    parser.add_argument("--measure", type=Path, help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.measure:
        print(json.dumps(measure(args.measure, args.repeat)))
        return
    trees = [*args.against, HERE.parent / "src"]
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "capture.log"
        sys.path.insert(0, str(HERE))
        write_shape(path, args.shape, args.frames)
        results: list[list[dict[str, Any]]] = [[] for _ in trees]
        rounds = args.repeat if args.against else 1
        for _ in range(rounds):  # one run of each tree per round: all see the same load
            for index, tree in enumerate(trees):
                results[index].append(run(tree, path, 2 if args.against else args.repeat))
    best = [_best(found) for found in results]
    print(f"{args.shape}, {args.frames:,} frames, load {os.getloadavg()[0]:.1f}")
    heads = [f"{tree.parent.name or tree}" for tree in trees]
    print(f"{'type':44} {'transfers':>9}" + "".join(f" {h[-12:]:>12}" for h in heads) + " ns/t")
    names = sorted(best[-1]["types"], key=lambda n: -best[-1]["types"][n][1])
    for name in names:
        count = best[-1]["types"][name][0]
        cells = [
            f"{1e9 * b['types'][name][1] / count:12.0f}" if name in b["types"] else " " * 12
            for b in best
        ]
        ratio = ""
        if len(best) > 1 and name in best[0]["types"]:
            ratio = f" {best[0]['types'][name][1] / best[-1]['types'][name][1]:5.2f}x"
        print(f"{name:44} {count:9,}" + " ".join(cells) + ratio)
    for stage in DRONECAN_STAGES:
        cells = [f"{1e9 * b['stages'][stage]:12.0f}" for b in best]
        print(f"{'stage ' + stage + ', ns a frame':54}" + " ".join(cells))
    totals = [f"{1e9 * sum(b['stages'].values()):12.0f}" for b in best]
    print(f"{'DroneCAN stages, ns a frame':54}" + " ".join(totals))


if __name__ == "__main__":
    main()
