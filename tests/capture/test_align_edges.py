"""`capture.align` and `write_csv` at their edges: a capture without timestamps, a table
without a time column, arguments of the wrong kind, and the CSV of float seconds, flags and
enums, written in this process.
"""

from __future__ import annotations

import datetime
from pathlib import Path

import pyarrow as pa
import pytest

from veronte4x import capture
from veronte4x.capture import AlignError, align
from veronte4x.capture.align import write_csv


def test_a_capture_without_timestamps_aligns_to_no_row(tmp_path: Path) -> None:
    """Candump's human view without ``-t`` has no time: there is no axis to put it on."""
    path = tmp_path / "untimed.log"
    path.write_text("  can0  009   [3]  00 FF 01\n  can0  009   [3]  00 FF 00\n")
    tables = capture.read_tables(path)
    assert tables["Ready"].num_rows == 2
    for grid in (align(tables, every="10ms"), align(tables, on="Ready")):
        assert (grid.column_names, grid.num_rows) == (["timestamp"], 0)
        assert grid.schema.field("timestamp").type == pa.timestamp("us", tz="UTC")
    empty = align({}, every=datetime.timedelta(milliseconds=10))
    assert (empty.column_names, empty.num_rows) == (["timestamp"], 0)
    assert empty.schema.field("timestamp").metadata == {b"unit": b"s"}


def test_a_table_without_a_time_column_is_named() -> None:
    tables = {"Ready": pa.table({"sender": ["AP1"], "ready": [True]})}
    with pytest.raises(AlignError) as raised:
        align(tables, every="10ms")
    assert str(raised.value) == "a table has no time column (time or timestamp)"


@pytest.mark.parametrize(
    ("arguments", "message"),
    [
        ({"every": "10ms", "direction": "sideways"},
         "direction 'sideways': expected one of backward, forward, nearest"),
        ({"every": True}, "every=True: expected seconds, a timedelta or text like 10ms"),
        ({"every": None, "on": "Ready", "tolerance": [1]},
         "tolerance=[1]: expected seconds, a timedelta or text like 10ms"),
        ({"every": "10ms", "tolerance": "-1ms"},
         "tolerance='-1ms': expected a time such as 10ms, 0.5s, 250us"),
        ({"every": "0.1us"}, "every='0.1us': expected a positive time of 1 us or more"),
    ],
)  # fmt: skip
def test_arguments_of_the_wrong_kind(arguments: dict[str, object], message: str) -> None:
    tables = {"Ready": pa.table({"time": [0.0, 0.01], "ready": [True, False]})}
    with pytest.raises(AlignError) as raised:
        align(tables, **arguments)  # type: ignore[arg-type]
    assert str(raised.value) == message


def test_a_tolerance_of_zero_takes_exact_times_only() -> None:
    tables = {"Ready": pa.table({"time": [0.0, 0.015], "ready": [True, False]})}
    grid = align(tables, every="10ms", tolerance=0)
    assert grid.column("time").to_pylist() == [0.0, 0.01]
    assert grid.column("Ready/ready").to_pylist() == [True, None]


def test_csv_of_seconds_flags_and_enums(tmp_path: Path) -> None:
    """Times in seconds stay seconds, flags are 0 or 1, enums their names, a missing value
    an empty cell."""
    health = pa.array(["OK", None, "WARNING"]).dictionary_encode()
    aligned = pa.table(
        {
            "time": pa.array([0.5, 0.25, 1e-6], pa.float64()),
            "Ready/AP1/ready": pa.array([True, None, False]),
            "NodeStatus/node 20/health": health,
            "NodeStatus/node 20/uptime_sec": pa.array([7, 8, None], pa.uint32()),
        }
    )
    out = tmp_path / "aligned.csv"
    assert write_csv(aligned, out) == 4
    assert out.read_text().splitlines() == [
        '"time","Ready/AP1/ready","NodeStatus/node 20/health","NodeStatus/node 20/uptime_sec"',
        '0.5,1,"OK",7',
        "0.25,,,8",
        '0.000001,0,"WARNING",',
    ]
