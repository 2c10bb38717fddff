"""Vendor DSDL namespaces at run time: `TypeSet`, `load_dsdl` and ``--dsdl``.

The vendor namespace is ``examples/dsdl/com`` (``com.example``, the docs' example): a message with
a nested type, a nested union, static and dynamic arrays (the last one with the tail array
optimisation), a nested standard type, enum constants and void padding, and a service.
The ``dronecan`` package, loaded with the same directory, is the reference for the
signatures, the frames and the values.
"""

from __future__ import annotations

import os
import pickle
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from dronecan_oracle import reference_builtin, reference_decode, reference_frames
from hypothesis import given, settings
from hypothesis import strategies as st
from test_dronecan_differential import schema_strategy
from tests.dsdl_support import write_namespace
from tests.plain_data import same

import dronecan as dc
from veronte4x import capture
from veronte4x import dronecan as v4
from veronte4x.dronecan import DsdlError, TypeSet

K = v4.TransferKind
VENDOR = Path(__file__).resolve().parents[2] / "examples" / "dsdl" / "com"
TYPES = TypeSet.standard().with_dsdl(VENDOR)
KEYS = {
    ("com.example.motor.Telemetry", K.MESSAGE): "com.example.motor.Telemetry",
    ("com.example.SetGain", K.REQUEST): "com.example.SetGain.Request",
    ("com.example.SetGain", K.RESPONSE): "com.example.SetGain.Response",
}


@pytest.fixture(scope="module")
def reference() -> Iterator[None]:
    """The ``dronecan`` package with the vendor namespace loaded beside its own."""
    dc.load_dsdl(str(VENDOR))
    yield
    dc.load_dsdl()


@pytest.fixture
def default_types() -> Iterator[None]:
    """Whatever a test loads into the default set is gone after it."""
    yield
    v4.set_default_types(TypeSet.standard())


def _telemetry(types: TypeSet = TYPES) -> Any:
    return v4.from_builtin(
        types["com.example.motor.Telemetry"],
        {
            "timestamp": {"usec": 1234567},
            "state": 2,
            "motor_index": 7,
            "reading": {"label": "rpm"},
            "name": "front left",
            "phase_current": [1, -2, 2047, -2048],
            "cells": [{"voltage": 3.5, "index": 1, "ok": True}, {"voltage": 4.0, "index": 2}],
        },
        types,
    )


def _candump(path: Path, frames: list[tuple[int, bytes]]) -> None:
    path.write_text(
        "".join(
            f"({i / 1000:.6f}) can0 {can_id:08X}#{data.hex().upper()}\n"
            for i, (can_id, data) in enumerate(frames)
        )
    )


# -- the types and their signatures ------------------------------------------------------


@pytest.mark.usefixtures("reference")
@pytest.mark.parametrize("key", list(KEYS), ids=[f"{n}-{k.name}" for n, k in KEYS])
def test_signature_and_id_equal_the_dronecan_package(key: tuple[str, v4.TransferKind]) -> None:
    name, kind = key
    codec = TYPES.by_class[TYPES[KEYS[key]]]
    theirs = dc.TYPENAMES[name]
    assert codec.data_type.signature == theirs.get_data_type_signature()
    assert codec.data_type.data_type_id == theirs.default_dtid
    assert codec.data_type.kind is kind
    assert codec.data_type.path.endswith(".uavcan")


def test_generated_classes_names_enums_and_union_members() -> None:
    telemetry = _telemetry()
    assert type(telemetry).__name__ == "Telemetry"
    assert telemetry.state is telemetry.state.__class__.FAULT  # STATE_* became an enum
    assert type(telemetry.state).__name__ == "TelemetryState"  # State is taken by the standard
    assert type(telemetry.reading).__name__ == "ReadingLabel"
    assert type(telemetry.timestamp) is v4.standard.Timestamp  # a standard nested type
    assert telemetry.cells[1].ok is False
    html = telemetry._repr_html_()  # veronte4x.display.HtmlDisplay, as the standard classes
    assert "<td>name</td><td>front left</td>" in html
    assert "<td>state</td><td>FAULT</td>" in html
    assert TYPES["com.example.SetGain.Request"].__name__ == "SetGainRequest"
    assert "com.example.motor.Telemetry" in TYPES
    assert "com.example.motor.Telemetry" not in TypeSet.standard()
    assert repr(TYPES).startswith("TypeSet(85 types, ")


def test_text_fields_follow_the_dsdl() -> None:
    from veronte4x.capture.readable import readable_fields

    standard = TypeSet.standard().text_fields
    standard_text = {(cls.__name__, attr) for cls, attrs in standard.items() for attr in attrs}
    vendor = {cls.__name__: a for cls, a in TYPES.text_fields.items() if cls not in standard}
    assert vendor == {
        "Telemetry": {"name"},
        "ReadingLabel": {"value"},
        "SetGainResponse": {"message"},
    }
    assert readable_fields(_telemetry())["name"] == "front left"
    assert readable_fields(_telemetry())["reading.value"] == "rpm"
    assert {
        ("GetNodeInfoResponse", "name"),
        ("GetSetRequest", "name"),
        ("GetSetResponse", "name"),
        ("StringValue", "value"),
        ("Path", "path"),
        ("BeginFirmwareUpdateResponse", "optional_error_message"),
        ("LogMessage", "text"),
        ("LogMessage", "source"),
        ("BatteryInfo", "model_name"),
    } <= standard_text
    assert not {("FileReadResponse", "data"), ("HardwareVersion", "unique_id")} & standard_text


def test_generated_source_is_in_linecache() -> None:
    import inspect

    source = inspect.getsource(TYPES["com.example.motor.Telemetry"])
    assert source.startswith("@frozen_dataclass\nclass Telemetry(HtmlDisplay):")
    assert "message 20990" in source


# -- both ways against the dronecan package ------------------------------------------------


@pytest.mark.usefixtures("reference")
@pytest.mark.parametrize("key", list(KEYS), ids=[f"{n}-{k.name}" for n, k in KEYS])
@settings(max_examples=60)
@given(data=st.data())
def test_frames_identical_and_cross_decoded(
    key: tuple[str, v4.TransferKind], data: st.DataObject
) -> None:
    name, kind = key
    codec = TYPES.by_class[TYPES[KEYS[key]]]
    fields = data.draw(schema_strategy(codec.data_type.schema), label="fields")
    source = data.draw(st.integers(1, 127), label="source")
    destination = None if kind is K.MESSAGE else data.draw(st.integers(1, 127), label="dst")
    transfer_id = data.draw(st.integers(0, 31), label="transfer_id")

    message: Any = v4.from_builtin(TYPES[KEYS[key]], fields, TYPES)
    ours = [
        (f.can_id, f.data)
        for f in v4.encode(
            message,
            source_node_id=source,
            destination_node_id=destination,
            transfer_id=transfer_id,
            types=TYPES,
        )
    ]
    reference_object = _reference_object(name, kind, fields)
    theirs = reference_frames(reference_object, source, destination, transfer_id, 16, kind)
    assert ours == theirs

    transfer = v4.decode_frames(theirs, 0.0, TYPES)
    assert same(v4.to_builtin(transfer.message, TYPES), reference_builtin(reference_decode(ours)))
    reassembler = v4.Reassembler(types=TYPES)
    fed = [reassembler.feed(can_id, d, 0.0) for can_id, d in theirs]
    assert fed[-1] is not None
    assert same(v4.to_builtin(fed[-1].message, TYPES), v4.to_builtin(transfer.message, TYPES))


def _reference_object(name: str, kind: v4.TransferKind, fields: dict[str, Any]) -> Any:
    from dronecan_oracle import reference_object

    return reference_object(name, kind, fields)


# -- two sets side by side, and the default set ----------------------------------------------


def test_two_sets_coexist_and_the_standard_one_does_not_know_the_vendor_types() -> None:
    frames = [
        (f.can_id, f.data)
        for f in v4.encode(_telemetry(), source_node_id=5, transfer_id=1, types=TYPES)
    ]
    with pytest.raises(v4.DecodeError, match="no message type with id 20990"):
        v4.decode_frames(frames, 0.0, TypeSet.standard())
    plain = v4.Reassembler(types=TypeSet.standard())
    assert [plain.feed(c, d, 0.0) for c, d in frames] == [None] * len(frames)
    assert plain.counts[v4.Problem.UNKNOWN_TYPE] == len(frames)  # counted per frame
    assert v4.decode_frames(frames, 0.0, TYPES).message == _telemetry()
    with pytest.raises(TypeError, match="a DroneCAN message"):
        v4.encode(_telemetry(), source_node_id=5, transfer_id=1, types=TypeSet.standard())
    other = TypeSet.standard().with_dsdl(VENDOR)  # loaded again: other classes, same wire
    assert other["com.example.motor.Telemetry"] is not TYPES["com.example.motor.Telemetry"]
    assert v4.decode_frames(frames, 0.0, other).message == _telemetry(other)
    assert TYPES.with_dsdl(VENDOR) is TYPES  # a directory already in the set is skipped


@pytest.mark.usefixtures("default_types")
def test_load_dsdl_extends_the_default_set() -> None:
    frames = [
        (f.can_id, f.data)
        for f in v4.encode(_telemetry(), source_node_id=5, transfer_id=1, types=TYPES)
    ]
    with pytest.raises(v4.DecodeError):
        v4.decode_frames(frames)
    loaded = v4.load_dsdl(VENDOR)
    assert v4.default_types() is loaded
    assert v4.load_dsdl(VENDOR) is loaded
    message = v4.decode_frames(frames).message
    assert type(message) is loaded["com.example.motor.Telemetry"]
    assert v4.to_builtin(message)["name"] == list(b"front left")
    again = v4.encode(message, source_node_id=5, transfer_id=1)
    assert [(f.can_id, f.data) for f in again] == frames
    assert v4.Reassembler().types is loaded


def test_a_set_pickles_by_its_directories() -> None:
    again = pickle.loads(pickle.dumps(TYPES))
    assert again.roots == TYPES.roots
    frames = [
        (f.can_id, f.data)
        for f in v4.encode(_telemetry(), source_node_id=5, transfer_id=1, types=TYPES)
    ]
    assert v4.to_builtin(v4.decode_frames(frames, 0.0, again).message, again) == v4.to_builtin(
        _telemetry(), TYPES
    )


def test_wrong_types_argument_is_a_type_error() -> None:
    with pytest.raises(TypeError, match="types"):
        v4.Reassembler(types="com")  # type: ignore[arg-type]
    with pytest.raises(TypeError, match="types"):
        v4.from_builtin(v4.NodeStatus, {}, types=[VENDOR])  # type: ignore[arg-type]


# -- errors in definitions ---------------------------------------------------------------


def _namespace(root: Path, files: dict[str, str]) -> Path:
    for name, text in files.items():
        path = root / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    return root


def test_an_id_claimed_twice_names_both_files(tmp_path: Path) -> None:
    other = _namespace(tmp_path / "org", {"20990.Other.uavcan": "uint8 x\n"})
    with pytest.raises(DsdlError) as error:
        TYPES.with_dsdl(other)
    message = str(error.value)
    assert "\n" not in message
    assert "20990.Other.uavcan" in message and "20990.Telemetry.uavcan" in message
    assert "message data type id 20990" in message
    standard = _namespace(tmp_path / "acme", {"341.Beat.uavcan": "uint8 x\n"})
    with pytest.raises(DsdlError, match=r"341.Beat.uavcan: .*uavcan.protocol.NodeStatus \(.*341"):
        TypeSet.standard().with_dsdl(standard)
    services = _namespace(tmp_path / "svc", {"225.Twin.uavcan": "uint8 x\n---\nuint8 y\n"})
    with pytest.raises(DsdlError, match=r"service data type id 225 .* com\.example\.SetGain"):
        TYPES.with_dsdl(services)


@pytest.mark.parametrize(
    ("text", "line", "problem"),
    [
        ("uint8 a\nMissing b\n", 2, "unknown type bad.Missing"),
        ("uint8 a\nuint99 b\n", 2, ""),
        ("uint8 a\nuint8 a\n", 2, "a defined twice"),
    ],
)
def test_a_malformed_file_gives_its_file_and_line(
    tmp_path: Path, text: str, line: int, problem: str, default_types: None
) -> None:
    root = _namespace(tmp_path / "bad", {"20999.Broken.uavcan": text})
    with pytest.raises(DsdlError) as error:
        v4.load_dsdl(root)
    assert error.value.line == line
    assert error.value.path.endswith("20999.Broken.uavcan")
    assert str(error.value).startswith(f"{error.value.path}:{line}: ")
    assert problem in error.value.problem
    assert v4.default_types() is TypeSet.standard()  # unchanged


# -- captures ------------------------------------------------------------------------------


def _capture(tmp_path: Path) -> Path:
    request = TYPES["com.example.SetGain.Request"](loop_index=3, gain=-0.25)
    response = TYPES["com.example.SetGain.Response"](ok=False, message=b"out of range")
    status = v4.NodeStatus(uptime_sec=9, health=v4.Health.OK, mode=v4.Mode.OPERATIONAL,
                           sub_mode=0, vendor_specific_status_code=0)  # fmt: skip
    frames = []
    for tid in range(3):
        for message, source, destination in (
            (_telemetry(), 5, None),
            (status, 5, None),
            (request, 10, 5),
            (response, 5, 10),
        ):
            frames += [
                (f.can_id, f.data)
                for f in v4.encode(
                    message,
                    source_node_id=source,
                    transfer_id=tid,
                    destination_node_id=destination,
                    types=TYPES,
                )
            ]
    frames.append((0x1FFFF00 | 5, bytes([0xC0])))  # a type no set knows
    path = tmp_path / "vendor.log"
    _candump(path, frames)
    return path


def test_capture_read_decodes_the_vendor_types(tmp_path: Path) -> None:
    path = _capture(tmp_path)
    records = list(capture.read(path, types=TYPES))
    kinds = [type(r.message).__name__ for r in records]
    assert kinds == ["Telemetry", "NodeStatus", "SetGainRequest", "SetGainResponse"] * 3 + [
        "NoneType"
    ]
    assert records[0].message == _telemetry()
    assert records[3].message.message == b"out of range"
    assert all(r.error is None for r in records)
    plain = list(capture.read(path))
    assert {type(r.message).__name__ for r in plain} == {"NodeStatus", "NoneType"}
    assert [r.message for r in plain if r.message is not None] == [records[1].message] * 3


def test_read_tables_equals_the_records_and_holds_every_value(tmp_path: Path) -> None:
    path = _capture(tmp_path)
    tables = capture.read_tables(path, types=TYPES, progress=False)
    expected = capture.tables_from_records(capture.read(path, types=TYPES), types=TYPES)
    assert tables.keys() == expected.keys()
    for kind, table in tables.items():
        assert table.equals(expected[kind]), kind
    telemetry = tables["Telemetry"].to_pylist()[0]
    assert telemetry["timestamp.usec"] == 1234567
    assert telemetry["state"] == "FAULT"
    assert telemetry["reading.type"] == "label" and telemetry["reading.label"] == "rpm"
    assert telemetry["phase_current"] == [1, -2, 2047, -2048]
    assert telemetry["cells"] == [
        {"voltage": 3.5, "index": 1, "ok": True},
        {"voltage": 4.0, "index": 2, "ok": False},
    ]
    request = tables["SetGainRequest"].to_pylist()[2]
    assert (request["node_id"], request["destination_node_id"]) == (10, 5)
    assert (request["loop_index"], request["gain"]) == (3, -0.25)
    assert "Telemetry" not in capture.read_tables(path, progress=False)


def test_to_parquet_writes_the_vendor_tables(tmp_path: Path) -> None:
    import pyarrow.parquet as pq

    path = _capture(tmp_path)
    summary = capture.to_parquet(path, tmp_path / "out", progress=False, types=TYPES)
    assert summary.records["Telemetry"] == 3
    table = pq.read_table(capture.dataset_files(tmp_path / "out", "Telemetry"))
    assert table.column("timestamp.usec").to_pylist() == [1234567] * 3


# -- the command line ----------------------------------------------------------------------


def _run(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "veronte4x", *args],
        capture_output=True,
        text=True,
        check=False,
        env={**os.environ, "COLUMNS": "200"},
    )


def test_cli_decode_with_dsdl(tmp_path: Path) -> None:
    path = _capture(tmp_path)
    result = _run("decode", str(path), "--dsdl", str(VENDOR))
    assert result.returncode == 0, result.stderr
    assert "Telemetry(timestamp=Timestamp(usec=1234567), state=FAULT" in result.stdout
    assert "SetGainRequest(loop_index=3, gain=-0.25)" in result.stdout
    assert "Telemetry" not in _run("decode", str(path)).stdout


def test_cli_bad_dsdl_is_one_line_and_exit_2(tmp_path: Path) -> None:
    path = _capture(tmp_path)
    bad = _namespace(tmp_path / "bad", {"20999.Broken.uavcan": "uint8 a\nnot a line at all\n"})
    for command in ("decode", "stats", "monitor"):
        result = _run(command, str(path), "--dsdl", str(VENDOR), "--dsdl", str(bad))
        assert result.returncode == 2, (command, result.stderr)
        assert result.stderr.count("\n") == 1 and "Traceback" not in result.stderr
        assert result.stderr.startswith(f"veronte4x: {bad / '20999.Broken.uavcan'}:2: ")
    twice = _namespace(tmp_path / "org", {"20990.Other.uavcan": "uint8 x\n"})
    result = _run("decode", str(path), "--dsdl", str(VENDOR), "--dsdl", str(twice))
    assert result.returncode == 2
    assert "20990.Other.uavcan" in result.stderr and "20990.Telemetry.uavcan" in result.stderr
    result = _run("esc", "nodes", "--dsdl", str(tmp_path / "missing"))
    assert result.returncode == 2
    assert (
        result.stderr == f"veronte4x: {tmp_path / 'missing'}: not a directory of DSDL definitions\n"
    )


def test_a_union_in_a_union_names_its_line(tmp_path: Path, default_types: None) -> None:
    """DSDL v0 allows it, veronte4x does not: it raised TypeError from the generated
    classes."""
    files = {"U.uavcan": "@union\nuint8 a\nbool b\n", "V.uavcan": "@union\nuint8 c\nU u\n"}
    root = _namespace(tmp_path / "bad", {**files, "20999.Broken.uavcan": "V v\n"})
    with pytest.raises(DsdlError) as error:
        v4.load_dsdl(root)
    assert str(error.value) == f"{root}/V.uavcan:3: a union in a union is not supported"
    assert v4.default_types() is TypeSet.standard()  # unchanged


def test_a_vendor_enumeration_type_decodes_to_its_enum(tmp_path: Path) -> None:
    """The generator's rule for vendor types too: one integer field taking one of the
    type's constants (none with the field's prefix) decodes to an enum of them."""
    root = write_namespace(
        tmp_path,
        "acme",
        {
            "Mode": "uint2 IDLE = 0\nuint2 RUN = 1\nuint2 FAULT = 3\nuint2 mode\n",
            "20901.Report": "Mode mode\nuint8 LIMIT = 7\nuint8 count\n",
        },
    )
    types = TypeSet.standard().with_dsdl(root)
    report = types["acme.Report"](types["acme.Mode"](3), 4)
    frames = v4.encode(report, source_node_id=5, transfer_id=0, types=types)
    decoded = v4.decode_frames([(f.can_id, f.data) for f in frames], 0.0, types).message
    assert decoded == report
    assert type(decoded.mode).__name__ == "AcmeMode"  # "Mode" is the standard's enum
    assert type(decoded.mode.mode).__name__ == "AcmeModeMode"  # the class name in front
    assert decoded.mode.mode.name == "FAULT"
    assert type(decoded.count) is int  # LIMIT is no value of count: a constant only


def test_a_signed_field_keeps_its_constants_as_attributes(tmp_path: Path) -> None:
    """``int8 TREND_DOWN = -1``: no enum (its members would not be the wire values); the
    field is an int, in its table an int8 column."""
    root = write_namespace(
        tmp_path,
        "acme",
        {
            "20902.Trend": "int8 TREND_DOWN = -1\nint8 TREND_FLAT = 0\nint8 TREND_UP = 1\n"
            "int8 trend\n"
        },
    )
    types = TypeSet.standard().with_dsdl(root)
    cls: Any = types["acme.Trend"]
    assert cls.TREND_DOWN == -1
    lines = []
    for tid, value in enumerate((-1, 0, 1, 5)):
        (frame,) = v4.encode(cls(value), source_node_id=9, transfer_id=tid, types=types)
        lines.append(f"({tid}.000000) can0 {frame.can_id:08X}#{frame.data.hex().upper()}")
    path = tmp_path / "trend.log"
    path.write_text("\n".join(lines) + "\n")
    assert [r.message.trend for r in capture.read(path, types=types)] == [-1, 0, 1, 5]
    table = capture.read_tables(path, types=types)["Trend"]
    assert table.column("trend").to_pylist() == [-1, 0, 1, 5]
    assert table.schema.field("trend").type == "int8"
