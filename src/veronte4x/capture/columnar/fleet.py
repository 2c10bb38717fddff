"""Captures converted on a Dask cluster: each file on a worker, into one dataset.

Needs the ``dask`` extra (``pip install 'veronte4x[dask]'``). Every worker runs
`dataset.convert_file` on whole files and puts each capture's directory into the same
dataset directory, which must be one every worker and the client see (a shared file
system); a capture's directory appears there by one rename, whichever worker wrote it, and
the hidden directories of its runs name the machine, so that a worker cleans up only after
runs of its own machine. A file is never split: the DroneCAN sessions and the line numbers
of a capture run from its start, so each file is decoded by one worker from its first line
to its last.
"""

from __future__ import annotations

import dataclasses
import os
from typing import Any

from veronte4x.capture.busmap import BusMap
from veronte4x.capture.columnar.dataset import Summary, convert_file
from veronte4x.codec import ByteOrder, Field, Layout
from veronte4x.extras import require
from veronte4x.progress import Bar


def convert_on(
    client: Any,
    paths: list[str],
    out_dir: str | os.PathLike[str],
    bus_map: BusMap | None,
    channel: str | None,
    batch_bytes: int,
    progress: bool | None,
    time: str = "timestamp",
) -> list[Summary]:
    """Convert the captures on the workers of a ``dask.distributed.Client``; return each
    file's summary, in the order of ``paths``. A failure on a worker is raised here."""
    distributed = require("distributed", "dask", "converting on a Dask cluster")
    futures = client.map(
        _convert,
        paths,
        out_dir=os.fspath(out_dir),
        bus_map=_portable(bus_map),
        channel=channel,
        batch_bytes=batch_bytes,
        time=time,
        pure=False,
    )
    bar = Bar(progress, len(futures), "file", "converting")
    try:
        for _ in distributed.as_completed(futures):
            bar.update(1)
    finally:
        bar.close()
    summaries: list[Summary] = client.gather(futures)
    return summaries


Portable = tuple[dict[str, Any], tuple[tuple[int, str, tuple[Field, ...], ByteOrder], ...]]
"""A bus map as plain data: its settings, and each declared layout's arguments."""


def _portable(bus_map: BusMap | None) -> Portable | None:
    """A bus map that pickles: declared layouts carry generated classes, which do not."""
    if bus_map is None:
        return None
    settings = {
        f.name: getattr(bus_map, f.name)
        for f in dataclasses.fields(bus_map)
        if f.init and f.name != "layouts"
    }
    layouts = tuple((x.command, x.name, x.fields, x.byte_order) for x in bus_map.layouts)
    return settings, layouts


def _convert(
    path: str,
    out_dir: str,
    bus_map: Portable | None,
    channel: str | None,
    batch_bytes: int,
    time: str,
) -> Summary:
    """`convert_file` on a worker, the bus map rebuilt there."""
    rebuilt = None
    if bus_map is not None:
        settings, layouts = bus_map
        rebuilt = BusMap(**settings, layouts=tuple(Layout(*args) for args in layouts))
    return convert_file(path, out_dir, rebuilt, channel, batch_bytes, time_form=time)
