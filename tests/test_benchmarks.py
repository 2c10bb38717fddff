"""Every benchmark of `make bench` runs to its end on tiny inputs and prints its rows: a
change of the library or of a shared helper cannot break one unnoticed. No figure is
checked (timings are for the performance page, never for tests)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

BENCHMARKS = Path(__file__).resolve().parent.parent / "benchmarks"

RUNS = [
    ("bench_codec.py", ["--seconds", "0.001"], ["ArbitrationVariable", "JetiTemperature"]),
    ("bench_decode_floor.py", ["--seconds", "0.001"], ["PwmSet", "ceiling"]),
    ("bench_dronecan.py", ["--seconds", "0.001"], ["NodeStatus"]),
    ("bench_bitstruct.py", ["--seconds", "0.001"], ["Status"]),
    (
        "bench_capture.py",
        ["--frames", "3000", "--repeat", "1"],
        ["third DroneCAN", "veronte4x to records", "veronte4x to DataFrame"],
    ),
    (
        "bench_dbc.py",
        ["--frames", "2000", "--repeat", "1"],
        ["columnar DBC pass, only DBC frames", "read_tables, only DBC frames"],
    ),
    (
        "bench_columnar.py",
        [
            "--frames",
            "20000",
            "--small",
            "5000",
            "--per-frame",
            "2000",
            "--repeat",
            "1",
            "--files",
            "2",
            "--session-frames",
            "2000",
            "--memory-mb",
            "1",
            "--many-frames",
            "20000",
            "--vehicle-frames",
            "2000",
            "--hour-frames",
            "3000",
        ],
        [
            "to_parquet of 3,000 frames",
            "asammdf",
            "1,500 sessions",
            "vehicle bus",
            "read_tables per stage",
            "read_tables, 20000 frames",
            "LocalCluster 2 workers",
            "100,000 sessions",
            "MB candump file",
        ],
    ),
    (
        "bench_cold.py",
        ["--quick"],
        [
            "import veronte4x.capture",
            "veronte4x decode",
            "read_tables",
            "pydronecan script",
            "python-can + cantools",
            "load_dsdl user ardupilot",
            "veronte4x, from the cache",
            "veronte4x monitor --speed 1",
        ],
    ),
    (
        "bench_dronecan_types.py",
        ["--frames", "3000", "--repeat", "1", "--shape", "every"],
        ["uavcan.protocol.param.GetSet", "DroneCAN stages, ns a frame"],
    ),
    ("bench_mf4_memory.py", ["--frames", "20000"], ["MF4 file: 20000 frames", "peak RSS", "bound"]),
    (
        "bench_fleet.py",
        ["--escs", "2", "--updates", "2", "--image-kb", "2"],
        ["read every parameter of 2 ESCs", "update 2 ESCs with a 2 kB image"],
    ),
]


@pytest.mark.parametrize(("script", "args", "rows"), RUNS, ids=[run[0] for run in RUNS])
def test_the_benchmark_runs(script: str, args: list[str], rows: list[str]) -> None:
    done = subprocess.run(
        [sys.executable, str(BENCHMARKS / script), *args],
        capture_output=True,
        text=True,
        cwd=BENCHMARKS.parent,
        timeout=600,
    )
    assert done.returncode == 0, done.stderr[-2000:]
    for row in rows:
        assert row in done.stdout
