"""One pandas DataFrame of a whole capture, from its Arrow tables."""

from __future__ import annotations

import os
from typing import TYPE_CHECKING

import numpy as np

from veronte4x.capture.busmap import BusMap

if TYPE_CHECKING:
    import pandas


def dataframe(
    path: str | os.PathLike[str],
    bus_map: BusMap | None = None,
    channel: str | None = None,
    time: str = "timestamp",
) -> pandas.DataFrame:
    """See `veronte4x.capture.to_dataframe`: every table of `read_tables` in one frame."""
    import pandas

    from veronte4x.capture.columnar import keyed_tables

    parts = []
    keys = []
    units: dict[str, str] = {}
    for kind, (table, key) in keyed_tables(path, bus_map, channel, time).items():
        for field in table.schema:
            if field.metadata and b"unit" in field.metadata:
                units[field.name] = field.metadata[b"unit"].decode()
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
    frame = joined.iloc[order].reset_index(drop=True)
    frame.attrs["units"] = units
    return frame
