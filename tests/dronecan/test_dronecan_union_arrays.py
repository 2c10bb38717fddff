"""Arrays of a union type (``U[<=3] us``, allowed by DSDL v0, refused by `load_dsdl`
before): a vendor namespace written for the purpose, static and dynamic arrays, with and
without the tail array optimisation, items of a few bits and items ending in one. The
``dronecan`` package, loaded with the same directory, is the reference for the signatures,
the frames and the values; the generated code is checked against the generic serializer.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

import pytest
from dronecan_oracle import reference_builtin, reference_decode, reference_frames
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from test_dronecan_compiled import _payloads, messages
from test_dronecan_differential import schema_strategy
from tests.plain_data import same

import dronecan as dc
from veronte4x import dronecan as v4
from veronte4x.dronecan import TypeSet
from veronte4x.dronecan.codec import TypeCodec
from veronte4x.dronecan.compiled import DECODE_FALLBACK
from veronte4x.errors import DecodeError

NAMESPACE = {
    "E": ["# No field."],
    "P": ["uint5 x", "bool[2] f"],
    "U": ["# Members of 0 to 24 bits.", "@union", "uint8 a", "float16 h", "P p", "E e"],
    "W": ["# Members of 8 bits at least: arrays of it take the TAO.", "@union", "uint8 a",
          "int16 b", "P p"],
    "Small": ["@union", "uint2 a", "bool b"],
    "T": ["# Ends in an array of unions.", "uint4 k", "U[<=2] us"],
    "24800.Tail": ["uint8 k", "W[<=3] ws"],
    "24801.Pair": ["U[2] pair", "uint8 after"],
    "24802.Lists": ["Small[<=5] smalls", "U[<=3] us"],
    "24803.Items": ["T[<=3] ts"],
    "24804.Statics": ["uint3 k", "Small[3] smalls"],
}  # fmt: skip
KINDS = ["Tail", "Pair", "Lists", "Items", "Statics"]


@pytest.fixture(scope="module")
def types(tmp_path_factory: pytest.TempPathFactory) -> Iterator[TypeSet]:
    """The namespace ``ua`` in our set, and loaded into the ``dronecan`` package."""
    root = tmp_path_factory.mktemp("dsdl") / "ua"
    root.mkdir()
    for name, lines in NAMESPACE.items():
        (root / f"{name}.uavcan").write_text("\n".join(lines) + "\n")
    dc.load_dsdl(str(root))
    yield TypeSet.standard().with_dsdl(root)
    dc.load_dsdl()


def _codec(types: TypeSet, kind: str) -> TypeCodec:
    return types.by_class[types[f"ua.{kind}"]]


def _frames(types: TypeSet, kind: str, fields: dict[str, Any]) -> list[tuple[int, bytes]]:
    message: Any = v4.from_builtin(types[f"ua.{kind}"], fields, types)
    made = v4.encode(message, source_node_id=5, transfer_id=3, types=types)
    return [(f.can_id, f.data) for f in made]


def _theirs(kind: str, fields: dict[str, Any]) -> list[tuple[int, bytes]]:
    from dronecan_oracle import reference_object

    made = reference_object(f"ua.{kind}", v4.TransferKind.MESSAGE, fields)
    return reference_frames(made, 5, None, 3, 16, v4.TransferKind.MESSAGE)


@pytest.mark.parametrize("kind", KINDS)
def test_signature_equals_the_dronecan_package(types: TypeSet, kind: str) -> None:
    assert _codec(types, kind).data_type.signature == (
        dc.TYPENAMES[f"ua.{kind}"].get_data_type_signature()
    )


def test_exact_bytes_of_an_array_of_unions(types: TypeSet) -> None:
    """``U[<=3] us`` in tail position, items under 8 bits at the least: a 2-bit length,
    then each item's 2-bit tag and member."""
    fields = {"smalls": [], "us": [{"a": 0xAB}, {"e": {}}, {"p": {"x": 3, "f": [True, False]}}]}
    [(_, data)] = _frames(types, "Lists", fields)
    # smalls: 0 (3 bits); us: 3 (2 bits); a: 00 10101011; e: 11; p: 10 00011 1 0
    bits = "000" + "11" + "00" + "10101011" + "11" + "10" + "00011" + "10"
    bits += "0" * (-len(bits) % 8)
    assert data[:-1] == int(bits, 2).to_bytes(len(bits) // 8, "big")
    assert _frames(types, "Lists", fields) == _theirs("Lists", fields)


@pytest.mark.parametrize("kind", KINDS)
@settings(max_examples=60, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(data=st.data())
def test_frames_identical_and_cross_decoded(types: TypeSet, kind: str, data: st.DataObject) -> None:
    """Every member, arrays empty, full or between: the same frames as the ``dronecan``
    package, and each decodes the other's to the same values."""
    codec = _codec(types, kind)
    fields = data.draw(schema_strategy(codec.data_type.schema), label="fields")
    ours = _frames(types, kind, fields)
    theirs = _theirs(kind, fields)
    assert ours == theirs
    transfer = v4.decode_frames(theirs, 0.0, types)
    assert same(v4.to_builtin(transfer.message, types), reference_builtin(reference_decode(ours)))


@pytest.mark.parametrize("kind", KINDS)
@settings(max_examples=60, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(data=st.data())
def test_generated_code_equals_the_generic_serializer(
    types: TypeSet, kind: str, data: st.DataObject
) -> None:
    """Valid values take the generated code both ways; any bytes decode as the generic
    serializer decodes them (or leave the generated code for its error)."""
    codec = _codec(types, kind)
    message = data.draw(messages(codec.data_type.schema, faults=False), label="message")
    payload = codec.fast.payload(message)  # never hands over: the values are valid
    assert payload == codec.generic.encode(message)
    assert same(
        v4.to_builtin(codec.fast.decode(payload), types),
        v4.to_builtin(codec.generic.decode(payload), types),
    )
    bytes_ = data.draw(_payloads(codec), label="payload")
    try:
        expected: Any = codec.generic.decode(bytes_)
    except DecodeError as error:
        expected = error
    try:
        decoded = codec.fast.decode(bytes_)
    except DECODE_FALLBACK:
        assert isinstance(expected, DecodeError)  # a valid payload never leaves the fast path
    else:
        assert repr(decoded) == repr(expected)
