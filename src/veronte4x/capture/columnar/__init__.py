"""The columnar engine: whole captures into typed Arrow tables, one per message type.

Needs the ``arrow`` extra (``pip install 'veronte4x[arrow]'``: pyarrow and NumPy). The
public entry points are `veronte4x.capture.read_tables` and
`veronte4x.capture.tables_from_records`; the modules here are its parts: `sources` opens a
capture as `frames.FrameColumns` (`candump` parses text column-wise), `engine` routes and
decodes (`veronte` and `dronecan` column-wise, the per-frame decoder for the rest), `schema`
fixes each table's columns and `tables` assembles them.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterable

from veronte4x.errors import MissingExtraError

try:
    import numpy as np
    import numpy.typing as npt
    import pyarrow as pa
except ModuleNotFoundError as missing:  # pragma: no cover - the arrow extra is installed in CI
    if missing.name not in ("numpy", "pyarrow"):
        raise
    raise MissingExtraError(missing.name, "arrow", "veronte4x.capture.columnar") from None

from veronte4x.capture.busmap import BusMap
from veronte4x.capture.columnar import batches
from veronte4x.capture.columnar.batches import Reread, ahead, rereadable
from veronte4x.capture.columnar.engine import tables_from_records
from veronte4x.capture.columnar.stream import StreamDecoder, TooManySessions
from veronte4x.capture.columnar.tables import Clock
from veronte4x.progress import Bar

__all__ = ["keyed_tables", "read_tables", "tables_from_records"]

CapturePath = str | os.PathLike[str]
"""The path of a capture file (``-`` for standard input)."""


def read_tables(
    source: CapturePath | Iterable[CapturePath],
    bus_map: BusMap | None = None,
    channel: str | None = None,
    time: str = "timestamp",
    progress: bool | None = False,
) -> dict[str, pa.Table]:
    """See `veronte4x.capture.read_tables`."""
    Clock(time)  # a wrong option fails before any file is read
    paths = [source] if isinstance(source, (str, os.PathLike)) else list(source)
    sizes = [_size(path) for path in paths]
    bar = Bar(progress, sum(sizes), "B", "decoding")
    try:
        parts = []
        for path, size in zip(paths, sizes, strict=True):
            progress_of = _Advance(bar, size)
            keyed = keyed_tables(path, bus_map, channel, time, progress_of.reach)
            parts.append({kind: table for kind, (table, _) in keyed.items()})
            progress_of.reach(size)
    finally:
        bar.close()
    if len(parts) == 1:
        return parts[0]
    kinds = list(dict.fromkeys(kind for part in parts for kind in part))
    return {
        kind: pa.concat_tables([part[kind] for part in parts if kind in part]).combine_chunks()
        for kind in kinds
    }


class _Advance:
    """Moves a bar as one file is read: to each batch's position in it, never back (a
    channel decoded again frame by frame reads the file again from its start)."""

    def __init__(self, bar: Bar, size: int) -> None:
        self._bar, self._size, self._reached = bar, size, 0

    def reach(self, position: int) -> None:
        """Count the file read up to ``position`` bytes."""
        step = min(position, self._size) - self._reached
        if step > 0:
            self._bar.update(step)
            self._reached += step


def _size(path: CapturePath) -> int:
    """Bytes of a capture file, for the progress bar (0 for standard input or a bad path,
    which the reader reports)."""
    try:
        return os.path.getsize(path) if os.fspath(path) != "-" else 0
    except OSError:
        return 0


def keyed_tables(
    path: CapturePath,
    bus_map: BusMap | None,
    channel: str | None,
    time: str = "timestamp",
    reached: Callable[[int], None] | None = None,
) -> dict[str, tuple[pa.Table, npt.NDArray[np.int64]]]:
    """The tables of one capture, each with the capture-order keys of its rows.

    The capture is decoded batch by batch (as `veronte4x.capture.to_parquet` decodes
    it), so that memory holds the tables and one batch, not the whole capture's frames;
    standard input and a pipe, which cannot be read twice, keep their batches as they come
    (to decode again a channel that must go frame by frame). ``reached``, if given, is
    called with the bytes of the file read so far after each batch (for a progress bar).
    ``time``: the form of the ``timestamp`` column (`veronte4x.times.TimeForm`).
    """
    clock = Clock(time, channel)
    return clock(_batched(rereadable(path, batches.BATCH_BYTES), bus_map, channel, reached, clock))


def _batched(
    read: Reread,
    bus_map: BusMap | None,
    channel: str | None,
    reached: Callable[[int], None] | None,
    clock: Clock,
) -> dict[str, tuple[pa.Table, npt.NDArray[np.int64]]]:
    per_frame: list[str] = []
    while True:  # once more per channel whose DroneCAN frames must go frame by frame
        decoder = StreamDecoder(bus_map, channel, per_frame)
        parts: dict[str, list[tuple[pa.Table, npt.NDArray[np.int64]]]] = {}
        try:
            for batch in ahead(read(), decoder.prepare):
                clock.see(batch.frames)
                for kind, part in decoder.feed_with_keys(batch.frames, batch.prepared).items():
                    parts.setdefault(kind, []).append(part)
                if reached is not None and batch.position is not None:
                    reached(batch.position)
            decoder.finish()
        except TooManySessions as signal:
            per_frame.append(signal.channel)
            continue
        return {
            kind: (pa.concat_tables([t for t, _ in got]), np.concatenate([k for _, k in got]))
            for kind, got in parts.items()
        }
