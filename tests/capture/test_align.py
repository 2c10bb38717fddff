"""`capture.align` against pandas' merge_asof, stream by stream, on generated tables."""

from __future__ import annotations

import datetime
import itertools
import math
import runpy
import subprocess
import sys
from pathlib import Path
from typing import Any

import pandas as pd
import pyarrow as pa
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from veronte4x import capture
from veronte4x.capture import AlignError, align
from veronte4x.capture.align import write_csv

EPOCH = datetime.datetime(1970, 1, 1, tzinfo=datetime.timezone.utc)
ROOT = Path(__file__).resolve().parents[2]

TABLES: dict[str, tuple[list[str], dict[str, Any]]] = {
    "Score": (["autopilot"], {"score": pa.float32()}),
    "Ready": ([], {"ready": pa.bool_()}),
    "EscStatus": (["esc_index"], {"rpm": pa.int32(), "temperature": pa.float32()}),
}


@st.composite
def tables(draw: st.DrawFn) -> dict[str, dict[str, list[Any]]]:
    """Columns of a few tables: times on a 1 ms lattice (ties and gaps), some null, two
    channels, several senders and keys."""
    out = {}
    for name in draw(st.lists(st.sampled_from(sorted(TABLES)), min_size=1, unique=True)):
        keys, values = TABLES[name]
        n = draw(st.integers(0, 25))
        column: dict[str, list[Any]] = {
            "time": [
                draw(st.one_of(st.none(), st.integers(0, 60).map(lambda k: k * 1000)))
                if draw(st.integers(0, 9)) == 0
                else draw(st.integers(0, 60)) * 1000
                for _ in range(n)
            ],
            "channel": [draw(st.sampled_from(["can0", "can0", "can1"])) for _ in range(n)],
            "sender": [draw(st.sampled_from(["arbiter", "AP1", "node 20"])) for _ in range(n)],
        }
        for key in keys:
            column[key] = [draw(st.integers(0, 2)) for _ in range(n)]
        for value in values:
            column[value] = list(range(n)) if value != "ready" else [i % 2 == 0 for i in range(n)]
        out[name] = column
    return out


def arrow(columns: dict[str, list[Any]], name: str, kind: str) -> pa.Table:
    base = 1_700_000_000_000_000
    times = [None if t is None else base + t for t in columns["time"]]
    if kind == "float":
        time = pa.array([None if t is None else t / 1e6 for t in times], pa.float64())
        time_name = "timestamp"
    else:
        time = pa.array(times, pa.int64()).cast(pa.timestamp("us", tz="UTC"))
        time_name = "time"
    keys, values = TABLES[name]
    fields = {time_name: time, "channel": pa.array(columns["channel"]).dictionary_encode()}
    fields["sender"] = pa.array(columns["sender"]).dictionary_encode()
    for key in keys:
        fields[key] = pa.array(columns[key], pa.uint8())
    for value, kind_ in values.items():
        fields[value] = pa.array(columns[value], kind_)
    return pa.table(fields)


def reference(
    data: dict[str, dict[str, list[Any]]], grid: list[int], direction: str, tolerance: int | None
) -> dict[str, list[Any]]:
    """Each stream through pandas' merge_asof on integer microseconds."""
    out: dict[str, list[Any]] = {}
    left = pd.DataFrame({"t": pd.Series(grid, dtype="int64")})
    for name, columns in data.items():
        keys, values = TABLES[name]
        frame = pd.DataFrame(columns).dropna(subset=["time"])
        frame["t"] = frame["time"].astype("int64")
        routing = ["channel", "sender"] if len(set(columns["channel"])) > 1 else ["sender"]
        parts = routing + keys
        groups = sorted(
            frame.groupby(parts if len(parts) > 1 else parts[0], sort=False).groups.items(),
            key=lambda item: tuple(str(v) for v in item[0]),
        )
        for found, index in groups:
            key = found if isinstance(found, tuple) else (found,)
            right = frame.loc[index].sort_values("t", kind="stable")
            merged = pd.merge_asof(left, right, on="t", direction=direction, tolerance=tolerance)
            label = [
                str(v) if p in ("channel", "sender") else f"{p}={v}"
                for p, v in zip(parts, key, strict=True)
            ]
            for value in values:
                got = merged[value].tolist()
                out["/".join([name, *label, value])] = [
                    None if isinstance(v, float) and math.isnan(v) else v for v in got
                ]
    return out


def plain(table: pa.Table) -> dict[str, list[Any]]:
    out = {}
    for name in table.column_names[1:]:
        out[name] = [
            None if v is None else (float(v) if isinstance(v, float) else v)
            for v in table.column(name).to_pylist()
        ]
    return out


def normalised(columns: dict[str, list[Any]]) -> dict[str, list[Any]]:
    return {
        k: [None if v is None else (bool(v) if k.endswith("ready") else float(v)) for v in vs]
        for k, vs in columns.items()
    }


@settings(max_examples=200, suppress_health_check=[HealthCheck.too_slow])
@given(
    tables(),
    st.sampled_from(["backward", "forward", "nearest"]),
    st.one_of(st.none(), st.sampled_from([0, 1000, 2500, 10_000])),
    st.sampled_from(["float", "timestamp"]),
    st.one_of(st.none(), st.sampled_from([1000, 3000, 7000])),
)
def test_align_is_merge_asof_per_stream(
    data: dict[str, dict[str, list[Any]]],
    direction: str,
    tolerance: int | None,
    kind: str,
    every: int | None,
) -> None:
    base = 1_700_000_000_000_000
    given_tables = {name: arrow(columns, name, kind) for name, columns in data.items()}
    times = sorted({t for c in data.values() for t in c["time"] if t is not None})
    if every is None:
        on = next(iter(data))
        grid = sorted({t for t in data[on]["time"] if t is not None})
        result = align(
            given_tables,
            on=on,
            tolerance=None if tolerance is None else tolerance / 1e6,
            direction=direction,
        )
    else:
        first = -(-(base + times[0]) // every) * every - base if times else 0
        grid = list(range(first, times[-1] + 1, every)) if times else []
        result = align(
            given_tables,
            every=datetime.timedelta(microseconds=every),
            tolerance=None if tolerance is None else f"{tolerance}us",
            direction=direction,
        )
    time = result.column(0)
    if kind == "float":
        assert result.column_names[0] == "timestamp"
        assert time.to_pylist() == [(base + t) / 1e6 for t in grid]
    else:
        assert result.column_names[0] == "time"
        assert time.type == pa.timestamp("us", tz="UTC")
        assert time.cast(pa.int64()).to_pylist() == [base + t for t in grid]
    assert normalised(plain(result)) == normalised(reference(data, grid, direction, tolerance))


@pytest.mark.parametrize("bad", [{}, {"on": "Score", "every": 1.0}, {"on": "Nope"}])
def test_bad_arguments_name_what_to_do(bad: dict[str, Any]) -> None:
    tables = {
        "Score": arrow(
            {
                "time": [0],
                "channel": ["can0"],
                "sender": ["arbiter"],
                "autopilot": [0],
                "score": [1.0],
            },
            "Score",
            "float",
        )
    }
    with pytest.raises(AlignError, match="on="):
        align(tables, **bad)


@pytest.mark.parametrize(
    ("every", "message"),
    [("10 parsecs", "expected a time"), (0, "positive"), (-1.0, "positive"), ("nan", "time")],
)
def test_bad_periods(every: Any, message: str) -> None:
    with pytest.raises(AlignError, match=message):
        align({}, every=every)


def test_the_example_on_a_10ms_grid() -> None:
    tables = capture.read_tables(ROOT / "examples" / "capture.log")
    grid = align(tables, every="10ms", tolerance="50ms")
    times = grid.column("timestamp").to_pylist()
    assert all(b - a == datetime.timedelta(milliseconds=10) for a, b in itertools.pairwise(times))
    assert "Score/arbiter/autopilot=1/score" in grid.column_names
    assert "errors" not in {name.split("/")[0] for name in grid.column_names}
    frame = grid.to_pandas()
    assert len(frame) == grid.num_rows
    assert grid.schema.field("timestamp").type == pa.timestamp("us", tz="UTC")
    seconds = align(capture.read_tables(ROOT / "examples" / "capture.log", time="seconds"),
                    every="10ms", tolerance="50ms")  # fmt: skip
    assert seconds.schema.field("timestamp").metadata == {b"unit": b"s"}
    assert seconds.column("timestamp").to_pylist() == [
        (t - EPOCH) / datetime.timedelta(seconds=1) for t in times
    ]


def test_units_carry_over(tmp_path: Path) -> None:
    runpy.run_path(str(ROOT / "examples" / "make_capture.py"))["generate"](0.05, 15.0, 4).write(
        tmp_path / "flight.log"
    )
    tables = capture.read_tables(tmp_path / "flight.log")
    grid = align(tables, on="EscStatus")
    field = grid.schema.field("EscStatus/node 21/esc_index=1/temperature")
    assert field.metadata == tables["EscStatus"].schema.field("temperature").metadata
    assert field.metadata == {b"unit": b"K"}


def convert(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "veronte4x", "convert", *args],
        capture_output=True,
        text=True,
        check=False,
    )


def test_convert_to_an_aligned_csv(tmp_path: Path) -> None:
    example = ROOT / "examples" / "capture.log"
    out = tmp_path / "flight.csv"
    done = convert(str(example), "--to", "csv", str(out), "--every", "10ms", "--tolerance", "50ms")
    assert (done.returncode, done.stdout) == (0, "")
    aligned = align(capture.read_tables(example), every="10ms", tolerance="50ms")
    frame = pd.read_csv(out)
    assert (
        done.stderr
        == f"veronte4x: {aligned.num_rows} rows, {len(frame.columns)} columns, in {out}\n"
    )
    assert frame["time"].tolist() == [
        t.strftime("%Y-%m-%dT%H:%M:%S.%fZ") for t in aligned.column("timestamp").to_pylist()
    ]
    for name in ["Score/arbiter/autopilot=1/score", "PwmSet/AP2/first_channel=0/values_0"]:
        want = [None if v is None else float(v) for v in aligned.column(name).to_pylist()]
        got = [None if math.isnan(v) else v for v in frame[name]]  # exact
        assert got == want, name
    ready = aligned.column("Ready/AP1/ready").to_pylist()
    assert [None if math.isnan(v) else bool(v) for v in frame["Ready/AP1/ready"]] == ready
    assert not any(c.startswith("ScorpionEscTelemetry") for c in frame.columns)  # raw bytes


def test_csv_keeps_text_and_leaves_out_bytes_and_lists(tmp_path: Path) -> None:
    text = ["ARMED", None, 'say "hi", then \u00b0C\nbye']
    aligned = pa.table(
        {
            "timestamp": pa.array([0, 1, 2], pa.int64()).cast(pa.timestamp("us", tz="UTC")),
            "LogMessage/node 20/text": pa.array(text, pa.string()),
            "LogMessage/node 20/source": pa.array(["a", "b", None], pa.large_string()),
            "Raw/node 20/payload": pa.array([b"\x00", b"", None], pa.binary()),
            "Array/node 20/values": pa.array([[1], [], None], pa.list_(pa.int8())),
        }
    )
    out = tmp_path / "text.csv"
    assert write_csv(aligned, out) == 3
    frame = pd.read_csv(out, keep_default_na=False)
    assert frame.columns.tolist() == [
        "time",
        "LogMessage/node 20/text",
        "LogMessage/node 20/source",
    ]
    assert frame["LogMessage/node 20/text"].tolist() == ["ARMED", "", text[2]]
    assert frame["LogMessage/node 20/source"].tolist() == ["a", "b", ""]


def test_convert_to_csv_usage_errors(tmp_path: Path) -> None:
    example = str(ROOT / "examples" / "capture.log")
    out = str(tmp_path / "x.csv")
    done = convert(example, "--to", "csv", out)
    assert (done.returncode, done.stderr) == (
        2,
        "veronte4x: --to csv needs one of --every PERIOD (10ms) or --on TABLE\n",
    )
    done = convert(example, "--to", "csv", out, "--every", "soon")
    assert (done.returncode, done.stderr) == (
        2,
        "veronte4x: every='soon': expected a time such as 10ms, 0.5s, 250us\n",
    )
    done = convert(example, "--to", "csv", out, "--on", "Nope")
    assert done.returncode == 2
    assert done.stderr.startswith("veronte4x: on='Nope' names no table; the tables are Status, ")
