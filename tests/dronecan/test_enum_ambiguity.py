"""Enums only where the DSDL makes every name unambiguous.

gnss.Fix2's ``SUB_MODE_*`` constants repeat their values across modes (``SUB_MODE_DGPS_OTHER
= 0`` and ``SUB_MODE_RTK_FLOAT = 0``, ``SUB_MODE_DGPS_SBAS = 1`` and ``SUB_MODE_RTK_FIXED =
1``): the enum built from them took the first name, and an RTK-fixed receiver read
``DGPS_SBAS`` in decode, tables and the monitor. Where the constants of a field's prefix repeat
a value, the field stays an int (its constants stay class attributes); checked here over every
standard type and every vendor namespace the tests can load.
"""

from __future__ import annotations

import enum
import json
import os
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from tests.dsdl_support import write_namespace

import dronecan as dc
from veronte4x import capture
from veronte4x import dronecan as v4
from veronte4x.dronecan import TypeSet, standard
from veronte4x.dronecan.parser import PrimitiveType
from veronte4x.dronecan.schema import Array, Struct, StructField, Union
from veronte4x.dronecan.standard import Fix2, Fix2Mode

STANDARD = TypeSet.standard()
PUBLIC_DSDL = Path(dc.__file__).parent / "dsdl_specs"
EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "dsdl" / "com"
VENDOR_ROOTS = [PUBLIC_DSDL / r for r in ("ardupilot", "cuav", "dronecan", "mppt")] + [EXAMPLE]


def _fields(schema: Struct | Union) -> Iterator[tuple[str, StructField]]:
    """Every (struct key, field) under ``schema``, nested types and union members included."""
    seen: set[str] = set()

    def walk(t: Any) -> Iterator[tuple[str, StructField]]:
        if isinstance(t, Array):
            yield from walk(t.item)
        elif isinstance(t, Union):
            for member in t.members:
                yield from walk(member.type)
        elif isinstance(t, Struct) and t.name not in seen:
            seen.add(t.name)
            for f in t.fields:
                yield t.name, f
                yield from walk(f.type)

    yield from walk(schema)


def _check_every_enum(types: TypeSet) -> set[tuple[str, str]]:
    """Assert that each enum field's members name each wire value once, and that each field
    whose prefix constants repeat a value has no enum; the (key, DSDL field) of each enum."""
    checked = set()
    for codec in types.codecs:
        for key, f in _fields(codec.data_type.schema):
            name = key.removesuffix(".Request").removesuffix(".Response")
            d = types.definitions[name]
            section = d.sections[1 if key.endswith(".Response") else 0]
            prefix = f.dsdl_name.upper() + "_"
            attribute = next((a for a in section.fields if a.name == f.dsdl_name), None)
            same = (
                [
                    c
                    for c in section.constants
                    if c.name.startswith(prefix) and c.type == attribute.type
                ]
                if attribute is not None and isinstance(attribute.type, PrimitiveType)
                else []
            )
            if len(same) >= 2 and len({c.value for c in same}) < len(same):
                assert f.enum is None, (key, f.name)
            if f.enum is None:
                continue
            checked.add((key, f.dsdl_name))
            assert issubclass(f.enum, enum.IntEnum)
            members = f.enum.__members__
            assert len({m.value for m in members.values()}) == len(members), (key, f.name)
            assert all(f.enum(m.value).name == n for n, m in members.items()), (key, f.name)
    return checked


def test_no_standard_enum_gives_a_value_two_names() -> None:
    assert _check_every_enum(STANDARD) == set(standard.ENUMS)
    for name in standard.__all__:
        cls = getattr(standard, name)
        if isinstance(cls, type) and issubclass(cls, enum.Enum):
            values = [m.value for m in cls.__members__.values()]
            assert len(set(values)) == len(values), name


def test_no_vendor_enum_gives_a_value_two_names(tmp_path: Path) -> None:
    ambiguous = write_namespace(
        tmp_path,
        "acme",
        {
            "20970.Mixed": "uint2 KIND_A = 0\nuint2 KIND_B = 1\nuint2 KIND_C = 1\nuint2 kind\n"
            "uint2 LEVEL_LOW = 0\nuint2 LEVEL_HIGH = 3\nuint2 level\n"
            "uint4 FLAG_X = 1\nuint4 FLAG_Y = 1\nuint4 flags\n",
        },
    )
    types = STANDARD.with_dsdl(*VENDOR_ROOTS, ambiguous)
    assert _check_every_enum(types) == set(types._enums)
    assert ("acme.Mixed", "level") in types._enums
    mixed: Any = types["acme.Mixed"]
    assert (mixed.KIND_B, mixed.KIND_C, mixed.FLAG_Y) == (1, 1, 1)  # constants stay
    message = mixed(kind=1, level=3, flags=1)
    frames = v4.encode(message, source_node_id=4, transfer_id=0, types=types)
    decoded = v4.decode_frames([(f.can_id, f.data) for f in frames], 0.0, types).message
    assert type(decoded.kind) is int and decoded.kind == 1
    assert decoded.level.name == "HIGH"  # its names are unambiguous: an enum
    assert type(decoded.flags) is int


@pytest.fixture
def fix2_log(tmp_path: Path) -> Path:
    """An RTK-fixed Fix2 (mode RTK, sub-mode RTK_FIXED = 1) and a DGPS one (SBAS = 1)."""
    lines: list[str] = []
    for tid, (mode, sub_mode) in enumerate(
        ((Fix2Mode.RTK, Fix2.SUB_MODE_RTK_FIXED), (Fix2Mode.DGPS, Fix2.SUB_MODE_DGPS_SBAS))
    ):
        message = Fix2(mode=mode, sub_mode=sub_mode, sats_used=12)
        for f in v4.encode(message, source_node_id=3, transfer_id=tid):
            lines.append(f"({len(lines) / 1000:.6f}) can0 {f.can_id:08X}#{f.data.hex().upper()}\n")
    path = tmp_path / "fix2.log"
    path.write_text("".join(lines))
    return path


def test_fix2_sub_mode_is_an_int_and_mode_an_enum(fix2_log: Path) -> None:
    assert (Fix2.SUB_MODE_RTK_FIXED, Fix2.SUB_MODE_DGPS_SBAS) == (1, 1)
    assert not hasattr(standard, "SubMode")
    records = list(capture.read(fix2_log))
    assert [(r.message.mode, r.message.sub_mode) for r in records] == [
        (Fix2Mode.RTK, 1),
        (Fix2Mode.DGPS, 1),
    ]
    assert [type(r.message.sub_mode) for r in records] == [int, int]
    table = capture.read_tables(fix2_log)["Fix2"]
    assert str(table.schema.field("sub_mode").type) == "uint8"
    assert table.select(["mode", "sub_mode"]).to_pylist() == [
        {"mode": "RTK", "sub_mode": 1},
        {"mode": "DGPS", "sub_mode": 1},
    ]


def test_cli_shows_fix2_sub_mode_as_its_number(fix2_log: Path) -> None:
    def run(*args: str) -> str:
        result = subprocess.run(
            [sys.executable, "-m", "veronte4x", "decode", str(fix2_log), *args],
            capture_output=True,
            text=True,
            check=False,
            env={**os.environ, "COLUMNS": "400"},
        )
        assert result.returncode == 0, result.stderr
        return result.stdout

    rows = [json.loads(line) for line in run("--output", "jsonl").splitlines()]
    assert [(r["mode"], r["sub_mode"]) for r in rows] == [("RTK", 1), ("DGPS", 1)]
    text = run()
    assert "mode=RTK, sub_mode=1," in text and "mode=DGPS, sub_mode=1," in text
    assert "SBAS" not in text and "RTK_FIXED" not in text
