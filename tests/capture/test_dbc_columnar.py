"""DBC frames in the columnar engine: generated DBC files (multiplexed, signed, scaled,
float, value tables, both byte orders, 11- and 29-bit IDs) decode to the rows cantools gives
frame by frame, in `read_tables`, `tables_from_records(read(...))` and a Parquet dataset
read back with DuckDB."""

from __future__ import annotations

import math
import os
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import Any

import cantools
import duckdb
import pyarrow.parquet as pq
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.capture.columnar_support import (
    DECLARED,
    assert_same_tables,
    frames_left_to_per_frame,
    write,
)
from tests.capture.dbc_reference import cantools_fields
from tests.capture.test_dataset import read_back
from veronte4x import capture
from veronte4x.capture import BusMap
from veronte4x.capture.columnar import dataset
from veronte4x.errors import SourceError

BUS_MAP = BusMap(dronecan=False)
PAYLOAD_DBC = Path(__file__).with_name("data") / "payload.dbc"
SCALES = st.sampled_from([1, 2, 1.0, 0.5, 0.01, 0.1, -1])
OFFSETS = st.sampled_from([0, -5, 3, 1.5, -40.0])


@st.composite
def chunk(draw: st.DrawFn, cursor: int, end: int, name: str) -> tuple[dict[str, Any], int] | None:
    """One signal at bit ``cursor`` or after, before ``end``; with the cursor past it."""
    kind = draw(st.sampled_from(["little", "big", "float"]))
    if kind != "little":
        cursor = -(-cursor // 8) * 8  # to a byte
    room = end - cursor
    if room <= 0 or (kind == "float" and room < 32):
        return None
    signal: dict[str, Any] = {"name": name, "float": kind == "float", "choices": None}
    signal["signed"] = draw(st.booleans()) and kind != "float"
    signal["length"] = 32 if kind == "float" else draw(st.integers(1, min(room, 64)))
    signal["order"] = "0" if kind == "big" or (kind == "float" and draw(st.booleans())) else "1"
    signal["start"] = cursor + 7 if signal["order"] == "0" else cursor
    signal["scale"] = 1 if kind == "float" else draw(SCALES)
    signal["offset"] = 0 if kind == "float" else draw(OFFSETS)
    signal["unit"] = draw(st.sampled_from(["", "V", "degC", "km/h"]))
    if not signal["signed"] and kind != "float" and draw(st.booleans()):
        signal["choices"] = {0: "idle", 1: "run", 3: "fault"}
    used = signal["length"] if signal["order"] == "1" else -(-signal["length"] // 8) * 8
    signal["end"] = cursor + used
    return signal, cursor + used


@st.composite
def signals(draw: st.DrawFn, begin: int, prefix: str) -> list[dict[str, Any]]:
    out: list[dict[str, Any]] = []
    cursor = begin
    for index in range(draw(st.integers(1, 4))):
        got = draw(chunk(cursor, 64, f"{prefix}{index}"))
        if got is None:
            break
        signal, cursor = got
        out.append(signal)
    return out


@st.composite
def messages(draw: st.DrawFn, count: int) -> list[dict[str, Any]]:
    out = []
    ids = draw(
        st.lists(
            st.one_of(
                st.tuples(st.integers(0x100, 0x7FF), st.just(False)),
                st.tuples(st.integers(0x100, 0x1FFFFFFF), st.just(True)),
            ),
            min_size=count,
            max_size=count,
            unique=True,
        )
    )
    for number, (can_id, extended) in enumerate(ids):
        if can_id in (255, 8, 9, 10, 11):
            can_id += 0x300
        multiplexed = draw(st.booleans())
        if multiplexed:
            mux = {"name": "mux", "start": 0, "length": 8, "order": "1", "signed": False,
                   "scale": 1, "offset": 0, "unit": "", "choices": None, "float": False,
                   "mux": "M"}  # fmt: skip
            listed: list[dict[str, Any]] = [mux]
            for value in range(3):
                for signal in draw(signals(8, f"m{value}_")):
                    listed.append({**signal, "mux": f"m{value}"})
        else:
            listed = [{**s, "mux": ""} for s in draw(signals(0, "s"))]
        length = max(-(-s.get("end", 8) // 8) for s in listed)  # the bytes its signals need
        out.append(
            {"name": f"Msg{number}", "id": can_id, "extended": extended, "signals": listed,
             "length": length}
        )  # fmt: skip
    return out


def dbc_text(listed: list[dict[str, Any]]) -> str:
    lines = ['VERSION ""', "", "NS_ :", "", "BS_:", "", "BU_: X", ""]
    extra = []
    for message in listed:
        ident = message["id"] | (0x80000000 if message["extended"] else 0)
        lines.append(f"BO_ {ident} {message['name']}: {message['length']} X")
        for s in message["signals"]:
            mux = f" {s['mux']}" if s["mux"] else ""
            sign = "-" if s["signed"] else "+"
            lines.append(
                f" SG_ {s['name']}{mux} : {s['start']}|{s['length']}@{s['order']}{sign}"
                f' ({s["scale"]},{s["offset"]}) [0|0] "{s["unit"]}" X'
            )
            if s["choices"]:
                named = " ".join(f'{k} "{v}"' for k, v in s["choices"].items())
                extra.append(f"VAL_ {ident} {s['name']} {named} ;")
            if s["float"]:
                extra.append(f"SIG_VALTYPE_ {ident} {s['name']} : 1;")
        lines.append("")
    return "\n".join([*lines, *extra, ""])


def expected_rows(database: Any, frames: list[tuple[int, bool, bytes]]) -> dict[str, list[Any]]:
    """cantools' own decoding, frame by frame: rows of signals by message, or None for a
    frame it refuses."""
    out: dict[str, list[Any]] = {}
    for can_id, extended, data in frames:
        try:
            message = database.get_message_by_frame_id(can_id | (0x80000000 if extended else 0))
        except KeyError:
            continue
        try:
            values = cantools_fields(message, data)
        except Exception:
            continue
        out.setdefault(message.name, []).append(values)
    return out


def comparable(value: Any) -> Any:
    return "NaN" if isinstance(value, float) and math.isnan(value) else value


@st.composite
def captures(draw: st.DrawFn) -> tuple[str, list[tuple[int, bool, bytes]]]:
    listed = draw(messages(draw(st.integers(1, 3))))
    ids = [(m["id"], m["extended"]) for m in listed] + [(0x7AB, False), (0x1ABCDE, True)]
    frames = draw(
        st.lists(
            st.tuples(
                st.sampled_from(ids),
                st.one_of(st.binary(min_size=8, max_size=8), st.binary(max_size=8)),
            ),
            max_size=40,
        )
    )
    return dbc_text(listed), [(c, e, d) for (c, e), d in frames]


def lines_of(frames: list[tuple[int, bool, bytes]]) -> list[str]:
    out = [
        f"({1.0 + i / 100:.6f}) can{i % 2} {c:{'08X' if e else '03X'}}#{d.hex()}"
        for i, (c, e, d) in enumerate(frames)
    ]
    return [*out, "(9.000000) can0 0FF#00FF8177FFFF", "not a frame", "(9.5) can0 123#R"]


@settings(max_examples=120, suppress_health_check=[HealthCheck.too_slow])
@given(captures(), st.integers(30, 400))
def test_columnar_equals_per_frame_and_cantools(
    shape: tuple[str, list[tuple[int, bool, bytes]]], batch_bytes: int
) -> None:
    text, frames = shape
    with tempfile.TemporaryDirectory() as folder:
        dbc = Path(folder) / "generated.dbc"
        dbc.write_text(text)
        database: Any = cantools.database.load_file(str(dbc))
        path = write(Path(folder) / "capture.log", lines_of(frames))
        tables = capture.read_tables(path, BUS_MAP, dbc=[dbc])
        reference = capture.tables_from_records(capture.read(path, BUS_MAP, dbc=[dbc]))
        assert_same_tables(tables, reference)
        dataset.to_parquet(
            path, Path(folder) / "out", BusMap(dronecan=False, dbc=(str(dbc),)),
            progress=False, batch_bytes=batch_bytes,
        )  # fmt: skip
        assert_same_tables(read_back(Path(folder) / "out"), tables)
        records = list(capture.read(path, BUS_MAP, dbc=[dbc]))
    for name, rows in expected_rows(database, frames).items():
        table = tables[name]
        got = [{k: comparable(r[k]) for k in rows[0]} for r in table.to_pylist()]
        assert got == [{k: comparable(v) for k, v in row.items()} for row in rows]
        message = database.get_message_by_name(name)
        for signal in message.signals:
            field = table.schema.field(signal.name)
            unit = (field.metadata or {}).get(b"unit", b"").decode()
            assert unit == (signal.unit or "")
    refused = sum(1 for r in records if r.error == "decode error")
    assert len(tables["errors"]) == refused + 2  # + the bad line and the remote frame


def test_parquet_read_back_with_duckdb(tmp_path: Path) -> None:
    path = write(
        tmp_path / "x.log",
        [
            "(1.0) can0 123#E803F6FF01190000",
            "(1.1) can0 18FF1234#02ECFF00",
            "(1.2) can0 0FF#00FF8177FFFF",
            "(1.3) can0 123#E803",
            "(1.4) can0 456#00",
        ],
    )
    out = tmp_path / "data"
    done = subprocess.run(
        [sys.executable, "-m", "veronte4x", "convert", str(path), "--to", "parquet", str(out),
         "--dbc", str(PAYLOAD_DBC), "--bus-map", str(_no_dronecan(tmp_path))],
        capture_output=True, text=True, check=False,
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    (directory,) = out.iterdir()
    assert sorted(p.name for p in directory.iterdir()) == [
        "BmsStatus.parquet", "Gimbal.parquet", "Status.parquet", "errors.parquet",
        "unknown.parquet",
    ]  # fmt: skip
    bms = f"{out}/capture=*/BmsStatus.parquet"
    assert duckdb.connect().execute(
        f"SELECT voltage, current, state, state_name, temperature FROM read_parquet('{bms}')"
    ).fetchall() == [(10.0, -6.0, 1, "charging", 25)]
    gimbal = f"{out}/capture=*/Gimbal.parquet"
    assert duckdb.connect().execute(
        f"SELECT can_id, mode, pitch, yaw FROM read_parquet('{gimbal}')"
    ).fetchall() == [(0x18FF1234, 2, None, -0.2)]
    errors = f"{out}/capture=*/errors.parquet"
    query = f"SELECT error, detail FROM read_parquet('{errors}')"
    assert duckdb.connect().execute(query).fetchall() == [
        ("decode error", capture.read_tables(path, BUS_MAP, dbc=[PAYLOAD_DBC])["errors"]
         .column("detail")[0].as_py())
    ]  # fmt: skip
    file = directory / "BmsStatus.parquet"
    schema = pq.read_schema(file)
    units = {n: (schema.field(n).metadata or {}).get(b"unit") for n in schema.names}
    assert units["voltage"] == b"V" and units["current"] == b"A" and units["state"] is None


def _no_dronecan(folder: Path) -> Path:
    path = folder / "bus.toml"
    path.write_text("[dronecan]\nenabled = false\n")
    return path


def test_without_a_dbc_the_tables_are_as_before(tmp_path: Path) -> None:
    path = write(tmp_path / "x.log", ["(1.0) can0 123#E803F6FF01190000"])
    assert list(capture.read_tables(path, BUS_MAP)) == ["unknown"]
    assert "BmsStatus" in capture.read_tables(path, BusMap(dronecan=False, dbc=(str(PAYLOAD_DBC),)))


def test_a_bad_dbc_fails_before_decoding(tmp_path: Path) -> None:
    path = write(tmp_path / "x.log", ["(1.0) can0 7FF#00"])
    with pytest.raises(SourceError, match=r"missing\.dbc: No such file or directory"):
        capture.read_tables(path, dbc=[tmp_path / "missing.dbc"])
    with pytest.raises(SourceError, match=r"missing\.dbc: No such file or directory"):
        capture.to_parquet(path, tmp_path / "out", dbc=[tmp_path / "missing.dbc"])
    assert not (tmp_path / "out").exists()


def test_64_bit_signals_keep_every_value(tmp_path: Path) -> None:
    """Integer signals past int64 (a 64-bit unsigned one, one scaled by 1000) get uint64
    and decimal columns, exact in the tables and read back with DuckDB."""
    dbc = tmp_path / "wide.dbc"
    dbc.write_text(
        'VERSION ""\nNS_ :\nBS_:\nBU_: X\n'
        'BO_ 256 Counter: 8 X\n SG_ count : 0|64@1+ (1,0) [0|0] "" X\n'
        'BO_ 257 Signed: 8 X\n SG_ delta : 0|64@1- (1,0) [0|0] "" X\n'
        'BO_ 258 Energy: 8 X\n SG_ energy : 0|64@1+ (1000,0) [0|0] "mJ" X\n'
    )
    top = "(1.0) can0 {:03X}#FFFFFFFFFFFFFFFF"
    path = write(tmp_path / "x.log", [top.format(256), top.format(257), top.format(258),
                                      "(2.0) can0 100#0000000000000080"])  # fmt: skip
    tables = capture.read_tables(path, BUS_MAP, dbc=[dbc])
    assert tables["Counter"].column("count").to_pylist() == [(1 << 64) - 1, 1 << 63]
    assert tables["Counter"].schema.field("count").type == "uint64"
    assert tables["Signed"].column("delta").to_pylist() == [-1]
    assert tables["Signed"].schema.field("delta").type == "int64"
    assert tables["Energy"].column("energy").to_pylist() == [((1 << 64) - 1) * 1000]
    assert str(tables["Energy"].schema.field("energy").type) == "decimal128(38, 0)"
    assert_same_tables(tables, capture.tables_from_records(capture.read(path, BUS_MAP, dbc=[dbc])))
    capture.to_parquet(path, tmp_path / "out", BusMap(dronecan=False, dbc=(str(dbc),)))
    counter = f"{tmp_path / 'out'}/capture=*/Counter.parquet"
    assert duckdb.connect().execute(f"SELECT count FROM read_parquet('{counter}')").fetchall() == [
        ((1 << 64) - 1,),
        (1 << 63,),
    ]


def test_a_signal_no_column_holds_is_refused(tmp_path: Path) -> None:
    dbc = tmp_path / "huge.dbc"
    scale = 10**70
    dbc.write_text(
        f'VERSION ""\nNS_ :\nBS_:\nBU_: X\nBO_ 256 Huge: 8 X\n'
        f' SG_ x : 0|64@1+ ({scale},0) [0|0] "" X\n'
    )
    path = write(tmp_path / "x.log", ["(1.0) can0 100#0000000000000001"])
    with pytest.raises(SourceError) as error:
        capture.read_tables(path, BUS_MAP, dbc=[dbc])
    assert str(error.value) == (
        f"{dbc}: signal x of Huge: its values have more than 76 digits, more than a table "
        "column holds"
    )


def test_names_that_veronte4x_takes_get_an_underscore(tmp_path: Path) -> None:
    dbc = tmp_path / "clash.dbc"
    dbc.write_text(
        'VERSION ""\nNS_ :\nBS_:\nBU_: X\nBO_ 1792 Status: 2 X\n'
        ' SG_ timestamp : 0|8@1+ (1,0) [0|255] "s" X\n SG_ class : 8|8@1+ (1,0) [0|255] "" X\n'
    )
    path = write(tmp_path / "x.log", ["(1.0) can0 700#0102", "(1.1) can0 0FF#00FF8177FFFF"])
    tables = capture.read_tables(path, dbc=[dbc])
    assert tables["Status_"].select(["timestamp_", "class_"]).to_pylist() == [
        {"timestamp_": 1, "class_": 2}
    ]
    assert len(tables["Status"]) == 1
    assert_same_tables(tables, capture.tables_from_records(capture.read(path, dbc=[dbc])))


def test_a_dbc_message_named_as_a_declared_layout_is_refused(tmp_path: Path) -> None:
    dbc = tmp_path / "clash.dbc"
    dbc.write_text(
        'VERSION ""\nNS_ :\nBS_:\nBU_: X\nBO_ 1792 ScorpionTelemetry: 1 X\n'
        ' SG_ a : 0|8@1+ (1,0) [0|255] "" X\n'
    )
    path = write(tmp_path / "x.log", ["(1.0) can0 700#01"])
    bus_map = BusMap(layouts=(DECLARED,))
    with pytest.raises(SourceError, match="both named ScorpionTelemetry: rename one"):
        capture.read_tables(path, bus_map, dbc=[dbc])


@pytest.mark.parametrize("source", ["file", "stdin"])
def test_dbc_frames_take_the_column_wise_path(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, source: str
) -> None:
    """A mutation survivor: the DBC pass skipped, its frames decoded one by one instead.

    A file is decoded batch by batch, standard input whole: each path has its DBC pass.
    """
    dbc = tmp_path / "one.dbc"
    dbc.write_text(
        'VERSION ""\nNS_ :\nBS_:\nBU_: X\nBO_ 1792 Pack: 2 X\n'
        ' SG_ volts : 0|16@1+ (0.01,0) [0|655.35] "V" X\n'
    )
    lines = [f"({i / 10:.6f}) can0 700#{i:02X}05" for i in range(20)]
    path = write(tmp_path / "x.log", lines)
    expected = capture.tables_from_records(capture.read(path, BUS_MAP, dbc=[dbc]))
    if source == "stdin":
        read, written = os.pipe()
        with open(written, "wb") as pipe:  # 20 lines: less than a pipe holds
            pipe.write(path.read_bytes())
        monkeypatch.setattr(sys, "stdin", open(read, encoding="utf-8"))  # noqa: SIM115
    taken = frames_left_to_per_frame(monkeypatch)
    tables = capture.read_tables(path if source == "file" else "-", BUS_MAP, dbc=[dbc])
    if source == "stdin":
        sys.stdin.close()
    assert_same_tables(tables, expected)
    assert tables["Pack"].column("volts").to_pylist()[:2] == [12.8, 12.81]
    assert taken and sum(taken) == 0
