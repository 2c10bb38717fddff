"""DSDL names that would be one Python attribute: each keeps an attribute, every value stays.

A field or constant named like a Python keyword takes ``_`` after it, and more while that is
another name of the class; a name that can be kept is kept (`generate.attribute_names`,
documented in docs/dronecan/types.md). Before, ``class`` and ``class_`` in one type were one
attribute ``class_``, and one wire value was lost. The ``dronecan`` package, which keeps the
DSDL names, is the reference for the values.
"""

from __future__ import annotations

import json
import keyword
import os
import subprocess
import sys
import tempfile
from collections.abc import Iterator
from dataclasses import fields
from pathlib import Path
from typing import Any

import pytest
from dronecan_oracle import reference_decode
from hypothesis import given, settings
from hypothesis import strategies as st
from tests.dsdl_support import write_namespace

import dronecan as dc
from veronte4x import capture
from veronte4x import dronecan as v4
from veronte4x.dronecan import TypeSet
from veronte4x.dronecan.schema import Struct, Union

STANDARD = TypeSet.standard()
TEXT = {
    "20980.Sorted": "uint8 class\nuint16 class_\nint8 if\n",
    "20981.Backwards": "uint16 class_\nuint8 class\n",
    "20982.WithConstant": "uint8 class_ = 5\nuint8 class\nuint8 value\n",
    "Choice": "@union\nuint8 class\nuint16 class_\n",
    "20983.Holder": "Choice choice\nuint8 None\n",
}


@pytest.fixture(scope="module")
def root() -> Iterator[Path]:
    """The namespace ``acme`` here, loaded into the ``dronecan`` package too."""
    with tempfile.TemporaryDirectory() as tmp:
        path = write_namespace(Path(tmp), "acme", TEXT)
        dc.load_dsdl(str(path))
        yield path
        dc.load_dsdl()


def _frames(message: Any, types: TypeSet) -> list[tuple[int, bytes]]:
    return [
        (f.can_id, f.data) for f in v4.encode(message, source_node_id=7, transfer_id=0, types=types)
    ]


def test_class_and_class_keep_both_values(root: Path, tmp_path: Path) -> None:
    types = STANDARD.with_dsdl(root)
    cls: Any = types["acme.Sorted"]
    assert [f.name for f in fields(cls)] == ["class__", "class_", "if_"]
    message = cls(class__=200, class_=60000, if_=-5)
    frames = _frames(message, types)
    theirs = reference_decode(frames)  # the dronecan package: by DSDL name
    assert (getattr(theirs, "class"), theirs.class_, getattr(theirs, "if")) == (200, 60000, -5)
    assert v4.decode_frames(frames, 0.0, types).message == message
    reassembler = v4.Reassembler(types=types)
    assert [reassembler.feed(i, d, 0.0) for i, d in frames][-1].message == message  # type: ignore[union-attr]
    assert v4.to_builtin(message, types) == {"class__": 200, "class_": 60000, "if_": -5}
    assert v4.from_builtin(cls, {"class__": 200, "class_": 60000, "if_": -5}, types) == message
    log = tmp_path / "sorted.log"
    ((can_id, data),) = frames
    log.write_text(f"(0.000000) can0 {can_id:08X}#{data.hex().upper()}\n")
    assert [r.message for r in capture.read(log, types=types)] == [message]
    table = capture.read_tables(log, types=types)["Sorted"]
    assert table.select(["class__", "class_", "if_"]).to_pylist() == [
        {"class__": 200, "class_": 60000, "if_": -5}
    ]
    result = subprocess.run(
        [sys.executable, "-m", "veronte4x", "decode", str(log), "--output", "jsonl",
         "--dsdl", str(root)],
        capture_output=True, text=True, check=False, env={**os.environ, "COLUMNS": "200"},
    )  # fmt: skip
    assert result.returncode == 0, result.stderr
    row = json.loads(result.stdout)
    assert {k: row[k] for k in ("class__", "class_", "if_")} == {
        "class__": 200,
        "class_": 60000,
        "if_": -5,
    }


def test_the_rule_does_not_depend_on_the_order_of_the_fields(root: Path) -> None:
    types = STANDARD.with_dsdl(root)
    assert [f.name for f in fields(types["acme.Backwards"])] == ["class_", "class__"]
    message: Any = types["acme.Backwards"](class_=1000, class__=3)
    theirs = reference_decode(_frames(message, types))
    assert (theirs.class_, getattr(theirs, "class")) == (1000, 3)


def test_a_constant_keeps_its_name_and_the_field_moves(root: Path) -> None:
    types = STANDARD.with_dsdl(root)
    cls: Any = types["acme.WithConstant"]
    assert cls.class_ == 5
    assert [f.name for f in fields(cls)] == ["class__", "value"]
    message = cls(class__=9, value=4)
    assert v4.decode_frames(_frames(message, types), 0.0, types).message == message


def test_the_dsdl_name_stays_in_the_schema(root: Path) -> None:
    types = STANDARD.with_dsdl(root)
    schema = types.by_class[types["acme.Sorted"]].data_type.schema
    assert [(f.name, f.dsdl_name) for f in schema.fields] == [
        ("class__", "class"),
        ("class_", "class_"),
        ("if_", "if"),
    ]
    holder = types.by_class[types["acme.Holder"]].data_type.schema
    choice = holder.fields[0].type
    assert isinstance(choice, Union)
    assert [(m.name, m.dsdl_name) for m in choice.members] == [
        ("class__", "class"),
        ("class_", "class_"),
    ]
    assert (holder.fields[1].name, holder.fields[1].dsdl_name) == ("None_", "None")
    nested = STANDARD.by_class[v4.NodeStatus].data_type.schema
    assert all(f.name == f.dsdl_name for f in nested.fields)


def test_union_members_of_one_attribute_name_both_decode(root: Path) -> None:
    types = STANDARD.with_dsdl(root)
    holder: Any = types["acme.Holder"]
    for member, dsdl, value in (("class__", "class", 7), ("class_", "class_", 40000)):
        message = v4.from_builtin(holder, {"choice": {member: value}, "None_": 1}, types)
        frames = _frames(message, types)
        decoded = v4.decode_frames(frames, 0.0, types).message
        assert decoded == message
        assert v4.to_builtin(decoded, types) == {"choice": {member: value}, "None_": 1}
        theirs = reference_decode(frames).choice
        assert (dc.get_active_union_field(theirs), getattr(theirs, dsdl)) == (dsdl, value)


NAMES = st.sampled_from(
    [*keyword.kwlist, *(k + "_" for k in keyword.kwlist[:8]), "class__", "value", "x"]
)


@settings(max_examples=40)
@given(st.lists(NAMES, min_size=1, max_size=6, unique=True), st.data())
def test_any_names_give_one_attribute_each_and_every_value_back(
    names: list[str], data: st.DataObject
) -> None:
    """Keywords, keywords with one ``_`` and more, plain names, in any order: one attribute
    per field, the same as the DSDL name where that is no keyword, every value back."""
    text = "".join(f"uint16 {name}\n" for name in names)
    with tempfile.TemporaryDirectory() as tmp:
        types = STANDARD.with_dsdl(write_namespace(Path(tmp), "acme", {"20984.Any": text}))
    schema = types.by_class[types["acme.Any"]].data_type.schema
    assert isinstance(schema, Struct)
    attributes = [f.name for f in schema.fields]
    assert [f.dsdl_name for f in schema.fields] == names
    assert len(set(attributes)) == len(names)
    assert all(a == n for a, n in zip(attributes, names, strict=True) if not keyword.iskeyword(n))
    assert not any(keyword.iskeyword(a) or not a.isidentifier() for a in attributes)
    values = data.draw(st.lists(st.integers(0, 65535), min_size=len(names), max_size=len(names)))
    message = schema.cls(*values)
    decoded = v4.decode_frames(_frames(message, types), 0.0, types).message
    assert [getattr(decoded, a) for a in attributes] == values
