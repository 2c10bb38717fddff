"""MF4 bus logging (ASAM MDF 4) read column-wise through asammdf, chunk by chunk.

Frames come out as python-can's MF4 reader gives them, in memory that does not grow with
the file: every CAN frame group (data, error and remote frames) is read in chunks of about
``batch_bytes`` of records, through a file object rather than asammdf's memory map of the
whole file (whose pages stay resident once read, so that the map grows to the file's
size). Timestamps are the file's start time plus each record's time, channels the bus
channel number as text, and the groups are merged as python-can merges them
(``heapq.merge`` on the timestamps, group order breaking ties). That merge equals a stable
sort of all rows by (the largest timestamp of its group so far, group, row), which is what
`merge` computes, chunk by chunk, releasing the rows no later chunk can precede.

An unfinalised file (a logger stopped before closing it), which asammdf finalises by
writing to what it reads, is opened by its path (asammdf then maps a finalised copy). A
file asammdf cannot open goes to python-can's reader, which says what is wrong with it (or
which extra is missing); a chunk asammdf cannot read hands the rest of the file to
python-can's reader from the frame where the chunks stopped.
"""

from __future__ import annotations

import contextlib
import dataclasses
import itertools
from collections.abc import Iterator
from typing import Any

import numpy as np
import numpy.typing as npt

from veronte4x.capture.columnar.batches import BATCH_FRAMES, Batch
from veronte4x.capture.columnar.frames import MAX_DATA, FrameColumns, concat, from_frames
from veronte4x.capture.readers.pythoncan import collect_quietly, quiet_parsers
from veronte4x.capture.readers.pythoncan import frames as python_can_frames
from veronte4x.capture.source import Source

_GROUPS = ("CAN_DataFrame", "CAN_ErrorFrame", "CAN_RemoteFrame")


def columns(source: Source) -> FrameColumns:
    """The whole file's frames as columns (the batches of `batches`, joined)."""
    return concat([batch.frames for batch in batches(source, 0, BATCH_FRAMES)] or [_empty()])


def batches(source: Source, batch_bytes: int, batch_frames: int) -> Iterator[Batch]:
    """The file's frames in batches of at most ``batch_frames`` and about ``batch_bytes``
    of records per frame group (``batch_bytes`` 0: ``batch_frames`` alone)."""
    size = max(batch_frames, 1)
    with contextlib.ExitStack() as files:
        try:
            with quiet_parsers():
                mdf = _open(source, files)
        except Exception:  # python-can's reader says how the file is damaged, or what it
            mdf = None  # can read, or which extra is missing (an ImportError)
        if mdf is None:
            collect_quietly()  # out here the parser's error and its traceback's frames are gone
            yield from _python_can(source, size, 0)
            return
        yield from _read(mdf, source, batch_bytes, size)


def _open(source: Source, files: contextlib.ExitStack) -> Any:
    """asammdf's reader of the file, on a file object that ``files`` closes."""
    from asammdf import MDF
    from asammdf.blocks.v4_blocks import FileIdentificationBlock

    stream = files.enter_context(open(source.path, "rb"))  # noqa: SIM115 (closed by files)
    unfinalised = FileIdentificationBlock(stream=stream).unfinalized_standard_flags
    stream.seek(0)
    # Without asammdf's bus-logging pass, which reads every group whole on opening (an
    # option of its MDF4 class that MDF passes on, missing from MDF's types).
    return MDF(source.path if unfinalised else stream, process_bus_logging=False)  # type: ignore[call-arg]


def _read(mdf: Any, source: Source, batch_bytes: int, size: int) -> Iterator[Batch]:
    """The frames of the opened file, then python-can's from where a chunk failed."""
    position = 0
    try:
        with quiet_parsers():
            start = mdf.header.start_time.timestamp()
            groups = [
                _chunks(mdf, index, kind, names, start, _records(mdf, index, batch_bytes, size))
                for index, kind, names in _groups(mdf)
            ]
        merged = merge(groups)
        while True:
            with quiet_parsers():
                frames = next(merged, None)
            if frames is None:
                return
            frames.order = np.arange(position + 1, position + len(frames) + 1, dtype=np.int64)
            position += len(frames)
            yield Batch(frames, None)
    except Exception:  # damage past the first chunk: python-can's reader goes on from here
        pass
    finally:
        mdf.close()
    collect_quietly()  # only after damage: the frames' end returns above
    yield from _python_can(source, size, position)


def _groups(mdf: Any) -> Iterator[tuple[int, str, set[str]]]:
    """The CAN frame groups holding records: their index, kind and channel names."""
    for index, group in enumerate(mdf.groups):
        names = {channel.name for channel in group.channels}
        kind = next((g for g in _GROUPS if g in names), None)
        if kind is not None and group.channel_group.cycles_nr:
            yield index, kind, names


def _records(mdf: Any, index: int, batch_bytes: int, batch_frames: int) -> int:
    """Records of group ``index`` read at once: about ``batch_bytes``, at most
    ``batch_frames``."""
    group = mdf.groups[index].channel_group
    record = int(group.samples_byte_nr) + int(group.invalidation_bytes_nr)
    if batch_bytes <= 0 or record <= 0:
        return batch_frames
    return max(1, min(batch_frames, batch_bytes // record))


def _chunks(
    mdf: Any, index: int, kind: str, names: set[str], start: float, size: int
) -> Iterator[FrameColumns]:
    """The records of one frame group, ``size`` at a time, as columns."""
    total = int(mdf.groups[index].channel_group.cycles_nr)
    for offset in range(0, total, size):
        yield _chunk(mdf, index, kind, names, start, offset, size)


def _chunk(
    mdf: Any, index: int, kind: str, names: set[str], start: float, offset: int, count: int
) -> FrameColumns:
    # The whole frame structure at once: asammdf reads only the chunk's records for it (for
    # the DataBytes array channel alone, it would read the whole group and slice it).
    chunk = mdf.get(kind, group=index, raw=True, record_offset=offset, record_count=count)
    samples = chunk.samples

    def get(field: str) -> np.ndarray:
        values: np.ndarray = samples[f"{kind}.{field}"]
        return values

    ids = get("ID").astype(np.uint32)
    stamps = chunk.timestamps + start
    n = len(ids)
    remote = kind == "CAN_RemoteFrame"
    length = np.zeros(n, np.int64) if remote else get("DataLength").astype(np.int64)
    data = np.zeros((n, MAX_DATA), np.uint8)
    long_data: dict[int, bytes] = {}
    if not remote:
        raw = get("DataBytes")
        width = min(raw.shape[1], MAX_DATA)
        data[:, :width] = raw[:, :width]
        data[~(np.arange(MAX_DATA) < length[:, None])] = 0
        for row in np.flatnonzero(length > MAX_DATA).tolist():
            long_data[row] = raw[row, : length[row]].tobytes()
    if f"{kind}.BusChannel" in names:
        values, codes = np.unique(get("BusChannel").astype(np.int64), return_inverse=True)
        channels = [str(v) for v in values.tolist()]
    else:
        codes, channels = np.zeros(n, np.int64), [""]
    flag = np.zeros(n, np.bool_)
    brs = get("BRS").astype(np.bool_) if f"{kind}.BRS" in names else flag
    esi = get("ESI").astype(np.bool_) if f"{kind}.ESI" in names else flag
    dlc = get("DLC").astype(np.int64) if remote and f"{kind}.DLC" in names else length
    dlc = dlc if remote else np.zeros(n, np.int64)
    odd = np.flatnonzero(brs | esi | (dlc != 0)).tolist()
    flags = {row: (bool(brs[row]), bool(esi[row]), int(dlc[row])) for row in odd}
    return FrameColumns(
        order=np.arange(n, dtype=np.int64),
        timestamp=stamps.astype(np.float64),
        has_time=np.ones(n, np.bool_),
        channel=codes.astype(np.int32).reshape(n),
        channels=channels,
        can_id=ids & np.uint32(0x1FFFFFFF),
        extended=get("IDE").astype(np.bool_) if f"{kind}.IDE" in names else flag.copy(),
        remote=np.full(n, remote),
        fd=get("EDL").astype(np.bool_) if f"{kind}.EDL" in names else flag.copy(),
        error=np.full(n, kind == "CAN_ErrorFrame"),
        length=length,
        data=data,
        long_data=long_data,
        flags=flags,
    )


class _Pending:
    """The rows of one group read and not yet merged, with their merge keys."""

    def __init__(self, chunks: Iterator[FrameColumns]) -> None:
        self.chunks = chunks
        self.rows: FrameColumns | None = None
        self.keys = np.zeros(0, np.float64)
        self.peak = -np.inf
        self.count = 0
        self.done = False

    def read(self) -> None:
        """Read the group's next chunk into the pending rows (or find it has no more)."""
        chunk = next(self.chunks, None)
        if chunk is None:
            self.done = True
            return
        keys = np.maximum.accumulate(np.maximum(chunk.timestamp, self.peak))
        if len(keys):
            self.peak = float(keys[-1])
        chunk = _numbered(chunk, self.count)  # increasing within the group, for concat
        self.count += len(chunk)
        self.rows = chunk if self.rows is None or not len(self.rows) else concat([self.rows, chunk])
        self.keys = np.concatenate([self.keys, keys])

    def release(self, below: float) -> tuple[FrameColumns, npt.NDArray[np.float64]] | None:
        """The pending rows whose key is below ``below``, removed from the pending ones."""
        cut = int(np.searchsorted(self.keys, below, "left"))
        if not cut or self.rows is None:
            return None
        rows, keys = self.rows, self.keys
        self.rows = rows.take(np.arange(cut, len(rows)))
        self.keys = keys[cut:]
        return rows.take(np.arange(cut)), keys[:cut]


def merge(groups: list[Iterator[FrameColumns]]) -> Iterator[FrameColumns]:
    """The frames of several groups, each given in chunks, merged as ``heapq.merge`` merges
    their frames by timestamp; each yielded part holds the rows no later chunk precedes."""
    pending = [_Pending(chunks) for chunks in groups]
    while True:
        for group in pending:
            while not group.done and not len(group.keys):
                group.read()
        live = [group for group in pending if not group.done]
        below = min((float(group.keys[-1]) for group in live), default=np.inf)
        released = [part for group in pending if (part := group.release(below)) is not None]
        if not released:
            if not live:
                return
            for group in live:  # every pending row is at ``below``: read on past it
                if group.keys[-1] == below:
                    group.read()
            continue
        keys = np.concatenate([keys for _, keys in released])
        starts = itertools.accumulate([len(rows) for rows, _ in released[:-1]], initial=0)
        joined = concat([_numbered(r, at) for (r, _), at in zip(released, starts, strict=True)])
        order = np.argsort(keys, kind="stable")
        yield joined.take(order, np.arange(len(order), dtype=np.int64))


def _numbered(frames: FrameColumns, start: int) -> FrameColumns:
    """``frames`` with positions ``start``, ``start + 1``, ..."""
    return dataclasses.replace(frames, order=np.arange(start, start + len(frames), dtype=np.int64))


def _python_can(source: Source, size: int, skip: int) -> Iterator[Batch]:
    """python-can's reader of the file, from frame ``skip`` on."""
    items = itertools.islice(enumerate(python_can_frames(source), 1), skip, None)
    while chunk := list(itertools.islice(items, size)):
        yield Batch(from_frames(chunk), None)


def _empty() -> FrameColumns:
    return from_frames([])
