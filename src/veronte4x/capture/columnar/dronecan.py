"""DroneCAN transfers, column-wise: sessions checked, frames joined and CRCs computed for
whole columns, payloads decoded field by field for all transfers of a type at once.

The per-frame `veronte4x.dronecan.Reassembler` is the reference. A session (a channel and
a CAN ID without its priority bits, as the reassembler keys them) is *regular* when its
frames form whole transfers one after the other: a start frame opens each, toggles
alternate from 0, the transfer id holds within a transfer and differs from the previous
transfer's unless the transfer-ID timeout passed in between, every frame but the last of a
transfer has 8 bytes, no frame comes later than the timeout after its transfer's first,
and the payload fits the type. On such a session the reassembler delivers every transfer
(or reports its CRC mismatch or bad payload) and nothing else, under libcanard's rules
(its default, the ones `capture.read` uses) as under its strict ones, which is what this
module computes: with every transfer taken, libcanard's expected transfer id is the one
after the previous transfer's, a first frame with another (not the previous one) restarts
the session harmlessly between transfers, and a repeat within the timeout (libcanard
refuses it for a multi-frame transfer, takes it for a single frame and moves its expected
id on) makes the session irregular. Every frame of any other session, and every frame the
reassembler refuses on its own (no tail byte, anonymous, unknown type, node id 0), goes to
the reassembler itself. Sessions interact only through the reassembler's table of
`MAX_SESSIONS` sessions per channel, which drops the session whose latest transfer began
first when a new one comes (see `Spans`): dropping a regular session between two of
its transfers changes nothing, so any number of sessions stays column-wise as long as no
drop can reach a transfer in progress or an irregular session; a channel where one might
goes to the reassembler whole.
"""

from __future__ import annotations

import functools
import weakref
from dataclasses import dataclass
from typing import Any

import numpy as np
import numpy.typing as npt

from veronte4x.capture.columnar.payloads import integer_dtype
from veronte4x.dronecan.can_id import TransferKind
from veronte4x.dronecan.codec import TypeCodec
from veronte4x.dronecan.crc import crc16_table
from veronte4x.dronecan.reassembler import TRANSFER_ID_TIMEOUT
from veronte4x.dronecan.scalar_code import be_runs, bit_runs
from veronte4x.dronecan.schema import Scalar, Struct
from veronte4x.dronecan.tail import END_OF_TRANSFER, START_OF_TRANSFER, TOGGLE, TRANSFER_ID_MASK
from veronte4x.dronecan.typeset import TypeSet, types_or_default

MAX_SESSIONS = 1024
"""The per-frame reassembler's session table (its default ``max_sessions``)."""


@dataclass(frozen=True, eq=False)
class TypeIndex:
    """The types of one type set, numbered for the columns: a type index is a position in
    ``codecs``, the set's codecs (standard types first, vendor types after).

    Attributes:
        codecs: The codec of each type index.
        message_types: Type index of each message data type id, -1 for none.
        service_types: Type index of each service data type id shifted left by one, a
            request's with the low bit set; -1 for none.
        limits: Largest payload of each type index, with its CRC.
        seeds: Transfer CRC seed of each type index.
    """

    codecs: tuple[TypeCodec, ...]
    message_types: npt.NDArray[np.int16]
    service_types: npt.NDArray[np.int16]
    limits: npt.NDArray[np.int64]
    seeds: npt.NDArray[np.uint32]

    def codec_of(self, index: int) -> TypeCodec:
        """The codec of a type index."""
        return self.codecs[index]


_INDEXES: weakref.WeakKeyDictionary[TypeSet, TypeIndex] = weakref.WeakKeyDictionary()


def type_index_of(types: TypeSet | None = None) -> TypeIndex:
    """The `TypeIndex` of a type set (None: the default set), built once per set."""
    types = types_or_default(types, "type_index_of")
    found = _INDEXES.get(types)
    if found is None:
        found = _INDEXES[types] = _build_index(types.codecs)
    return found


def _build_index(codecs: tuple[TypeCodec, ...]) -> TypeIndex:
    message_types = np.full(1 << 16, -1, np.int16)
    service_types = np.full(1 << 10, -1, np.int16)
    for index, codec in enumerate(codecs):
        t = codec.data_type
        if t.kind is TransferKind.MESSAGE:
            message_types[t.data_type_id] = index
        else:
            service_types[t.data_type_id << 1 | (t.kind is TransferKind.REQUEST)] = index
    limits = np.array([c.max_payload + 2 for c in codecs], np.int64)
    seeds = np.array([c.crc_seed for c in codecs], np.uint32)
    return TypeIndex(codecs, message_types, service_types, limits, seeds)


_CRC_TABLE = np.array(crc16_table(), np.uint32)


def _crc_pairs() -> npt.NDArray[np.uint32]:
    """The CRC register after two zero bytes from each 16-bit register: feeding bytes
    ``a``, ``b`` to register ``c`` is ``_CRC_PAIRS[c ^ (a << 8 | b)]`` (the CRC is linear)."""
    crc = np.arange(1 << 16, dtype=np.uint32)
    for _ in range(2):
        crc = ((crc << 8) & 0xFFFF) ^ _CRC_TABLE[crc >> 8]
    return crc


_CRC_PAIRS = _crc_pairs()


@dataclass
class Transfers:
    """The transfers of regular sessions, one row each, in no particular order.

    Attributes:
        last: Row (in the frames given) of each transfer's last frame.
        first: Row of its first frame.
        type_index: Its type's index (see `TypeIndex`).
        payload: Payload bytes of every transfer, one after the other.
        offsets: Where each transfer's payload starts in `payload` (one more at the end).
        crc: The CRC a multi-frame transfer carries, or -1 for a single frame.
    """

    last: npt.NDArray[np.int64]
    first: npt.NDArray[np.int64]
    type_index: npt.NDArray[np.int16]
    payload: npt.NDArray[np.uint8]
    offsets: npt.NDArray[np.int64]
    crc: npt.NDArray[np.int64]

    def payload_of(self, transfer: int) -> bytes:
        """One transfer's payload."""
        return self.payload[self.offsets[transfer] : self.offsets[transfer + 1]].tobytes()


def type_index(
    can_id: npt.NDArray[np.uint32], known: TypeIndex | None = None
) -> npt.NDArray[np.int16]:
    """The type of each frame among ``known`` (None: the default set's), as the reassembler
    finds it; -1 where it refuses the frame whatever its session (anonymous, unknown type,
    node id 0, beyond 29 bits)."""
    if known is None:
        known = type_index_of()
    cid = can_id.astype(np.int64)
    service = (cid & 0x80) != 0
    source = cid & 0x7F
    found = np.where(
        service,
        known.service_types[(cid >> 15) & 0x1FF],
        known.message_types[(cid >> 8) & 0xFFFF],
    )
    refused = (source == 0) | (service & (((cid >> 8) & 0x7F) == 0)) | ((cid >> 29) != 0)
    return np.where(refused, -1, found).astype(np.int16)


def regular_sessions(
    channel: npt.NDArray[np.int32],
    can_id: npt.NDArray[np.uint32],
    stamp: npt.NDArray[np.float64],
    length: npt.NDArray[np.int64],
    tail: npt.NDArray[np.uint8],
    types: npt.NDArray[np.int16],
    known: TypeIndex,
    timeout: float = TRANSFER_ID_TIMEOUT,
) -> tuple[npt.NDArray[np.int64], npt.NDArray[np.bool_]]:
    """Sort frames by session and find the regular sessions.

    Args:
        channel, can_id, stamp, length, tail, types: Per frame, in capture order: channel
            code, CAN ID, timestamp as the reassembler is fed it, data length, tail byte
            and type index (all >= 0).
        known: The types the indexes number.
        timeout: The transfer-ID timeout.

    Returns:
        The frames' order by session (capture order within one), and for each frame in
        that order whether its session is regular.
    """
    key = channel.astype(np.int64) << 24 | (can_id.astype(np.int64) & 0xFFFFFF)
    order = np.argsort(key, kind="stable")
    key = key[order]
    n = len(order)
    tail = tail[order]
    size = length[order]
    ts = stamp[order]
    opens = np.ones(n, np.bool_)
    opens[1:] = key[1:] != key[:-1]
    session = np.cumsum(opens) - 1
    start = (tail & START_OF_TRANSFER) != 0
    end = (tail & END_OF_TRANSFER) != 0
    toggle = (tail & TOGGLE) != 0
    tid = tail & TRANSFER_ID_MASK
    bad = opens & ~start
    transfer = np.cumsum(start) - 1
    first = np.flatnonzero(start)
    if len(first):
        transfer = np.maximum(transfer, 0)
        head = first[transfer]
        position = np.arange(n) - head
        last = np.ones(n, np.bool_)
        last[:-1] = opens[1:] | start[1:]
        bad |= toggle != ((position & 1) == 1)
        bad |= tid != tid[head]
        bad |= end != last
        bad |= ~last & (size != 8)
        bad |= (size < 1) | (size > 8)
        bad |= (position > 0) & (ts - ts[head] > timeout)
        sizes = np.add.reduceat(size - 1, first)
        multi = ~last[first]  # transfers of more than one frame
        bad[first[multi & (sizes > known.limits[types[order][first]])]] = True
        # A new transfer repeats the previous one's id only after the timeout.
        follows = first[1:][~opens[first[1:]]]
        before = first[np.searchsorted(first, follows) - 1]
        repeat = (tid[follows] == tid[before]) & ~(ts[follows] - ts[before] > timeout)
        bad[follows[repeat]] = True
    else:
        bad[:] = True
    sessions = session[-1] + 1 if n else 0
    broken = np.bincount(session[bad], minlength=sessions) > 0 if n else np.zeros(0, np.bool_)
    regular = ~broken[session] if n else np.zeros(0, np.bool_)
    return order, regular


class Spans:
    """The first and last frame positions of sessions, to bound how many sessions used the
    table between two frames.

    The table holds `MAX_SESSIONS` sessions; a new session drops the one whose latest
    transfer began (or that entered the table) first. So a session is dropped only after
    ``MAX_SESSIONS`` other sessions used the table since its latest transfer began, and
    only sessions with a frame between two frames can have used it in between: at most the
    sessions whose first frame comes before the later frame and whose last frame after the
    earlier one (`reach`). A channel is safe when, so counted, no drop can fall within a
    multi-frame transfer of a regular session nor between the first and last frames of an
    irregular one, it has at most ``MAX_SESSIONS`` irregular sessions (so that the
    reassembler fed those alone never drops one either), and no session left holding a
    transfer at the end has ``MAX_SESSIONS`` others after its last frame (`later`). A
    regular session dropped between transfers comes back as it was (its next transfer
    neither repeats nor continues anything).
    """

    def __init__(
        self,
        channel: npt.NDArray[np.int32],
        first: npt.NDArray[np.int64],
        last: npt.NDArray[np.int64],
    ) -> None:
        self.span = np.int64(last.max(initial=0)) + 2
        base = channel.astype(np.int64) * self.span
        self.firsts, self.lasts = np.sort(base + first), np.sort(base + last)

    def reach(self, channel: np.ndarray, after: np.ndarray, before: np.ndarray) -> np.ndarray:
        """Most sessions of ``channel`` (other than the one asked about, whose frames
        ``after`` and ``before`` are) with a frame between ``after`` and ``before``: those
        alive across, and never more than the frames between."""
        offset = channel.astype(np.int64) * self.span
        began = np.searchsorted(self.firsts, offset + before, "left")
        ended = np.searchsorted(self.lasts, offset + after, "right")
        count: np.ndarray = np.minimum(began - ended - 1, before - after - 1)
        return count

    def later(self, channel: np.ndarray, last: np.ndarray) -> np.ndarray:
        """Sessions of ``channel`` whose last frame comes after ``last``."""
        offset = channel.astype(np.int64) * self.span
        after: np.ndarray = np.searchsorted(self.lasts, offset + self.span, "left") - (
            np.searchsorted(self.lasts, offset + last, "right")
        )
        return after


def transfers(
    rows: npt.NDArray[np.int64],
    data: npt.NDArray[np.uint8],
    length: npt.NDArray[np.int64],
    types: npt.NDArray[np.int16],
) -> Transfers:
    """Join the frames of regular sessions into transfers.

    Args:
        rows: Frames of regular sessions, in session order (see `regular_sessions`).
        data, length, types: Per frame (indexed by ``rows``).
    """
    used = length[rows] - 1
    start = (data[rows, np.maximum(used, 0)] & START_OF_TRANSFER) != 0
    first = np.flatnonzero(start)
    last = np.empty(len(first), np.int64)
    last[:-1] = first[1:] - 1
    if len(first):
        last[-1] = len(rows) - 1
    multi = last != first
    heads = rows[first[multi]]
    crc = np.full(len(first), -1, np.int64)
    crc[multi] = data[heads, 0].astype(np.int64) | data[heads, 1].astype(np.int64) << 8
    # The data bytes but the tail byte and, in multi-frame transfers, the two CRC bytes.
    keep = np.arange(8) < used[:, None]
    keep[first[multi], :2] = False
    payload = data[rows][keep]
    sizes = np.add.reduceat(used, first) - 2 * multi if len(first) else np.zeros(0, np.int64)
    offsets = np.zeros(len(first) + 1, np.int64)
    np.cumsum(sizes, out=offsets[1:])
    return Transfers(rows[last], rows[first], types[rows[first]], payload, offsets, crc)


def crc_ok(
    found: Transfers, which: npt.NDArray[np.int64], known: TypeIndex
) -> npt.NDArray[np.int64]:
    """The transfer CRC computed over each of ``which`` (multi-frame) transfers' payloads
    (their types numbered by ``known``), two bytes at a time over the transfers that long
    (longest first: a prefix), then the odd last byte of the others."""
    sizes = found.offsets[which + 1] - found.offsets[which]
    longest = np.argsort(-sizes, kind="stable")
    sizes, starts = sizes[longest], found.offsets[which][longest]
    crc = known.seeds[found.type_index[which][longest]].astype(np.uint32)
    payload = found.payload
    pairs = np.arange(int(sizes.max(initial=0)) // 2)
    counts = np.searchsorted(-sizes, -(2 * pairs + 2), "right")  # transfers that long
    for pair, active in enumerate(counts.tolist()):
        at = starts[:active] + 2 * pair
        word = payload[at].astype(np.uint32) << 8 | payload[at + 1]
        crc[:active] = _CRC_PAIRS[crc[:active] ^ word]
    odd = np.flatnonzero(sizes & 1)
    if len(odd):
        value, byte = crc[odd], payload[starts[odd] + sizes[odd] - 1]
        crc[odd] = ((value << 8) & 0xFFFF) ^ _CRC_TABLE[((value >> 8) ^ byte) & 0xFF]
    computed = np.empty(len(sizes), np.int64)
    computed[longest] = crc
    return computed


# Payload decoding ------------------------------------------------------------------------


def payload_matrix(found: Transfers, which: npt.NDArray[np.int64], size: int) -> np.ndarray:
    """The payloads of ``which`` transfers, all ``size`` bytes long, as rows (plus padding)."""
    matrix = np.zeros((len(which), size + 8), np.uint8)
    if not size or not len(which):
        return matrix
    if which[-1] - which[0] == len(which) - 1 and (np.diff(which) == 1).all():
        low = int(found.offsets[which[0]])  # one after the other: a slice of the payloads
        matrix[:, :size] = found.payload[low : low + len(which) * size].reshape(-1, size)
    else:
        matrix[:, :size] = found.payload[found.offsets[which][:, None] + np.arange(size)]
    return matrix


def _bits(matrix: np.ndarray, start: int, width: int) -> npt.NDArray[np.uint64]:
    """Bits ``start..start+width`` of each row read as one little-endian integer."""
    out = np.zeros(len(matrix), np.uint64)
    done = 0
    while done < width:
        piece = min(width - done, 56)
        at = start + done
        first, shift = at // 8, at % 8
        word = np.zeros(len(matrix), np.uint64)
        for k in range((shift + piece + 7) // 8):
            word |= matrix[:, first + k].astype(np.uint64) << np.uint64(8 * k)
        word = (word >> np.uint64(shift)) & np.uint64((1 << piece) - 1)
        out |= word << np.uint64(done)
        done += piece
    return out


_WHOLE: dict[int, np.dtype[Any]] = {
    8: np.dtype("u1"),
    16: np.dtype("<u2"),
    32: np.dtype("<u4"),
    64: np.dtype("<u8"),
}
"""Scalars of whole bytes, which the stream holds as little-endian bytes."""

_bit_runs = functools.cache(bit_runs)


_be_runs = functools.cache(be_runs)


def _window(matrix: np.ndarray, first: int, windows: dict[int, np.ndarray]) -> np.ndarray:
    """The 8 bytes of each row from byte ``first`` on as one big-endian integer (the rows
    hold 8 bytes of padding), made once per byte for all the fields it holds."""
    word = windows.get(first)
    if word is None:
        octets = np.ascontiguousarray(matrix[:, first : first + 8])
        word = windows[first] = octets.view(">u8")[:, 0].astype(np.uint64)
    return word


def scalar(
    matrix: np.ndarray, t: Scalar, offset: int, windows: dict[int, np.ndarray] | None = None
) -> np.ndarray:
    """A DSDL scalar at bit ``offset`` of the stream, for every row, as the codec decodes it
    (integers sign-extended, floats widened exactly, bools). ``windows``: the rows' 8-byte
    windows already read (`_window`), shared by the fields of one matrix."""
    first, shift = divmod(offset, 8)
    if not shift and t.bits in _WHOLE:  # whole bytes, little-endian: one view
        whole = np.ascontiguousarray(matrix[:, first : first + t.bits // 8])
        raw = whole.view(_WHOLE[t.bits])[:, 0].astype(np.uint64)
    elif shift + t.bits <= 64:  # within one 8-byte window: its bit runs from one read
        word = _window(matrix, first, {} if windows is None else windows)
        raw = np.zeros(len(matrix), np.uint64)
        for source, width, at in _be_runs(shift, t.bits, 64):
            raw |= ((word >> np.uint64(at)) & np.uint64((1 << width) - 1)) << np.uint64(source)
    else:
        raw = np.zeros(len(matrix), np.uint64)
        for source, width, dest in _bit_runs(offset, t.bits):
            raw |= _bits(matrix, dest, width) << np.uint64(source)
    if t.kind == "int":
        spare = np.uint64(64 - t.bits)  # sign-extended by shifts: any width up to 64
        signed: np.ndarray = (raw << spare).view(np.int64) >> spare.astype(np.int64)
        return signed
    if t.kind == "float":
        if t.bits == 16:
            widened: np.ndarray = raw.astype(np.uint16).view(np.float16).astype(np.float32)
            return widened
        single: np.ndarray = raw.astype(np.uint32).view(np.float32)
        return single if t.bits == 32 else raw.view(np.float64)
    flags: np.ndarray = raw != 0
    return flags if t.kind == "bool" else raw


def fixed_size(struct: Struct) -> int | None:
    """Payload bytes of a struct of scalars only (its every field at a fixed place)."""
    bits = 0
    for f in struct.fields:
        if not isinstance(f.type, Scalar):
            return None
        bits += f.type.bits
    return (bits + 7) // 8


def decode_fixed(struct: Struct, matrix: np.ndarray) -> dict[str, Any]:
    """Every field of a struct of scalars, by name (enum fields as their wire value)."""
    out: dict[str, Any] = {}
    offset = 0
    windows: dict[int, np.ndarray] = {}
    for f in struct.fields:
        assert isinstance(f.type, Scalar)
        if f.name:
            value = scalar(matrix, f.type, offset, windows)
            if f.type.kind in ("int", "uint"):  # as the column holds it
                value = value.astype(integer_dtype(f.type))
            out[f.name] = value
        offset += f.type.bits
    return out
