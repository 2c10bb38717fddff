"""``veronte4x decode`` writes the exact decoded values in JSON lines and CSV: the same as
`capture.read` and cantools, bit for bit (a float64 as its ``repr``; NaN and infinities as
``"NaN"``, ``"Infinity"``, ``"-Infinity"``), read back so by pandas, Polars and DuckDB.

The CLI runs as a subprocess, twice per generated capture (JSON lines, CSV), on few
captures of many frames each.
"""

from __future__ import annotations

import csv
import io
import json
import math
import struct
import subprocess
import sys
from pathlib import Path
from typing import Any

import cantools
import duckdb
import pandas as pd
import polars as pl
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from veronte4x import capture
from veronte4x.capture.busmap import BusMap

BUS_MAP = """\
[[veronte.layouts]]
command = 5
name = "Wheel"
fields = [{ kind = "unsigned", name = "speed", bits = 16, scale = [0, 65535, 0.0, 1023.984375] }]

[[veronte.layouts]]
command = 6
name = "Volts"
fields = [{ kind = "float32", name = "volts" }]
"""

DBC = """\
VERSION ""

NS_ :

BS_:

BU_: ECU

BO_ 768 Gps: 8 ECU
 SG_ GPS_Time : 0|32@1+ (0.001,0) [0|4294967.295] "s" ECU
 SG_ Speed : 32|16@1+ (0.015625,0) [0|1023.984375] "km/h" ECU
 SG_ Offset : 48|16@1- (0.1,-3.5) [-3280.3|3273.2] "" ECU

BO_ 769 Floats: 8 ECU
 SG_ Single : 0|32@1- (1,0) [0|0] "" ECU
 SG_ Halved : 32|32@1- (0.5,0) [0|0] "" ECU

BO_ 770 Double: 8 ECU
 SG_ Wide : 0|64@1- (1,0) [0|0] "" ECU

SIG_VALTYPE_ 769 Single : 1;
SIG_VALTYPE_ 769 Halved : 1;
SIG_VALTYPE_ 770 Wide : 2;
"""

_SPECIAL_32 = (0, 0x8000_0000, 0x7FC0_0000, 0xFFC0_0001, 0x7F80_0000, 0xFF80_0000, 1, 0x7F7F_FFFF)
_SPECIAL_64 = (0, 1 << 63, 0x7FF8 << 48, 0x7FF0 << 48, 0xFFF0 << 48, 1, 0x7FEF_FFFF_FFFF_FFFF)
_BITS_32 = st.sampled_from(_SPECIAL_32) | st.integers(0, (1 << 32) - 1)
_BITS_64 = st.sampled_from(_SPECIAL_64) | st.integers(0, (1 << 64) - 1)


def _le(value: int, size: int) -> bytes:
    return value.to_bytes(size, "little")


FRAMES = st.one_of(
    st.builds(lambda n, b: ("008", bytes([0, n]) + _le(b, 4)), st.integers(0, 31), _BITS_32),
    st.builds(lambda raw: ("008", b"\x05" + _le(raw, 2)), st.integers(0, 0xFFFF)),
    st.builds(lambda b: ("008", b"\x06" + _le(b, 4)), _BITS_32),
    st.builds(lambda data: ("300", data), st.binary(min_size=8, max_size=8)),
    st.builds(lambda a, b: ("301", _le(a, 4) + _le(b, 4)), _BITS_32, _BITS_32),
    st.builds(lambda b: ("302", _le(b, 8)), _BITS_64),
)


def _json_form(value: Any) -> Any:
    """What the rule says a JSON line holds for a decoded value."""
    if type(value) is float and not math.isfinite(value):
        return "NaN" if value != value else ("Infinity" if value > 0 else "-Infinity")
    return value


def _files(tmp: Path, frames: list[tuple[str, bytes]]) -> tuple[Path, Path, Path]:
    log, bus_map, dbc = tmp / "capture.log", tmp / "bus.toml", tmp / "vehicle.dbc"
    lines = [
        f"({i / 100:.6f}) can0 {can_id}#{data.hex()}\n" for i, (can_id, data) in enumerate(frames)
    ]
    log.write_text("".join(lines), encoding="ascii")
    bus_map.write_text(BUS_MAP, encoding="ascii")
    dbc.write_text(DBC, encoding="ascii")
    return log, bus_map, dbc


def _decode(log: Path, bus_map: Path, dbc: Path, output: str) -> str:
    result = subprocess.run(
        [
            sys.executable,
            "-m",
            "veronte4x",
            "decode",
            str(log),
            "--output",
            output,
            "--bus-map",
            str(bus_map),
            "--dbc",
            str(dbc),
        ],
        capture_output=True,
        text=True,
        check=False,
    )
    assert (result.returncode, result.stderr.count("\n")) == (0, 1), result.stderr
    return result.stdout


@given(frames=st.lists(FRAMES, min_size=1, max_size=300))
@settings(max_examples=4, suppress_health_check=[HealthCheck.function_scoped_fixture])
def test_json_lines_and_csv_are_capture_read_and_cantools_bit_for_bit(
    tmp_path: Path, frames: list[tuple[str, bytes]]
) -> None:
    log, bus_map, dbc = _files(tmp_path, frames)
    records = list(capture.read(log, BusMap.from_toml(bus_map), dbc=[dbc]))
    assert len(records) == len(frames) and all(r.message is not None for r in records)
    reference = cantools.database.load_string(DBC)
    assert isinstance(reference, cantools.database.can.Database)
    rows = [json.loads(line) for line in _decode(log, bus_map, dbc, "jsonl").splitlines()]
    table = list(csv.DictReader(io.StringIO(_decode(log, bus_map, dbc, "csv"))))
    assert len(rows) == len(table) == len(records)
    for record, row, cells in zip(records, rows, table, strict=True):
        assert repr(row["timestamp"]) == repr(record.timestamp) == cells["timestamp"]
        fields = capture.fields(record.message)
        assert set(row) - set(fields) == {"timestamp", "channel", "can_id", "sender", "message"}
        for name, value in fields.items():
            assert repr(row[name]) == repr(_json_form(value)), (record, name)
            assert cells[name] == str(_json_form(value)), (record, name)
        if record.can_id >= 0x300:  # a DBC frame: cantools' values, bit for bit
            expected = reference.decode_message(record.can_id, record.data)
            assert isinstance(expected, dict)
            assert {k: repr(_json_form(v)) for k, v in expected.items()} == {
                k: repr(row[k]) for k in expected
            }


def test_nan_infinities_zeros_and_missing_read_back_in_pandas_polars_and_duckdb(
    tmp_path: Path,
) -> None:
    """Each JSON and CSV reader gets the floats back exactly, NaN apart from a missing value
    (pandas' float64 has no missing value but NaN: it is left out of that check). pandas
    needs ``precise_float=True``: its fast parser is an ulp off (0.10000000149011612 read
    as 0.10000000149011611)."""
    frames = [
        ("301", _le(0x7FC0_0000, 4) + _le(0x7F80_0000, 4)),  # NaN, inf (Halved: inf * 0.5)
        ("301", _le(0xFF80_0000, 4) + _le(0x8000_0000, 4)),  # -inf, -0.0
        ("301", _le(0x3DCC_CCCD, 4) + _le(1, 4)),  # 0.1 as float32, the smallest subnormal
        ("008", b"\x05\xff\xff"),  # 1023.984375: Single and Halved missing from here on
        ("302", _le(0x7FEF_FFFF_FFFF_FFFF, 8)),
    ]
    log, bus_map, dbc = _files(tmp_path, frames)
    records = list(capture.read(log, BusMap.from_toml(bus_map), dbc=[dbc]))
    columns = ("Single", "Halved", "speed", "Wide")
    expected = {name: [capture.fields(r.message).get(name) for r in records] for name in columns}
    assert expected["Single"][:3] == [expected["Single"][0], -math.inf, 0.10000000149011612]
    jsonl, table = tmp_path / "out.jsonl", tmp_path / "out.csv"
    jsonl.write_text(_decode(log, bus_map, dbc, "jsonl"), encoding="utf-8")
    table.write_text(_decode(log, bus_map, dbc, "csv"), encoding="utf-8")

    def same(got: list[Any], missing_is_nan: bool = False) -> None:
        for name, values in expected.items():
            want = [math.nan if v is None and missing_is_nan else v for v in values]
            assert [_bits(v) for v in got[columns.index(name)]] == [_bits(v) for v in want], name

    for frame in (pd.read_json(jsonl, lines=True, precise_float=True), pd.read_csv(table)):
        same([frame[name].tolist() for name in columns], missing_is_nan=True)
    floats = {name: pl.Float64 for name in columns}
    for polars_frame in (
        pl.read_ndjson(jsonl, infer_schema_length=None).cast(floats),  # type: ignore[arg-type]
        pl.read_csv(table, schema_overrides=floats),
    ):
        same([polars_frame[name].to_list() for name in columns])
    types = ", ".join(f"{name}: 'DOUBLE'" for name in columns)
    selected = ", ".join(f'"{name}"' for name in columns)
    for reader in (
        f"read_json('{jsonl}', columns={{{types}}})",
        f"read_csv('{table}', types={{{types}}})",
    ):
        with duckdb.connect() as connection:
            got = connection.sql(f"select {selected} from {reader}").fetchall()
        same([list(column) for column in zip(*got, strict=True)])


def _bits(value: float | None) -> Any:
    """A float's bits (every NaN one), None as itself."""
    if value is None:
        return None
    return "nan" if value != value else struct.pack("<d", value)
