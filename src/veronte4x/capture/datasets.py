"""Datasets of `veronte4x.capture.to_parquet`: one directory per capture, one file per
table, and one table read over every capture.

The layout::

    out_dir/capture=flight1.log-3f2a9c01d2e4/Status.parquet
    out_dir/capture=flight1.log-3f2a9c01d2e4/EscStatus.parquet
    out_dir/capture=flight1.log-3f2a9c01d2e4/errors.parquet

A capture's directory appears, and is replaced, by one rename (see
`veronte4x.capture.columnar.dataset`): a reader sees all of a capture's tables or none.
One table over every capture is the glob ``out_dir/capture=*/Status.parquet`` (DuckDB,
Polars, Dask), or the files `dataset_files` lists (pyarrow, pandas).
"""

from __future__ import annotations

import errno
import hashlib
import os
import re
from pathlib import Path
from typing import TYPE_CHECKING

from veronte4x.extras import require

if TYPE_CHECKING:
    import pyarrow.dataset

CAPTURE = "capture="
"""What the name of a capture's directory starts with (Hive style: a ``capture`` column)."""
ESCAPE = "table-"
"""Put before a table's name that starts with ``.`` or ``_`` (a DBC message may):
readers skip files named so."""
SUFFIX = ".parquet"
STEM = 200
"""Characters of a capture's base name kept in its directory's name: with the run's suffix
(`veronte4x.capture.columnar.dataset`), the name stays within the 255 bytes file systems
take."""


def capture_directory(source: str) -> str:
    """The name of a capture's directory: ``capture=``, its base name (characters other
    than letters, digits, ``.``, ``_`` and ``-`` replaced, leading ``.`` and ``_``
    dropped, cut to ``STEM`` characters) and a digest of its path, both of the path
    resolved (`resolved`): every spelling of one file names one directory."""
    path = resolved(source)
    stem = re.sub(r"[^A-Za-z0-9._-]", "_", os.path.basename(path)).lstrip("._")[:STEM]
    stem = stem or "capture"
    digest = hashlib.sha256(path.encode("utf-8", "surrogateescape")).hexdigest()[:12]
    return f"{CAPTURE}{stem}-{digest}"


def resolved(source: str) -> str:
    """A capture's path made absolute, with symbolic links, ``.`` and ``..`` resolved:
    ``flight.log``, ``./flight.log``, its absolute path and a link to it are one capture."""
    return os.path.realpath(source)


def table_file(table: str) -> str:
    """The name of a table's file in a capture's directory: ``Status.parquet``;
    ``table-_Private.parquet`` for a table whose name starts with ``.`` or ``_``."""
    return f"{ESCAPE if table.startswith(('.', '_')) else ''}{table}{SUFFIX}"


def _table_of(file: str) -> str:
    """The table a file of a capture's directory holds (`table_file` undone)."""
    table = file.removesuffix(SUFFIX)
    return table.removeprefix(ESCAPE) if table.startswith((f"{ESCAPE}.", f"{ESCAPE}_")) else table


def dataset_files(out_dir: str | os.PathLike[str], table: str) -> list[str]:
    """The files of one table over every capture of a dataset, sorted by path: for
    ``pq.read_table``, ``pd.read_parquet`` or ``pyarrow.dataset.dataset``."""
    name = table_file(table)
    return sorted(os.fspath(p) for p in Path(out_dir).glob(f"{CAPTURE}*/{name}"))


def dataset_tables(out_dir: str | os.PathLike[str]) -> list[str]:
    """The tables some capture of a dataset has, sorted."""
    files = Path(out_dir).glob(f"{CAPTURE}*/*{SUFFIX}")
    return sorted({_table_of(p.name) for p in files})


def open_dataset(out_dir: str | os.PathLike[str], table: str) -> pyarrow.dataset.Dataset:
    """One table over every capture of a dataset, as a ``pyarrow.dataset.Dataset``, with
    the ``capture`` column of its directories' names (as DuckDB and Polars read it).
    Needs the ``parquet`` extra.

    Raises:
        FileNotFoundError: No capture of the dataset has this table; the message lists
            those it has.
    """
    ds = require("pyarrow.dataset", "parquet", "reading a dataset")

    files = dataset_files(out_dir, table)
    if not files:
        tables = ", ".join(dataset_tables(out_dir)) or "none"
        raise FileNotFoundError(
            errno.ENOENT, f"no capture has a table {table} (the tables: {tables})", str(out_dir)
        )
    return ds.dataset(
        files, format="parquet", partitioning="hive", partition_base_dir=os.fspath(out_dir)
    )
