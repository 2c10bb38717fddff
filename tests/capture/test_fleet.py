"""Captures converted on a real Dask cluster (2 worker processes): the same dataset as in
one process; the command line against the cluster's scheduler."""

from __future__ import annotations

import gzip
import shutil
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import dask
import distributed
import pytest

from tests.capture.columnar_support import DECLARED, assert_same_tables, write
from tests.capture.test_dataset import FLIGHT, read_back
from tests.capture.test_stream import _interleaved_flight
from veronte4x import capture
from veronte4x.capture import BusMap
from veronte4x.errors import SourceError


@pytest.fixture(scope="module")
def client() -> Iterator[distributed.Client]:
    with (
        dask.config.set({"distributed.nanny.pre-spawn-environ.MALLOC_MMAP_THRESHOLD_": 1 << 25}),
        distributed.LocalCluster(  # type: ignore[no-untyped-call]
            n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0"
        ) as cluster,
        distributed.Client(cluster) as client,  # type: ignore[no-untyped-call]
    ):
        yield client


@pytest.fixture
def fleet(tmp_path: Path) -> list[Path]:
    folder = tmp_path / "captures"
    folder.mkdir()
    flight = write(folder / "interleaved.log", _interleaved_flight())
    packed = folder / "example.log.gz"
    packed.write_bytes(gzip.compress(FLIGHT.read_bytes()))
    shutil.copy(FLIGHT, folder / "example.log")
    return [folder / "example.log", flight, packed]


def test_cluster_writes_the_dataset_of_one_process(
    client: distributed.Client, fleet: list[Path], tmp_path: Path
) -> None:
    here = capture.to_parquet(fleet, tmp_path / "here", progress=False)
    there = capture.to_parquet(fleet, tmp_path / "there", client=client, progress=False)
    assert (there.files, there.frames, there.records) == (here.files, here.frames, here.records)
    for path in fleet:
        expected = capture.read_tables(path)
        assert_same_tables(read_back(tmp_path / "there", str(path)), expected)
    assert sorted(p.relative_to(tmp_path / "there") for p in (tmp_path / "there").rglob("*")) == (
        sorted(p.relative_to(tmp_path / "here") for p in (tmp_path / "here").rglob("*"))
    )


def test_a_failure_on_a_worker_is_raised_here(
    client: distributed.Client, fleet: list[Path], tmp_path: Path
) -> None:
    with pytest.raises(SourceError, match="directory"):
        capture.to_parquet([*fleet, tmp_path], tmp_path / "out", client=client, progress=False)


def test_cli_on_the_scheduler(
    client: distributed.Client, fleet: list[Path], tmp_path: Path
) -> None:
    out = tmp_path / "data"
    address = str(client.scheduler_info()["address"])
    result = subprocess.run(
        [sys.executable, "-m", "veronte4x", "convert", *map(str, fleet), "--to", "parquet",
         str(out), "--scheduler", address],
        capture_output=True, text=True, check=False,
    )  # fmt: skip
    assert result.returncode == 0, result.stderr
    assert result.stderr.startswith("veronte4x: 3 files, ")
    for path in fleet:
        assert_same_tables(read_back(out, str(path)), capture.read_tables(path))


def test_declared_layouts_travel_to_the_workers(client: distributed.Client, tmp_path: Path) -> None:
    bus_map = BusMap(layouts=(DECLARED,), allow_excess=True)
    message = DECLARED.message_class(50.0, -3, 25.5)
    data = DECLARED.encode(message).hex().upper()
    path = write(tmp_path / "declared.log", [f"({t}.0) can0 008#{data}" for t in range(5)])
    capture.to_parquet(path, tmp_path / "data", bus_map, client=client, progress=False)
    expected = capture.read_tables(path, bus_map)
    assert len(expected["ScorpionTelemetry"]) == 5
    assert_same_tables(read_back(tmp_path / "data"), expected)


def test_dbc_files_travel_to_the_workers(client: distributed.Client, tmp_path: Path) -> None:
    dbc = Path(__file__).with_name("data") / "payload.dbc"
    lines = [f"({t}.0) can0 123#E803F6FF0119{t:04X}" for t in range(5)]
    path = write(tmp_path / "payload.log", [*lines, "(6.0) can0 123#E8"])
    bus_map = BusMap(dronecan=False)
    capture.to_parquet(path, tmp_path / "data", bus_map, client=client, progress=False, dbc=[dbc])
    expected = capture.read_tables(path, bus_map, dbc=[dbc])
    assert (len(expected["BmsStatus"]), len(expected["errors"])) == (5, 1)
    assert_same_tables(read_back(tmp_path / "data"), expected)
