"""What a Dask worker runs for `capture.to_parquet(..., client=...)`
(``capture/columnar/fleet.py``), run here in this process: the bus map made plain data,
pickled as Dask pickles a task's arguments, rebuilt and converted on the "worker".
``tests/capture/test_fleet.py`` runs the same on a real cluster, in worker processes that
coverage does not follow; these tests measure those lines and pin their values."""

from __future__ import annotations

import pickle
from pathlib import Path

from tests.capture.columnar_support import DECLARED, assert_same_tables, write
from tests.capture.test_dataset import FLIGHT, read_back
from veronte4x import capture
from veronte4x.capture import BusMap
from veronte4x.capture.columnar import fleet
from veronte4x.capture.columnar.batches import BATCH_BYTES


def _declared_capture(folder: Path) -> Path:
    data = DECLARED.encode(DECLARED.message_class(50.0, -3, 25.5)).hex().upper()
    return write(folder / "declared.log", [f"({t}.0) can0 008#{data}" for t in range(5)])


def test_a_bus_map_with_declared_layouts_travels_as_plain_data(tmp_path: Path) -> None:
    bus_map = BusMap(layouts=(DECLARED,), allow_excess=True)
    portable = fleet._portable(bus_map)
    assert portable is not None
    settings, layouts = portable
    assert settings["allow_excess"] is True
    assert "layouts" not in settings
    assert layouts == ((5, "ScorpionTelemetry", DECLARED.fields, DECLARED.byte_order),)
    assert pickle.loads(pickle.dumps(portable)) == portable


def test_a_worker_rebuilds_the_bus_map_and_writes_the_tables_of_one_process(
    tmp_path: Path,
) -> None:
    path = _declared_capture(tmp_path)
    bus_map = BusMap(layouts=(DECLARED,), allow_excess=True)
    portable = pickle.loads(pickle.dumps(fleet._portable(bus_map)))
    out = tmp_path / "data"
    summary = fleet._convert(str(path), str(out), portable, None, BATCH_BYTES, "timestamp")
    assert (summary.files, summary.frames) == (1, 5)
    assert summary.records["ScorpionTelemetry"] == 5
    expected = capture.read_tables(path, bus_map)
    assert len(expected["ScorpionTelemetry"]) == 5
    assert_same_tables(read_back(out), expected)


def test_without_a_bus_map_a_worker_decodes_with_the_default_one(tmp_path: Path) -> None:
    assert fleet._portable(None) is None
    out = tmp_path / "data"
    summary = fleet._convert(str(FLIGHT), str(out), None, None, BATCH_BYTES, "timestamp")
    assert summary.files == 1
    assert_same_tables(read_back(out), capture.read_tables(FLIGHT))
