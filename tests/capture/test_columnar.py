"""The columnar engine: schemas, exact values, every input form, and the fast paths taken."""

from __future__ import annotations

import gzip
import runpy
import subprocess
import sys
from datetime import datetime, timedelta, timezone
from pathlib import Path

import can
import pyarrow as pa
import pytest

from tests.capture.columnar_support import assert_same_tables, frames_left_to_per_frame, rows
from veronte4x import capture

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "capture.log"


@pytest.fixture(scope="module")
def flight(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """Twenty seconds of the example flight: Veronte, four ESCs, a GetNodeInfo exchange."""
    path = tmp_path_factory.mktemp("flight") / "flight.log"
    make = runpy.run_path(str(ROOT / "examples" / "make_capture.py"))
    make["generate"](1 / 3, 15.0, 4).write(path)
    return path


def test_schemas_are_fixed_by_the_layouts() -> None:
    tables = capture.read_tables(EXAMPLE)
    assert tables["Score"].schema == pa.schema(
        [
            ("timestamp", pa.timestamp("us", tz="UTC")),
            ("channel", pa.dictionary(pa.int32(), pa.string())),
            ("can_id", pa.uint32()),
            ("sender", pa.dictionary(pa.int16(), pa.string())),
            ("autopilot", pa.uint8()),
            ("autopilot_name", pa.dictionary(pa.uint8(), pa.string())),
            ("score", pa.float32()),
        ]
    )
    status = tables["Status"].schema
    assert status.names[4:9] == ["selected", "selected_name", "arbitrating", "alive_0", "alive_1"]
    names = tables["Status"].column("selected_name").combine_chunks().dictionary.to_pylist()
    assert names == ["AP1", "AP2", "AP3", "external AP"]  # as the exported DBC names them
    assert status.field("normal_mode").type == pa.bool_()


def test_exact_values_of_the_example() -> None:
    tables = capture.read_tables(EXAMPLE)
    ready = rows(tables["Ready"])[0]
    assert ready == {
        "timestamp": datetime(2025, 11, 21, 15, 0, 0, 10000, tzinfo=timezone.utc),
        "channel": "can0",
        "can_id": 8,
        "sender": "AP1",
        "ready": True,
    }
    variable = rows(tables["ArbitrationVariable"])[0]
    assert variable["number"] == 0
    assert variable["value"] == pytest.approx(0.12, rel=1e-7)  # float32 0x3DF5C28F
    statuses = rows(tables["Status"])
    assert statuses[0]["selected"] == 1 and statuses[0]["cbit_ok"] is True
    assert statuses[1]["cbit_ok"] is None  # the 4-byte CEX form has no flags


def test_dronecan_tables(flight: Path) -> None:
    tables = capture.read_tables(flight)
    esc = tables["EscStatus"]
    assert esc.schema.names[:5] == ["timestamp", "channel", "can_id", "sender", "node_id"]
    assert esc.schema.field("voltage").type == pa.float32()
    assert esc.schema.field("rpm").type == pa.int32()
    node = tables["NodeStatus"]
    assert node.schema.field("health").type == pa.dictionary(pa.uint8(), pa.string())
    assert set(node.column("health").to_pylist()) <= {"OK", "WARNING", "ERROR", "CRITICAL"}
    assert tables["RawCommand"].schema.field("cmd").type == pa.list_(pa.int16())
    info = tables["GetNodeInfoResponse"]
    assert "destination_node_id" in info.schema.names
    assert info.schema.field("name").type == pa.string()
    assert info.column("name").to_pylist()[0] == "iq_motion.esc"
    exact = capture.read_tables(flight, text="binary")["GetNodeInfoResponse"]
    assert exact.column("name").to_pylist()[0] == b"iq_motion.esc"


def test_flight_agrees_and_takes_the_fast_paths(
    flight: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    expected = capture.tables_from_records(capture.read(flight))
    taken = frames_left_to_per_frame(monkeypatch)
    assert_same_tables(capture.read_tables(flight), expected)
    assert taken == [0]  # every frame of a clean flight decoded column-wise


@pytest.mark.parametrize("stamped", [True, False])
def test_human_view_is_parsed_column_wise(
    flight: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch, stamped: bool
) -> None:
    human = tmp_path / "human.log"
    with human.open("w") as out:
        for message in can.CanutilsLogReader(str(flight)):
            ident = f"{message.arbitration_id:0{8 if message.is_extended_id else 3}X}"
            stamp = f"({message.timestamp:.6f})  " if stamped else "  "
            data = " ".join(f"{byte:02X}" for byte in message.data)
            out.write(f"{stamp}can0  {ident}   [{len(message.data)}]  {data}\n")
    expected = capture.tables_from_records(capture.read(human))
    taken = frames_left_to_per_frame(monkeypatch)
    assert_same_tables(capture.read_tables(human), expected)
    ready = expected["Ready"]
    assert ready.column("timestamp").null_count == (0 if stamped else ready.num_rows)
    assert taken == [0]


def test_gzip_list_and_channel(flight: Path, tmp_path: Path) -> None:
    packed = tmp_path / "flight.log.gz"
    packed.write_bytes(gzip.compress(flight.read_bytes()))
    expected = capture.tables_from_records(capture.read(flight))
    assert_same_tables(capture.read_tables(packed), expected)
    twice = capture.read_tables([flight, str(packed)])
    assert twice["Ready"].num_rows == 2 * expected["Ready"].num_rows
    assert capture.read_tables(flight, channel="can1") == {}


def test_standard_input(flight: Path) -> None:
    script = (
        "from veronte4x import capture; t = capture.read_tables('-'); "
        "print(sorted((k, v.num_rows) for k, v in t.items()))"
    )
    done = subprocess.run(
        [sys.executable, "-c", script],
        input=flight.read_bytes(),
        capture_output=True,
        check=True,
    )
    expected = capture.read_tables(flight)
    assert done.stdout.decode().strip() == str(sorted((k, v.num_rows) for k, v in expected.items()))


def test_lone_carriage_returns_are_line_breaks(tmp_path: Path) -> None:
    path = tmp_path / "mac.log"
    path.write_bytes(EXAMPLE.read_bytes().replace(b"\n", b"\r", 5))
    assert_same_tables(capture.read_tables(path), capture.tables_from_records(capture.read(path)))


@pytest.mark.parametrize("suffix", [".mf4", ".blf", ".asc"])
def test_python_can_formats(flight: Path, tmp_path: Path, suffix: str) -> None:
    path = tmp_path / f"flight{suffix}"
    with can.Logger(str(path)) as logger:
        for message in can.CanutilsLogReader(str(flight)):
            logger.on_message_received(message)
    expected = capture.tables_from_records(capture.read(path))
    assert_same_tables(capture.read_tables(path), expected)


def test_dataframe_from_a_path_has_every_row_in_order(flight: Path) -> None:
    import pandas

    frame = capture.to_dataframe(flight)
    records = list(capture.read(flight))
    assert len(frame) == len(records)
    assert list(frame["message"].head(50)) == [
        None if r.error or r.message is None else r.kind for r in records[:50]
    ]
    assert frame["timestamp"].tolist() == [
        pandas.Timestamp(round((r.timestamp or 0.0) * 1e6), unit="us", tz="UTC") for r in records
    ]


def test_missing_extra_names_it() -> None:
    script = (
        "import sys; sys.modules['pyarrow'] = None\n"
        "from veronte4x import capture\n"
        "try:\n    capture.read_tables('examples/capture.log')\n"
        "except ImportError as e:\n    print(e)\n"
    )
    done = subprocess.run(
        [sys.executable, "-c", script], capture_output=True, text=True, cwd=ROOT, check=True
    )
    assert done.stdout.strip() == (
        "decoding into Arrow tables needs the 'pyarrow' package: pip install 'veronte4x[arrow]'"
    )


def test_truncated_gzip_ends_as_the_per_frame_path_ends(flight: Path, tmp_path: Path) -> None:
    packed = gzip.compress(flight.read_bytes())
    cut = tmp_path / "cut.log.gz"
    cut.write_bytes(packed[: len(packed) // 2])
    expected = capture.tables_from_records(capture.read(cut))
    assert rows(expected["errors"])[-1]["error"] == "truncated"
    assert_same_tables(capture.read_tables(cut), expected)


def test_units_in_field_metadata_and_dataframe_attrs(flight: Path) -> None:
    esc = capture.read_tables(flight)["EscStatus"].schema
    assert esc.field("voltage").metadata == {b"unit": b"V"}
    assert esc.field("temperature").metadata == {b"unit": b"K"}
    assert esc.field("timestamp").metadata is None  # a timestamp; seconds carry "s"
    seconds = capture.read_tables(flight, time="seconds")["EscStatus"].schema
    assert seconds.field("timestamp").metadata == {b"unit": b"s"}
    assert esc.field("esc_index").metadata is None
    for frame in (capture.to_dataframe(flight), capture.to_dataframe(capture.read(flight))):
        units = frame.attrs["units"]
        assert units["voltage"] == "V" and units["rpm"] == "rpm" and "timestamp" not in units
        assert "selected" not in units


def test_relative_time(flight: Path) -> None:
    absolute = capture.read_tables(flight)
    relative = capture.read_tables(flight, time="relative")
    first = min(t.column("timestamp")[0].as_py() for t in absolute.values())
    for kind, table in absolute.items():
        expected = [
            (s - first) / timedelta(seconds=1) for s in table.column("timestamp").to_pylist()
        ]
        assert relative[kind].column("timestamp").to_pylist() == expected, kind
    assert min(t.column("timestamp")[0].as_py() for t in relative.values()) == 0.0
    frame = capture.to_dataframe(flight, time="relative")
    per_record = capture.to_dataframe(capture.read(flight), time="relative")
    assert frame["timestamp"].tolist() == per_record["timestamp"].tolist()
    assert frame["timestamp"].iloc[0] == 0.0


def test_importing_the_columnar_path_loads_neither_pandas_nor_matplotlib() -> None:
    """Issue 19, lean imports: an Arrow or Polars user never asked for pandas. (Building
    the first Arrow array is pyarrow's own business: it imports pandas when installed.)"""
    code = (
        "import sys\n"
        "from veronte4x import capture\n"
        "from veronte4x.capture.columnar import dataset, engine, fleet, stream, tables\n"
        "print(sorted(m for m in ('pandas', 'matplotlib') if m in sys.modules))\n"
    )
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "[]"
