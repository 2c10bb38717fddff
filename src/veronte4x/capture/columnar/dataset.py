"""Captures into a Parquet dataset, one file per capture and message type.

The layout (Hive partitioning, one directory per table of `read_tables`)::

    out_dir/message=Status/flight1-3f2a9c01d2e4.parquet
    out_dir/message=EscStatus/flight1-3f2a9c01d2e4.parquet
    out_dir/message=errors/flight1-3f2a9c01d2e4.parquet

Each file holds the rows one capture gives for one table, in capture order, with the
table's fixed schema and a last column ``source``: the capture's path as given. A file is
written under a hidden temporary name of its run (``.name.PID-TOKEN.tmp``, which Parquet
readers skip); when the whole capture is decoded, the run writes a hidden commit journal
(``out_dir/.commit-name.PID-TOKEN.json``: the renames to make), renames its files into
place one table after the other, and removes the journal. The renames of several
directories cannot be one atomic step for readers that list each directory: a run killed
during them leaves its journal, and the next run into the same directory finishes them
before anything else, so the dataset then holds all of that capture's tables or, when the
kill came before the journal, none of the new ones. Converting a capture again replaces its
files (and removes those of tables it no longer has). Two runs on the same capture at once
both succeed (the last to finish puts its files in place); the temporary files of a run
killed outright are removed by the next run into the same directory.
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import os
import re
import secrets
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
from veronte4x.capture.columnar.batches import BATCH_BYTES, ahead, read_batches
from veronte4x.capture.columnar.stream import StreamDecoder, TooManySessions
from veronte4x.capture.columnar.tables import Clock
from veronte4x.capture.source import STDIN
from veronte4x.errors import SourceError
from veronte4x.progress import Bar

SOURCE = pa.field("source", pa.dictionary(pa.int32(), pa.string()))
"""The column naming the capture a row comes from."""
ROW_GROUP = 1 << 17
"""Rows of a table gathered before they are written as one row group."""
BUFFERED = 1 << 25
"""Bytes of rows all tables may hold back together; past it the largest is written."""

Progress = Callable[[int], None]
"""Told the bytes of a capture read so far."""


def _reached(stage: str) -> None:
    """Told each stage of a commit as it is passed (``written``, ``journal``,
    ``renamed KIND``, ``committed``): the tests replace it to kill the process or raise a
    file system error at every stage."""


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

    def line(self) -> str:
        """One line for a person: files, frames, records per table, errors and time."""
        kinds = sorted((k for k in self.records if k != "errors"), key=lambda k: -self.records[k])
        total = sum(self.records[k] for k in kinds)
        per_kind = ", ".join(f"{kind} {self.records[kind]}" for kind in kinds)
        return (
            f"{self.files} files, {self.frames} frames, {total} records"
            + (f" ({per_kind})" if per_kind else "")
            + f", {self.errors} errors, {self.seconds:.3g} s"
        )


def convert_file(
    path: str | os.PathLike[str],
    out_dir: str | os.PathLike[str],
    bus_map: BusMap | None = None,
    channel: str | None = None,
    batch_bytes: int = BATCH_BYTES,
    progress: Progress | None = None,
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
    per_frame: list[str] = []
    truncated: list[str] = []
    while True:  # once more per channel with more DroneCAN sessions than a table holds
        writer = _Writer(Path(out_dir), name)
        decoder = StreamDecoder(bus_map, channel, per_frame)
        clock = Clock(time_form, channel)
        frames = 0
        truncated.clear()
        try:
            for batch in ahead(read_batches(name, batch_bytes)):
                frames += len(batch.frames)
                clock.see(batch.frames)
                for kind, (table, _) in clock(decoder.feed_with_keys(batch.frames)).items():
                    if kind == "errors":
                        truncated.extend(_truncations(table))
                    writer.write(kind, table)
                if progress is not None and batch.position is not None:
                    progress(batch.position)
            decoder.finish()
        except TooManySessions as signal:
            writer.abort()
            per_frame.append(signal.channel)
            continue
        except BaseException:
            writer.abort()
            raise
        records = writer.commit()
        return Summary(1, frames, records, time.perf_counter() - started, truncated)


def _truncations(errors: pa.Table) -> list[str]:
    """The details of an ``errors`` table's ``truncated`` rows."""
    ends = errors.filter(pc.equal(errors["error"].cast(pa.string()), "truncated"))
    return [detail or "the input ends early" for detail in ends["detail"].to_pylist()]


def file_name(source: str) -> str:
    """The name of a capture's files in the dataset: its base name (characters other than
    letters, digits, ``.``, ``_`` and ``-`` replaced, leading ``.`` and ``_`` dropped) and a
    digest of its path as given."""
    stem = re.sub(r"[^A-Za-z0-9._-]", "_", os.path.basename(source)).lstrip("._")
    stem = stem or "capture"  # a name starting "." or "_" is one dataset readers skip
    digest = hashlib.sha256(source.encode("utf-8", "surrogateescape")).hexdigest()[:12]
    return f"{stem}-{digest}.parquet"


def remove_stale(out_dir: Path) -> None:
    """Finish the commits and remove the temporary files that runs no longer alive left in
    ``out_dir`` (killed outright): those named by a process id that is not running on this
    machine, or by none."""
    for journal in sorted(out_dir.glob(".commit-*.json")):
        if not _dead(journal.name.removesuffix(".json")):
            continue
        with contextlib.suppress(OSError, ValueError):  # another run may finish it first
            listed = json.loads(journal.read_text(encoding="utf-8"))
            _finish(out_dir, listed["remove"], listed["rename"])
            journal.unlink()
    for temporary in [*out_dir.glob("message=*/.*.tmp"), *out_dir.glob(".commit-*.tmp")]:
        if _dead(temporary.name.removesuffix(".tmp")):
            with contextlib.suppress(OSError):  # another run may remove it first
                temporary.unlink()


def _dead(name: str) -> bool:
    """Whether the run a temporary name ends with (``.PID-TOKEN``) is not alive."""
    pid = name.rsplit(".", 1)[-1].partition("-")[0]
    return not (pid.isdigit() and _alive(int(pid)))


def _finish(out_dir: Path, remove: list[str], rename: list[list[str]]) -> None:
    """Make the removals and renames a commit journal lists (paths relative to ``out_dir``);
    those already made are skipped."""
    for stale in remove:
        (out_dir / stale).unlink(missing_ok=True)
    for temporary, final in rename:
        if (out_dir / temporary).exists():
            os.replace(out_dir / temporary, out_dir / final)


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except OSError:  # another user's process
        return True
    return True


class _Writer:
    """The files of one capture: written under temporary names, renamed on `commit`.

    Row groups are compressed and written on a thread of their own, one at a time, while
    the next batch is decoded.
    """

    def __init__(self, out_dir: Path, source: str) -> None:
        self.out_dir = out_dir
        self.source = source
        self.name = file_name(source)
        # Each run its own temporary names: two runs on one capture never share a file.
        self._run = f"{os.getpid()}-{secrets.token_hex(4)}"
        remove_stale(out_dir)
        self._writers: dict[str, pq.ParquetWriter] = {}
        self._buffers: dict[str, list[pa.Table]] = {}
        self._bytes: dict[str, int] = {}
        self.counts: dict[str, int] = {}
        self._thread = ThreadPoolExecutor(1)
        self._writing: Future[None] | None = None

    def _paths(self, kind: str) -> tuple[Path, Path]:
        folder = self.out_dir / f"message={kind}"
        return folder / f".{self.name}.{self._run}.tmp", folder / self.name

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
        buffer = self._buffers.pop(kind, [])
        self._bytes.pop(kind, None)
        if buffer:
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
            temporary, _ = self._paths(kind)
            temporary.parent.mkdir(parents=True, exist_ok=True)
            writer = self._writers[kind] = pq.ParquetWriter(temporary, table.schema)
        writer.write_table(table, row_group_size=max(len(table), 1))

    def commit(self) -> dict[str, int]:
        """Finish every file and put them all in place; return the rows written per table.

        On an error before the journal is in place none of the files is put in place, after
        it the rest are; then the temporary files and the journal are removed.
        """
        journal = self.out_dir / f".commit-{self.name}.{self._run}.json"
        stale: list[str] = []
        renames: list[list[str]] = []
        try:
            for kind in list(self._buffers):
                self._flush(kind)
            self._wait()
            self._thread.shutdown()
            for writer in self._writers.values():
                writer.close()
            _reached("written")
            stale = [
                p.relative_to(self.out_dir).as_posix()
                for p in self.out_dir.glob(f"message=*/{self.name}")
                if p.parent.name.removeprefix("message=") not in self._writers
            ]
            renames = [
                [p.relative_to(self.out_dir).as_posix() for p in self._paths(kind)]
                for kind in self._writers
            ]
            written = journal.with_name(journal.name + ".tmp")
            self.out_dir.mkdir(parents=True, exist_ok=True)
            written.write_text(json.dumps({"remove": stale, "rename": renames}), "utf-8")
            os.replace(written, journal)  # from here on, a later run finishes the commit
            _reached("journal")
            for name in stale:
                (self.out_dir / name).unlink(missing_ok=True)
            for kind in self._writers:
                temporary, final = self._paths(kind)
                os.replace(temporary, final)
                _reached(f"renamed {kind}")
            journal.unlink()
            _reached("committed")
        except BaseException:
            if journal.exists():  # past the point of no return: put the rest in place
                with contextlib.suppress(OSError):
                    _finish(self.out_dir, stale, renames)
            self.abort()
            for path in (journal, journal.with_name(journal.name + ".tmp")):
                with contextlib.suppress(OSError):
                    path.unlink()
            raise
        return {kind: self.counts[kind] for kind in self._writers}

    def abort(self) -> None:
        """Drop the files being written."""
        with contextlib.suppress(Exception):
            self._wait()
        self._thread.shutdown()
        for kind, writer in self._writers.items():
            _discard(writer)
            with contextlib.suppress(OSError):
                self._paths(kind)[0].unlink(missing_ok=True)
        self._writers.clear()
        self._buffers.clear()


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
    """The capture paths of a `to_parquet` call, checked to exist, each once."""
    paths = [source] if isinstance(source, (str, os.PathLike)) else list(source)
    names = list(dict.fromkeys(os.fspath(p) for p in paths))  # each capture once
    for name in names:
        if name == STDIN:
            raise SourceError("a dataset is written from files: give a capture file, not -")
        if not os.path.exists(name):
            raise FileNotFoundError(f"{name}: no such file")
    return names
