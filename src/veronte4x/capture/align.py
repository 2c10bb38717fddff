"""One time base for several message tables: as-of joins onto a regular grid or a table's times.

Every question about a flight joins streams that arrive at their own rates (ESC temperature
against throttle, score against selection). `align` puts the tables of `read_tables` on one
time axis, the way pandas' ``merge_asof`` does for two frames: for each grid time, the row
of each stream at or before it (``backward``), at or after it (``forward``) or the nearest
one, no further than ``tolerance``. Rows are kept apart per stream: per sender, and per
the key that tells one stream of a message type from another (the autopilot of a Score,
the number of an arbitration variable, an ESC's index, ...), and per channel when a table
has several. Each stream's value columns become columns named
``Table/sender/key=value/column`` (``Score/arbiter/autopilot=0/score``), a tree in
PlotJuggler. Times are compared in whole microseconds, whether the tables carry them as
float seconds or as an Arrow timestamp.
"""

from __future__ import annotations

import datetime
import math
import os
import re
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

from veronte4x.errors import Veronte4xError
from veronte4x.extras import require
from veronte4x.files import whole_file
from veronte4x.times import EPOCH_THRESHOLD

if TYPE_CHECKING:
    import numpy
    import pyarrow

TIME_COLUMNS = ("time", "timestamp")
"""The names a table's time column may have, the first one found is used."""

ROUTING_COLUMNS = frozenset({"channel", "can_id", "sender", "node_id", "destination_node_id"})
"""Columns that say where a row came from: never values of their own in the result."""

KEYS: Mapping[str, tuple[str, ...]] = {
    "Score": ("autopilot",),
    "ArbitrationVariable": ("number",),
    "PwmSet": ("first_channel",),
    "EscStatus": ("esc_index",),
    "Temperature": ("device_id",),
}
"""The columns that tell one stream of a message type from another, besides the sender."""

SKIPPED_TABLES = frozenset({"errors", "unknown"})
"""Tables that are not signals: left out of the result."""

DIRECTIONS = ("backward", "forward", "nearest")

_UNITS = {"us": 1, "ms": 1000, "s": 1_000_000, "min": 60_000_000}


class AlignError(Veronte4xError, ValueError):
    """Arguments `align` cannot use: neither or both of ``on`` and ``every``, a bad period."""


def align(
    tables: Mapping[str, pyarrow.Table],
    on: str | None = None,
    every: float | str | datetime.timedelta | None = None,
    tolerance: float | str | datetime.timedelta | None = None,
    direction: str = "backward",
    by: Mapping[str, Sequence[str]] | None = None,
) -> pyarrow.Table:
    """Join message tables onto one time axis. Needs the ``arrow`` extra.

    Args:
        tables: Tables by name, as `read_tables` returns them (``errors`` and ``unknown``
            are left out).
        on: Name of the table whose row times are the axis (each distinct time once).
        every: A regular axis instead: the period in seconds or as text (``10ms``,
            ``0.5s``, ``250us``, ``1min``), from the first multiple of it at or after the
            earliest row to the latest row.
        tolerance: The largest distance between an axis time and the row it takes
            (seconds or text as ``every``); None for no limit.
        direction: ``backward`` (the last row at or before), ``forward`` (the first row at
            or after) or ``nearest`` (the closer one; the earlier on a tie).
        by: Key columns per table name, in place of `KEYS`.

    Returns:
        An Arrow table: the time column (named and typed as the tables' own: float seconds,
        or ``timestamp[us, tz=UTC]``), then one column per stream and value column, null
        where no row is within the tolerance, with its unit in the field metadata as in the
        tables. ``.to_pandas()`` makes it a DataFrame, ``polars.from_arrow`` a Polars one.

    Raises:
        AlignError: Neither or both of ``on`` and ``every``, ``on`` naming no table, a
            period or tolerance that is not a positive time, an unknown direction.

    Examples:
        >>> from veronte4x import capture
        >>> tables = capture.read_tables("examples/capture.log")
        >>> grid = capture.align(tables, every="100ms", tolerance="100ms")
        >>> grid.column_names[:3]
        ['timestamp', 'Status/arbiter/selected', 'Status/arbiter/selected_name']
    """
    for module in ("numpy", "pyarrow"):
        require(module, "arrow", "aligning tables")
    import numpy as np
    import pyarrow as pa

    if (on is None) == (every is None):
        raise AlignError("align needs exactly one of on= (a table's name) or every= (a period)")
    if direction not in DIRECTIONS:
        raise AlignError(f"direction {direction!r}: expected one of {', '.join(DIRECTIONS)}")
    keys = KEYS if by is None else by
    kept = {name: table for name, table in tables.items() if name not in SKIPPED_TABLES}
    times = {name: _micros(table) for name, table in kept.items()}
    timestamp = any(_time_type(t) is not None for t in kept.values())
    if on is not None:
        if on not in times:
            raise AlignError(f"on={on!r} names no table; the tables are {', '.join(kept)}")
        values, valid = times[on]
        grid = np.unique(values[valid])
    else:
        assert every is not None
        period = _period(every, "every")
        found = [values[valid] for values, valid in times.values() if valid.any()]
        if found:
            low = min(int(v.min()) for v in found)
            high = max(int(v.max()) for v in found)
            grid = np.arange(-(-low // period) * period, high + 1, period, dtype=np.int64)
        else:
            grid = np.zeros(0, dtype=np.int64)
    limit = None if tolerance is None else _period(tolerance, "tolerance")
    time_name = next(
        (_time_name(t) for t in kept.values() if _time_type(t) is not None),
        next((_time_name(t) for t in kept.values()), "timestamp"),
    )
    if timestamp:
        time_column = pa.array(grid, pa.int64()).cast(pa.timestamp("us", tz="UTC"))
    else:
        time_column = pa.array(grid / 1e6, pa.float64())
    unit = None if timestamp else {"unit": "s"}
    fields = [pa.field(time_name, time_column.type, metadata=unit)]
    columns = [time_column]
    for name, table in kept.items():
        values, valid = times[name]
        table_keys = [k for k in keys.get(name, ()) if k in table.column_names]
        for label, rows in _streams(table, table_keys, valid):
            picked = _pick(values, rows, grid, direction, limit)
            indices = pa.array(picked, pa.int64(), mask=picked < 0)
            for column in table.column_names:
                if column in ROUTING_COLUMNS or column in table_keys or column in TIME_COLUMNS:
                    continue
                source = table.schema.field(column)  # keeps its unit (field metadata)
                fields.append(source.with_name("/".join([name, *label, column])))
                columns.append(table.column(column).take(indices))
    return pa.table(columns, schema=pa.schema(fields))


def _time_name(table: pyarrow.Table) -> str:
    for name in TIME_COLUMNS:
        if name in table.column_names:
            return name
    raise AlignError(f"a table has no time column ({' or '.join(TIME_COLUMNS)})")


def _time_type(table: pyarrow.Table) -> Any:
    import pyarrow as pa

    kind = table.schema.field(_time_name(table)).type
    return kind if pa.types.is_timestamp(kind) else None


def _micros(table: pyarrow.Table) -> tuple[numpy.ndarray[Any, Any], numpy.ndarray[Any, Any]]:
    """A table's times in whole microseconds (0 where null), and which are not null."""
    import numpy as np
    import pyarrow as pa
    import pyarrow.compute as pc

    column = table.column(_time_name(table))
    valid = column.is_valid().to_numpy(zero_copy_only=False)
    if pa.types.is_timestamp(column.type):
        micros = pc.cast(pc.cast(column, pa.timestamp("us", tz="UTC")), pa.int64())
        values = micros.fill_null(0).to_numpy()
    else:
        seconds = column.cast(pa.float64()).fill_null(0.0).to_numpy()
        valid &= np.isfinite(seconds)
        values = np.round(np.where(valid, seconds, 0.0) * 1e6).astype(np.int64)
    return values.astype(np.int64), valid


def _streams(
    table: pyarrow.Table, keys: list[str], valid: numpy.ndarray[Any, Any]
) -> list[tuple[list[str], numpy.ndarray[Any, Any]]]:
    """(label parts, row numbers in time order) of each stream of a table."""
    import numpy as np

    routing = [c for c in ("channel", "sender") if c in table.column_names]
    if "channel" in routing and len(table.column("channel").unique()) < 2:
        routing.remove("channel")
    parts = routing + keys
    columns = [table.column(c).to_pylist() for c in parts]
    groups: dict[tuple[Any, ...], list[int]] = {}
    for row, key in enumerate(zip(*columns, strict=True) if parts else [()] * table.num_rows):
        if valid[row]:
            groups.setdefault(key, []).append(row)
    out = []
    for key in sorted(groups, key=lambda k: tuple((v is None, str(v)) for v in k)):
        label = [
            str(value) if column in ("channel", "sender") else f"{column}={value}"
            for column, value in zip(parts, key, strict=True)
        ]
        out.append((label, np.asarray(groups[key], dtype=np.int64)))
    return out


def _pick(
    values: numpy.ndarray[Any, Any],
    rows: numpy.ndarray[Any, Any],
    grid: numpy.ndarray[Any, Any],
    direction: str,
    limit: int | None,
) -> numpy.ndarray[Any, Any]:
    """For each grid time, the row of ``rows`` (at least one: `_streams` makes no empty
    stream) it takes, or -1."""
    import numpy as np

    order = rows[np.argsort(values[rows], kind="stable")]
    times = values[order]
    n = len(times)
    before = np.searchsorted(times, grid, side="right") - 1
    after = np.searchsorted(times, grid, side="left")
    has_before = before >= 0
    has_after = after < n
    gap_before = np.where(has_before, grid - times[np.clip(before, 0, n - 1)], 0)
    gap_after = np.where(has_after, times[np.clip(after, 0, n - 1)] - grid, 0)
    if direction == "backward":
        chosen, ok, gap = before, has_before, gap_before
    elif direction == "forward":
        chosen, ok, gap = after, has_after, gap_after
    else:
        take_before = has_before & (~has_after | (gap_before <= gap_after))
        chosen = np.where(take_before, before, after)
        ok = has_before | has_after
        gap = np.where(take_before, gap_before, gap_after)
    if limit is not None:
        ok = ok & (gap <= limit)
    result: numpy.ndarray[Any, Any] = np.where(ok, order[np.clip(chosen, 0, n - 1)], -1)
    return result


def _period(value: float | str | datetime.timedelta, name: str) -> int:
    """A positive time in whole microseconds, from seconds, text or a timedelta."""
    micros: float
    if isinstance(value, datetime.timedelta):
        micros = value / datetime.timedelta(microseconds=1)
    elif isinstance(value, str):
        match = re.fullmatch(r"\s*([0-9]*\.?[0-9]+(?:e-?[0-9]+)?)\s*(us|ms|s|min)\s*", value)
        if match is None:
            raise AlignError(f"{name}={value!r}: expected a time such as 10ms, 0.5s, 250us")
        micros = float(match.group(1)) * _UNITS[match.group(2)]
    elif isinstance(value, (int, float)) and not isinstance(value, bool):
        micros = float(value) * 1e6
    else:
        raise AlignError(f"{name}={value!r}: expected seconds, a timedelta or text like 10ms")
    if name == "tolerance" and micros == 0:
        return 0
    if not math.isfinite(micros) or round(micros) <= 0:
        raise AlignError(f"{name}={value!r}: expected a positive time of 1 us or more")
    return round(micros)


def write_csv(aligned: pyarrow.Table, path: str | os.PathLike[str]) -> int:
    """Write an `align` result as a flat CSV that PlotJuggler or a spreadsheet opens.

    The first column, ``time``, holds the time as ISO 8601 in UTC to the microsecond
    (``2025-11-21T15:00:00.010000Z``) when the tables carry timestamps, else their seconds
    (``time="seconds"`` or ``"relative"``), and timestamps of a capture's own clock (below
    `veronte4x.times.EPOCH_THRESHOLD`: time since boot, not a time of 1970) as their seconds;
    numbers are exact (a float32 0.1 is ``0.10000000149011612``, as `veronte4x.numbers`
    says), flags are 0 or 1, enums their names, text as text (quoted where it needs), and a
    missing value is an empty cell.
    Columns a plot or a spreadsheet cannot use (raw bytes, lists, structs) are left out.

    Returns:
        The number of columns written, time included.

    Raises:
        OSError: The file cannot be written.
    """
    import pyarrow as pa
    import pyarrow.compute as pc
    import pyarrow.csv

    time = aligned.column(0)
    if pa.types.is_timestamp(time.type):
        micros = pc.cast(pc.cast(time, pa.timestamp("us", tz="UTC")), pa.timestamp("us"))
        first = pc.min(micros.cast(pa.int64())).as_py()
        if first is not None and first < EPOCH_THRESHOLD * 1_000_000:  # a clock since boot
            time = pc.divide(micros.cast(pa.int64()).cast(pa.float64()), 1e6)
        else:
            time = pc.strftime(micros, format="%Y-%m-%dT%H:%M:%SZ")  # %S: with microseconds
    else:
        time = time.cast(pa.float64())
    names, columns = ["time"], [time]
    for name, column in zip(aligned.column_names[1:], aligned.columns[1:], strict=True):
        kind = column.type
        if pa.types.is_boolean(kind):
            column = column.cast(pa.uint8())
        elif pa.types.is_dictionary(kind):
            column = column.cast(kind.value_type)
        elif pa.types.is_float16(kind) or pa.types.is_float32(kind):
            column = column.cast(pa.float64())  # written exact, as veronte4x.numbers says
        elif not (
            pa.types.is_integer(kind)
            or pa.types.is_floating(kind)
            or pa.types.is_string(kind)
            or pa.types.is_large_string(kind)
        ):
            continue
        names.append(name)
        columns.append(column)
    with whole_file(path) as file:
        pyarrow.csv.write_csv(
            pa.table(columns, names=names),
            file,
            pyarrow.csv.WriteOptions(quoting_style="needed"),
        )
    return len(names)
