"""Captures converted on a Dask cluster: each file on a worker, into one dataset.

Needs the ``dask`` extra (``pip install 'veronte4x[dask]'``). Every worker runs
`dataset.convert_file` on whole files and writes its files into the same dataset
directory, which must be one every worker and the client see (a shared file system). A
file is never split: the DroneCAN sessions and the line numbers of a capture run from its
start, so each file is decoded by one worker from its first line to its last.
"""

from __future__ import annotations

import os
from typing import Any

from veronte4x.capture.busmap import BusMap
from veronte4x.capture.columnar.dataset import Summary, convert_file
from veronte4x.capture.columnar.progress import Bar
from veronte4x.extras import require


def convert_on(
    client: Any,
    paths: list[str],
    out_dir: str | os.PathLike[str],
    bus_map: BusMap | None,
    channel: str | None,
    batch_bytes: int,
    progress: bool | None,
) -> list[Summary]:
    """Convert the captures on the workers of a ``dask.distributed.Client``; return each
    file's summary, in the order of ``paths``. A failure on a worker is raised here."""
    distributed = require("distributed", "dask", "converting on a Dask cluster")
    futures = client.map(
        convert_file,
        paths,
        out_dir=os.fspath(out_dir),
        bus_map=bus_map,
        channel=channel,
        batch_bytes=batch_bytes,
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
