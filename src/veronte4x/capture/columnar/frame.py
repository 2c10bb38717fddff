"""One pandas DataFrame of a whole capture, from its Arrow tables."""

from __future__ import annotations

import os
from typing import TYPE_CHECKING

import numpy as np

from veronte4x.capture.busmap import BusMap
from veronte4x.capture.columnar.engine import decode_into
from veronte4x.capture.columnar.sources import read_frames

if TYPE_CHECKING:
    import pandas


def dataframe(
    path: str | os.PathLike[str], bus_map: BusMap | None = None, channel: str | None = None
) -> pandas.DataFrame:
    """See `veronte4x.capture.to_dataframe`: every table of `read_tables` in one frame."""
    import pandas

    parts = []
    keys = []
    tables = decode_into(read_frames(path), bus_map, channel).finish_with_keys()
    for kind, (table, key) in tables.items():
        frame = table.to_pandas(types_mapper=pandas.ArrowDtype)
        if kind in ("errors", "unknown"):
            frame.insert(4, "message", None)
            frame["data"] = [value.hex() for value in table.column("data").to_pylist()]
        else:
            frame.insert(4, "message", kind)
        parts.append(frame)
        keys.append(key)
    if not parts:
        return pandas.DataFrame(columns=["timestamp", "channel", "can_id", "sender", "message"])
    joined = pandas.concat(parts, ignore_index=True, sort=False)
    order = np.argsort(np.concatenate(keys), kind="stable")
    return joined.iloc[order].reset_index(drop=True)
