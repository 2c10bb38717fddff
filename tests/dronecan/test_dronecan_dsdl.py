"""The DSDL compiler: the packaged standard set, signatures, generated classes, errors."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import dronecan as dc
import veronte4x
import veronte4x.dronecan
from veronte4x import dronecan
from veronte4x.dronecan import shipped_source
from veronte4x.dronecan.definitions import DATA_TYPES, NESTED_SIGNATURES
from veronte4x.dronecan.parser import (
    check_references,
    parse_namespaces,
    signature,
)
from veronte4x.dronecan.types import standard_definitions
from veronte4x.dronecan.vendor_roots import DSDL_ROOT
from veronte4x.errors import DsdlError


def test_the_standard_set_is_package_data_with_its_licence() -> None:
    package = Path(veronte4x.dronecan.__file__).parent
    assert package / "dsdl" == DSDL_ROOT
    assert len(list((DSDL_ROOT / "uavcan").rglob("*.uavcan"))) == 86
    assert (
        "MIT" in (DSDL_ROOT / "LICENSE").read_text()
        or "Permission" in (DSDL_ROOT / "LICENSE").read_text()
    )
    assert len(standard_definitions()) == 86


def test_every_signature_and_id_equals_the_dronecan_package() -> None:
    definitions = standard_definitions()
    for name, d in definitions.items():
        reference = dc.TYPENAMES[name]
        assert signature(name, definitions) == reference.get_data_type_signature(), name
        assert d.default_id == reference.default_dtid, name
    assert len(DATA_TYPES) == 82
    for t in DATA_TYPES:
        assert t.signature == dc.TYPENAMES[t.full_name].get_data_type_signature()
    for name, value in NESTED_SIGNATURES.items():
        assert value == dc.TYPENAMES[name].get_data_type_signature()


def test_the_generated_modules_are_up_to_date() -> None:
    """``python -m veronte4x.dronecan.generate`` rewrites every module generated from the
    shipped DSDL (classes, data, fast paths); each must be current, and no other fast-path
    module may linger."""
    package = Path(veronte4x.dronecan.__file__).parent
    found = shipped_source.sources()
    for relative, text in found.items():
        assert (package / relative).read_text(encoding="utf-8") == text, relative
    on_disk = {f"fast/{p.name}" for p in (package / "fast").glob("*.py")}
    assert on_disk == {k for k in found if k.startswith("fast/")}


def test_the_generator_runs_from_a_broken_package(tmp_path: Path) -> None:
    """A stale or broken ``standard.py`` (a DSDL file added, a bad edit) does not stop the
    generator: it imports none of the modules it writes."""
    source = Path(veronte4x.__file__).parent
    copy = tmp_path / "src" / "veronte4x"
    shutil.copytree(source, copy, ignore=shutil.ignore_patterns("__pycache__"))
    dronecan_copy = copy / "dronecan"
    for name in ("standard.py", "standard_data.py", "vendor.py", "vendor_data.py"):
        (dronecan_copy / name).write_text("raise KeyError('broken')\n")
    (dronecan_copy / "fast" / "uavcan_protocol_NodeStatus.py").unlink()
    done = subprocess.run(
        [sys.executable, "-m", "veronte4x.dronecan.generate"],
        capture_output=True,
        text=True,
        env={**os.environ, "PYTHONPATH": str(tmp_path / "src")},
        cwd=tmp_path,
        timeout=300,
    )
    assert done.returncode == 0, done.stderr
    for relative, text in shipped_source.sources().items():
        assert (dronecan_copy / relative).read_text(encoding="utf-8") == text, relative


def test_names_are_predictable() -> None:
    for name in (
        "BatteryInfo",
        "Fix2",
        "ArrayCommand",
        "ActuatorStatus",
        "CameraGimbalMode",
        "LogMessage",
        "GetTransportStatsRequest",
        "ActuatorCommand",
        "NodeStatus",
        "EscStatus",
        "GetSetRequest",
        "Health",
        "Mode",
        "CommandType",
        "FixStatus",
    ):
        assert name in dronecan.__all__, name
    assert dronecan.ArmingStatus(dronecan.ArmingStatusStatus.FULLY_ARMED).status == 255


def test_enum_fields_decode_to_their_enum() -> None:
    message = dronecan.ArrayCommand(
        (dronecan.ActuatorCommand(3, dronecan.CommandType.PWM, 1500.0),)
    )
    frames = dronecan.encode(message, source_node_id=1, transfer_id=0)
    decoded = dronecan.decode_frames([(f.can_id, f.data) for f in frames]).message
    assert decoded == message
    assert decoded.commands[0].command_type is dronecan.CommandType.PWM


def test_an_enumeration_type_decodes_to_its_enum() -> None:
    message = dronecan.LogMessage(level=dronecan.LogLevel(2), source=b"GPS", text=b"no fix")
    frames = dronecan.encode(message, source_node_id=70, transfer_id=0)
    decoded = dronecan.decode_frames([(f.can_id, f.data) for f in frames]).message
    assert decoded == message
    assert decoded.level.value is dronecan.LogLevelValue.WARNING
    assert [m.name for m in dronecan.LogLevelValue] == ["DEBUG", "INFO", "WARNING", "ERROR"]
    assert dronecan.LogLevel.WARNING == dronecan.LogLevelValue.WARNING  # the constant stays
    request = dronecan.GetDataTypeInfoRequest(id=341, kind=dronecan.DataTypeKind(1))
    frames = dronecan.encode(request, source_node_id=1, destination_node_id=2, transfer_id=0)
    asked = dronecan.decode_frames([(f.can_id, f.data) for f in frames]).message
    assert asked.kind.value == dronecan.DataTypeKindValue.MESSAGE
    assert asked.kind.value is dronecan.DataTypeKindValue.MESSAGE  # decoded: the enum itself
    assert int(dronecan.ProtocolProtocol.UNDEFINED) == 255
    assert dronecan.FileErrorCode(2).value.__class__ is int  # a type of before: unchanged


def test_numpy_scalars_are_accepted_never_narrowed() -> None:
    message = dronecan.BatteryInfo(
        voltage=np.float32(12.5),
        battery_id=np.uint8(2),
        state_of_charge_pct=np.int64(80),
    )
    plain = dronecan.BatteryInfo(voltage=12.5, battery_id=2, state_of_charge_pct=80)
    assert [f.data for f in dronecan.encode(message, source_node_id=1, transfer_id=0)] == [
        f.data for f in dronecan.encode(plain, source_node_id=1, transfer_id=0)
    ]
    with pytest.raises(dronecan.EncodeError):
        dronecan.encode(
            dronecan.BatteryInfo(battery_id=np.float64(2.0)),
            source_node_id=1,
            transfer_id=0,
        )
    with pytest.raises(dronecan.EncodeError):
        dronecan.encode(
            dronecan.BatteryInfo(battery_id=np.int64(256)),
            source_node_id=1,
            transfer_id=0,
        )
    armed = dronecan.ArmingStatus(status=np.uint8(255))
    assert dronecan.encode(armed, source_node_id=1, transfer_id=0)
    ok = dronecan.RestartNodeResponse(ok=np.bool_(True))  # type: ignore[arg-type]
    frames = dronecan.encode(ok, source_node_id=1, destination_node_id=2, transfer_id=0)
    assert frames[0].data[0] == 0x80


def _write(root: Path, relative: str, text: str) -> Path:
    path = root / relative
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    return path


@pytest.mark.parametrize(
    ("text", "line", "problem"),
    [
        ("uint8 a\nuint99 b\n", 2, "uint99: no such type"),
        ("uint8 a\nuint8 a\n", 2, "a defined twice"),
        ("uint8 X = 300\n", 1, "out of range"),
        ("@union\nuint8 a\n", None, "at least two fields"),
        ("uint8[<=0] a\n", 1, "at least one item"),
        ("saturated Foo a\n", 1, "cast mode"),
        ("@sealed\n", 1, "unsupported directive @sealed"),
        ("uint8 a b c\n", 1, "cannot read"),
    ],
)
def test_malformed_definitions_name_file_line_and_problem(
    tmp_path: Path, text: str, line: int | None, problem: str
) -> None:
    path = _write(tmp_path, "vendor/20000.Thing.uavcan", text)
    with pytest.raises(DsdlError, match=problem) as caught:
        parse_namespaces([tmp_path / "vendor"])
    assert caught.value.path == str(path)
    assert caught.value.line == line
    assert str(caught.value).startswith(f"{path}")


def test_unknown_nested_type_names_the_file(tmp_path: Path) -> None:
    path = _write(tmp_path, "vendor/20000.Thing.uavcan", "uint8 a\nMissing b\n")
    definitions = parse_namespaces([tmp_path / "vendor"])
    with pytest.raises(DsdlError, match=r"unknown type vendor\.Missing") as caught:
        check_references(definitions)
    assert (caught.value.path, caught.value.line) == (str(path), 2)


def test_a_type_defined_twice_names_both_files(tmp_path: Path) -> None:
    _write(tmp_path, "a/vendor/20000.Thing.uavcan", "uint8 a\n")
    _write(tmp_path, "b/vendor/20001.Thing.uavcan", "uint8 a\n")
    with pytest.raises(DsdlError, match=r"vendor\.Thing also in"):
        parse_namespaces([tmp_path / "a" / "vendor", tmp_path / "b" / "vendor"])


def test_a_bad_file_name_is_an_error(tmp_path: Path) -> None:
    _write(tmp_path, "vendor/thing.uavcan", "uint8 a\n")
    with pytest.raises(DsdlError, match="not a DSDL file name"):
        parse_namespaces([tmp_path / "vendor"])
