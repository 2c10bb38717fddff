"""Unions inside arrays of structs, and unions whose members are structs or arrays, in the
tables of both decoding paths (issue 18): a vendor namespace written for the purpose,
decoded column-wise against the serializer and through the engine against the per-frame
path, values checked exactly, and Parquet read back with DuckDB.

A union inside a list's struct is a struct of the union's top-level columns: ``type``, the
member's name, and a field per member with a value, null but for the member set.
"""

from __future__ import annotations

import tempfile
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.capture.columnar_support import (
    BUS_MAPS,
    any_payload,
    assert_same_tables,
    captures,
    rows,
    transfer_frames,
    write,
)
from tests.capture.test_columnar_payloads import check
from veronte4x import capture, dronecan
from veronte4x.capture import BusMap
from veronte4x.capture.columnar.schema import dronecan_specs
from veronte4x.dronecan import TypeSet
from veronte4x.dronecan.codec import CODECS, TypeCodec

pa = pytest.importorskip("pyarrow")

NAMESPACE = {
    "Nothing": ["# No field at all."],
    "Choice": [
        "# A union: a byte, a float16, a flag, a text or nothing.",
        "@union",
        "uint8 small",
        "float16 half",
        "bool flag",
        "uint8[<=5] label",
        "Nothing nothing",
    ],
    "Holder": ["# A struct holding a union.", "uint8 key", "Choice choice"],
    "Outer": [
        "# A struct holding a union, and an array of them.",
        "Holder inner",
        "Holder[<=2] holders",
    ],
    "Wide": [
        "# A union of a struct holding a union, an array of those, a list, a text, nothing.",
        "@union",
        "Holder holder",
        "Holder[<=2] holders",
        "int5[<=3] nibbles",
        "uint8[<=3] name",
        "Nothing nothing",
    ],
    "Boxed": ["# Padding, and a union with struct and array members.", "void3", "Wide wide"],
    "20300.Fixed": ["# A static array, before another field.", "Holder[2] pair", "uint8 after"],
    "20301.Tail": [
        "# A dynamic array in tail position (TAO).",
        "uint8 code",
        "Holder[<=3] holders",
    ],
    "20302.Middle": [
        "# A dynamic array before another field.",
        "Holder[<=3] holders",
        "uint8 after",
    ],
    "20303.Deep": [
        "# Arrays of structs holding arrays of structs holding a union.",
        "Outer[<=2] outers",
    ],
    "20304.Top": ["# A top-level union with struct and array members.", "Wide value"],
    "Row": ["# Ends in an array of a union.", "uint4 k", "Choice[<=2] choices"],
    "20306.Choices": ["# An array of a union in tail position.", "Choice[<=3] choices"],
    "20307.Pairs": [
        "# A static array of a union, before another field.",
        "Choice[2] pair",
        "uint8 after",
    ],
    "20308.Rows": ["# Items ending in an array of a union.", "Row[<=3] rows"],
    "Tagged": ["# A member named as the tag.", "@union", "uint8 type", "int4 c", "bool b"],
    "20309.Tags": ["Tagged tag", "Tagged[<=2] tags"],
    "20305.Boxes": [
        "# Items holding that union, before another field.",
        "Boxed[<=2] boxes",
        "uint4 after",
    ],
}
"""The namespace ``uni``: every message holds a union inside an array of structs, an
array of a union, or a union with struct and array members."""
KINDS = ["Fixed", "Tail", "Middle", "Deep", "Top", "Boxes", "Choices", "Pairs", "Rows", "Tags"]


@dataclass(frozen=True)
class Uni:
    """The namespace loaded: its type set, a bus map with it, and its tables' specs."""

    types: TypeSet
    bus_map: BusMap
    specs: dict[str, Any]

    def codec(self, name: str) -> TypeCodec:
        [found] = [c for c in self.types.codecs if c.data_type.schema.cls.__name__ == name]
        return found

    def encode(self, name: str, data: dict[str, Any]) -> bytes:
        found = self.codec(name)
        message: Any = dronecan.from_builtin(found.data_type.schema.cls, data, self.types)
        return found.encode(message, True)

    def lines(self, items: list[tuple[str, dict[str, Any]]]) -> list[str]:
        """candump lines of one transfer per item from node 42, a NodeStatus between."""
        status = dronecan.NodeStatus(7, dronecan.Health.OK, dronecan.Mode.OPERATIONAL, 0, 0)
        frames: list[tuple[int, bytes, bool]] = []
        for tid, (name, data) in enumerate(items):
            frames += transfer_frames(self.codec(name), self.encode(name, data), 42, None, tid % 32)
            made = dronecan.encode(status, source_node_id=9, transfer_id=tid % 32)
            frames += [(f.can_id, f.data, True) for f in made]
        return [
            f"({1_700_000_000 + n / 1000:.6f}) can0 {can_id:08X}#{data.hex().upper()}"
            for n, (can_id, data, _) in enumerate(frames)
        ]


def _load(root: Path) -> Uni:
    folder = root / "uni"
    folder.mkdir()
    for name, lines in NAMESPACE.items():
        (folder / f"{name}.uavcan").write_text("\n".join(lines) + "\n")
    types = TypeSet.standard().with_dsdl(folder)
    return Uni(types, BusMap(dronecan_types=types), dronecan_specs(types, "binary"))


@pytest.fixture(scope="module")
def uni(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Uni]:
    yield _load(tmp_path_factory.mktemp("dsdl"))


def _choice(member: str, value: Any) -> dict[str, Any]:
    """A ``Choice`` as its columns hold it: the member's name, its value, null elsewhere."""
    out: dict[str, Any] = {"type": member, "small": None, "half": None, "flag": None}
    out["label"] = None
    if member != "nothing":
        out[member] = value
    return out


CHOICES: list[tuple[dict[str, Any], dict[str, Any]]] = [
    ({"small": 200}, _choice("small", 200)),
    ({"half": -1.5}, _choice("half", -1.5)),
    ({"flag": True}, _choice("flag", True)),
    ({"label": "é"}, _choice("label", "é".encode())),
    ({"nothing": {}}, _choice("nothing", None)),
]
"""Every member of ``Choice``: its plain data and its column value."""


def _holder(key: int, choice: int) -> tuple[dict[str, Any], dict[str, Any]]:
    data, column = CHOICES[choice]
    return {"key": key, "choice": data}, {"key": key, "choice": column}


def _wide(member: str, value: Any) -> dict[str, Any]:
    """A ``Wide`` as its columns hold it (without the prefix ``value.``)."""
    out: dict[str, Any] = {"type": member, "holder": None, "holders": None, "nibbles": None}
    out["name"] = None
    if member != "nothing":
        out[member] = value
    return out


def _tables(uni: Uni, path: Path) -> dict[str, Any]:
    """``read_tables``, checked equal to the per-frame records made tables."""
    got = capture.read_tables(path, uni.bus_map)
    assert_same_tables(
        got, capture.tables_from_records(capture.read(path, uni.bus_map), uni.bus_map)
    )
    return got


def test_a_union_in_a_list_is_a_struct_of_its_top_level_columns(uni: Uni) -> None:
    choice = pa.struct(
        [
            ("type", pa.dictionary(pa.uint8(), pa.string())),
            ("small", pa.uint8()),
            ("half", pa.float32()),
            ("flag", pa.bool_()),
            ("label", pa.binary()),
        ]
    )
    holder = pa.struct([("key", pa.uint8()), ("choice", choice)])
    columns = {c.name: c.type for c in uni.specs["Fixed"].columns}
    assert columns == {"pair": pa.list_(holder), "after": pa.uint8()}
    top = dronecan_specs(uni.types)["Top"]  # text as strings, the default
    assert {c.name: c.type for c in top.columns} == {
        "value.type": pa.dictionary(pa.uint8(), pa.string()),
        "value.holder": holder,
        "value.holders": pa.list_(holder),
        "value.nibbles": pa.list_(pa.int8()),
        "value.name": pa.string(),
    }
    assert {c.name for c in top.columns if c.text} == {"value.name"}  # inside structs: binary
    [tag] = [c for c in top.columns if c.name == "value.type"]
    assert tag.names == ("holder", "holders", "nibbles", "name", "nothing")


def test_every_member_in_static_and_dynamic_arrays(uni: Uni, tmp_path: Path) -> None:
    """Every member of the union in every place, arrays empty and full, exact values."""
    items: list[tuple[str, dict[str, Any]]] = []
    expected: dict[str, list[dict[str, Any]]] = {kind: [] for kind in KINDS}
    for n in range(5):
        a, b = _holder(n, n), _holder(255 - n, 4 - n)
        items.append(("Fixed", {"pair": [a[0], b[0]], "after": n}))
        expected["Fixed"].append({"pair": [a[1], b[1]], "after": n})
    for count in range(4):
        held = [_holder(10 * count + k, (count + k) % 5) for k in range(count)]
        for kind, other in (("Tail", "code"), ("Middle", "after")):
            items.append((kind, {other: count, "holders": [h[0] for h in held]}))
            expected[kind].append({other: count, "holders": [h[1] for h in held]})
    path = write(tmp_path / "arrays.log", uni.lines(items))
    got = _tables(uni, path)
    assert sorted(got) == ["Fixed", "Middle", "NodeStatus", "Tail"]
    for kind in ("Fixed", "Tail", "Middle"):
        fields = [c.name for c in uni.specs[kind].columns]
        assert [{k: row[k] for k in fields} for row in rows(got[kind])] == expected[kind], kind


def test_arrays_of_a_union(uni: Uni, tmp_path: Path) -> None:
    """``Choice[<=3]`` in tail position, ``Choice[2]`` before a field, and items ending in
    ``Choice[<=2]``: every member, arrays empty and full, exact values."""
    items: list[tuple[str, dict[str, Any]]] = []
    expected: dict[str, list[Any]] = {"Choices": [], "Pairs": [], "Rows": []}
    for n in range(5):
        chosen = [CHOICES[(n + k) % 5] for k in range(min(n, 3))]
        items.append(("Choices", {"choices": [data for data, _ in chosen]}))
        expected["Choices"].append({"choices": [column for _, column in chosen]})
        pair = [CHOICES[n], CHOICES[4 - n]]
        items.append(("Pairs", {"pair": [data for data, _ in pair], "after": n}))
        expected["Pairs"].append({"pair": [column for _, column in pair], "after": n})
        rows_ = [(k, [CHOICES[(n + k + j) % 5] for j in range(k % 3)]) for k in range(n % 4)]
        items.append(("Rows", {"rows": [{"k": k, "choices": [d for d, _ in c]} for k, c in rows_]}))
        expected["Rows"].append(
            {"rows": [{"k": k, "choices": [c for _, c in cs]} for k, cs in rows_]}
        )
    path = write(tmp_path / "choices.log", uni.lines(items))
    got = _tables(uni, path)
    for kind, values in expected.items():
        fields = [c.name for c in uni.specs[kind].columns]
        assert [{k: row[k] for k in fields} for row in rows(got[kind])] == values, kind
    choice = uni.specs["Fixed"].columns[0].type.value_type.field("choice").type
    assert [c.type for c in uni.specs["Choices"].columns] == [pa.list_(choice)]


def test_a_member_named_type_keeps_the_tag_column(uni: Uni, tmp_path: Path) -> None:
    """A member ``type`` has the column ``tag.type_``; ``tag.type`` stays the tag (two
    columns ``tag.type`` before, and a table that could not be built)."""
    tagged = pa.struct(
        [
            ("type", pa.dictionary(pa.uint8(), pa.string())),
            ("type_", pa.uint8()),
            ("c", pa.int8()),
            ("b", pa.bool_()),
        ]
    )
    assert {c.name: c.type for c in uni.specs["Tags"].columns} == {
        "tag.type": tagged.field("type").type,
        "tag.type_": pa.uint8(),
        "tag.c": pa.int8(),
        "tag.b": pa.bool_(),
        "tags": pa.list_(tagged),
    }
    items: list[tuple[str, dict[str, Any]]] = [
        ("Tags", {"tag": {"type": 200}, "tags": [{"type": 9}, {"c": -8}]}),
        ("Tags", {"tag": {"c": 7}, "tags": []}),
    ]
    got = _tables(uni, write(tmp_path / "tags.log", uni.lines(items)))
    fields = [c.name for c in uni.specs["Tags"].columns]
    none = {"type_": None, "c": None, "b": None}
    assert [[row[k] for k in fields] for row in rows(got["Tags"])] == [
        [
            "type",
            200,
            None,
            None,
            [{**none, "type": "type", "type_": 9}, {**none, "type": "c", "c": -8}],
        ],
        ["c", None, 7, None, []],
    ]


def test_unions_one_level_further_and_with_struct_and_array_members(
    uni: Uni, tmp_path: Path
) -> None:
    h0, h1, h2 = _holder(1, 0), _holder(2, 1), _holder(3, 2)
    outers = [
        {"inner": h0[0], "holders": []},
        {"inner": h1[0], "holders": [h2[0], h0[0]]},
    ]
    wides = [
        ({"holder": h1[0]}, _wide("holder", h1[1])),
        ({"holders": [h2[0], h0[0]]}, _wide("holders", [h2[1], h0[1]])),
        ({"holders": []}, _wide("holders", [])),
        ({"nibbles": [-16, 15, 0]}, _wide("nibbles", [-16, 15, 0])),
        ({"nothing": {}}, _wide("nothing", None)),
        ({"name": "ab"}, _wide("name", "ab")),  # a text: a string at the top level
    ]
    items: list[tuple[str, dict[str, Any]]] = [
        ("Deep", {"outers": outers}),
        ("Deep", {"outers": []}),
    ]
    items += [("Top", {"value": data}) for data, _ in wides]
    items += [("Boxes", {"boxes": [{"wide": data} for data, _ in wides[:2]], "after": 9})]
    items += [("Boxes", {"boxes": [{"wide": data} for data, _ in wides[2:4]], "after": 15})]
    items += [("Boxes", {"boxes": [], "after": 0})]
    items += [("Boxes", {"boxes": [{"wide": {"name": "ab"}}], "after": 1})]
    path = write(tmp_path / "deep.log", uni.lines(items))
    got = _tables(uni, path)
    deep = [row["outers"] for row in rows(got["Deep"])]
    assert deep == [
        [{"inner": h0[1], "holders": []}, {"inner": h1[1], "holders": [h2[1], h0[1]]}],
        [],
    ]
    top = [
        {k.removeprefix("value."): v for k, v in row.items() if k.startswith("value.")}
        for row in rows(got["Top"])
    ]
    assert top == [column for _, column in wides]
    boxes = [(row["boxes"], row["after"]) for row in rows(got["Boxes"])]
    assert boxes == [
        ([{"wide": column} for _, column in wides[:2]], 9),
        ([{"wide": column} for _, column in wides[2:4]], 15),
        ([], 0),
        ([{"wide": _wide("name", b"ab")}], 1),  # a text inside a list: its bytes
    ]


@pytest.mark.parametrize("kind", KINDS)
def test_every_type_on_uniform_and_short_payloads(uni: Uni, kind: str) -> None:
    """Column-wise against the serializer: values, and the payloads refused (union tags
    without a member among them: ``Choice`` has four members, ``0xFF`` bytes none)."""
    found = uni.codec(kind)
    sizes = range(found.max_payload + 2)
    check(found, [bytes([fill]) * n for fill in (0x00, 0xFF, 0x5A, 0xA5) for n in sizes], uni.specs)


@settings(max_examples=200, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(data=st.data())
def test_any_payloads_agree(uni: Uni, data: st.DataObject) -> None:
    """Encoded values (every member, arrays empty, full or between), cut short,
    lengthened, any bytes."""
    drawn = data.draw(st.lists(any_payload(uni.types), min_size=1, max_size=12))
    by_type: dict[int, list[bytes]] = {}
    for found, payload in drawn:
        by_type.setdefault(uni.types.codecs.index(found), []).append(payload)
    for index, items in by_type.items():
        check(uni.types.codecs[index], items, uni.specs)


@settings(max_examples=100, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data())
def test_generated_captures_agree(uni: Uni, data: st.DataObject) -> None:
    """``read_tables`` equals ``tables_from_records(read())`` on captures with the
    namespace's types among other traffic (Veronte, standard DroneCAN, unknown ids, bad
    lines), faults included, under any bus map."""
    bus_map = data.draw(BUS_MAPS).with_types(uni.types)
    lines = data.draw(captures(bus_map))
    with tempfile.TemporaryDirectory() as folder:
        path = write(Path(folder) / "capture.log", lines)
        expected = capture.tables_from_records(capture.read(path, bus_map), bus_map)
        got = capture.read_tables(path, bus_map)
    assert_same_tables(got, expected)


def test_the_namespace_types_are_vendor_types(uni: Uni) -> None:
    names = [c.data_type.schema.cls.__name__ for c in uni.types.codecs[len(CODECS) :]]
    assert names == KINDS


def _duckdb(out: Path, query: str) -> list[tuple[Any, ...]]:
    duckdb = pytest.importorskip("duckdb")
    rows: list[tuple[Any, ...]] = duckdb.connect().sql(query.format(out=out)).fetchall()
    return rows


def test_to_parquet_read_back_with_duckdb(uni: Uni, tmp_path: Path) -> None:
    h0, h1 = _holder(7, 0), _holder(8, 1)
    items: list[tuple[str, dict[str, Any]]] = [
        ("Middle", {"holders": [h0[0], h1[0]], "after": 3}),
        ("Middle", {"holders": [], "after": 4}),
        ("Top", {"value": {"holders": [h1[0]]}}),
        ("Top", {"value": {"nibbles": [-3]}}),
        ("Choices", {"choices": [{"flag": True}, {"label": "é"}]}),
    ]
    path = write(tmp_path / "capture.log", uni.lines(items))
    out = tmp_path / "out"
    summary = capture.to_parquet(path, out, uni.bus_map, progress=False)
    assert summary.records["Middle"] == 2
    middle = "SELECT {column} FROM read_parquet('{{out}}/capture=*/Middle.parquet')"
    got = _duckdb(
        out, middle.format(column="holders[1].choice.type, holders[2].choice.half, after")
    )
    assert got == [("small", -1.5, 3), (None, None, 4)]
    got = _duckdb(out, middle.format(column="len(holders), holders[2].key"))
    assert got == [(2, 8), (0, None)]
    top = "SELECT {column} FROM read_parquet('{{out}}/capture=*/Top.parquet')"
    got = _duckdb(out, top.format(column='"value.type", "value.holders"[1].choice.half'))
    assert got == [("holders", -1.5), ("nibbles", None)]
    got = _duckdb(out, top.format(column='"value.nibbles", "value.holder"'))
    assert got == [(None, None), ([-3], None)]
    choices = "SELECT choices[1].type, choices[1].flag, choices[2].label FROM read_parquet("
    got = _duckdb(out, choices + "'{out}/capture=*/Choices.parquet')")
    assert got == [("flag", True, "é".encode())]
    expected = capture.read_tables(path, uni.bus_map)
    duckdb = pytest.importorskip("duckdb")
    for kind in ("Middle", "Top", "Choices"):
        files = f"'{out}/capture=*/{kind}.parquet'"
        query = f"SELECT * EXCLUDE (source) FROM read_parquet({files}, hive_partitioning = false)"
        assert rows(duckdb.connect().sql(query).to_arrow_table()) == rows(expected[kind]), kind
