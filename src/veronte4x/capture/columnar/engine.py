"""Decode `FrameColumns` into one Arrow table per message type.

Frames are routed by the bus map as the per-frame decoder routes them: Veronte frames go to
the column-wise layout decoders, DroneCAN frames of regular sessions to the column-wise
reassembly, and everything else (bad lines, error, remote and FD frames, unknown IDs,
frames a layout refuses, irregular DroneCAN sessions) to the per-frame `CaptureDecoder`, fed
in capture order. The tables therefore hold exactly the records `veronte4x.capture.read`
gives, whichever path decoded them.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator

import numpy as np
import numpy.typing as npt
import pyarrow as pa

from veronte4x.capture.busmap import BusMap
from veronte4x.capture.columnar import dronecan, payloads, veronte
from veronte4x.capture.columnar.frames import FrameColumns
from veronte4x.capture.columnar.schema import NODE_SENDER, SENDER_INDEX, all_specs, field_column
from veronte4x.capture.columnar.tables import SUB, Tables
from veronte4x.capture.decoder import CaptureDecoder, problem_record
from veronte4x.capture.frames import BadLine, Frame
from veronte4x.capture.records import Record, transfer_record
from veronte4x.codec import Codec
from veronte4x.codec.messages import Sender
from veronte4x.dronecan.codec import TypeCodec
from veronte4x.dronecan.reassembler import Problem, ProblemReport
from veronte4x.errors import DecodeError


def decode_veronte(
    frames: FrameColumns, bus_map: BusMap, tables: Tables
) -> tuple[npt.NDArray[np.bool_], npt.NDArray[np.int64]]:
    """Decode the Veronte frames column-wise into ``tables``.

    Returns:
        Which rows are decoded, and the rows that may be DroneCAN (plain 29-bit frames on
        no Veronte ID), in capture order.
    """
    plain, sender_code = _routes(frames, bus_map)
    done = _decode_senders(frames, bus_map, sender_code, tables)
    return done, np.flatnonzero(plain & frames.extended & (sender_code < 0))


def _routes(
    frames: FrameColumns, bus_map: BusMap
) -> tuple[npt.NDArray[np.bool_], npt.NDArray[np.int16]]:
    """Which frames are plain (classic data frames of up to 8 bytes), and the sender code
    of each plain frame on a Veronte ID (-1 for the others)."""
    plain = ~(frames.remote | frames.fd | frames.error) & (frames.length <= 8)
    if frames.long_data:
        plain[list(frames.long_data)] = False
    if bus_map.dbc_ids:  # 29-bit IDs DroneCAN leaves to a DBC (`BusMap.dbc_first`)
        plain &= ~(frames.extended & np.isin(frames.can_id, list(bus_map.dbc_ids)))
    sender_code = np.full(len(frames), -1, np.int16)
    veronte_ids = plain & (frames.extended == bus_map.extended)
    for can_id, (_, index) in bus_map.veronte_roles.items():
        code = SENDER_INDEX["arbiter"] if index is None else SENDER_INDEX["AP1"] + index
        sender_code[veronte_ids & (frames.can_id == can_id)] = code
    return plain, sender_code


def _decode_senders(
    frames: FrameColumns, bus_map: BusMap, sender_code: npt.NDArray[np.int16], tables: Tables
) -> npt.NDArray[np.bool_]:
    """Decode every Veronte frame column-wise, by sender; return which rows are decoded."""
    codec = bus_map.codec()
    done = np.zeros(len(frames), np.bool_)
    arbiter = sender_code == SENDER_INDEX["arbiter"]
    for sender, rows in (
        (Sender.ARBITER, np.flatnonzero(arbiter)),
        (Sender.AUTOPILOT, np.flatnonzero((sender_code >= 0) & ~arbiter)),
    ):
        taken = _decode_veronte(frames, rows, codec, sender, sender_code, bus_map, tables)
        done[taken] = True
    return done


def only_channel(frames: FrameColumns, channel: str) -> FrameColumns:
    """The frames of one interface (and every bad line)."""
    if channel not in frames.channels:
        return frames.take(np.zeros(0, np.int64))
    return frames.take(np.flatnonzero(frames.channel == frames.channels.index(channel)))


def _head(frames: FrameColumns, rows: npt.NDArray[np.int64]) -> dict[str, np.ndarray]:
    return {
        "time": frames.time[rows],
        "has_time": frames.has_time[rows],
        "channel": frames.channel[rows],
        "can_id": frames.can_id[rows],
    }


def _decode_veronte(
    frames: FrameColumns,
    rows: npt.NDArray[np.int64],
    codec: Codec,
    sender: Sender,
    sender_code: npt.NDArray[np.int16],
    bus_map: BusMap,
    tables: Tables,
) -> npt.NDArray[np.int64]:
    """Decode one sender's frames column-wise; return the rows decoded."""
    excess = bus_map.allow_excess
    data = frames.data.view("<u8")[rows, 0]
    length = frames.length[rows]
    target = veronte.targets(codec, sender, data, length, excess)
    layouts = veronte.layout_list(codec)
    decoded = []
    for index in np.unique(target[target >= 0]).tolist():
        layout = layouts[index]
        picked = np.flatnonzero(target == index)
        good, columns = veronte.decode(layout, data[picked], length[picked], excess)
        taken = rows[picked[good]]
        head = _head(frames, taken)
        head["sender"] = sender_code[taken]
        fields = {
            name: (value.filter(pa.array(good)) if isinstance(value, pa.Array) else value[good])
            for name, value in columns.items()
        }
        tables.add_columns(layout.name, frames.order[taken] * SUB, head, fields)
        decoded.append(taken)
    return np.concatenate(decoded) if decoded else np.zeros(0, np.int64)


def dronecan_inputs(
    frames: FrameColumns, rows: npt.NDArray[np.int64], known: dronecan.TypeIndex
) -> tuple[npt.NDArray[np.int64], npt.NDArray[np.int16], npt.NDArray[np.float64]]:
    """The candidate rows the reassembler may take (a type of ``known``, a tail byte), with
    each frame's type index and the timestamp the reassembler is fed (0.0 for none)."""
    types = np.full(len(frames), -1, np.int16)
    types[rows] = dronecan.type_index(frames.can_id[rows], known)
    rows = rows[(types[rows] >= 0) & (frames.length[rows] >= 1)]
    stamp = np.zeros(len(frames))
    stamp[rows] = np.where(frames.has_time[rows], frames.timestamp[rows], 0.0)
    return rows, types, stamp


def decode_transfers(
    frames: FrameColumns,
    taken: npt.NDArray[np.int64],
    types: npt.NDArray[np.int16],
    stamp: npt.NDArray[np.float64],
    known: dronecan.TypeIndex,
    tables: Tables,
    skip: npt.NDArray[np.bool_] | None = None,
) -> None:
    """Decode the transfers of ``taken`` (whole transfers of regular sessions, in session
    order, of the types ``known`` numbers) into ``tables``, leaving out those whose last
    frame is a ``skip`` row."""
    # Frames of one type together (a session's frames are all of one type, in order):
    # each type's transfers and payloads come out one after the other.
    taken = taken[np.argsort(types[taken], kind="stable")]
    found = dronecan.transfers(taken, frames.data, frames.length, types)
    keep = np.ones(len(found.last), np.bool_) if skip is None else ~skip[found.last]
    multi = np.flatnonzero(keep & (found.crc >= 0))
    computed = dronecan.crc_ok(found, multi, known)
    mismatch = computed != found.crc[multi]
    wrong = multi[mismatch]
    records = _crc_mismatches(frames, found, wrong, computed[mismatch], stamp)
    keep[wrong] = False
    kinds = found.type_index
    bounds = np.flatnonzero(kinds[1:] != kinds[:-1]) + 1
    for begin, end in zip([0, *bounds.tolist()], [*bounds.tolist(), len(kinds)], strict=True):
        which = begin + np.flatnonzero(keep[begin:end])
        if len(which):  # in capture order: the table needs no sorting
            which = which[np.argsort(found.last[which], kind="stable")]
            codec = known.codec_of(int(kinds[begin]))
            records += _decode_type(frames, found, codec, which, stamp, tables)
    tables.add_records(records)


def _crc_mismatches(
    frames: FrameColumns,
    found: dronecan.Transfers,
    wrong: np.ndarray,
    computed: np.ndarray,
    stamp: np.ndarray,
) -> list[tuple[int, Record]]:
    out = []
    for transfer, crc in zip(wrong.tolist(), computed.tolist(), strict=True):
        last, carried = int(found.last[transfer]), int(found.crc[transfer])
        report = ProblemReport(
            Problem.CRC_MISMATCH,
            int(frames.can_id[last]),
            frames.data[last, : frames.length[last]].tobytes(),
            frames.fed(int(found.first[transfer])),
            f"CRC {carried:#06x}, computed {crc:#06x}",
        )
        channel = frames.channels[frames.channel[last]]
        out.append((int(frames.order[last]) * SUB, problem_record(report, channel)))
    return out


def _decode_type(
    frames: FrameColumns,
    found: dronecan.Transfers,
    codec: TypeCodec,
    which: np.ndarray,
    stamp: np.ndarray,
    tables: Tables,
) -> list[tuple[int, Record]]:
    """Decode one type's transfers column-wise; those the serializer refuses one by one
    (to report its error)."""
    schema = codec.data_type.schema
    kind = schema.cls.__name__
    starts = found.offsets[which]
    sizes = found.offsets[which + 1] - starts
    fixed = dronecan.fixed_size(schema)
    if fixed is not None:  # every field at one place: read from a matrix of the payloads
        good = which[sizes == fixed]
        matrix = dronecan.payload_matrix(found, good, fixed)
        _add_transfers(frames, found, good, kind, dronecan.decode_fixed(schema, matrix), tables)
        left = which[sizes != fixed]
    else:
        low, high = int(starts.min()), int((starts + sizes).max())
        fields, refused = payloads.decode(schema, found.payload[low:high], starts - low, sizes)
        kept = ~refused
        if not kept.all():
            mask = pa.array(kept)
            fields = {
                name: value.filter(mask) if isinstance(value, pa.Array) else value[kept]
                for name, value in fields.items()
            }
        _add_transfers(frames, found, which[kept], kind, fields, tables)
        left = which[refused]
    return [item for t in left.tolist() for item in _one_transfer(frames, found, t, codec, stamp)]


def _add_transfers(
    frames: FrameColumns,
    found: dronecan.Transfers,
    which: np.ndarray,
    kind: str,
    fields: dict[str, object],
    tables: Tables,
) -> None:
    last = found.last[which]
    head = _head(frames, last)
    can_id = frames.can_id[last].astype(np.int64)
    source = can_id & 0x7F
    head["node_id"] = source
    head["sender"] = (NODE_SENDER + source).astype(np.int16)
    head["destination_node_id"] = (can_id >> 8) & 0x7F
    named = {field_column(name): value for name, value in fields.items()}
    tables.add_columns(kind, frames.order[last] * SUB, head, named)


def _one_transfer(
    frames: FrameColumns,
    found: dronecan.Transfers,
    transfer: int,
    codec: TypeCodec,
    stamp: np.ndarray,
) -> list[tuple[int, Record]]:
    """A transfer the column decoders do not take, decoded as the reassembler does."""
    last, first = int(found.last[transfer]), int(found.first[transfer])
    can_id = int(frames.can_id[last])
    channel = frames.channels[frames.channel[last]]
    key = int(frames.order[last]) * SUB
    payload = found.payload_of(transfer)
    try:
        message = codec.decode(payload)
    except DecodeError as error:
        report = ProblemReport(Problem.BAD_PAYLOAD, can_id, payload, frames.fed(first), str(error))
        return [(key, problem_record(report, channel))]
    record = transfer_record(
        frames.seconds(last),
        channel,
        can_id,
        can_id & 0x7F,
        message,
        frames.data[last, : frames.length[last]].tobytes(),
        (can_id >> 8) & 0x7F if can_id & 0x80 else None,
    )
    return [(key, record)]


def per_frame(
    frames: FrameColumns, rows: npt.NDArray[np.int64], decoder: CaptureDecoder
) -> Iterator[tuple[int, Record]]:
    """The records of ``rows`` and the bad lines, through the per-frame decoder, in order."""
    orders: list[int] = frames.order[rows].tolist()
    items: list[Frame | BadLine] = [*frames.frames_of(rows)]
    if frames.bad_lines:
        both = sorted([*zip(orders, items, strict=True), *frames.bad_lines], key=_first)
        orders, items = [order for order, _ in both], [item for _, item in both]
    # One decode over all items: the record of each item comes before the next item is
    # read, so the item in hand numbers the records it gives.
    at, sub, current = -1, 0, -1
    source = iter(items)

    def counted() -> Iterator[Frame | BadLine]:
        nonlocal at
        for item in source:
            at += 1
            yield item

    for record in decoder.decode(counted()):
        if at != current:
            current, sub = at, 0
        yield orders[at] * SUB + sub, record
        sub += 1


def _first(item: tuple[int, object]) -> int:
    return item[0]


def tables_from_records(
    records: Iterable[Record], bus_map: BusMap | None = None
) -> dict[str, pa.Table]:
    """The tables of records decoded one by one (a live bus, `veronte4x.capture.read`).

    Rows keep the order of ``records``. The exact reference of the column-wise path.
    """
    bus_map = bus_map or BusMap()
    tables = Tables(all_specs(bus_map.codec(), bus_map.dronecan_types, bus_map.dronecan_text), [])
    tables.add_records((index * SUB, record) for index, record in enumerate(records))
    return tables.finish()
