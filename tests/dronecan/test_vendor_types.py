"""Every public vendor type (the shipped roots of dronecan/DSDL, loaded together) against the
``dronecan`` package, the reference: signatures and data type ids, then frames both ways.

The reference types are the package's own (``dronecan.TYPENAMES``, which its ``load_dsdl``
fills from its ``dsdl_specs``); ``mppt``, which the package ships but does not load, is
parsed from the same ``dsdl_specs`` by the package's parser and registered for the test
(``dronecan.DATATYPES``, ``base_crc`` and instantiation, as ``load_dsdl`` does it).
Values: the extremes of every field (arrays empty and full, each union branch) and
hypothesis values within the limits, encoded by both: the frames must be identical, and
each decodes the other's (veronte4x through `decode_frames` and the `Reassembler`) to
equal values.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from dronecan_oracle import _fill, reference_builtin, reference_decode, reference_frames
from hypothesis import given, settings
from hypothesis import strategies as st
from test_dronecan_differential import schema_strategy
from tests.plain_data import same

import dronecan as dc
from dronecan import dsdl, transport
from veronte4x import dronecan
from veronte4x.dronecan import TypeSet
from veronte4x.dronecan.definitions import DataType
from veronte4x.dronecan.parser import parse_namespaces, signature
from veronte4x.dronecan.schema import Array, Scalar, Struct, Union
from veronte4x.dronecan.vendor_roots import SHIPPED, shipped_roots

K = dronecan.TransferKind
SPECS = Path(dc.__file__).with_name("dsdl_specs")
TYPES = TypeSet.standard().with_dsdl(*shipped_roots())
VENDOR = [t for t in TYPES.data_types if t.full_name.split(".")[0] in SHIPPED]
REFERENCE = {
    t.full_name: t
    for t in dsdl.parse_namespaces([str(SPECS / root) for root in ("uavcan", *SHIPPED)])
}
KIND_NAMES = {K.MESSAGE: None, K.REQUEST: "request", K.RESPONSE: "response"}


def _reference_type(full_name: str) -> Any:
    return dc.TYPENAMES.get(full_name, REFERENCE[full_name])


def _instance_maker(t: Any) -> Any:
    """What ``load_dsdl`` gives a type to instantiate it with."""

    def instantiate(_mode: str | None = None) -> Any:
        return transport.CompoundValue(t, _mode)

    return instantiate


@pytest.fixture(scope="module", autouse=True)
def _unloaded_roots_registered() -> Iterator[None]:
    """The types the ``dronecan`` package ships but does not load (mppt), registered as
    its ``load_dsdl`` registers the others, for this module's tests only."""
    with pytest.MonkeyPatch.context() as patch:
        for name, t in REFERENCE.items():
            if name not in dc.TYPENAMES and t.default_dtid is not None:
                signature_bytes = t.get_data_type_signature().to_bytes(8, "little")
                patch.setattr(t, "base_crc", dsdl.crc16_from_bytes(signature_bytes), False)
                patch.setattr(t, "_instantiate", _instance_maker(t))
                patch.setitem(dc.DATATYPES, (t.default_dtid, t.kind), t)
        yield


def test_every_vendor_type_is_there_with_the_package_s_id_and_signature() -> None:
    theirs = {
        (t.full_name, kind)
        for t in REFERENCE.values()
        if t.default_dtid is not None and t.full_name.split(".")[0] in SHIPPED
        for kind in ((K.REQUEST, K.RESPONSE) if t.kind == t.KIND_SERVICE else (K.MESSAGE,))
    }
    assert {(t.full_name, t.kind) for t in VENDOR} == theirs
    assert len(VENDOR) == 73
    for t in VENDOR:
        reference = REFERENCE[t.full_name]
        assert (t.data_type_id, t.signature) == (
            reference.default_dtid,
            reference.get_data_type_signature(),
        ), t.full_name
        loaded = dc.TYPENAMES.get(t.full_name)
        if loaded is not None:  # the package's loaded type: the same
            assert loaded.get_data_type_signature() == t.signature


def test_every_definition_nested_ones_too_has_the_package_s_signature() -> None:
    """Every definition of the shipped trees (nested ones have no id but a signature,
    those with ``OVERRIDE_SIGNATURE`` included), our files against the package's."""
    ours = {**TYPES.definitions, **parse_namespaces(shipped_roots())}
    known: dict[str, int] = {}
    vendor = [name for name in ours if name.split(".")[0] in SHIPPED]
    assert len(vendor) == 61
    assert sum(ours[name].override_signature is not None for name in vendor) == 27
    for name in vendor:
        assert signature(name, ours, known) == REFERENCE[name].get_data_type_signature(), name


def _extreme(t: Any, high: bool, branch: int) -> Any:
    """Plain data of ``t`` at one end: every number at its low or high end, every dynamic
    array empty or full, every union on member ``branch`` (modulo its members)."""
    if isinstance(t, Struct):
        return {f.name: _extreme(f.type, high, branch) for f in t.fields if f.name}
    if isinstance(t, Union):
        member = t.members[branch % len(t.members)]
        return {member.name: _extreme(member.type, high, branch)}
    if isinstance(t, Array):
        size = t.max_size if high or not t.dynamic else 0
        return [_extreme(t.item, high, branch) for _ in range(size)]
    assert isinstance(t, Scalar)
    if t.kind == "float":
        return {16: 65504.0, 32: 3.4028234663852886e38, 64: 1.7976931348623157e308}[t.bits] * (
            1 if high else -1
        )
    if t.kind == "bool":
        return high
    return t.high if high else t.low


def _branches(t: Any) -> int:
    """The most members of any union in ``t`` (1 if none)."""
    if isinstance(t, Struct):
        return max((_branches(f.type) for f in t.fields), default=1)
    if isinstance(t, Union):
        return max(len(t.members), *(_branches(m.type) for m in t.members))
    if isinstance(t, Array):
        return _branches(t.item)
    return 1


def _both_ways(t: DataType, fields: dict[str, Any], source: int, transfer_id: int) -> None:
    destination = None if t.kind is K.MESSAGE else 42
    message: Any = dronecan.from_builtin(TYPES[_key(t)], fields, TYPES)
    ours = [
        (f.can_id, f.data)
        for f in dronecan.encode(
            message,
            source_node_id=source,
            destination_node_id=destination,
            transfer_id=transfer_id,
            types=TYPES,
        )
    ]
    reference = transport.CompoundValue(_reference_type(t.full_name), KIND_NAMES[t.kind])
    _fill(reference, fields)
    theirs = reference_frames(reference, source, destination, transfer_id, 16, t.kind)
    assert ours == theirs
    expected = reference_builtin(reference_decode(ours))
    decoded = dronecan.decode_frames(theirs, types=TYPES).message
    assert same(dronecan.to_builtin(decoded, TYPES), expected)
    reassembler = dronecan.Reassembler(types=TYPES)
    transfer = [reassembler.feed(can_id, data, timestamp=0.0) for can_id, data in theirs][-1]
    assert transfer is not None
    assert same(dronecan.to_builtin(transfer.message, TYPES), expected)


def _key(t: DataType) -> str:
    if t.kind is K.MESSAGE:
        return t.full_name
    return f"{t.full_name}.{'Request' if t.kind is K.REQUEST else 'Response'}"


IDS = [_key(t) for t in VENDOR]


@pytest.mark.parametrize("t", VENDOR, ids=IDS)
def test_the_extremes_both_ways(t: DataType) -> None:
    """Low ends with empty arrays, high ends with full arrays, each union branch."""
    for branch in range(_branches(t.schema)):
        for high in (False, True):
            _both_ways(t, _extreme(t.schema, high, branch), 127 if high else 1, 31 * high)


@pytest.mark.parametrize("t", VENDOR, ids=IDS)
@settings(max_examples=5)
@given(data=st.data())
def test_values_within_the_limits_both_ways(t: DataType, data: st.DataObject) -> None:
    fields = data.draw(schema_strategy(t.schema), label="fields")
    _both_ways(t, fields, data.draw(st.integers(1, 127)), data.draw(st.integers(0, 31)))
