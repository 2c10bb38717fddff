"""DroneCAN text fields in tables: strings by the DSDL's rule, bytes that are not UTF-8 a
null and a ``bad text`` row holding them, exact bytes with ``text="binary"``."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tests.capture.columnar_support import assert_same_tables, rows, texts, write
from veronte4x import capture, dronecan
from veronte4x.capture import BusMap
from veronte4x.capture.columnar import text
from veronte4x.capture.columnar.schema import dronecan_specs

pa = pytest.importorskip("pyarrow")


def _lines(messages: list[dronecan.LogMessage]) -> list[str]:
    out = []
    for number, message in enumerate(messages):
        for frame in dronecan.encode(message, source_node_id=10, transfer_id=number % 32):
            stamp = 1_700_000_000 + number / 100
            out.append(f"({stamp:.6f}) can0 {frame.can_id:08X}#{frame.data.hex().upper()}")
    return out


def _decoded(value: bytes) -> str | None:
    try:
        return value.decode("utf-8")
    except UnicodeDecodeError:
        return None


@settings(max_examples=60)
@given(st.lists(st.tuples(texts(31), texts(90)), min_size=1, max_size=12))
def test_log_text_is_strings_and_bad_bytes_are_error_rows(
    tmp_path_factory: pytest.TempPathFactory, fields: list[tuple[bytes, bytes]]
) -> None:
    messages = [dronecan.LogMessage(source=source, text=body) for source, body in fields]
    path = write(tmp_path_factory.mktemp("text") / "log.log", _lines(messages))
    got = capture.read_tables(path)
    assert_same_tables(got, capture.tables_from_records(capture.read(path)))
    table = got["LogMessage"]
    assert table.schema.field("text").type == pa.string()
    assert [(row["message.source"], row["text"]) for row in rows(table)] == [
        (_decoded(source), _decoded(body)) for source, body in fields
    ]
    bad = [
        (f"LogMessage.{name}", value)
        for source, body in fields
        for name, value in (("message.source", source), ("text", body))
        if _decoded(value) is None
    ]
    errors = rows(got["errors"]) if "errors" in got else []
    assert [(row["error"], row["detail"].split()[0], row["data"]) for row in errors] == [
        ("bad text", name, value) for name, value in bad
    ]
    exact = capture.read_tables(path, text="binary")
    assert "errors" not in exact
    assert exact["LogMessage"].select(["message.source", "text"]).to_pylist() == [
        {"message.source": source, "text": body} for source, body in fields
    ]


def test_a_log_source_and_the_dataset_source_are_two_columns(tmp_path: Path) -> None:
    """A dataset adds ``source`` (the capture's file) to every table: LogMessage's own
    ``source`` field is ``message.source``, so that the dataset opens."""
    pytest.importorskip("pyarrow.parquet")
    messages = [dronecan.LogMessage(source=b"EKF", text=b"aligned")]
    path = write(tmp_path / "flight.log", _lines(messages))
    capture.to_parquet(path, tmp_path / "out", progress=False)
    table = capture.open_dataset(tmp_path / "out", "LogMessage").to_table()
    assert table.select(["source", "message.source", "text"]).to_pylist() == [
        {"source": str(path), "message.source": "EKF", "text": "aligned"}
    ]


@settings(max_examples=200)
@given(st.lists(st.none() | texts(40)), st.booleans())
def test_strings_decode_as_python_does(values: list[bytes | None], arrow: bool) -> None:
    given_values = pa.array(values, pa.binary()) if arrow else values
    strings, bad = text.strings(given_values)
    assert strings.type == pa.string()
    assert strings.to_pylist() == [None if v is None else _decoded(v) for v in values]
    assert bad.tolist() == [v is not None and _decoded(v) is None for v in values]


def test_the_rule_types_the_standard_text_fields() -> None:
    strings = {
        (kind, column.name)
        for kind, spec in dronecan_specs().items()
        for column in spec.columns
        if column.type == pa.string()
    }
    assert {
        ("GetNodeInfoResponse", "name"),
        ("GetSetRequest", "name"),
        ("GetSetResponse", "value.string_value"),
        ("GetSetResponse", "default_value.string_value"),
        ("LogMessage", "message.source"),
        ("LogMessage", "text"),
        ("KeyValue", "key"),
        ("FileReadRequest", "path.path"),
        ("BatteryInfo", "model_name"),
        ("Panic", "reason_text"),
    } <= strings
    data = {("FileReadResponse", "data"), ("Allocation", "unique_id"), ("Broadcast", "buffer")}
    specs = dronecan_specs()
    assert all(specs[kind].schema.field(name).type == pa.binary() for kind, name in data)
    binary = dronecan_specs(text="binary")
    assert not [c for spec in binary.values() for c in spec.columns if c.type == pa.string()]


def test_a_wrong_text_form_is_refused_before_reading(tmp_path: Path) -> None:
    with pytest.raises(ValueError, match="text='strings': give 'string'"):
        capture.read_tables(tmp_path / "missing.log", text="strings")  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="text='bytes'"):
        BusMap(dronecan_text="bytes")  # type: ignore[arg-type]


def test_parquet_keeps_the_form_and_duckdb_reads_strings(tmp_path: Path) -> None:
    duckdb = pytest.importorskip("duckdb")
    pytest.importorskip("pyarrow.parquet")
    messages = [
        dronecan.LogMessage(source=b"gps", text="fix \u00e9".encode()),
        dronecan.LogMessage(source=b"imu", text=b"\xff\xfe"),
    ]
    path = write(tmp_path / "log.log", _lines(messages))
    forms = (("string", ["fix \u00e9", None]), ("binary", [m.text for m in messages]))
    for form, expected in forms:
        out = tmp_path / form
        summary = capture.to_parquet(path, out, progress=False, text=form)  # type: ignore[arg-type]
        assert summary.errors == (1 if form == "string" else 0)
        glob = f"{out}/capture=*/LogMessage.parquet"
        with duckdb.connect() as connection:
            kinds = connection.sql(f"DESCRIBE SELECT text FROM '{glob}'").fetchall()
            values = connection.sql(f"SELECT text FROM '{glob}'").fetchall()
        assert kinds[0][1] == ("VARCHAR" if form == "string" else "BLOB")
        assert [value for (value,) in values] == expected


def _convert(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "veronte4x", "convert", *args],
        capture_output=True,
        text=True,
        check=False,
    )


def test_convert_text_binary_on_the_command_line(tmp_path: Path) -> None:
    pq = pytest.importorskip("pyarrow.parquet")
    path = write(tmp_path / "log.log", _lines([dronecan.LogMessage(text=b"\xc3")]))
    for form, errors in (("string", "1 error"), ("binary", "0 errors")):
        out = tmp_path / form
        result = _convert(str(path), "--to", "parquet", str(out), "--text", form)
        assert result.returncode == 0, result.stderr
        assert f", {errors}, " in result.stderr
        (file,) = capture.dataset_files(out, "LogMessage")
        table = pq.read_table(file, columns=["text"])
        assert table.column("text").to_pylist() == [None if form == "string" else b"\xc3"]
    bus_map = tmp_path / "bus.toml"
    bus_map.write_text('[dronecan]\ntext = "binary"\n')
    for option, value in (((), b"\xc3"), (("--text", "string"), None)):  # the option wins
        out = tmp_path / f"map{len(option)}"
        result = _convert(
            str(path), "--to", "parquet", str(out), "--bus-map", str(bus_map), *option
        )
        assert result.returncode == 0, result.stderr
        (file,) = capture.dataset_files(out, "LogMessage")
        assert pq.read_table(file, columns=["text"]).column("text").to_pylist() == [value]
    result = _convert(str(path), "--to", "parquet", str(tmp_path / "x"), "--text", "utf8")
    assert result.returncode == 2
    assert "--text: invalid choice: 'utf8'" in result.stderr
