"""DroneCAN text fields as Arrow strings, their bytes never altered.

DSDL v0 has no text type: names, paths and log text are ``uint8`` arrays, text by the rule
of `veronte4x.dronecan.generate.is_text`. With the text form ``string`` (the default,
`veronte4x.capture.busmap.TextForm`) their columns are Arrow ``string``; bytes that are
not UTF-8 are not replaced or dropped silently: the value is null, and the row gets a
``bad text`` row in the ``errors`` table (same time, channel, CAN ID and sender) whose
``data`` holds the field's bytes. `veronte4x.capture.columnar.tables.Tables` applies this
to every row whichever path decoded it, so `read_tables` and `tables_from_records` agree.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np
import numpy.typing as npt
import pyarrow as pa

BAD_TEXT = "bad text"
"""The ``error`` of a text field whose bytes are not UTF-8."""

_HEAD = ("time", "has_time", "channel", "can_id", "sender")
"""The head columns a ``bad text`` row takes from the row of its field."""


def strings(values: Any) -> tuple[pa.Array, npt.NDArray[np.bool_]]:
    """A text field's values (a binary Arrow array, or bytes and None) as Arrow strings.

    Returns:
        The strings, null where the bytes are not UTF-8, and which rows those are.
    """
    binary = values if isinstance(values, pa.Array) else pa.array(list(values), pa.binary())
    try:
        return binary.cast(pa.string()), np.zeros(len(binary), np.bool_)
    except pa.ArrowInvalid:  # rare: find the values that are not UTF-8, one by one
        pass
    texts: list[str | None] = []
    bad = np.zeros(len(binary), np.bool_)
    for row, value in enumerate(binary.to_pylist()):
        try:
            texts.append(None if value is None else value.decode("utf-8"))
        except UnicodeDecodeError:
            texts.append(None)
            bad[row] = True
    return pa.array(texts, pa.string()), bad


def bad_text_rows(
    kind: str,
    column: str,
    head: Mapping[str, Any],
    values: Any,
    bad: npt.NDArray[np.bool_],
) -> dict[str, Any]:
    """The head columns of the ``errors`` rows of the ``bad`` rows of a text column.

    Args:
        kind: The table.
        column: The text column.
        head: The head columns of the table's rows, as `Tables.add_columns` takes them.
        values: The column's values as given (binary, or bytes and None).
        bad: Which rows are not UTF-8 (`strings`).
    """
    rows = np.flatnonzero(bad)
    binary = values if isinstance(values, pa.Array) else pa.array(list(values), pa.binary())
    found: dict[str, Any] = {name: np.asarray(head[name])[rows] for name in _HEAD}
    found["error"] = [BAD_TEXT] * len(rows)
    detail = (
        f"{kind}.{column} is not UTF-8: null in the table, its bytes here "
        "(text='binary' keeps every uint8 array as bytes)"
    )
    found["detail"] = [detail] * len(rows)
    found["data"] = binary.take(pa.array(rows)).to_pylist()
    return found
