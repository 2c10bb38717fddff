"""A vendor union whose member is text, alone and in arrays, as `format_message`,
`readable_fields`, `capture.fields`, ``decode`` and `read_tables` show it. An array of a
union (or of a struct holding one) gave the member objects, printed with ``b'...'`` bytes,
where the union alone gave its flattened value, printed as text."""

from __future__ import annotations

import os
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from tests.dsdl_support import write_namespace
from veronte4x import capture
from veronte4x import dronecan as v4
from veronte4x.capture.readable import format_message, readable_fields
from veronte4x.dronecan import TypeSet

NAMESPACE = {
    "Choice": "@union\nuint8[<=16] name\nfloat32 number\n",
    "Wrap": "Choice choice\n",
    "20901.Named": "uint8[<=16] name\nChoice choice\nChoice[<=2] choices\nWrap[<=1] wraps\n",
}
VALUES = {
    "name": "abc",
    "choice": {"name": "xyz"},
    "choices": [{"name": "p"}, {"number": 1.5}],
    "wraps": [{"choice": {"name": "q"}}],
}


@pytest.fixture
def root(tmp_path: Path) -> Iterator[Path]:
    """The namespace ``acme``, loaded into the default type set for the test only."""
    root = write_namespace(tmp_path, "acme", NAMESPACE)
    v4.load_dsdl(root)
    yield root
    v4.set_default_types(TypeSet.standard())


def _message() -> Any:
    return v4.from_builtin(v4.load_dsdl()["acme.Named"], VALUES)  # the default set


def test_union_members_in_arrays_print_like_the_union_alone(root: Path) -> None:
    assert format_message(_message()) == (
        "Named(name='abc', choice=ChoiceName(value='xyz'), "
        "choices=(ChoiceName(value='p'), ChoiceNumber(value=1.5)), "
        "wraps=(Wrap(choice=ChoiceName(value='q'))))"
    )
    assert readable_fields(_message()) == {
        "name": "abc",
        "choice.value": "xyz",
        "choices_0.value": "p",
        "choices_1.value": 1.5,
        "wraps_0.choice.value": "q",
    }
    assert capture.fields(_message()) == {
        "name": b"abc",
        "choice.value": b"xyz",
        "choices_0.value": b"p",
        "choices_1.value": 1.5,
        "wraps_0.choice.value": b"q",
    }


def _log(path: Path) -> Path:
    sent = v4.encode(_message(), source_node_id=9, transfer_id=0)
    lines = [
        f"(1.{i:06d}) can0 {f.can_id:08X}#{f.data.hex().upper()}\n" for i, f in enumerate(sent)
    ]
    path.write_text("".join(lines), encoding="utf-8")
    return path


def test_fields_agree_with_read_tables(root: Path, tmp_path: Path) -> None:
    pytest.importorskip("pyarrow")
    [row] = capture.read_tables(_log(tmp_path / "named.log"))["Named"].to_pylist()
    flat = capture.fields(_message())
    assert (row["name"], row["choice.type"], row["choice.name"]) == ("abc", "name", "xyz")
    assert flat["choice.value"].decode() == row["choice.name"]
    for index, item in enumerate(row["choices"]):  # inside a list, uint8 arrays are binary
        assert flat[f"choices_{index}.value"] == item[item["type"]]
    [wrap] = row["wraps"]
    assert flat["wraps_0.choice.value"] == wrap["choice"][wrap["choice"]["type"]]


def test_decode_prints_the_union_member_as_text(root: Path, tmp_path: Path) -> None:
    log = _log(tmp_path / "named.log")
    result = subprocess.run(
        [sys.executable, "-m", "veronte4x", "decode", str(log), "--dsdl", str(root)],
        capture_output=True,
        text=True,
        check=False,
        env={**os.environ, "COLUMNS": "200"},
    )
    assert (result.returncode, result.stderr) == (
        0,
        "veronte4x: 1 record, 0 undecoded, 0 bad (skip)\n",
    )
    [line] = result.stdout.splitlines()
    assert line.endswith(f" {format_message(_message())}"), line
    assert "b'" not in line
