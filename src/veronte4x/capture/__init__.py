"""Captures in notebooks: read a capture into records, count them, tabulate and plot them.

The capture layer, in one package: readers (`veronte4x.capture.readers`), where a source
comes from (`veronte4x.capture.source`), the bus map, the per-frame decoder, records, stats,
DataFrames and plots. This module is its public face.

Examples:
    >>> from veronte4x import capture
    >>> records = list(capture.read("examples/capture.log"))
    >>> records[2].sender, records[2].message
    ('AP1', Ready(ready=True))
"""

from __future__ import annotations

import dataclasses
import os
from collections.abc import Iterable, Iterator
from typing import TYPE_CHECKING, Any

from veronte4x.capture.aio import stream
from veronte4x.capture.align import AlignError, align
from veronte4x.capture.arbitration import replay
from veronte4x.capture.busmap import BusMap, BusMapError, Role, TextForm
from veronte4x.capture.dataframe import fields, to_dataframe
from veronte4x.capture.datasets import dataset_files, dataset_tables, open_dataset
from veronte4x.capture.dbc import export_dbc, write_dbc
from veronte4x.capture.dbc_in import DbcDecoder, decoder_of
from veronte4x.capture.decoder import CaptureDecoder
from veronte4x.capture.frames import BadLine, Frame
from veronte4x.capture.records import Record
from veronte4x.capture.source import open_frames, resolve
from veronte4x.capture.stats import Stats
from veronte4x.dronecan.typeset import TypeSet
from veronte4x.extras import require
from veronte4x.times import TimeForm

if TYPE_CHECKING:
    import pyarrow

    from veronte4x.capture.columnar.dataset import Summary

__all__ = [
    "AlignError",
    "BadLine",
    "BusMap",
    "BusMapError",
    "CaptureDecoder",
    "DbcDecoder",
    "Frame",
    "Record",
    "Role",
    "Stats",
    "align",
    "dataset_files",
    "dataset_tables",
    "export_dbc",
    "fields",
    "open_dataset",
    "open_frames",
    "read",
    "read_tables",
    "replay",
    "stats",
    "stream",
    "tables_from_records",
    "to_dataframe",
    "to_parquet",
    "write_dbc",
]


def read(
    path: str | os.PathLike[str],
    bus_map: BusMap | None = None,
    channel: str | None = None,
    dbc: Iterable[str | os.PathLike[str]] = (),
    types: TypeSet | None = None,
    strict_transfers: bool | None = None,
) -> Iterator[Record]:
    """Stream the decoded records of a capture file.

    Args:
        path: candump text (``.log``, ``.txt``, gzipped or not, or any other name whose
            content is candump; ``-`` for standard input), or a format python-can reads
            (``.asc``, ``.blf``, ``.csv``, ``.db``, ``.mf4``, ``.trc``; needs the ``can`` extra),
            or a format registered in `veronte4x.capture.readers.registry`.
        bus_map: CAN IDs and codec choices; defaults to Embention's template IDs.
        channel: Keep only this interface's frames.
        dbc: DBC files: the frames outside the bus map whose CAN ID one of them knows are
            decoded by cantools (the ``dbc`` extra; see `veronte4x.capture.dbc_in`), after
            those of the bus map's own ``dbc``.
        types: The DroneCAN types to decode (a `veronte4x.dronecan.TypeSet`, for example
            ``TypeSet.standard().with_dsdl("dsdl/com")``); None for the bus map's, else
            the default set (the standard one, plus what `veronte4x.dronecan.load_dsdl`
            added).
        strict_transfers: Reassemble DroneCAN transfers under veronte4x's strict rules
            (``Reassembler(strict=True)``) instead of libcanard's, which accept a transfer
            wherever libcanard's ``canardHandleRxFrame`` does; None for the bus map's
            ``strict_transfers`` (off unless set). See "Transfer acceptance" in the
            DroneCAN reassembly docs.

    Raises:
        SourceError: The path is a directory or a file in no format veronte4x knows, or
            a DBC file cantools cannot read (raised by the call, before any record).
        MissingExtraError: The format needs python-can (or a DBC cantools) and it is not
            installed.
        OSError: The file cannot be opened.
    """
    bus_map = with_dbc(bus_map, dbc).with_types(types).with_strict_transfers(strict_transfers)
    dbc_decoder = decoder_of(bus_map.dbc, bus_map.dbc_lax) if bus_map.dbc else None
    source = resolve(path)
    records = source.reader.read_records(source, CaptureDecoder(bus_map), channel)
    return records if dbc_decoder is None else dbc_decoder.records(records)


def stats(records: Iterable[Record]) -> Stats:
    """Count records per message type, per sender and errors per kind."""
    counts = Stats()
    for record in records:
        counts.add(record)
    return counts


def read_tables(
    source: str | os.PathLike[str] | Iterable[str | os.PathLike[str]],
    bus_map: BusMap | None = None,
    channel: str | None = None,
    time: TimeForm = "timestamp",
    progress: bool | None = None,
    dbc: Iterable[str | os.PathLike[str]] = (),
    types: TypeSet | None = None,
    text: TextForm | None = None,
    strict_transfers: bool | None = None,
) -> dict[str, pyarrow.Table]:
    """Decode whole captures into typed Arrow tables, one per message type.

    The columnar path: frames are parsed, routed, reassembled and decoded as whole columns
    (see the Tables page of the docs). It gives exactly the records of `read`, arranged in
    tables: one per `Record.kind` of a message (``Status``, ``EscStatus``, ...), plus
    ``errors`` (every record whose ``error`` is set: columns ``error``, ``detail``,
    ``data``) and ``unknown`` (undecoded traffic), each only when the capture has such
    rows. Every table starts with ``timestamp`` (the capture's time: by default an Arrow
    ``timestamp[us, tz=UTC]``, exactly the log's microseconds), ``channel``, ``can_id`` and
    ``sender``
    (DroneCAN tables then ``node_id``, and ``destination_node_id`` for services), then one
    column per message field, with an Arrow type fixed by the layout (a field with a
    physical unit carries it in its metadata: ``unit`` ``V``, ``A``, ``K``, ...). Rows keep
    capture order; several files are decoded one by one and their tables joined in the
    order given. Needs the ``arrow`` extra.

    Args:
        source: A capture file (any format `read` takes, ``-`` for candump text on
            standard input) or a list of them.
        bus_map: CAN IDs and codec choices; defaults to Embention's template IDs.
        channel: Keep only this interface's frames.
        time: The form of the ``timestamp`` column: ``timestamp`` (the default), UTC times
            to the microsecond; ``relative``, float seconds from each capture's first
            timestamped frame, as ``candump -t z`` shows them; ``seconds``, float seconds as
            logged (Unix time for candump). A time outside the years 1 to 9999, or one
            python-can gives as NaN, is null.
        progress: Show a progress bar over the captures' bytes (tqdm's, in a terminal or
            a notebook); None shows it when standard error is a terminal or in a
            notebook, and tqdm is installed.
        dbc: DBC files: the frames outside the bus map on a CAN ID one of them knows
            (after the bus map's own ``dbc``) fill tables of their own instead of
            ``unknown``, one per DBC message, a column per signal with its unit in the
            field's metadata (the ``dbc`` extra; see `veronte4x.capture.dbc_in`).
        types: The DroneCAN types to decode (a `veronte4x.dronecan.TypeSet`, for example
            ``TypeSet.standard().with_dsdl("dsdl/com")``); None for the bus map's, else
            the default set (the standard one, plus what `veronte4x.dronecan.load_dsdl`
            added).
        text: The form of the DroneCAN text fields (names, paths, log text: the ``uint8``
            arrays the DSDL makes text, see the Tables page of the docs): ``string``, Arrow
            strings, a value that is not UTF-8 null with a ``bad text`` row in ``errors``
            holding its bytes; ``binary``, every ``uint8`` array as its exact bytes. None
            for the bus map's ``dronecan_text`` (``string`` unless set).
        strict_transfers: Reassemble DroneCAN transfers under veronte4x's strict rules
            (``Reassembler(strict=True)``) instead of libcanard's, which accept a transfer
            wherever libcanard's ``canardHandleRxFrame`` does; None for the bus map's
            ``strict_transfers`` (off unless set). See "Transfer acceptance" in the
            DroneCAN reassembly docs.

    Raises:
        SourceError: The path is a directory or a file in no format veronte4x knows.
        MissingExtraError: The ``arrow`` extra (or the ``can`` extra, for formats other
            than candump text and MF4) is not installed; the message names it.
        ValueError: ``time`` or ``text`` is none of the forms above.

    Examples:
        >>> from veronte4x import capture
        >>> tables = capture.read_tables("examples/capture.log")
        >>> scores = tables["Score"]
        >>> scores.column_names
        ['timestamp', 'channel', 'can_id', 'sender', 'autopilot', 'autopilot_name', 'score']
        >>> str(scores.column("timestamp")[0])
        '2025-11-21 15:00:00.260000+00:00'
        >>> capture.read_tables("examples/capture.log", time="seconds")["Score"][0][0]
        <pyarrow.DoubleScalar: 1763737200.26>
        >>> scores.column("sender")[0].as_py(), scores.column("score").type
        ('arbiter', DataType(float))
        >>> tables["errors"].column("error").to_pylist()
        ['unknown command']
    """
    bus_map = with_dbc(bus_map, dbc).with_types(types).with_text(text)
    bus_map = bus_map.with_strict_transfers(strict_transfers)
    if bus_map.dbc:
        decoder_of(bus_map.dbc, bus_map.dbc_lax)  # a bad DBC fails before any decoding
    tables: dict[str, pyarrow.Table] = _columnar().read_tables(
        source, bus_map, channel, time, progress
    )
    return tables


def tables_from_records(
    records: Iterable[Record],
    bus_map: BusMap | None = None,
    types: TypeSet | None = None,
    text: TextForm | None = None,
) -> dict[str, pyarrow.Table]:
    """The tables of `read_tables` from records decoded one by one (a live bus, `read`).

    Rows keep the order of the records. Needs the ``arrow`` extra. ``types``: the DroneCAN
    type set the records were decoded with, as in `read`; ``text``: the form of DroneCAN
    text fields, as in `read_tables` (the records keep their bytes either way).
    """
    bus_map = (bus_map or BusMap()).with_types(types).with_text(text)
    tables: dict[str, pyarrow.Table] = _columnar().tables_from_records(records, bus_map)
    return tables


def to_parquet(
    source: str | os.PathLike[str] | Iterable[str | os.PathLike[str]],
    out_dir: str | os.PathLike[str],
    bus_map: BusMap | None = None,
    client: Any = None,
    progress: bool | None = None,
    channel: str | None = None,
    dbc: Iterable[str | os.PathLike[str]] = (),
    types: TypeSet | None = None,
    time: TimeForm = "timestamp",
    text: TextForm | None = None,
    strict_transfers: bool | None = None,
) -> Summary:
    """Decode captures into a Parquet dataset, in memory that does not grow with a file.

    The dataset holds the tables of `read_tables`, one directory per capture and one file
    per table in it: the rows of capture ``flight1.log`` for table ``EscStatus`` go to
    ``out_dir/capture=flight1.log-<digest>/EscStatus.parquet``, with the table's schema
    and a last column ``source``, the capture's path as given. One table over every
    capture is the glob ``out_dir/capture=*/EscStatus.parquet`` (DuckDB, Polars, Dask), or
    `dataset_files` and `open_dataset` (pyarrow, pandas). Each capture is decoded in
    batches of frames, DroneCAN transfers reassembled across the batch boundaries exactly
    as in one piece, so that the rows read back equal those of `read_tables`, in capture
    order. A capture's directory is written under a hidden name and put in place by one
    rename once whole: a reader sees all of its tables or none, never a part; converting
    it again replaces the directory, in one step on Linux. The directory is named after
    the capture's resolved path: ``flight.log``, ``./flight.log``, its absolute path and a
    link to it are one capture, in one directory. Needs the ``parquet`` extra
    (the ``dask`` extra with ``client``).

    Args:
        source: A capture file or a list of them (not standard input; a capture given
            twice, by any spelling of its path, is converted once).
        out_dir: The dataset's directory (created if missing).
        bus_map: CAN IDs and codec choices; defaults to Embention's template IDs.
        client: A ``dask.distributed.Client``: the files are converted on its workers,
            each file by one worker, into ``out_dir``, which they must all see.
        progress: Show a progress bar (tqdm's, in a terminal or a notebook); None shows
            it when standard error is a terminal or in a notebook.
        channel: Keep only this interface's frames.
        dbc: DBC files, as `read_tables` takes them: each DBC message a table
            (``BmsStatus.parquet``); with ``client``, every worker must see them too.
        types: The DroneCAN types to decode (a `veronte4x.dronecan.TypeSet`, for example
            ``TypeSet.standard().with_dsdl("dsdl/com")``); None for the bus map's, else
            the default set (the standard one, plus what `veronte4x.dronecan.load_dsdl`
            added). Dask workers load the same DSDL directories, which they must see.
        time: The form of the ``timestamp`` column, as in `read_tables`: ``timestamp``
            (the default; Parquet ``TIMESTAMP(isAdjustedToUTC=true, MICROS)``, which
            DuckDB reads as ``TIMESTAMP WITH TIME ZONE`` and Polars as
            ``Datetime(us, UTC)``), ``relative`` or ``seconds`` (float64). Keep one form
            per dataset: files of two forms do not read back as one table.
        text: The form of DroneCAN text fields, as in `read_tables`: ``string`` (Parquet
            ``BYTE_ARRAY`` annotated ``STRING``, DuckDB's ``VARCHAR``) or ``binary``
            (``BLOB``); None for the bus map's. Keep one form per dataset, as for ``time``.
        strict_transfers: The DroneCAN transfer rules, as in `read_tables`.

    Returns:
        A ``Summary``: files, frames, rows per table, errors and seconds.

    Raises:
        FileNotFoundError: A capture does not exist.
        FileExistsError: ``out_dir`` holds a dataset of the older layout (``message=TABLE``
            directories).
        SourceError: A path is a directory or a file in no format veronte4x knows.
        MissingExtraError: An extra it needs is not installed; the message names it.
        ValueError: ``time`` or ``text`` is none of the forms `read_tables` takes.
    """
    _columnar()
    require("pyarrow.parquet", "parquet", "writing Parquet")
    from veronte4x.capture.columnar.dataset import to_parquet as convert

    bus_map = with_dbc(bus_map, dbc).with_types(types).with_text(text)
    bus_map = bus_map.with_strict_transfers(strict_transfers)
    if bus_map.dbc:
        decoder_of(bus_map.dbc, bus_map.dbc_lax)  # a bad DBC fails before any file
    summary: Summary = convert(source, out_dir, bus_map, client, progress, channel, time_form=time)
    return summary


def with_dbc(bus_map: BusMap | None, dbc: Iterable[str | os.PathLike[str]]) -> BusMap:
    """``bus_map`` (or the default one) with these DBC files after its own."""
    bus_map = bus_map or BusMap()
    paths = tuple(os.fspath(path) for path in dbc)
    return dataclasses.replace(bus_map, dbc=(*bus_map.dbc, *paths)) if paths else bus_map


def _columnar() -> Any:
    for module in ("numpy", "pyarrow"):
        require(module, "arrow", "decoding into Arrow tables")
    from veronte4x.capture import columnar

    return columnar
