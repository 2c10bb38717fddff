"""The fleet page's table of readers runs: each command reads one table over every
capture of a dataset, the same rows, with the ``capture`` column of the Hive partitions."""

from __future__ import annotations

import re
import warnings
from pathlib import Path

import dask.dataframe as dd
import duckdb
import pandas as pd
import polars as pl
import pyarrow as pa
import pyarrow.parquet as pq
import pytest

from veronte4x import capture

ROOT = Path(__file__).resolve().parent.parent
PAGE = ROOT / "docs" / "fleet.md"
FLIGHT = ROOT / "examples" / "capture.log"
ROW = re.compile(r"^\| (DuckDB|Polars|Dask|pyarrow|pandas) \| `(.+)` .*\|$", re.MULTILINE)


def _rows(result: object) -> tuple[int, list[str]]:
    """Rows and column names of whatever a reader gives."""
    if isinstance(result, duckdb.DuckDBPyRelation):
        return len(result.fetchall()), result.columns
    if isinstance(result, pl.LazyFrame):
        frame = result.collect()
        return frame.height, frame.columns
    if isinstance(result, dd.DataFrame):
        with warnings.catch_warnings():  # dask's own use of pandas, deprecated in pandas 3.1
            warnings.simplefilter("ignore")
            computed = result.compute(scheduler="sync")  # type: ignore[no-untyped-call]
        return len(computed), list(computed.columns)
    if isinstance(result, pd.DataFrame):
        return len(result), list(result.columns)
    table = result if isinstance(result, pa.Table) else result.to_table()  # type: ignore[attr-defined]
    return table.num_rows, table.column_names


def test_every_reader_of_the_table_reads_every_capture(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    captures = [tmp_path / "flight1.log", tmp_path / "flight2.log"]
    for path in captures:
        path.write_bytes(FLIGHT.read_bytes())
    capture.to_parquet(captures, "dataset", progress=False)
    rows = 2 * len(capture.read_tables(FLIGHT)["Status"])
    commands = ROW.findall(PAGE.read_text())
    assert sorted({reader for reader, _ in commands}) == [
        "Dask", "DuckDB", "Polars", "pandas", "pyarrow"
    ]  # fmt: skip
    namespace = {"capture": capture, "dd": dd, "pd": pd, "pl": pl, "pq": pq}
    for reader, command in commands:
        with duckdb.connect() as connection:
            result = connection.sql(command) if reader == "DuckDB" else eval(command, namespace)
            count, columns = _rows(result)
        assert count == rows, command
        assert columns[-2:] == ["source", "capture"], command
