"""Questions across a fleet's flights, asked of a Parquet dataset with DuckDB and Polars.

Usage: python examples/fleet.py [WORK_DIR] [PLOT.png]

Simulates a small fleet (three flights of `make_capture.py`, each losing its selected
autopilot at a different time), converts the captures into one dataset with
`capture.to_parquet`, then answers two questions, each with DuckDB (SQL) and with Polars
(a lazy scan), and plots the answers:

1. Every autopilot switch, with the scores the arbiter last sent before it.
2. ESC temperature against throttle, over all flights.

Needs the ``parquet``, ``query`` and ``plot`` extras.
"""

from __future__ import annotations

import runpy
import sys
from pathlib import Path

import duckdb
import polars as pl
from matplotlib.figure import Figure
from polars.testing import assert_frame_equal

from veronte4x import capture

HERE = Path(__file__).parent
RAW_FULL_SCALE = 8191
"""RawCommand value of full throttle (esc.RawCommand: -8192..8191)."""


def make_fleet(
    folder: Path, minutes: float = 1.0, fail_at: tuple[float, ...] = (0.3, 0.5, 0.7)
) -> list[Path]:
    """Simulate one flight per failure time (a fraction of the flight), a day apart;
    return the capture files."""
    generate = runpy.run_path(str(HERE / "make_capture.py"))["generate"]
    folder.mkdir(parents=True, exist_ok=True)
    paths = []
    for number, failure in enumerate(fail_at):
        start = 1_763_737_200.0 + 86_400 * number
        path = folder / f"flight{number + 1}.log"
        generate(minutes, failure * minutes * 60, number).write(path, start)
        paths.append(path)
    return paths


# Question 1: every autopilot switch with its scores ------------------------------------

SWITCHES_SQL = """
WITH status AS (
    SELECT source, timestamp, selected_name AS selected,
           lag(selected_name) OVER (PARTITION BY source ORDER BY timestamp) AS previous
    FROM read_parquet('{data}/capture=*/Status.parquet')
), switches AS (
    SELECT source, timestamp, previous, selected FROM status WHERE selected <> previous
), scores AS (
    SELECT source, timestamp,
           last_value(CASE WHEN autopilot_name = 'AP1' THEN score END IGNORE NULLS) OVER w AS ap1,
           last_value(CASE WHEN autopilot_name = 'AP2' THEN score END IGNORE NULLS) OVER w AS ap2,
           last_value(CASE WHEN autopilot_name = 'AP3' THEN score END IGNORE NULLS) OVER w AS ap3
    FROM read_parquet('{data}/capture=*/Score.parquet')
    WINDOW w AS (PARTITION BY source ORDER BY timestamp ROWS UNBOUNDED PRECEDING)
)
SELECT w.source, w.timestamp, w.previous, w.selected,
       s.timestamp AS scored_at, s.ap1, s.ap2, s.ap3
FROM switches w ASOF JOIN scores s ON w.source = s.source AND w.timestamp >= s.timestamp
ORDER BY w.source, w.timestamp
"""


def switches_duckdb(data: Path) -> pl.DataFrame:
    """Question 1 in SQL: the switches, and each autopilot's last score before them."""
    with duckdb.connect() as connection:  # its own, not the module's shared connection
        switches = connection.sql(SWITCHES_SQL.format(data=data.as_posix())).pl()
    # DuckDB gives TIMESTAMP WITH TIME ZONE in the session's zone: shown here in UTC.
    return switches.with_columns(pl.col(pl.Datetime).dt.convert_time_zone("UTC"))


def _scan(data: Path, kind: str) -> pl.LazyFrame:
    """One table over every capture of the dataset, scanned lazily (``source`` as plain
    text)."""
    frame = pl.scan_parquet(f"{data.as_posix()}/capture=*/{kind}.parquet")
    return frame.with_columns(pl.col("source").cast(pl.String))


def switches_polars(data: Path) -> pl.DataFrame:
    """Question 1 with Polars: the same answer from lazy scans."""
    switches = (
        _scan(data, "Status")
        .sort("source", "timestamp")
        .with_columns(selected=pl.col("selected_name").cast(pl.String))
        .with_columns(previous=pl.col("selected").shift(1).over("source"))
        .filter(pl.col("selected") != pl.col("previous"))
        .select("source", "timestamp", "previous", "selected")
    )
    scores = (
        _scan(data, "Score")
        .sort("source", "timestamp")
        .with_columns(
            pl.when(pl.col("autopilot") == index)
            .then(pl.col("score"))
            .forward_fill()
            .over("source")
            .alias(f"ap{index + 1}")
            for index in range(3)
        )
        .with_columns(scored_at=pl.col("timestamp"))
        .sort("timestamp")
    )
    joined = switches.sort("timestamp").join_asof(
        scores, on="timestamp", by="source", check_sortedness=False
    )
    return (
        joined.select(
            "source", "timestamp", "previous", "selected", "scored_at", "ap1", "ap2", "ap3"
        )
        .sort("source", "timestamp")
        .collect()
    )


# Question 2: ESC temperature against throttle -----------------------------------------

HEAT_SQL = """
SELECT round(c.cmd[e.esc_index + 1] / {full}, 1) AS throttle,
       avg(e.temperature - 273.15) AS temperature_c,
       count(*) AS samples
FROM read_parquet('{data}/capture=*/EscStatus.parquet') e
ASOF JOIN read_parquet('{data}/capture=*/RawCommand.parquet') c
    ON e.source = c.source AND e.timestamp >= c.timestamp
GROUP BY ALL
ORDER BY throttle
"""


def heat_duckdb(data: Path) -> pl.DataFrame:
    """Question 2 in SQL: mean ESC temperature (degC) per tenth of throttle, each status
    paired with the last RawCommand before it in the same flight."""
    with duckdb.connect() as connection:
        return connection.sql(HEAT_SQL.format(data=data.as_posix(), full=RAW_FULL_SCALE)).pl()


def heat_polars(data: Path) -> pl.DataFrame:
    """Question 2 with Polars: the same answer from lazy scans."""
    status = _scan(data, "EscStatus").select("source", "timestamp", "esc_index", "temperature")
    command = _scan(data, "RawCommand").select("source", "timestamp", "cmd").sort("timestamp")
    joined = status.sort("timestamp").join_asof(
        command, on="timestamp", by="source", check_sortedness=False
    )
    throttle = pl.col("cmd").list.get(pl.col("esc_index").cast(pl.Int64)) / RAW_FULL_SCALE
    return (
        joined.with_columns(throttle=throttle.round(1))
        .group_by("throttle")
        .agg(
            temperature_c=(pl.col("temperature").cast(pl.Float64) - 273.15).mean(),
            samples=pl.len().cast(pl.Int64),
        )
        .sort("throttle")
        .collect()
    )


def plot(switches: pl.DataFrame, heat: pl.DataFrame, path: Path) -> None:
    """The scores at each switch, and temperature against throttle."""
    figure = Figure(figsize=(10, 4))
    left, right = figure.subplots(1, 2)
    labels = [f"{Path(s).stem}\n{p}->{n}" for s, p, n in switches.select(
        "source", "previous", "selected").iter_rows()]  # fmt: skip
    for offset, column in enumerate(("ap1", "ap2", "ap3")):
        x = [i + 0.25 * (offset - 1) for i in range(len(labels))]
        left.bar(x, switches[column].to_list(), width=0.25, label=column.upper())
    left.set_xticks(range(len(labels)), labels)
    left.set_ylabel("score before the switch")
    left.set_title("Autopilot switches")
    left.legend()
    right.plot(heat["throttle"].to_list(), heat["temperature_c"].to_list(), marker="o")
    right.set_xlabel("throttle (fraction of full scale)")
    right.set_ylabel("mean ESC temperature (degC)")
    right.set_title("ESC temperature against throttle, all flights")
    figure.tight_layout()
    figure.savefig(path)


def _readable(frame: pl.DataFrame) -> pl.DataFrame:
    """File names for paths, times to the millisecond (they are UTC timestamps already)."""
    return frame.with_columns(
        pl.col("source").str.split("/").list.last(),
        pl.col("timestamp", "scored_at").dt.round("1ms"),
    )


def main(work: Path, plot_path: Path, minutes: float = 1.0) -> None:
    """Make the fleet, convert it, ask both questions both ways, plot."""
    captures = make_fleet(work / "captures", minutes)
    data = work / "dataset"
    summary = capture.to_parquet(captures, data)
    print(summary.line())

    switches = switches_duckdb(data)
    assert_frame_equal(switches, switches_polars(data))  # DuckDB and Polars agree
    print(f"\n{len(switches)} autopilot switches (autopilot 0 is AP1):")
    print(_readable(switches))

    heat = heat_duckdb(data)
    assert_frame_equal(heat, heat_polars(data))
    print("\nESC temperature against throttle, all flights:")
    print(heat)
    plot(switches, heat, plot_path)
    print(f"\nplot written to {plot_path}")


if __name__ == "__main__":
    main(
        Path(sys.argv[1] if len(sys.argv) > 1 else HERE / "fleet"),
        Path(sys.argv[2] if len(sys.argv) > 2 else HERE / "fleet.png"),
    )
