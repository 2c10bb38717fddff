"""Which Parquet columns a dataset dictionary-encodes: exactly the text leaves of every
table's schema (`dataset.text_columns`), found as Parquet names them, for every table the
engine can write (every standard DroneCAN type, both text forms, the Veronte tables, the
errors and unknown tables) and in the files a conversion writes."""

from __future__ import annotations

import io
from pathlib import Path

import pyarrow as pa
import pyarrow.parquet as pq
import pytest

from tests.capture.test_dataset import FLIGHT
from veronte4x import capture
from veronte4x.capture.columnar import dataset
from veronte4x.capture.columnar.schema import ERRORS, UNDECODED, all_specs
from veronte4x.codec import Codec


def _schemas() -> dict[str, pa.Schema]:
    schemas = {}
    for text in ("string", "binary"):
        for kind, spec in all_specs(Codec(), None, text).items():
            schemas[f"{kind} ({text})"] = spec.schema.append(dataset.SOURCE)
    for spec in (ERRORS, UNDECODED):
        schemas[spec.kind] = spec.schema.append(dataset.SOURCE)
    return schemas


SCHEMAS = _schemas()


def _parquet_text_leaves(schema: pa.Schema) -> list[str]:
    """The leaves a Parquet file of ``schema`` stores as text, by their paths in it."""
    out = io.BytesIO()
    pq.write_table(schema.empty_table(), out)
    out.seek(0)
    stored = pq.ParquetFile(out).schema
    columns = [stored.column(index) for index in range(len(stored))]
    return [column.path for column in columns if str(column.logical_type) == "String"]


def test_the_schemas_include_nested_text() -> None:
    nested = [name for name, schema in SCHEMAS.items() if "." in str(dataset.text_columns(schema))]
    assert "GetNodeInfoResponse (string)" in nested  # name: a uint8 array read as text
    assert len(nested) >= 20


@pytest.mark.parametrize("name", sorted(SCHEMAS))
def test_the_text_columns_are_the_leaves_parquet_stores_as_text(name: str) -> None:
    schema = SCHEMAS[name]
    assert dataset.text_columns(schema) == _parquet_text_leaves(schema)


def test_nested_text_is_named_by_its_parquet_path() -> None:
    schema = pa.schema(
        [
            ("names", pa.list_(pa.string())),
            (
                "point",
                pa.struct([("label", pa.dictionary(pa.int8(), pa.string())), ("x", pa.int8())]),
            ),
            ("raw", pa.binary()),
            (
                "rows",
                pa.list_(pa.struct([("name", pa.string()), ("values", pa.list_(pa.uint8()))])),
            ),
        ]
    )
    assert dataset.text_columns(schema) == [
        "names.list.element",
        "point.label",
        "rows.list.element.name",
    ]
    assert dataset.text_columns(schema) == _parquet_text_leaves(schema)


def test_a_conversion_dictionary_encodes_text_and_nothing_else(tmp_path: Path) -> None:
    capture.to_parquet(FLIGHT, tmp_path)
    files = sorted(tmp_path.glob("capture=*/*.parquet"))
    assert len(files) > 5
    for path in files:
        metadata = pq.ParquetFile(path).metadata
        text = set(dataset.text_columns(pq.read_schema(path)))
        assert text >= {"channel", "source"}
        for group in range(metadata.num_row_groups):
            for index in range(metadata.num_columns):
                chunk = metadata.row_group(group).column(index)
                dictionary = chunk.has_dictionary_page
                assert dictionary == (chunk.path_in_schema in text), (path.name, chunk)
