"""What is generated ahead of time from the shipped DSDL against what run-time compilation
makes of the same files (`veronte4x.dronecan.shipped_source`).

Per frame: every shipped type's fast paths, imported from `veronte4x.dronecan.fast`, give
what the same code compiled at run time (`compiled.compile_fast`) gives, value for value,
or both hand over to the generic serializer. As data: the schemas, ids, signatures and
field facts written into the package are those the parser and `types.data_types` compute.
Column-wise: `capture.read_tables` with the shipped set gives the tables of the same
roots loaded at run time.
"""

from __future__ import annotations

import itertools
import re
import typing
from typing import Any

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from test_dronecan_compiled import messages
from tests.capture.columnar_support import assert_same_tables, schema_values, transfer_frames

from veronte4x import capture, dronecan
from veronte4x.dronecan import standard, standard_data
from veronte4x.dronecan.codec import TypeCodec
from veronte4x.dronecan.compiled import (
    DECODE_FALLBACK,
    ENCODE_FALLBACK,
    FastPaths,
    compile_fast,
    transport_of,
)
from veronte4x.dronecan.parser import check_references, parse_namespaces
from veronte4x.dronecan.schema import DataType
from veronte4x.dronecan.serializer import EnumValues, enum_table
from veronte4x.dronecan.types import data_types, nested_signatures
from veronte4x.dronecan.typeset import TypeSet
from veronte4x.dronecan.vendor_roots import DSDL_ROOT, shipped_roots

SHIPPED = TypeSet.shipped()
_IDS = [f"{c.data_type.full_name}-{c.data_type.kind.name}" for c in SHIPPED.codecs]


def _outcome(function: Any, *args: Any) -> Any:
    """What a fast path gives: its result, or the fallback it raised (by type)."""
    try:
        return repr(function(*args))
    except (*ENCODE_FALLBACK, *DECODE_FALLBACK) as error:
        return type(error)


def _run_time(codec: TypeCodec) -> FastPaths:
    return compile_fast(codec.data_type.schema, transport_of(codec.data_type))


@pytest.mark.parametrize("codec", SHIPPED.codecs, ids=_IDS)
@settings(max_examples=8, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data())
def test_the_generated_fast_paths_are_those_compiled_at_run_time(
    codec: TypeCodec, data: st.DataObject
) -> None:
    assert codec.fast_module is not None
    ahead, compiled = codec.fast, _run_time(codec)
    assert ahead.payload.__code__.co_filename.endswith(codec.fast_module.rsplit(".", 1)[1] + ".py")
    assert (ahead.decode_frame is None) == (compiled.decode_frame is None)
    message = data.draw(messages(codec.data_type.schema, faults=True), label="message")
    service = codec.data_type.kind is not dronecan.TransferKind.MESSAGE
    transport = (42, 17, 9, 7 if service else None)
    assert _outcome(ahead.payload, message) == _outcome(compiled.payload, message)
    assert _outcome(ahead.frames, message, *transport) == _outcome(
        compiled.frames, message, *transport
    )
    payload = data.draw(
        st.binary(max_size=codec.max_payload + 3)
        | st.builds(codec.generic.encode, messages(codec.data_type.schema, faults=False)),
        label="payload",
    )
    assert _outcome(ahead.decode, payload) == _outcome(compiled.decode, payload)
    if ahead.decode_frame is not None and len(payload) <= 7:
        frame = payload + b"\xc5"
        assert _outcome(ahead.decode_frame, frame) == _outcome(compiled.decode_frame, frame)


def test_the_generated_data_is_what_the_parser_computes() -> None:
    """Schemas, ids, signatures (OVERRIDE_SIGNATURE included) and files of every shipped
    type, from the DSDL at run time, equal those written into the package."""
    parsed = parse_namespaces([DSDL_ROOT / "uavcan"])
    check_references(parsed)
    found = data_types(parsed, parsed, standard.CLASSES, standard.ENUMS, standard.UNION_MEMBERS)
    assert found == list(standard_data.DATA_TYPES)
    assert nested_signatures(parsed) == standard_data.NESTED_SIGNATURES
    loaded = TypeSet.standard().with_dsdl(*shipped_roots())  # compiled at run time
    assert [_shape(t) for t in loaded.data_types] == [_shape(t) for t in SHIPPED.data_types]
    assert _names(loaded) == _names(SHIPPED)
    assert _facts(loaded) == _facts(SHIPPED)


def _classes(types: TypeSet) -> list[type]:
    """Every class of a set, a union's members for its alias."""
    found = []
    for c in types.classes.values():
        found += [c] if isinstance(c, type) else list(typing.get_args(c))
    return found


def _names(types: TypeSet) -> dict[str, Any]:
    """The class name of each key (of a union, its members')."""
    return {
        k: c.__name__ if isinstance(c, type) else [m.__name__ for m in typing.get_args(c)]
        for k, c in types.classes.items()
    }


def _facts(types: TypeSet) -> dict[tuple[str, str], Any]:
    """The text, float16 and float32 attributes each class declares, by class name."""
    return {
        (c.__name__, fact): getattr(c, fact)
        for c in _classes(types)
        for fact in ("_TEXT_FIELDS_", "_FLOAT16_FIELDS_", "_FLOAT32_FIELDS_")
        if hasattr(c, fact)
    }


def _shape(t: DataType) -> tuple[Any, ...]:
    """A type as data, its classes by name (those loaded at run time live elsewhere)."""
    schema = re.sub(r"<\w+ '[\w.]*\.(\w+)'>", r"\1", repr(t.schema))
    return t.full_name, t.kind, t.data_type_id, t.signature, t.path, schema


@st.composite
def _capture(draw: st.DrawFn, types: TypeSet) -> list[str]:
    """Lines of one transfer of each of some shipped types, valid values."""
    lines = []
    codecs = draw(st.lists(st.sampled_from(types.codecs), min_size=1, max_size=12))
    for index, found in enumerate(codecs):
        value = draw(schema_values(found.data_type.schema))
        message: Any = dronecan.from_builtin(found.data_type.schema.cls, value, types)
        service = found.data_type.kind is not dronecan.TransferKind.MESSAGE
        frames = transfer_frames(
            found, found.encode(message, True), 10 + index, 5 if service else None, index % 32
        )
        for can_id, data, _ in frames:
            lines.append(f"({index:.6f}) can0 {can_id:08X}#{data.hex().upper()}")
    return lines


@settings(max_examples=10, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data())
def test_the_shipped_set_reads_tables_as_the_roots_loaded_at_run_time(
    tmp_path_factory: pytest.TempPathFactory, data: st.DataObject
) -> None:
    lines = data.draw(_capture(SHIPPED))
    path = tmp_path_factory.mktemp("aot") / "bus.log"
    path.write_text("".join(line + "\n" for line in lines))
    assert_same_tables(
        capture.read_tables(path, types=SHIPPED), capture.read_tables(path, types=_LOADED)
    )


_LOADED = TypeSet.standard().with_dsdl(*shipped_roots())
"""The shipped vendor roots compiled at run time (the reference of the tests above)."""


def test_a_wide_enum_field_is_looked_up_not_tabled() -> None:
    """``ardupilot.gnss.Status.status`` is a ``uint23`` of flags: its table of members by raw
    value looks each value up (a tuple would hold 8,388,608 entries, built on the type's
    first transfer), with the tuple's values."""
    schema = SHIPPED.by_class[SHIPPED["ardupilot.gnss.Status"]].data_type.schema
    flags = next(f.enum for f in schema.fields if f.enum is not None)
    table = enum_table(flags, 23)
    assert isinstance(table, EnumValues) and len(table) == 1 << 23
    members = {int(m): m for m in flags}  # type: ignore[attr-defined]
    for value in (0, *members, 3, (1 << 23) - 1):
        assert table[value] is members.get(value, value) or table[value] == value
        assert type(table[value]) is (flags if value in members else int)
    assert list(itertools.islice(table, 5)) == [table[i] for i in range(5)]
    with pytest.raises(IndexError):
        table[1 << 23]
    assert enum_table(flags, 8) == tuple(members.get(i, i) for i in range(256))
