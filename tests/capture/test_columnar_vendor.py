"""Vendor DroneCAN types in the columnar engine: decoded column-wise like the standard
ones, fields named as head columns renamed ``message.<name>`` in both paths, one table
and index per type set, and Parquet read back with DuckDB."""

from __future__ import annotations

import gc
import math
import weakref
from pathlib import Path
from typing import Any
from unittest import mock

import numpy as np
import pytest

from tests.capture.columnar_support import VENDOR_DSDL, VENDOR_TYPES, assert_same_tables, write
from veronte4x import capture, dronecan
from veronte4x.capture import BusMap
from veronte4x.capture.columnar import dronecan as dronecan_columns
from veronte4x.capture.columnar import engine
from veronte4x.capture.columnar.schema import dronecan_specs
from veronte4x.dronecan import TypeSet

ACME = VENDOR_DSDL[1]
OTHER = ACME.parent / "other"
"""A namespace whose ``Sample`` has ``acme.Sample``'s id and another layout."""


def _sample(types: TypeSet, **values: Any) -> Any:
    return dronecan.from_builtin(types["acme.Sample"], values, types)


def _lines(types: TypeSet) -> list[str]:
    """Vendor messages and services (single and multi-frame) beside a standard message."""
    status = dronecan.NodeStatus(7, dronecan.Health.OK, dronecan.Mode.OPERATIONAL, 0, 0)
    request: Any = dronecan.from_builtin(
        types["acme.probe.Probe.Request"],
        {
            "destination_node_id": 99,
            "sender": True,
            "readings": [{"channel": 1, "timestamp": -5}, {"channel": 2, "timestamp": 6}],
            "data": b"\x01\x02\x03",
        },
        types,
    )
    response: Any = dronecan.from_builtin(
        types["acme.probe.Probe.Response"],
        {"error": {"level": 0.5}, "detail": b"a long probe detail"},
        types,
    )
    lines = []
    stamp = 10.0
    for tid in range(3):
        sample = _sample(types, channel=tid, timestamp=1000 + tid, can_id=7, node_id=-3, value=1.5)
        for message, source, destination in (
            (sample, 42, None),
            (status, 42, None),
            (request, 42, 43),
            (response, 43, 42),
        ):
            frames = dronecan.encode(
                message,
                source_node_id=source,
                transfer_id=tid,
                destination_node_id=destination,
                types=types,
            )
            for f in frames:
                stamp += 0.001
                lines.append(f"({stamp:.6f}) can0 {f.can_id:08X}#{f.data.hex().upper()}")
    return lines


def test_fields_named_as_head_columns_become_message_columns(tmp_path: Path) -> None:
    path = write(tmp_path / "vendor.log", _lines(VENDOR_TYPES))
    bus_map = BusMap(dronecan_types=VENDOR_TYPES)
    expected = capture.tables_from_records(capture.read(path, bus_map), bus_map)
    got = capture.read_tables(path, bus_map)
    assert_same_tables(got, expected)
    sample = got["Sample"]
    assert sample.column_names == [
        "timestamp", "channel", "can_id", "sender", "node_id",
        "message.channel", "message.timestamp", "message.can_id", "message.node_id", "value",
    ]  # fmt: skip
    first = sample.to_pylist()[0]
    assert (first["channel"], first["can_id"] & 0x7F, first["node_id"]) == ("can0", 42, 42)
    assert (first["message.channel"], first["message.timestamp"]) == (0, 1000)
    assert (first["message.can_id"], first["message.node_id"], first["value"]) == (7, -3, 1.5)
    request = got["ProbeRequest"].to_pylist()[0]
    assert (request["destination_node_id"], request["message.destination_node_id"]) == (43, 99)
    assert request["message.sender"] is True and request["sender"] == "node 42"
    # Inside a list of structs, and where no head column has the name, names stay.
    assert request["readings"] == [{"channel": 1, "timestamp": -5}, {"channel": 2, "timestamp": 6}]
    assert request["data"] == b"\x01\x02\x03"
    response = got["ProbeResponse"].to_pylist()[0]
    assert (response["error.type"], response["error.level"]) == ("level", 0.5)
    assert response["detail"] == b"a long probe detail"
    assert [len(got[k]) for k in ("Sample", "NodeStatus", "ProbeRequest", "ProbeResponse")] == [
        3
    ] * 4


def test_vendor_transfers_are_decoded_column_wise(tmp_path: Path) -> None:
    """No vendor frame of a regular session goes to the per-frame decoder."""
    path = write(tmp_path / "vendor.log", _lines(VENDOR_TYPES))
    seen: list[int] = []
    original = engine.per_frame

    def spy(frames: Any, rows: Any, decoder: Any) -> Any:
        seen.extend(rows.tolist())
        return original(frames, rows, decoder)

    with mock.patch.object(engine, "per_frame", spy):
        tables = capture.read_tables(path, BusMap(dronecan_types=VENDOR_TYPES))
    assert seen == []
    assert "errors" not in tables and "unknown" not in tables
    # The standard set does not know them: they go frame by frame, as unknown records.
    with mock.patch.object(engine, "per_frame", spy):
        plain = capture.read_tables(path, types=TypeSet.standard())
    assert len(seen) == len(_lines(VENDOR_TYPES)) - 3
    assert set(plain) == {"NodeStatus", "unknown"}


def test_two_type_sets_keep_their_own_tables_and_indexes(tmp_path: Path) -> None:
    """Two sets with a different type on one id, used in turn in one process."""
    acme = TypeSet.standard().with_dsdl(ACME)
    other = TypeSet.standard().with_dsdl(OTHER)
    assert dronecan_columns.type_index_of(acme) is dronecan_columns.type_index_of(acme)
    assert dronecan_columns.type_index_of(acme) is not dronecan_columns.type_index_of(other)
    assert [c.name for c in dronecan_specs(other)["Sample"].columns] == ["level", "note"]
    path = write(tmp_path / "vendor.log", _lines(acme))
    for types in (acme, other, acme, None, other):
        bus_map = BusMap(dronecan_types=types)
        expected = capture.tables_from_records(capture.read(path, bus_map), bus_map)
        got = capture.read_tables(path, bus_map)
        assert_same_tables(got, expected)
        if types is acme:
            assert got["Sample"]["message.timestamp"].to_pylist() == [1000, 1001, 1002]
        elif types is other:  # acme's signature is not other's: CRC mismatches
            assert "Sample" not in got
            assert "CRC" in got["errors"]["detail"].to_pylist()[0]
        else:
            assert "Sample" not in got and "ProbeRequest" not in got
    other_lines = [
        f"(1.{i:06d}) can0 {f.can_id:08X}#{f.data.hex().upper()}"
        for i, f in enumerate(
            dronecan.encode(
                dronecan.from_builtin(other["other.Sample"], {"level": -9, "note": b"hi"}, other),
                source_node_id=5,
                transfer_id=1,
                types=other,
            )
        )
    ]
    path = write(tmp_path / "other.log", other_lines)
    got = capture.read_tables(path, BusMap(dronecan_types=other))
    assert got["Sample"].select(["level", "note"]).to_pylist() == [{"level": -9, "note": b"hi"}]


def test_type_index_numbers_the_set_standard_types_first() -> None:
    known = dronecan_columns.type_index_of(VENDOR_TYPES)
    assert known.codecs == VENDOR_TYPES.codecs
    standard = dronecan_columns.type_index_of(TypeSet.standard())
    assert known.codecs[: len(standard.codecs)] == standard.codecs
    sample = VENDOR_TYPES.by_class[VENDOR_TYPES["acme.Sample"]]
    frame, *_ = dronecan.encode(
        _sample(VENDOR_TYPES), source_node_id=3, transfer_id=0, types=VENDOR_TYPES
    )
    found = dronecan_columns.type_index(np.array([frame.can_id], np.uint32), known)
    assert known.codec_of(int(found[0])) is sample
    assert dronecan_columns.type_index(np.array([frame.can_id], np.uint32), standard)[0] == -1


def _duckdb_rows(out: Path, kind: str) -> list[dict[str, Any]]:
    duckdb = pytest.importorskip("duckdb")
    files = f"'{out}/capture=*/{kind}.parquet'"
    query = f"SELECT * EXCLUDE (source) FROM read_parquet({files}, hive_partitioning = false)"
    table = duckdb.connect().sql(query).to_arrow_table()
    return [{k: _plain(v) for k, v in row.items()} for row in table.to_pylist()]


def _plain(value: Any) -> Any:
    if isinstance(value, float) and math.isnan(value):
        return "NaN"
    if isinstance(value, list):
        return [_plain(v) for v in value]
    if isinstance(value, dict):
        return {k: _plain(v) for k, v in value.items()}
    return value


def test_to_parquet_read_back_with_duckdb_equals_read_tables(tmp_path: Path) -> None:
    path = write(tmp_path / "vendor.log", _lines(VENDOR_TYPES))
    out = tmp_path / "out"
    bus_map = BusMap(dronecan_types=VENDOR_TYPES)
    summary = capture.to_parquet(path, out, bus_map, progress=False)
    expected = capture.read_tables(path, bus_map)
    assert summary.records == {kind: len(table) for kind, table in expected.items()}
    for kind, table in expected.items():
        got = _duckdb_rows(out, kind)
        assert got == [{k: _plain(v) for k, v in row.items()} for row in table.to_pylist()], kind


def test_a_type_set_no_one_holds_is_freed(tmp_path: Path) -> None:
    """The engine's per-set caches (tables, indexes, session tables) do not keep a type set
    alive: a notebook that loads its DSDL again and again does not grow."""
    types = TypeSet.standard().with_dsdl(ACME)
    path = write(tmp_path / "vendor.log", _lines(types))
    bus_map = BusMap(dronecan_types=types)
    tables = capture.read_tables(path, bus_map)
    records = list(capture.read(path, bus_map))
    assert "Sample" in tables and records
    gone = weakref.ref(types)
    del types, bus_map, tables, records
    gc.collect()
    assert gone() is None
