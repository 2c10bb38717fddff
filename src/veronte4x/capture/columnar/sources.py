"""Open any capture as `FrameColumns`: the columnar side of `veronte4x.capture.source`.

candump text (files, gzip, standard input) is parsed column-wise; MF4 bus logging is read
as whole arrays through asammdf; every other format python-can reads (BLF, ASC, TRC, CSV)
is read message by message through python-can and buffered into columns. Each gives the
frames the per-frame readers give, in the same order.
"""

from __future__ import annotations

import gzip
import io
import os
import sys
import zlib
from collections.abc import Iterable
from typing import Any

import numpy as np

from veronte4x.capture.columnar.candump import parse_stream, parse_text
from veronte4x.capture.columnar.frames import MAX_DATA, FrameColumns, concat, from_frames
from veronte4x.capture.frames import BadLine, Frame
from veronte4x.capture.readers.candump import parse_candump
from veronte4x.capture.source import (
    Format,
    Source,
    Truncated,
    open_binary,
    open_lines,
    resolve,
)


def read_frames(path: str | os.PathLike[str]) -> FrameColumns:
    """The frames of one capture, as columns.

    Raises:
        ImportError: The format needs python-can (or asammdf) and it is not installed.
    """
    source = resolve(path)
    if source.format is Format.CANDUMP:
        return _candump(source)
    from veronte4x.capture.readers.pythoncan import (
        collect_quietly,
        quiet_parsers,
        read_with_python_can,
    )

    if source.path.lower().endswith(".mf4"):
        try:
            with quiet_parsers():
                return _mf4(source.path)
        except ImportError:
            pass  # python-can says which extra is missing
        except Exception:  # a damaged file: python-can's reader says how, or what it can read
            collect_quietly()

    return from_frames(list(enumerate(read_with_python_can(source.path), 1)))


def _candump(source: Source) -> FrameColumns:
    if source.is_stdin:
        text = sys.stdin.buffer.read()
        columns = parse_text(text)
        if columns is not None:
            return columns
        return _line_by_line(io.TextIOWrapper(io.BytesIO(text), "utf-8", "replace"), "-")
    try:
        with open_binary(source) as stream:
            columns = parse_stream(stream)
    except (EOFError, gzip.BadGzipFile, zlib.error):
        columns = None  # a truncated gzip file: where it ends is the per-frame reader's call
    if columns is not None:
        return columns
    with open_lines(source) as lines:
        return _line_by_line(lines, source.path)


def _line_by_line(lines: Iterable[str], path: str) -> FrameColumns:
    """Text the column parser does not read as the per-frame reader does (lone carriage
    returns, a truncated gzip file): parse it line by line, with that reader's lines."""
    items: list[tuple[int, Frame | BadLine]] = []
    try:
        for number, line in enumerate(lines, 1):
            items += [(number, item) for item in parse_candump((line,), first_line=number)]
    except Truncated as cut:
        items.append((cut.line_number, cut.bad_line()))
    return from_frames(items)


_GROUPS = ("CAN_DataFrame", "CAN_ErrorFrame", "CAN_RemoteFrame")


def _mf4(path: str) -> FrameColumns:
    """MF4 bus logging (ASAM MDF 4): every CAN frame group read as whole arrays.

    Frames come out as python-can's MF4 reader gives them: timestamps are the file's start
    time plus each record's time, channels the bus channel number as text, groups merged
    in time order (a stable merge, group order breaking ties).
    """
    from asammdf import MDF

    mdf = MDF(path)
    start = mdf.header.start_time.timestamp()
    parts = []
    groups: list[Any] = mdf.groups
    for index, group in enumerate(groups):
        names = {channel.name for channel in group.channels}
        kind = next((g for g in _GROUPS if g in names), None)
        if kind is None or not group.channel_group.cycles_nr:
            continue
        parts.append(_mf4_group(mdf, index, kind, names, start))
    mdf.close()
    if not parts:
        return from_frames([])
    stamps = np.concatenate([p.timestamp for p in parts])
    order = np.argsort(stamps, kind="stable")
    joined = concat(
        [
            FrameColumns(**{**vars(p), "order": np.arange(len(p), dtype=np.int64) + offset})
            for p, offset in zip(parts, np.cumsum([0] + [len(p) for p in parts[:-1]]), strict=True)
        ]
    )
    return joined.take(order, np.arange(1, len(order) + 1, dtype=np.int64))


def _mf4_group(mdf: Any, index: int, kind: str, names: set[str], start: float) -> FrameColumns:
    def get(field: str) -> np.ndarray:
        samples: np.ndarray = mdf.get(f"{kind}.{field}", group=index, raw=True).samples
        return samples

    ids = get("ID").astype(np.uint32)
    stamps = mdf.get(f"{kind}.ID", group=index, raw=True).timestamps + start
    n = len(ids)
    remote = kind == "CAN_RemoteFrame"
    length = np.zeros(n, np.int64) if remote else get("DataLength").astype(np.int64)
    data = np.zeros((n, MAX_DATA), np.uint8)
    long_data: dict[int, bytes] = {}
    if not remote:
        raw = get("DataBytes")
        width = min(raw.shape[1], MAX_DATA)
        data[:, :width] = raw[:, :width]
        mask = np.arange(MAX_DATA) < length[:, None]
        data[~mask] = 0
        for row in np.flatnonzero(length > MAX_DATA).tolist():
            long_data[row] = raw[row, : length[row]].tobytes()
    if f"{kind}.BusChannel" in names:
        bus = get("BusChannel").astype(np.int64)
        values, codes = np.unique(bus, return_inverse=True)
        channels = [str(v) for v in values.tolist()]
    else:
        codes, channels = np.zeros(n, np.int64), [""]
    flag = np.zeros(n, np.bool_)
    return FrameColumns(
        order=np.arange(n, dtype=np.int64),
        timestamp=stamps.astype(np.float64),
        has_time=np.ones(n, np.bool_),
        channel=codes.astype(np.int32),
        channels=channels,
        can_id=ids & np.uint32(0x1FFFFFFF),
        extended=get("IDE").astype(np.bool_) if f"{kind}.IDE" in names else flag.copy(),
        remote=np.full(n, remote),
        fd=get("EDL").astype(np.bool_) if f"{kind}.EDL" in names else flag.copy(),
        error=np.full(n, kind == "CAN_ErrorFrame"),
        length=length,
        data=data,
        long_data=long_data,
    )
