"""Decode a capture batch by batch, in memory that does not grow with it.

The one driver of the columnar engine, for files, pipes and standard input alike.
`StreamDecoder` takes the frames of a capture in consecutive batches and gives, for each,
the rows of `veronte4x.capture.read_tables` that batch completes, in capture order: the
batches' tables, one after the other, are those of the whole capture.

Veronte frames, bad lines and everything the per-frame decoder takes are decoded frame by
frame or column by column with no state between batches, except the DroneCAN reassembly:

- One per-frame `CaptureDecoder` serves the whole capture, so its reassemblers keep their
  sessions from one batch to the next.
- A DroneCAN session (a channel and a CAN ID without its priority bits) stays on the
  column-wise path while its frames are regular (see `veronte4x.capture.columnar.dronecan`).
  Its last whole transfer is carried into the next batch as *context* (checked again with
  the new frames, never decoded twice), and so are the frames of a transfer still open at
  the end of a batch, provided they are a flawless beginning: then the reassembler would
  report nothing on them either, whatever follows. A batch is joined only the context of
  the sessions with frames in it; the others' is kept aside until theirs come, so that a
  batch costs the same whether the capture has ten sessions or a hundred thousand.
- A session found irregular leaves the column path for good: its last whole transfer is fed
  to the reassembler again (the result dropped: it came out in the batch before), which
  leaves the session's state as that transfer left it in one piece (a session's state after
  a transfer depends on that transfer only, while its sessions never fill the table), and
  the reassembler takes the session's frames from there on.
- A channel with more sessions than the reassembler's table stays column-wise while the
  table cannot reach a transfer in progress or an irregular session (the rule of
  `veronte4x.capture.columnar.dronecan.Spans`, checked with every session's first
  and last frame so far, and at `finish` for sessions left holding a transfer). Where it
  could, the channel goes to the per-frame decoder whole; the batches seen so far are
  then wrong, and `TooManySessions` says to start over with that channel in
  ``per_frame_channels``.

Records always belong to a frame of the batch that completes them, so rows never go back
in capture order across batches.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Iterator
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt
import pyarrow as pa

from veronte4x.capture.busmap import BusMap
from veronte4x.capture.columnar import dbc, dronecan, engine
from veronte4x.capture.columnar.frames import FrameColumns, concat
from veronte4x.capture.columnar.schema import all_specs
from veronte4x.capture.columnar.tables import Keyed, Tables
from veronte4x.capture.decoder import CaptureDecoder
from veronte4x.dronecan.reassembler import Reassembler

_END = 0x40
_START = 0x80


class TooManySessions(Exception):
    """A channel has more DroneCAN sessions than the reassembler's table and the table could
    drop one that matters: decode the capture again with this channel in
    ``per_frame_channels``."""

    def __init__(self, channel: str) -> None:
        super().__init__(
            f"more than {dronecan.MAX_SESSIONS} DroneCAN sessions at once on {channel}"
        )
        self.channel = channel


class StreamDecoder:
    """Decode one capture's frames batch by batch into the tables of `read_tables`.

    Args:
        bus_map: CAN IDs and codec choices; defaults to Embention's template IDs.
        channel: Keep only this interface's frames.
        per_frame_channels: Channels whose DroneCAN frames all go to the per-frame decoder.
    """

    def __init__(
        self,
        bus_map: BusMap | None = None,
        channel: str | None = None,
        per_frame_channels: Iterable[str] = (),
    ) -> None:
        self.bus_map = bus_map or BusMap()
        self.channel = channel
        self.per_frame_channels = frozenset(per_frame_channels)
        self.decoder = CaptureDecoder(self.bus_map)
        self._specs = all_specs(
            self.bus_map.codec(), self.bus_map.dronecan_types, self.bus_map.dronecan_text
        )
        self._known = dronecan.type_index_of(self.bus_map.dronecan_types)
        # Frames carried to the next batch (capture order), whether each is context (else
        # a transfer still open), and each one's session key.
        self._pending: FrameColumns | None = None
        self._context = np.zeros(0, np.bool_)
        self._pending_keys = np.zeros(0, np.int64)
        # The carried frames of sessions without frames in the batch being decoded.
        self._kept: FrameColumns | None = None
        self._kept_keys = np.zeros(0, np.int64)
        self._channel_ids: dict[str, int] = {}
        self._irregular = np.zeros(0, np.int64)
        # Every session's key, first and last frame position so far (keys sorted).
        self._keys_seen = np.zeros(0, np.int64)
        self._first = np.zeros(0, np.int64)
        self._last = np.zeros(0, np.int64)

    def feed(self, frames: FrameColumns) -> dict[str, pa.Table]:
        """The rows the next batch completes, by kind (kinds without rows left out).

        Raises:
            TooManySessions: Start over with the channel it names decoded frame by frame.
        """
        return {kind: table for kind, (table, _) in self.feed_with_keys(frames).items()}

    def prepare(self, frames: FrameColumns) -> Prepared:
        """The part of a batch's decoding that needs nothing of the batches before it (its
        Veronte frames), which a second thread can do while this decoder takes the batch
        before (see `veronte4x.capture.columnar.batches.ahead`); give it to
        `feed_with_keys` with the same frames."""
        if self.channel is not None:
            frames = engine.only_channel(frames, self.channel)
        tables = Tables(self._specs, list(frames.channels))
        done, candidates = engine.decode_veronte(frames, self.bus_map, tables)
        return Prepared(frames, done, candidates, tables.finish_with_keys())

    def feed_with_keys(
        self, frames: FrameColumns, prepared: Prepared | None = None
    ) -> dict[str, tuple[pa.Table, npt.NDArray[np.int64]]]:
        """`feed`, each table with the capture-order keys of its rows (``prepared``:
        `prepare` of the same frames, if made)."""
        if prepared is None:
            prepared = self.prepare(frames)
        frames = prepared.frames
        pending, context = self._take_pending(frames)
        done, candidates = prepared.done, prepared.candidates
        if pending is not None and len(pending):
            joined = concat([pending, frames])  # the carried frames come first
            context = np.concatenate([context, np.zeros(len(frames), np.bool_)])
            # Carried frames are DroneCAN candidates, never Veronte frames.
            done = np.concatenate([np.zeros(len(pending), np.bool_), done])
            candidates = np.concatenate([np.arange(len(pending)), candidates + len(pending)])
        else:
            joined, context = frames, np.zeros(len(frames), np.bool_)
        tables = Tables(self._specs, list(joined.channels))
        if self.bus_map.dronecan:
            done |= self._dronecan(joined, candidates, context, tables)
        self._keep_pending()
        done |= context
        dbc.decode_dbc_frames(joined, self.bus_map, done, tables)
        tables.add_records(engine.per_frame(joined, np.flatnonzero(~done), self.decoder))
        return merged(prepared.tables, tables.finish_with_keys())

    def _dronecan(
        self,
        frames: FrameColumns,
        candidates: npt.NDArray[np.int64],
        context: npt.NDArray[np.bool_],
        tables: Tables,
    ) -> npt.NDArray[np.bool_]:
        """Decode the regular sessions, carry what the next batch needs; return the rows
        taken (decoded or carried)."""
        taken = np.zeros(len(frames), np.bool_)
        rows, types, stamp = engine.dronecan_inputs(frames, candidates, self._known)
        if not len(rows):
            return taken
        keys = self._keys(frames, rows)
        by_session = stable_order(keys)
        rows, keys = rows[by_session], keys[by_session]
        self._add_spans(keys, frames.order[rows])
        column = ~np.isin(keys, self._irregular)
        if self.per_frame_channels:
            names = np.array([c in self.per_frame_channels for c in frames.channels], np.bool_)
            column &= ~names[frames.channel[rows]]
        rows, keys = rows[column], keys[column]
        if not len(rows):
            return taken
        length = frames.length[rows]
        tail = frames.data[rows, length - 1]
        opens = np.ones(len(rows), np.bool_)
        opens[1:] = keys[1:] != keys[:-1]
        session = np.cumsum(opens) - 1
        ends = np.append(np.flatnonzero(opens)[1:] - 1, len(rows) - 1)
        # Transfers left open at the batch end: checked as if they ended there, carried.
        group = np.maximum.accumulate(np.where((tail & _START) != 0, np.arange(len(rows)), -1))
        open_end = ends[((tail[ends] & _END) == 0) & (group[ends] >= 0) & (length[ends] == 8)]
        open_end = open_end[group[open_end] >= np.flatnonzero(opens)[session[open_end]]]
        carried = np.zeros(len(rows), np.bool_)
        for end in open_end.tolist():
            carried[group[end] : end + 1] = True
        checked = tail.copy()
        checked[open_end] |= _END
        order, in_order = dronecan.regular_sessions(
            frames.channel[rows],
            frames.can_id[rows],
            stamp[rows],
            length,
            checked,
            types[rows],
            self._known,
        )
        regular = np.empty(len(rows), np.bool_)
        regular[order] = in_order
        self._leave_column_path(frames, rows, keys, stamp, context, ~regular & opens)
        self._check_table(frames, rows, keys, regular & ~carried, tail)
        decoded = regular & ~carried
        engine.decode_transfers(
            frames, rows[decoded], types, stamp, self._known, tables, skip=context
        )
        taken[rows[regular]] = True
        self._carry(frames, rows[regular], tail[regular], carried[regular])
        return taken

    def _take_pending(
        self, frames: FrameColumns
    ) -> tuple[FrameColumns | None, npt.NDArray[np.bool_]]:
        """The carried frames the batch ``frames`` needs, and which are context: every
        transfer still open, and the context of the sessions with frames in the batch.
        The context of the others is kept aside until a batch has their frames: alone it
        would only be checked and carried again."""
        pending, context, keys = self._pending, self._context, self._pending_keys
        self._pending, self._context = None, np.zeros(0, np.bool_)
        self._pending_keys = np.zeros(0, np.int64)
        if pending is None or not len(pending):
            return None, context
        batch = self._keys(frames)
        needed = ~context
        by_key = stable_order(keys)  # look-ups in order: fast
        if len(keys) * 8 < len(batch):  # few carried: look the batch's keys up in theirs
            carried = keys[by_key]
            at = np.minimum(np.searchsorted(carried, batch), len(carried) - 1)
            found = np.zeros(len(carried) + 1, np.bool_)
            found[np.where(carried[at] == batch, at, len(carried))] = True
            # Rows of one key are adjacent in key order: the first found marks them all.
            same = np.searchsorted(carried, carried)
            needed[by_key] |= found[same]
        elif len(batch):
            batch = batch[stable_order(batch)]
            at = np.minimum(np.searchsorted(batch, keys[by_key]), len(batch) - 1)
            needed[by_key] |= batch[at] == keys[by_key]
        if needed.all():
            return pending, context
        aside = np.flatnonzero(~needed)
        self._kept, self._kept_keys = pending.take(aside), keys[aside]
        taken = np.flatnonzero(needed)
        return pending.take(taken), context[taken]

    def _keep_pending(self) -> None:
        """Join the context kept aside to the frames carried from this batch."""
        kept = self._kept
        if kept is None:
            return
        self._kept = None
        pending = self._pending
        if pending is None or not len(pending):
            self._pending, self._pending_keys = kept, self._kept_keys
            self._context = np.ones(len(kept), np.bool_)
            return
        by_order = stable_order(np.concatenate([kept.order, pending.order]))
        self._pending = concat([kept, pending])
        self._context = np.concatenate([np.ones(len(kept), np.bool_), self._context])[by_order]
        self._pending_keys = np.concatenate([self._kept_keys, self._pending_keys])[by_order]

    def _keys(
        self, frames: FrameColumns, rows: npt.NDArray[np.int64] | None = None
    ) -> npt.NDArray[np.int64]:
        """Session keys that hold across batches (of ``rows``, else of every frame): a
        channel number of this decoder's and the CAN ID without its priority bits."""
        codes = np.array(
            [self._channel_ids.setdefault(c, len(self._channel_ids)) for c in frames.channels]
            or [0],
            np.int64,
        )
        channel = codes[frames.channel if rows is None else frames.channel[rows]]
        can_id = frames.can_id if rows is None else frames.can_id[rows]
        keys: npt.NDArray[np.int64] = channel << 24 | (can_id & 0xFFFFFF)
        return keys

    def finish(self) -> None:
        """Check the end of the capture, after its last batch.

        Raises:
            TooManySessions: The session table of the full reassembler would have dropped
                a session holding a transfer after its last frame (and reported it).
        """
        spans, crowded = self._crowded()
        pending = self._pending
        if pending is not None and len(pending):  # transfers still open, column-wise
            rows = np.flatnonzero(~self._context)
            keys = np.unique(self._keys(pending, rows))
            channel = (keys >> 24).astype(np.int32)
            last = self._last[np.searchsorted(self._keys_seen, keys)]
            late = crowded[channel] & (spans.later(channel, last) >= dronecan.MAX_SESSIONS)
            if late.any():
                names = {code: name for name, code in self._channel_ids.items()}
                raise TooManySessions(names[int(channel[late][0])])
        for name, reassembler in self.decoder.reassemblers.items():
            code = self._channel_ids.get(name)
            if code is None or not crowded[code] or name in self.per_frame_channels:
                continue
            reports = reassembler.expire_reports(math.inf)
            keys = np.array([code << 24 | report.can_id for report in reports], np.int64)
            last = self._last[np.searchsorted(self._keys_seen, keys)]
            channel = np.full(len(keys), code, np.int32)
            if (spans.later(channel, last) >= dronecan.MAX_SESSIONS).any():
                raise TooManySessions(name)

    def _add_spans(self, keys: npt.NDArray[np.int64], positions: npt.NDArray[np.int64]) -> None:
        """Take the sessions' frames of a batch (``keys`` sorted) into their first and last
        positions."""
        if not len(keys):
            return
        opens = np.flatnonzero(np.append(True, keys[1:] != keys[:-1]))
        unique = keys[opens]
        first = np.minimum.reduceat(positions, opens)
        last = np.maximum.reduceat(positions, opens)
        at = np.searchsorted(self._keys_seen, unique)
        known = at < len(self._keys_seen)
        known[known] = self._keys_seen[at[known]] == unique[known]
        old = at[known]
        self._first[old] = np.minimum(self._first[old], first[known])
        self._last[old] = np.maximum(self._last[old], last[known])
        new, where = ~known, at[~known]
        self._keys_seen = np.insert(self._keys_seen, where, unique[new])
        self._first = np.insert(self._first, where, first[new])
        self._last = np.insert(self._last, where, last[new])

    def _crowded(self) -> tuple[dronecan.Spans, npt.NDArray[np.bool_]]:
        """The sessions' spans, and per channel code whether it has more sessions than the
        table (and is not decoded frame by frame)."""
        channel = (self._keys_seen >> 24).astype(np.int32)
        spans = dronecan.Spans(channel, self._first, self._last)
        crowded = np.bincount(channel, minlength=len(self._channel_ids) + 1) > (
            dronecan.MAX_SESSIONS
        )
        for name in self.per_frame_channels:
            if name in self._channel_ids:
                crowded[self._channel_ids[name]] = False
        return spans, crowded

    def _check_table(
        self,
        frames: FrameColumns,
        rows: npt.NDArray[np.int64],
        keys: npt.NDArray[np.int64],
        whole: npt.NDArray[np.bool_],
        tail: npt.NDArray[np.uint8],
    ) -> None:
        """Raise `TooManySessions` for a channel whose table could drop an irregular session
        within its frames or a regular one within a multi-frame transfer (of ``rows``, in
        session order, those ``whole``)."""
        spans, crowded = self._crowded()
        if not crowded.any():
            return
        names = {code: name for name, code in self._channel_ids.items()}
        size = len(crowded)
        at = np.searchsorted(self._keys_seen, self._irregular)
        channel = (self._irregular >> 24).astype(np.int32)
        reach = spans.reach(channel, self._first[at], self._last[at])
        reach[self._first[at] == self._last[at]] = 0
        bad = np.bincount(channel, weights=reach >= dronecan.MAX_SESSIONS, minlength=size) > 0
        bad |= np.bincount(channel, minlength=size) > dronecan.MAX_SESSIONS
        # Multi-frame transfers of regular sessions (rows in session order).
        begins = np.flatnonzero(whole & ((tail & _START) != 0))
        ends = np.flatnonzero(whole & ((tail & _END) != 0))
        if len(begins) == len(ends):
            multi = ends > begins
            begins, ends = begins[multi], ends[multi]
            owner = (keys[begins] >> 24).astype(np.int32)
            position = frames.order[rows]
            reach = spans.reach(owner, position[begins], position[ends])
            bad |= np.bincount(owner, weights=reach >= dronecan.MAX_SESSIONS, minlength=size) > 0
        else:  # cannot happen for regular sessions; be safe
            bad |= crowded
        for code in np.flatnonzero(bad & crowded).tolist():
            raise TooManySessions(names[code])

    def _leave_column_path(
        self,
        frames: FrameColumns,
        rows: npt.NDArray[np.int64],
        keys: npt.NDArray[np.int64],
        stamp: npt.NDArray[np.float64],
        context: npt.NDArray[np.bool_],
        newly_irregular: npt.NDArray[np.bool_],
    ) -> None:
        """Hand irregular sessions to the per-frame decoder for good, each session's last
        whole transfer (its context) fed to the reassembler first, its result dropped (it
        was decoded in the batch before), so that the session is as that transfer left it."""
        starts = np.flatnonzero(newly_irregular)
        if not len(starts):
            return
        self._irregular = np.union1d(self._irregular, keys[starts])
        for start in starts.tolist():
            if not context[rows[start]]:
                continue  # the session starts in this batch: the reassembler starts fresh
            name = frames.channels[frames.channel[rows[start]]]
            reassembler = self.decoder.reassemblers.get(name)
            if reassembler is None:
                reassembler = self.decoder.reassemblers[name] = Reassembler(
                    types=self.bus_map.dronecan_types, strict=self.bus_map.strict_transfers
                )
            at = start
            while at < len(rows) and context[rows[at]]:  # the last whole transfer, again
                row = int(rows[at])
                data = frames.data[row, : frames.length[row]].tobytes()
                reassembler.push(int(frames.can_id[row]), data, float(stamp[row]))
                at += 1

    def _carry(
        self,
        frames: FrameColumns,
        rows: npt.NDArray[np.int64],
        tail: npt.NDArray[np.uint8],
        carried: npt.NDArray[np.bool_],
    ) -> None:
        """Keep for the next batch each regular session's open transfer and the whole
        transfer before it (``rows`` in session order, each session opening a transfer)."""
        transfer = np.cumsum((tail & _START) != 0)
        whole = np.flatnonzero(~carried)
        channel = frames.channel[rows[whole]]
        can_id = frames.can_id[rows[whole]] & 0xFFFFFF
        last = np.ones(len(whole), np.bool_)
        last[:-1] = (channel[1:] != channel[:-1]) | (can_id[1:] != can_id[:-1])
        context = np.isin(transfer, transfer[whole[last]])
        keep = np.flatnonzero(context | carried)
        by_order = stable_order(rows[keep])
        pending = frames.take(rows[keep][by_order])
        pending.bad_lines = []
        self._pending = pending
        self._context = context[keep][by_order]
        self._pending_keys = self._keys(pending)


@dataclass
class Prepared:
    """A batch's frames (of the decoder's channel) and their Veronte decoding: which rows
    are decoded, the rows that may be DroneCAN, and the tables of the decoded rows."""

    frames: FrameColumns
    done: npt.NDArray[np.bool_]
    candidates: npt.NDArray[np.int64]
    tables: Keyed


def merged(first: Keyed, second: Keyed) -> Keyed:
    """Two sets of keyed tables of one batch as one, each table's rows in key order."""
    out = dict(first)
    for kind, (table, keys) in second.items():
        if kind not in out:
            out[kind] = table, keys
            continue
        other, other_keys = out[kind]
        joined = np.concatenate([other_keys, keys])
        order = np.argsort(joined, kind="stable")
        out[kind] = pa.concat_tables([other, table]).take(pa.array(order)), joined[order]
    return out


def stable_order(values: npt.NDArray[np.int64]) -> npt.NDArray[np.int64]:
    """`np.argsort` of ``values`` (>= 0), stable: two radix passes of 16 bits where they
    fit in 32 (many distinct values cost no more than a few)."""
    if not len(values) or int(values.max()) >= 1 << 32:
        return np.argsort(values, kind="stable")
    low = np.argsort((values & 0xFFFF).astype(np.uint16), kind="stable")
    high = np.argsort((values[low] >> 16).astype(np.uint16), kind="stable")
    order: npt.NDArray[np.int64] = low[high]
    return order


def split(frames: FrameColumns, sizes: Iterable[int]) -> Iterator[FrameColumns]:
    """Cut whole-capture columns into consecutive batches of ``sizes`` frames (the rest in a
    last batch), each with the bad lines before its frames and after the previous batch's."""
    bad = frames.bad_lines
    at = taken = 0
    for size in [*sizes, len(frames)]:
        stop = min(at + size, len(frames))
        upto = len(bad)
        if stop < len(frames):
            next_order = int(frames.order[stop])
            upto = taken
            while upto < len(bad) and bad[upto][0] < next_order:
                upto += 1
        part = frames.take(np.arange(at, stop))
        part.bad_lines = bad[taken:upto]
        yield part
        taken, at = upto, stop
        if stop == len(frames):
            return
