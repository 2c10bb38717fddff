"""An enum field wider than 16 bits (``ardupilot.gnss.Status.status``, 23 bits of flags)
is an integer column holding the wire value in `read_tables`: a dictionary of every one of
its 8,388,608 wire values cost every `read_tables` seconds, the type seen or not."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pyarrow as pa

from tests.capture.columnar_support import assert_same_tables, write
from veronte4x import capture, dronecan
from veronte4x.dronecan.typeset import default_types


def test_a_wide_enum_field_is_its_number(tmp_path: Path) -> None:
    types = default_types()
    cls = types["ardupilot.gnss.Status"]
    message: Any = dronecan.from_builtin(
        cls, {"error_codes": 7, "healthy": True, "status": 0x400003}, types
    )
    frames = dronecan.encode(message, source_node_id=10, transfer_id=0)
    lines = [
        f"(1.{i:06d}) can0 {f.can_id:08X}#{f.data.hex().upper()}" for i, f in enumerate(frames)
    ]
    path = write(tmp_path / "gnss.log", lines)
    tables = capture.read_tables(path)
    column = tables[cls.__name__].column("status")
    assert pa.types.is_integer(column.type)
    assert column.to_pylist() == [0x400003]
    assert_same_tables(tables, capture.tables_from_records(list(capture.read(path))))
