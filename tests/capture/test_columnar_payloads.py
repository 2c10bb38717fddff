"""Column-wise DSDL payload decoding against the serializer, over every standard type."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tests.capture.columnar_support import VENDOR_TYPES, any_payload
from tests.plain_data import same
from veronte4x.capture.columnar import payloads
from veronte4x.capture.columnar.schema import dronecan_specs, field_column
from veronte4x.dronecan.codec import CODECS, TypeCodec
from veronte4x.errors import DecodeError

pa = pytest.importorskip("pyarrow")
SPECS = dronecan_specs(text="binary")  # payloads give bytes; `Tables` makes text strings
VENDOR_SPECS = dronecan_specs(VENDOR_TYPES, "binary")
VENDOR_CODECS = VENDOR_TYPES.codecs[len(CODECS) :]


def check(found: TypeCodec, items: list[bytes], specs: dict[str, Any] = SPECS) -> None:
    """Decode ``items`` of one type column-wise and one by one: the same values, and the
    same payloads refused (``specs``: the tables of the type's set)."""
    schema = found.data_type.schema
    spec = specs[schema.cls.__name__]
    sizes = np.array([len(p) for p in items], np.int64)
    starts = np.concatenate([[0], np.cumsum(sizes)[:-1]]).astype(np.int64)
    blob = np.frombuffer(b"".join(items) + b"\0", np.uint8)[: int(sizes.sum())]
    columns, refused = payloads.decode(schema, blob, starts, sizes)
    columns = {field_column(name): value for name, value in columns.items()}
    assert set(columns) == {c.name for c in spec.columns}
    for row, payload in enumerate(items):
        try:
            message = found.decode(payload)
        except DecodeError:
            assert refused[row], payload.hex()
            continue
        assert not refused[row], payload.hex()
        for column in spec.columns:
            value = columns[column.name]
            got = value[row].as_py() if isinstance(value, pa.Array) else value[row].item()
            if column.names is None:  # through Arrow, as the record tables hold it
                expected = pa.array(column.values([message]), column.type)[0].as_py()
            else:
                expected = column.get(message)
            assert same(got, expected), (column.name, payload.hex())


@settings(max_examples=300)
@given(st.lists(any_payload(), min_size=1, max_size=12))
def test_any_types_and_payloads_agree(drawn: list[tuple[TypeCodec, bytes]]) -> None:
    by_type: dict[int, list[bytes]] = {}
    for found, payload in drawn:
        by_type.setdefault(CODECS.index(found), []).append(payload)
    for index, items in by_type.items():
        check(CODECS[index], items)


@pytest.mark.parametrize("found", CODECS, ids=[c.data_type.schema.cls.__name__ for c in CODECS])
def test_every_type_on_zeros_and_short_payloads(found: TypeCodec) -> None:
    sizes = range(min(found.max_payload, 64) + 2)
    check(found, [bytes(n) for n in sizes] + [bytes([0xFF]) * n for n in sizes])


@settings(max_examples=200)
@given(st.lists(any_payload(VENDOR_TYPES), min_size=1, max_size=12))
def test_vendor_types_and_payloads_agree(drawn: list[tuple[TypeCodec, bytes]]) -> None:
    by_type: dict[int, list[bytes]] = {}
    for found, payload in drawn:
        by_type.setdefault(VENDOR_TYPES.codecs.index(found), []).append(payload)
    for index, items in by_type.items():
        check(VENDOR_TYPES.codecs[index], items, VENDOR_SPECS)


@pytest.mark.parametrize(
    "found", VENDOR_CODECS, ids=[c.data_type.schema.cls.__name__ for c in VENDOR_CODECS]
)
def test_every_vendor_type_on_zeros_and_short_payloads(found: TypeCodec) -> None:
    sizes = range(min(found.max_payload, 64) + 2)
    check(found, [bytes(n) for n in sizes] + [bytes([0xFF]) * n for n in sizes], VENDOR_SPECS)
