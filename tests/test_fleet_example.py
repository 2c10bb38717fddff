"""The fleet example runs: a generated fleet converted, both questions answered alike by
DuckDB and Polars, the answers plotted."""

from __future__ import annotations

import runpy
from pathlib import Path

import pytest

from tests.capture.columnar_support import assert_same_tables
from tests.capture.test_dataset import read_back
from veronte4x import capture

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"


def test_fleet_example(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    module = runpy.run_path(str(EXAMPLES / "fleet.py"))
    module["main"](tmp_path, tmp_path / "fleet.png", 0.3)
    out = capsys.readouterr().out
    assert out.startswith("3 files, ")
    assert "3 autopilot switches" in out
    assert (tmp_path / "fleet.png").stat().st_size > 10_000
    data = tmp_path / "dataset"
    switches = module["switches_duckdb"](data)
    assert switches["source"].to_list() == [
        str(tmp_path / "captures" / f"flight{n}.log") for n in (1, 2, 3)
    ]
    assert all(row["previous"] != row["selected"] for row in switches.iter_rows(named=True))
    heat = module["heat_duckdb"](data)
    assert (
        heat["samples"].sum()
        == len(capture.read_tables(tmp_path / "captures" / "flight1.log")["EscStatus"]) * 3
    )
    for path in sorted((tmp_path / "captures").iterdir()):
        assert_same_tables(read_back(data, str(path)), capture.read_tables(path))
