"""Parquet datasets: read back, they equal `read_tables`, whatever the batches; files are
whole or absent; a second run replaces the first."""

from __future__ import annotations

import gzip
import os
import shutil
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from typing import Any

import numpy as np
import pyarrow as pa
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.capture.columnar_support import BUS_MAPS, assert_same_tables, captures, write
from tests.capture.test_stream import _interleaved_flight
from veronte4x import capture
from veronte4x.capture import BusMap, datasets
from veronte4x.capture.columnar import dataset
from veronte4x.capture.columnar.batches import read_batches
from veronte4x.capture.columnar.frames import concat
from veronte4x.capture.columnar.sources import read_frames
from veronte4x.capture.datasets import capture_directory
from veronte4x.capture.frames import BadLine, Frame, Truncation
from veronte4x.errors import NotACaptureError

FLIGHT = Path(__file__).parents[2] / "examples" / "capture.log"


def read_back(out: Path, source: str | None = None) -> dict[str, pa.Table]:
    """Every table of a dataset (one capture's rows if ``source``), read with
    `capture.open_dataset`; ``source`` and ``capture`` dropped."""
    tables = {}
    for kind in capture.dataset_tables(out):
        table = capture.open_dataset(out, kind).to_table()
        if source is not None:
            table = table.filter(pa.compute.equal(table["source"].cast(pa.string()), source))
        if len(table):
            tables[kind] = table.drop_columns(["source", "capture"]).unify_dictionaries()
    return tables


@settings(max_examples=40, suppress_health_check=[HealthCheck.too_slow])
@given(st.data(), BUS_MAPS, st.sampled_from([None, "can0"]), st.integers(1, 400))
def test_dataset_equals_read_tables(
    data: st.DataObject, bus_map: BusMap, channel: str | None, batch_bytes: int
) -> None:
    lines = data.draw(captures(bus_map))
    with tempfile.TemporaryDirectory() as folder:
        path = write(Path(folder) / "capture.log", lines)
        out = Path(folder) / "out"
        items = list(capture.open_frames(path))
        bad = any(isinstance(i, BadLine) and not isinstance(i, Truncation) for i in items)
        if bad and not any(isinstance(i, Frame) for i in items):  # refused, as convert does
            with pytest.raises(NotACaptureError):
                dataset.to_parquet(path, out, bus_map, channel=channel, progress=False)
            return
        summary = dataset.to_parquet(
            path, out, bus_map, channel=channel, progress=False, batch_bytes=batch_bytes
        )
        expected = capture.read_tables(path, bus_map, channel)
        got = read_back(out)
    assert_same_tables(got, expected)
    assert summary.records == {kind: len(table) for kind, table in expected.items()}


def test_batches_join_to_the_whole_file(tmp_path: Path) -> None:
    text = "".join(line + "\n" for line in _interleaved_flight())
    odd = text.replace("\n", "\r", 3).encode() + b"(1.0) can0 123#R\r\n(2.0) can0 1"
    cases = {"plain.log": text.encode(), "odd.log": odd}
    for name, content in cases.items():
        (tmp_path / name).write_bytes(content)
        (tmp_path / f"{name}.gz").write_bytes(gzip.compress(content))
    truncated = gzip.compress(text.encode())
    (tmp_path / "cut.log.gz").write_bytes(truncated[: len(truncated) // 2])
    for path in sorted(tmp_path.iterdir()):
        whole = read_frames(path)
        for size in (1, 100, 1 << 20):
            joined = concat([b.frames for b in read_batches(path, size, 7)])
            assert len(joined) == len(whole), path
            for name in ("order", "timestamp", "can_id", "length", "data"):
                got, expected = getattr(joined, name), getattr(whole, name)
                assert np.array_equal(got, expected, equal_nan=name == "timestamp"), path
            assert joined.bad_lines == whole.bad_lines, path


def test_several_captures_and_a_second_run(tmp_path: Path) -> None:
    flight = write(tmp_path / "flight.log", _interleaved_flight())
    paths = [FLIGHT, flight]
    out = tmp_path / "data"
    first = dataset.to_parquet(paths, out, progress=False, batch_bytes=300)
    second = capture.to_parquet(paths, out, progress=False)
    assert first.records == second.records
    assert first.files == second.files == 2
    for path in paths:
        assert_same_tables(read_back(out, str(path)), capture.read_tables(path))
    assert {p.name for p in out.iterdir()} == {capture_directory(str(p)) for p in paths}


def test_an_interrupted_run_leaves_nothing(tmp_path: Path) -> None:
    out = tmp_path / "data"
    stop = KeyboardInterrupt()

    def interrupt(position: int) -> None:
        raise stop

    with pytest.raises(KeyboardInterrupt):
        dataset.convert_file(FLIGHT, out, batch_bytes=200, progress=interrupt)
    assert list(out.iterdir()) == []


def test_what_runs_killed_outright_left_is_removed_by_the_next(tmp_path: Path) -> None:
    """Their hidden directories: those of runs of this machine no longer running are
    removed; a live run's and another machine's stay; a capture a killed run moved aside
    (and did not replace) is put back."""
    out = tmp_path / "data"
    dead = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"],
                          capture_output=True, text=True, check=True).stdout.strip()  # fmt: skip
    name = capture_directory("other.log")
    stale = [
        out / f".{name}.{dataset.HOST}-{dead}-0a1b2c3d",
        out / f".{capture_directory('third.log')}.{dataset.HOST}-{dead}-0a1b2c3d",
    ]
    alive = [
        out / f".{name}.{dataset.HOST}-{os.getpid()}-0a1b2c3d",  # a run still going
        out / f".{name}.0badcafe-{dead}-0a1b2c3d",  # another machine's
        out / f".{name}",  # not named as a run's: not the conversion's to remove
    ]
    for path in [*stale, *alive]:
        (path / "new").mkdir(parents=True)
        (path / "new" / "Status.parquet").write_bytes(b"PAR1 half")
    shutil.copytree(dataset_of(FLIGHT, tmp_path / "before"), stale[1] / "old")
    capture.to_parquet(FLIGHT, out, progress=False)
    assert [p for p in [*stale, *alive] if p.exists()] == alive
    put_back = out / capture_directory("third.log")
    published = out / capture_directory(str(FLIGHT))
    assert sorted(p.name for p in put_back.iterdir()) == sorted(p.name for p in published.iterdir())
    for path in [*alive, put_back]:
        shutil.rmtree(path)
    assert_same_tables(read_back(out, str(FLIGHT)), capture.read_tables(FLIGHT))


def dataset_of(path: Path, out: Path) -> Path:
    """A capture converted alone: its directory."""
    capture.to_parquet(path, out, progress=False)
    (directory,) = out.iterdir()
    return directory


@pytest.mark.parametrize("name", [".hidden.log", "_under.log", "..log", "_"])
def test_captures_named_as_readers_skip_are_still_read(tmp_path: Path, name: str) -> None:
    path = tmp_path / name
    path.write_bytes(FLIGHT.read_bytes())
    capture.to_parquet(path, tmp_path / "data", progress=False)
    names = [p.name for p in (tmp_path / "data").rglob("*")]  # directories and files
    assert names and not [n for n in names if n.startswith((".", "_"))]
    assert_same_tables(read_back(tmp_path / "data"), capture.read_tables(path))


def test_two_conversions_of_one_capture_at_once_both_succeed(tmp_path: Path) -> None:
    out = tmp_path / "data"
    with ThreadPoolExecutor(2) as pool:
        runs = [pool.submit(dataset.convert_file, FLIGHT, out, None, None, 200) for _ in range(4)]
        summaries = [run.result() for run in runs]
    assert all(s.records == summaries[0].records for s in summaries)
    assert [p.name for p in out.iterdir()] == [capture_directory(str(FLIGHT))]
    assert_same_tables(read_back(out), capture.read_tables(FLIGHT))


def test_two_conversions_at_once_without_an_exchanging_rename(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Where the system cannot exchange two directories, each run moves the capture's
    directory aside before it puts its own in place: runs at once take turns."""
    monkeypatch.setattr(dataset, "_renameat2_call", None)
    test_two_conversions_of_one_capture_at_once_both_succeed(tmp_path)


def test_a_second_run_removes_tables_the_capture_no_longer_has(tmp_path: Path) -> None:
    out = tmp_path / "data"
    capture.to_parquet(FLIGHT, out, progress=False)
    capture.to_parquet(FLIGHT, out, progress=False, channel="no-such-bus")
    assert [list(p.iterdir()) for p in out.iterdir()] == [[]]  # the capture, with no table


def test_progress_bar_on_request(tmp_path: Path, capsys: Any) -> None:
    capture.to_parquet(FLIGHT, tmp_path / "data", progress=True)
    assert "converting" in capsys.readouterr().err
    capture.to_parquet(FLIGHT, tmp_path / "data", progress=False)
    assert capsys.readouterr().err == ""


def test_standard_input_and_missing_files_are_refused(tmp_path: Path) -> None:
    with pytest.raises(ValueError, match="not -"):
        capture.to_parquet("-", tmp_path)
    with pytest.raises(FileNotFoundError, match=r"nothing\.log"):
        capture.to_parquet([FLIGHT, tmp_path / "nothing.log"], tmp_path)


@pytest.mark.parametrize("suffix", [".asc", ".blf", ".mf4"])
def test_python_can_formats_in_batches(tmp_path: Path, suffix: str) -> None:
    import can

    whole = read_frames(FLIGHT)
    path = tmp_path / f"capture{suffix}"
    with can.Logger(str(path)) as logger:
        for row in range(len(whole)):
            frame = whole.frame(row)
            logger(
                can.Message(
                    timestamp=frame.timestamp or 0.0,
                    arbitration_id=frame.can_id,
                    is_extended_id=frame.extended,
                    data=frame.data,
                    channel=0,
                )
            )
    expected = read_frames(path)
    joined = concat([b.frames for b in read_batches(path, batch_frames=5)])
    assert joined.order.tolist() == expected.order.tolist()
    assert joined.data.tolist() == expected.data.tolist()
    out = tmp_path / "data"
    dataset.to_parquet(path, out, progress=False)
    assert_same_tables(read_back(out), capture.read_tables(path))


def test_a_full_uint8_enum_dictionary_joins_across_batches_and_files(tmp_path: Path) -> None:
    """ExecuteOpcode's opcode has 256 names: pyarrow's unify_dictionaries refuses to join
    them (an index type it thinks too small), so batches and files are joined otherwise."""
    from veronte4x import dronecan

    lines = []
    for tid in range(40):
        request = dronecan.ExecuteOpcodeRequest(opcode=tid % 3, argument=tid)
        frame = dronecan.encode(
            request, source_node_id=10, transfer_id=tid % 32, destination_node_id=20
        )[0]
        lines.append(f"({1700000000 + tid}.000000) can0 {frame.can_id:08X}#{frame.data.hex()}")
    path = write(tmp_path / "opcodes.log", lines)
    expected = capture.tables_from_records(capture.read(path))
    dataset.convert_file(path, tmp_path / "data", batch_bytes=100)
    assert_same_tables(read_back(tmp_path / "data"), expected)
    both = capture.read_tables([path, path])
    assert both["ExecuteOpcodeRequest"].num_rows == 80


def test_a_table_named_as_readers_skip_is_written_under_another_name(tmp_path: Path) -> None:
    """A DBC message ``_Private``: its file is ``table-_Private.parquet``, found again by
    its table's name."""
    dbc = (Path(__file__).with_name("data") / "payload.dbc").read_text()
    path = tmp_path / "private.dbc"
    path.write_text(dbc.replace("BO_ 291 BmsStatus:", "BO_ 291 _Private:"))
    log = write(tmp_path / "bms.log", ["(1.0) can0 123#E803F6FF01190000"])
    out = tmp_path / "data"
    capture.to_parquet(log, out, BusMap(dronecan=False), progress=False, dbc=[path])
    (directory,) = out.iterdir()
    assert "table-_Private.parquet" in {p.name for p in directory.iterdir()}
    assert capture.dataset_tables(out) == ["_Private"]
    assert capture.open_dataset(out, "_Private").to_table()["voltage"].to_pylist() == [10.0]


@given(st.from_regex(r"[A-Za-z_][A-Za-z0-9_]{0,20}", fullmatch=True))
def test_table_files_name_their_table_and_never_start_as_readers_skip(table: str) -> None:
    """Tables are named as identifiers (messages, DroneCAN types, DBC messages)."""
    name = datasets.table_file(table)
    assert not name.startswith((".", "_"))
    assert datasets._table_of(name) == table
