"""Captures into a Parquet dataset: one directory per capture, one file per table.

The layout (`veronte4x.capture.datasets`)::

    out_dir/capture=flight1.log-3f2a9c01d2e4/Status.parquet
    out_dir/capture=flight1.log-3f2a9c01d2e4/EscStatus.parquet
    out_dir/capture=flight1.log-3f2a9c01d2e4/errors.parquet

Each file holds the rows one capture gives for one table, in capture order, with the
table's fixed schema and a last column ``source``: the capture's path as given.

A run writes a capture's files into a hidden directory of its own
(``out_dir/.capture=flight1.log-3f2a9c01d2e4.HOST-PID-TOKEN/new``, which no documented
reader takes: the globs name ``capture=*``, pyarrow skips names starting with ``.``) and,
once the whole capture is decoded, puts that directory in place by one rename: readers see
all of the capture's tables or none. A capture converted before is replaced in one step
where the system can (Linux's ``renameat2`` exchange: readers see the old tables or the new
ones; one that lists the files and opens them later may take tables of both, each whole),
else its directory is first moved into the run's (readers see none of it until the new one
is in place). A run that fails puts back what it moved aside and removes its
directory; the next run into ``out_dir`` does the same for runs of this machine killed
outright. Two runs on the same capture at once both succeed: the last one's tables stay.
"""

from __future__ import annotations

import contextlib
import ctypes
import errno
import hashlib
import os
import re
import secrets
import shutil
import socket
import sys
import time
from collections.abc import Callable, Iterable
from concurrent.futures import Future, ThreadPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import pyarrow as pa
import pyarrow.compute as pc
import pyarrow.parquet as pq

from veronte4x.capture.busmap import BusMap
from veronte4x.capture.columnar.batches import BATCH_BYTES, ahead, rereadable
from veronte4x.capture.columnar.stream import StreamDecoder, TooManySessions
from veronte4x.capture.columnar.tables import Clock
from veronte4x.capture.datasets import CAPTURE, capture_directory, resolved, table_file
from veronte4x.capture.source import STDIN
from veronte4x.errors import NotACaptureError, SourceError
from veronte4x.progress import Bar
from veronte4x.words import counted

SOURCE = pa.field("source", pa.dictionary(pa.int32(), pa.string()))
"""The column naming the capture a row comes from."""
ROW_GROUP = 1 << 17
"""Rows of a table gathered before they are written as one row group."""
BUFFERED = 1 << 25
"""Bytes of rows all tables may hold back together; past it the largest is written."""

ReadProgress = Callable[[int], None]
"""Told the bytes of a capture read so far."""


def _reached(stage: str) -> None:
    """Told each stage of a commit as it is passed (``written``: every file closed;
    ``aside``: the capture's directory moved aside, where it cannot be exchanged;
    ``published``: the run's in place; ``committed``: the run's directory removed): the
    tests replace it to kill the process or raise a file system error at every stage."""


@dataclass
class Summary:
    """What a conversion wrote.

    Attributes:
        files: Captures converted.
        frames: Frames read (bad lines not counted).
        records: Rows written per table.
        seconds: Wall time.
        truncated: Where each capture that ends early ends (the ``detail`` of its
            ``truncated`` error row, e.g. "f.log.gz: the gzip data ends early, at line
            14: the file is truncated").
    """

    files: int = 0
    frames: int = 0
    records: dict[str, int] = field(default_factory=dict)
    seconds: float = 0.0
    truncated: list[str] = field(default_factory=list)

    @property
    def errors(self) -> int:
        """Rows of the ``errors`` table."""
        return self.records.get("errors", 0)

    def add(self, other: Summary) -> None:
        """Count another conversion's files, frames and rows in this one (not its time)."""
        self.files += other.files
        self.frames += other.frames
        for kind, count in other.records.items():
            self.records[kind] = self.records.get(kind, 0) + count
        self.truncated.extend(other.truncated)

    def __repr__(self) -> str:
        """As a dataclass's, ``seconds`` to 3 significant digits (exact in the attribute)."""
        return (
            f"Summary(files={self.files}, frames={self.frames}, records={self.records!r}, "
            f"seconds={self.seconds:.3g}, truncated={self.truncated!r})"
        )

    def _repr_html_(self) -> str:
        """Jupyter's view: the counts and time, the rows per table, where captures end early."""
        from veronte4x.display import side_by_side, table

        kinds = self._kinds()
        head = [
            ("files", self.files),
            ("frames", self.frames),
            ("records", sum(self.records[k] for k in kinds)),
            ("errors", self.errors),
            ("seconds", f"{self.seconds:.3g} s"),
        ]
        parts = [table("Summary", ("", ""), head, header=False)]
        if kinds:
            parts.append(
                table("rows per table", ("", "rows"), [(k, self.records[k]) for k in kinds])
            )
        if self.truncated:
            parts.append(table("ends early", ("capture",), [(t,) for t in self.truncated]))
        return side_by_side(parts)

    def _kinds(self) -> list[str]:
        """The tables written but ``errors``, the largest first."""
        return sorted((k for k in self.records if k != "errors"), key=lambda k: -self.records[k])

    def line(self) -> str:
        """One line for a person: files, frames, records per table, errors and time."""
        kinds = self._kinds()
        total = sum(self.records[k] for k in kinds)
        per_kind = ", ".join(f"{kind} {self.records[kind]}" for kind in kinds)
        return (
            f"{counted(self.files, 'file')}, {counted(self.frames, 'frame')}, "
            f"{counted(total, 'record')}"
            + (f" ({per_kind})" if per_kind else "")
            + f", {counted(self.errors, 'error')}, {self.seconds:.3g} s"
        )


def convert_file(
    path: str | os.PathLike[str],
    out_dir: str | os.PathLike[str],
    bus_map: BusMap | None = None,
    channel: str | None = None,
    batch_bytes: int = BATCH_BYTES,
    progress: ReadProgress | None = None,
    time_form: str = "timestamp",
) -> Summary:
    """Decode one capture batch by batch into the dataset at ``out_dir``, its
    ``timestamp`` column in the form ``time_form`` names (`veronte4x.times.TimeForm`).

    Raises:
        SourceError: The path is standard input (a dataset names its files).
    """
    name = os.fspath(path)
    if name == STDIN:
        raise SourceError("a dataset is written from files: give a capture file, not -")
    started = time.perf_counter()
    read = rereadable(name, batch_bytes)  # a pipe is read once
    per_frame: list[str] = []
    truncated: list[str] = []
    while True:  # once more per channel with more DroneCAN sessions than a table holds
        writer = _Writer(Path(out_dir), name)
        decoder = StreamDecoder(bus_map, channel, per_frame)
        clock = Clock(time_form, channel)
        frames = bad = 0
        truncated.clear()
        try:
            for batch in ahead(read(), decoder.prepare):
                frames += len(batch.frames)
                clock.see(batch.frames)
                tables = decoder.feed_with_keys(batch.frames, batch.prepared)
                for kind, (table, _) in clock(tables).items():
                    if kind == "errors":
                        truncated.extend(_truncations(table))
                        bad += _bad_lines(table)
                    writer.write(kind, table)
                if progress is not None and batch.position is not None:
                    progress(batch.position)
            decoder.finish()
            if bad and not frames:
                raise NotACaptureError(name, bad)
        except TooManySessions as signal:
            writer.abort()
            per_frame.append(signal.channel)
            continue
        except BaseException:
            writer.abort()
            raise
        records = writer.commit()
        return Summary(1, frames, records, time.perf_counter() - started, truncated)


def _bad_lines(errors: pa.Table) -> int:
    """The ``bad line`` rows of an ``errors`` table."""
    count: int = pc.sum(pc.equal(errors["error"].cast(pa.string()), "bad line")).as_py() or 0
    return count


def _truncations(errors: pa.Table) -> list[str]:
    """The details of an ``errors`` table's ``truncated`` rows."""
    ends = errors.filter(pc.equal(errors["error"].cast(pa.string()), "truncated"))
    return [detail or "the input ends early" for detail in ends["detail"].to_pylist()]


def remove_stale(out_dir: Path) -> None:
    """Put back what runs of this machine no longer alive (killed outright) moved aside,
    and remove their hidden directories (``.capture=NAME.HOST-PID-TOKEN``).

    Raises:
        FileExistsError: ``out_dir`` holds a dataset of the layout before captures had
            directories (``message=TABLE``): a reader would see two layouts.
    """
    with os.scandir(out_dir) as entries:
        names = [entry.name for entry in entries]
    if any(name.startswith("message=") for name in names):
        raise FileExistsError(
            errno.EEXIST,
            "holds a dataset of the older layout (message=TABLE directories); convert into a "
            "new directory, or convert its captures again there",
            str(out_dir),
        )
    for name in names:
        if not name.startswith(f".{CAPTURE}"):
            continue
        run = _RUN.fullmatch(name)
        if run is None:  # no run's: left by something else
            continue
        final, host, pid = run.groups()
        if host != HOST or _alive(int(pid)):
            continue
        home = out_dir / name
        if (home / "old").is_dir() and not (out_dir / final).exists():  # killed with it aside
            with contextlib.suppress(OSError):  # another run may put it back first
                _rename_new(home / "old", out_dir / final)
        shutil.rmtree(home, ignore_errors=True)


HOST = hashlib.sha256(socket.gethostname().encode()).hexdigest()[:8]
"""This machine, in the names of its runs' directories: a run judges only its own
machine's runs dead or alive (several may write into a shared file system)."""
_RUN = re.compile(r"\.(capture=.+)\.([0-9a-f]{8})-([0-9]+)-[0-9a-f]{8}")
"""The name of a run's hidden directory: its capture's directory, machine, process, token."""


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except OSError:  # another user's process
        return True
    return True


_RENAME_NOREPLACE, _RENAME_EXCHANGE = 1, 2
_UNSUPPORTED = {errno.EINVAL, errno.ENOSYS, errno.EOPNOTSUPP}


def _renameat2() -> Any:
    """Linux's renameat2 (glibc 2.28 and later), or None."""
    try:
        function = ctypes.CDLL(None, use_errno=True).renameat2
    except (AttributeError, OSError):
        return None
    function.argtypes = [ctypes.c_int, ctypes.c_char_p, ctypes.c_int, ctypes.c_char_p]
    function.argtypes += [ctypes.c_uint]
    function.restype = ctypes.c_int
    return function


_renameat2_call = _renameat2() if sys.platform == "linux" else None


def _rename2(source: Path, target: Path, flags: int) -> bool | None:
    """renameat2 with ``flags``: True when done, None when the system or the file system
    does not have it.

    Raises:
        OSError: Any other failure (``FileExistsError`` when ``target`` exists and
            ``flags`` says not to replace it, ``FileNotFoundError`` when it is missing and
            ``flags`` says to exchange).
    """
    if _renameat2_call is None:
        return None
    at_cwd = -100
    if _renameat2_call(at_cwd, os.fsencode(source), at_cwd, os.fsencode(target), flags) == 0:
        return True
    code = ctypes.get_errno()
    if code in _UNSUPPORTED:
        return None
    raise OSError(code, os.strerror(code), os.fspath(source), None, os.fspath(target))


def _rename_new(source: Path, target: Path) -> bool:
    """Rename directory ``source`` to ``target`` unless a capture's directory is there
    already: False then."""
    try:
        if _rename2(source, target, _RENAME_NOREPLACE) is None:
            os.rename(source, target)  # onto an empty directory only, if one is there
    except OSError as error:
        if error.errno in (errno.EEXIST, errno.ENOTEMPTY):
            return False
        raise
    return True


TRIES = 100
"""Times a run tries to put its capture's directory in place while other runs of the same
capture replace it at the same moment."""


def _publish(new: Path, final: Path, old: Path) -> None:
    """Put directory ``new`` in place at ``final`` by one rename, whatever was there.

    A directory already at ``final`` is exchanged with ``new`` in one step where the system
    can (Linux's renameat2), else moved to ``old`` first (readers then see none of that
    capture for a moment). Either way the replaced directory ends in the run's own.

    Raises:
        OSError: (``EBUSY``) other runs of the same capture replaced it every time.
    """
    for _ in range(TRIES):
        if _rename_new(new, final):
            return
        try:
            if _rename2(new, final, _RENAME_EXCHANGE):
                return
        except FileNotFoundError:  # another run moved it aside meanwhile
            continue
        if old.exists():
            shutil.rmtree(old)
        try:
            os.rename(final, old)
        except FileNotFoundError:
            continue
        _reached("aside")
    raise OSError(
        errno.EBUSY,
        "other conversions of this capture keep replacing it; convert it again when they end",
        str(final),
    )


class _Writer:
    """The files of one capture: written into a hidden directory of the run, which
    `commit` renames into place.

    Row groups are compressed and written on a thread of their own, one at a time, while
    the next batch is decoded.
    """

    def __init__(self, out_dir: Path, source: str) -> None:
        self.source = source
        out_dir.mkdir(parents=True, exist_ok=True)
        remove_stale(out_dir)
        name = capture_directory(source)
        # Each run its own directory: two runs on one capture never share a file.
        run = f"{HOST}-{os.getpid()}-{secrets.token_hex(4)}"
        self.final = out_dir / name
        self.home = out_dir / f".{name}.{run}"
        self.new, self.old = self.home / "new", self.home / "old"
        self._writers: dict[str, pq.ParquetWriter] = {}
        self._buffers: dict[str, list[pa.Table]] = {}
        self._bytes: dict[str, int] = {}
        self.counts: dict[str, int] = {}
        self._thread = ThreadPoolExecutor(1)
        self._writing: Future[None] | None = None

    def write(self, kind: str, table: pa.Table) -> None:
        buffer = self._buffers.setdefault(kind, [])
        buffer.append(table)
        self.counts[kind] = self.counts.get(kind, 0) + len(table)
        self._bytes[kind] = self._bytes.get(kind, 0) + table.nbytes
        if sum(len(t) for t in buffer) >= ROW_GROUP:
            self._flush(kind)
        elif sum(self._bytes.values()) > BUFFERED:
            self._flush(max(self._bytes, key=self._bytes.__getitem__))

    def _flush(self, kind: str) -> None:
        buffer = self._buffers.pop(kind)  # never empty: `write` adds a table with its key
        del self._bytes[kind]
        self._wait()
        self._writing = self._thread.submit(self._write, kind, buffer)

    def _wait(self) -> None:
        if self._writing is not None:
            writing, self._writing = self._writing, None
            writing.result()

    def _write(self, kind: str, buffer: list[pa.Table]) -> None:
        # combine_chunks, not unify_dictionaries: the latter refuses a full uint8 enum
        # dictionary (256 names) even when every chunk has the same.
        table = pa.concat_tables(buffer).combine_chunks()
        source = pa.DictionaryArray.from_arrays(
            pa.array(np.zeros(len(table), np.int32)), pa.array([self.source], pa.string())
        )
        table = table.append_column(SOURCE, source)
        writer = self._writers.get(kind)
        if writer is None:
            self.new.mkdir(parents=True, exist_ok=True)
            writer = pq.ParquetWriter(
                self.new / table_file(kind),
                table.schema,
                use_dictionary=text_columns(table.schema),
            )
            self._writers[kind] = writer
        writer.write_table(table, row_group_size=max(len(table), 1))

    def commit(self) -> dict[str, int]:
        """Finish every file and put the capture's directory in place by one rename
        (replacing the one a run before wrote); return the rows written per table.

        On an error the capture is left as it was before the run, or as the run left it
        once in place, and the run's hidden directory is removed.
        """
        try:
            for kind in list(self._buffers):
                self._flush(kind)
            self._wait()
            self._thread.shutdown()
            for writer in self._writers.values():
                writer.close()
            self.new.mkdir(parents=True, exist_ok=True)  # a capture with no table: empty
            _reached("written")
            _publish(self.new, self.final, self.old)
            _reached("published")
            shutil.rmtree(self.home)
            _reached("committed")
        except BaseException:
            self.abort()
            raise
        return {kind: self.counts[kind] for kind in self._writers}

    def abort(self) -> None:
        """Drop the files being written; put back the capture's directory if the run
        moved it aside and did not put its own in place."""
        with contextlib.suppress(Exception):
            self._wait()
        self._thread.shutdown()
        for writer in self._writers.values():
            _discard(writer)
        self._writers.clear()
        self._buffers.clear()
        if self.old.is_dir() and not self.final.exists():
            with contextlib.suppress(OSError):
                _rename_new(self.old, self.final)
        shutil.rmtree(self.home, ignore_errors=True)


def text_columns(schema: pa.Schema) -> list[str]:
    """The Parquet column paths of ``schema``'s text leaves (strings and dictionaries),
    the only columns worth dictionary encoding: numbers written plainly take about half
    the CPU time and, compressed, no more room (docs/performance.md, "Parquet datasets")."""
    paths: list[str] = []

    def walk(path: str, kind: pa.DataType) -> None:
        if pa.types.is_struct(kind):
            for index in range(kind.num_fields):
                child = kind.field(index)
                walk(f"{path}.{child.name}", child.type)
        elif pa.types.is_list(kind):
            walk(f"{path}.list.element", kind.value_type)
        elif pa.types.is_dictionary(kind) or pa.types.is_string(kind):
            paths.append(path)

    for column in schema:
        walk(column.name, column.type)
    return paths


def _discard(writer: pq.ParquetWriter) -> None:
    """Close a writer whatever fails (a full disk fails the close too)."""
    try:
        writer.close()
    except Exception:
        writer.is_open = False  # else its __del__ closes it again and prints the error
        if writer.file_handle is not None:
            with contextlib.suppress(Exception):
                writer.file_handle.close()


def to_parquet(
    source: str | os.PathLike[str] | Iterable[str | os.PathLike[str]],
    out_dir: str | os.PathLike[str],
    bus_map: BusMap | None = None,
    client: Any = None,
    progress: bool | None = None,
    channel: str | None = None,
    batch_bytes: int = BATCH_BYTES,
    time_form: str = "timestamp",
) -> Summary:
    """See `veronte4x.capture.to_parquet` (``time_form``: its ``time``)."""
    Clock(time_form)  # a wrong option fails before any file is read
    started = time.perf_counter()
    paths = sources(source)
    if client is not None:
        from veronte4x.capture.columnar.fleet import convert_on

        parts = convert_on(
            client, paths, out_dir, bus_map, channel, batch_bytes, progress, time_form
        )
    else:
        parts = _convert_here(paths, out_dir, bus_map, channel, batch_bytes, progress, time_form)
    total = Summary()
    for part in parts:
        total.add(part)
    total.seconds = time.perf_counter() - started
    return total


def _convert_here(
    paths: list[str],
    out_dir: str | os.PathLike[str],
    bus_map: BusMap | None,
    channel: str | None,
    batch_bytes: int,
    progress: bool | None,
    time_form: str,
) -> list[Summary]:
    """Convert the captures one after the other in this process."""
    sizes = [os.path.getsize(p) for p in paths]
    bar = Bar(progress, sum(sizes), "B", "converting")
    parts = []
    try:
        for path, size in zip(paths, sizes, strict=True):
            read = [0]

            def advance(position: int, read: list[int] = read) -> None:
                bar.update(position - read[0])
                read[0] = position

            parts.append(
                convert_file(path, out_dir, bus_map, channel, batch_bytes, advance, time_form)
            )
            bar.update(size - read[0])
    finally:
        bar.close()
    return parts


def sources(source: str | os.PathLike[str] | Iterable[str | os.PathLike[str]]) -> list[str]:
    """The capture paths of a `to_parquet` call, checked to exist, each capture once (by
    its resolved path: the first of its spellings is kept)."""
    paths = [source] if isinstance(source, (str, os.PathLike)) else list(source)
    firsts: dict[str, str] = {}
    for given in paths:
        path = os.fspath(given)
        firsts.setdefault(path if path == STDIN else resolved(path), path)
    names = list(firsts.values())
    for name in names:
        if name == STDIN:
            raise SourceError("a dataset is written from files: give a capture file, not -")
        if not os.path.exists(name):
            raise FileNotFoundError(f"{name}: {os.strerror(errno.ENOENT)}")  # as `decode` says
    return names
