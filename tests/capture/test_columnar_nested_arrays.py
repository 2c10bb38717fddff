"""Arrays of structs in the shapes no standard type has, decoded column-wise against the
serializer and through the engine against the per-frame path: items of variable size (in
tail position and before another field), items of a few bits in tail position (ending in
a scalar, a static array, a nested struct, an array of structs), a static array of structs
in tail position, and items without named fields (an empty struct, padding alone).

A branch of `veronte4x.capture.columnar.payloads` no input reaches:
``payloads.py:239`` (the loop of ``tail_structs`` running to its end): its last pass,
``k == t.max_size``, breaks whether any element still has a whole byte left (too many
items: refused) or not. Unions inside arrays of structs are in `test_columnar_unions`.
"""

from __future__ import annotations

import tempfile
from pathlib import Path
from typing import Any

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.capture.columnar_support import (
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

NEST = Path(__file__).resolve().parent / "data" / "dsdl" / "nest"
NEST_TYPES = TypeSet.standard().with_dsdl(NEST)
NEST_CODECS = NEST_TYPES.codecs[len(CODECS) :]
NEST_SPECS = dronecan_specs(NEST_TYPES, "binary")
BUS_MAP = BusMap(dronecan_types=NEST_TYPES)


def _codec(name: str) -> TypeCodec:
    [found] = [c for c in NEST_CODECS if c.data_type.schema.cls.__name__ == name]
    return found


def _encode(name: str, data: dict[str, Any]) -> bytes:
    found = _codec(name)
    message: Any = dronecan.from_builtin(found.data_type.schema.cls, data, NEST_TYPES)
    return found.encode(message, True)


def test_the_namespace_has_the_shapes() -> None:
    assert [c.data_type.schema.cls.__name__ for c in NEST_CODECS] == [
        "Holes",
        "Flags",
        "Wraps",
        "Nibs",
        "Duos",
        "Words",
        "Mixed",
        "Hollows",
    ]


@pytest.mark.parametrize(
    "found", NEST_CODECS, ids=[c.data_type.schema.cls.__name__ for c in NEST_CODECS]
)
def test_every_shape_on_uniform_and_short_payloads(found: TypeCodec) -> None:
    sizes = range(found.max_payload + 2)
    fills = (0x00, 0xFF, 0x5A, 0xA5)
    check(found, [bytes([fill]) * n for fill in fills for n in sizes], NEST_SPECS)


@settings(max_examples=300)
@given(st.lists(any_payload(NEST_TYPES), min_size=1, max_size=12))
def test_any_payloads_of_the_shapes_agree(drawn: list[tuple[TypeCodec, bytes]]) -> None:
    """Encoded values (arrays empty, full or between), cut short, lengthened, any bytes."""
    by_type: dict[int, list[bytes]] = {}
    for found, payload in drawn:
        by_type.setdefault(NEST_TYPES.codecs.index(found), []).append(payload)
    for index, items in by_type.items():
        check(NEST_TYPES.codecs[index], items, NEST_SPECS)


def _bits(text: str) -> bytes:
    """Bytes from a bit string (spaces ignored), padded with zeros to a whole byte."""
    text = text.replace(" ", "")
    text += "0" * (-len(text) % 8)
    return int(text, 2).to_bytes(len(text) // 8, "big")


def _octets(data: bytes) -> str:
    return " ".join(f"{byte:08b}" for byte in data)


def test_the_last_item_of_variable_size_takes_the_rest_of_the_payload() -> None:
    """``Word[<=4] words`` in tail position: the array's length is there (items under 8
    bits: no tail array optimisation), each item's bytes behind their length but the last
    item's, which run to the end of the payload."""
    data = {"count": 3, "words": [{"letters": b"ab"}, {"letters": b"xyz"}]}
    payload = _encode("Words", data)
    # count 3 (4 bits), 2 words (3 bits), 2 letters (2 bits) "ab", then "xyz" alone
    assert payload == _bits(f"0011 010 10 {_octets(b'ab')} {_octets(b'xyz')}")
    message: Any = _codec("Words").decode(payload)
    assert [word.letters for word in message.words] == [b"ab", b"xyz"]
    shorter: Any = _codec("Words").decode(payload[:-1])  # "z" cut: 7 bits, not a letter
    assert [word.letters for word in shorter.words] == [b"ab", b"xy"]
    with pytest.raises(dronecan.DecodeError, match=r"words\[1\]\.letters: 4 items, more than 3"):
        _codec("Words").decode(payload + b"q")
    check(_codec("Words"), [payload, payload + b"q", payload[:-1]], NEST_SPECS)


def _lines(items: list[tuple[str, bytes]]) -> list[str]:
    out = []
    stamp = 1_700_000_000.0
    for tid, (name, payload) in enumerate(items):
        for can_id, data, _ in transfer_frames(_codec(name), payload, 42, None, tid % 32):
            stamp += 0.001
            out.append(f"({stamp:.6f}) can0 {can_id:08X}#{data.hex().upper()}")
    return out


def test_items_without_named_fields_are_empty_structs_in_both_paths(tmp_path: Path) -> None:
    """Arrays of an empty struct, and of padding alone, are lists of empty structs (the
    per-frame path's; the column-wise one raised TypeError before)."""
    holes = _encode("Holes", {"code": 9, "nothings": [{}, {}]})
    hollows = _encode(
        "Hollows",
        {"pads": [{}, {}], "hollows": [{"code": 1, "nothing": {}}, {"code": 2, "nothing": {}}]},
    )
    path = write(tmp_path / "holes.log", _lines([("Holes", holes), ("Hollows", hollows)]))
    expected = capture.tables_from_records(capture.read(path, BUS_MAP), BUS_MAP)
    got = capture.read_tables(path, BUS_MAP)
    assert_same_tables(got, expected)
    [row] = rows(got["Holes"])
    assert (row["code"], row["nothings"]) == (9, [{}, {}])
    [row] = rows(got["Hollows"])
    assert row["pads"] == [{}, {}]
    assert row["hollows"] == [{"code": 1, "nothing": {}}, {"code": 2, "nothing": {}}]


@settings(max_examples=80, suppress_health_check=[HealthCheck.too_slow])
@given(st.data())
def test_generated_captures_with_the_shapes_agree(data: st.DataObject) -> None:
    """The shapes beside standard types, faults included, through the whole engine."""
    lines = data.draw(captures(BUS_MAP))
    with tempfile.TemporaryDirectory() as folder:
        path = write(Path(folder) / "capture.log", lines)
        expected = capture.tables_from_records(capture.read(path, BUS_MAP), BUS_MAP)
        got = capture.read_tables(path, BUS_MAP)
    assert_same_tables(got, expected)


def test_an_enum_inside_an_empty_array_of_structs_keeps_its_names(tmp_path: Path) -> None:
    """Transfers whose array of structs is empty in every row still give the enum field
    its whole dictionary (the wire value is the index), so that a batch of them and a
    batch with items combine (Arrow refused to unify an empty dictionary with 256 names)."""
    empty = dronecan.encode(dronecan.ArrayCommand(()), source_node_id=10, transfer_id=0)
    lines = [f"(1.{i:06d}) can0 {f.can_id:08X}#{f.data.hex().upper()}" for i, f in enumerate(empty)]
    got = capture.read_tables(write(tmp_path / "empty.log", lines))
    column = got["ArrayCommand"].column("commands")
    command_type = column.combine_chunks().flatten().field("command_type")
    assert len(command_type.dictionary) == 256
    assert command_type.dictionary[:2].to_pylist() == ["UNITLESS", "POSITION"]
