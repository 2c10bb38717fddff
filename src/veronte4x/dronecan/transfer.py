"""Frames and transfers: `encode` a message, `decode_frames` one transfer.

A transfer of at most 7 payload bytes is one frame; a longer one is prefixed with the
transfer CRC seeded with the type signature and cut into 7-byte chunks (spec 4.1). The stateful
receiver for a stream of frames is
`Reassembler`.
"""

from __future__ import annotations

import struct
import weakref
from binascii import crc_hqx  # the transfer CRC, see veronte4x.dronecan.crc
from collections.abc import Callable, Iterable
from typing import Any, NamedTuple

from veronte4x.dronecan import typeset as _typeset
from veronte4x.dronecan.can_id import TransferKind, parse_can_id
from veronte4x.dronecan.codec import BY_CLASS, TypeCodec
from veronte4x.dronecan.compiled import (
    DECODE_FALLBACK,
    ENCODE_FALLBACK,
    FramesFunction,
    can_id_base,
)
from veronte4x.dronecan.crc import crc16
from veronte4x.dronecan.frame import TransferFrame
from veronte4x.dronecan.tail import (
    FRAME_FLAGS,
    MULTI_FRAME_TAILS,
    SINGLE_FRAME,
    SINGLE_FRAME_MAX,
    TRANSFER_ID_MASK,
    frame_count,
    split_payload,
    tail_byte,
)
from veronte4x.dronecan.typeset import TypeSet, types_or_default
from veronte4x.errors import BytesLike, DecodeError, EncodeError, argument_type_error
from veronte4x.words import counted

DEFAULT_PRIORITY = 16
"""Priority used when none is given: the middle of 0 (highest) to 31, libcanard's
``CANARD_TRANSFER_PRIORITY_MEDIUM``. The spec sets no default."""


class Transfer(NamedTuple):
    """A complete, checked transfer.

    Attributes:
        message: The decoded message, request or response.
        source_node_id: Sender, 1..127; None for an anonymous message (spec 4.1, "Anonymous
            message transfers": source node id 0 on the wire).
        destination_node_id: Receiver of a service transfer, ``None`` for a message.
        priority: 0 (highest) to 31.
        transfer_id: 0..31.
        timestamp: The timestamp given with the transfer's first frame.
        kind: Message, request or response.
        data_type_id: The data type id of the CAN ID.
    """

    message: Any
    source_node_id: int | None
    destination_node_id: int | None
    priority: int
    transfer_id: int
    timestamp: float
    kind: TransferKind
    data_type_id: int

    def _repr_html_(self) -> str:
        """Jupyter's view: the transfer and its message as tables (`veronte4x.dronecan.view`)."""
        from veronte4x.dronecan.view import transfer_html

        return transfer_html(self)


_new_tuple = tuple.__new__


def received(
    message: Any,
    can_id: int,
    transfer_id: int,
    timestamp: float,
    kind: TransferKind,
    data_type_id: int,
) -> Transfer:
    """The `Transfer` of a ``message`` received with a valid 29-bit ``can_id``: its sender,
    receiver and priority read from the CAN ID (spec 4.1 "ID field"), the sender None for an
    anonymous message. Every received transfer is built here."""
    return _new_tuple(
        Transfer,
        (
            message,
            can_id & 0x7F or None,
            (can_id >> 8) & 0x7F if can_id & 0x80 else None,
            can_id >> 24,
            transfer_id,
            timestamp,
            kind,
            data_type_id,
        ),
    )


_FAST: dict[type, FramesFunction] = {}
"""The generated frames function of each class used so far (see `_fast_frames`)."""


def _fast_frames(cls: type) -> FramesFunction | None:
    """The generated frames function of a class, compiled on its first use; None if the
    class is no DroneCAN type."""
    codec = BY_CLASS.get(cls)
    if codec is None:
        return None
    fast = _FAST[cls] = codec.fast.frames
    return fast


def encode(
    message: Any,
    *,
    source_node_id: int,
    transfer_id: int,
    priority: int = DEFAULT_PRIORITY,
    destination_node_id: int | None = None,
    saturate: bool = False,
    types: TypeSet | None = None,
) -> list[TransferFrame]:
    """Encode a message, request or response into the frames of one transfer.

    Args:
        message: An instance of one of the message, request or response classes.
        source_node_id: The sender, 1..127 (anonymous messages are decoded, not sent).
        transfer_id: 0..31.
        priority: 0 (highest) to 31.
        destination_node_id: The receiver, 1..127; required for requests and responses,
            must be None for messages.
        saturate: Clamp out-of-range integers to their DSDL range (the spec's saturated
            cast) instead of raising.
        types: The `TypeSet` that knows the message's class; None for the default set
            (the standard one, plus what `veronte4x.dronecan.load_dsdl` added).

    Raises:
        EncodeError: A field the type cannot hold, or a transport field out of range.
        TypeError: ``message`` not an instance of a DroneCAN message, request or response
            class, or a transport argument that is not an int.
    """
    if not saturate:
        # Generated fast path; on anything unusual the checked path raises the precise error.
        if types is None:
            fast = _FAST.get(message.__class__) or _fast_frames(message.__class__)
        else:  # that set's own codec, never the default set's
            codec = types_or_default(types, "encode").by_class.get(message.__class__)
            fast = None if codec is None else codec.fast.frames
        if fast is not None:
            try:
                return fast(message, source_node_id, transfer_id, priority, destination_node_id)
            except ENCODE_FALLBACK:
                pass
    return _encode_checked(
        message,
        source_node_id,
        transfer_id,
        priority,
        destination_node_id,
        saturate,
        types,
    )


def _encode_checked(
    message: Any,
    source_node_id: int,
    transfer_id: int,
    priority: int,
    destination_node_id: int | None,
    saturate: bool,
    types: TypeSet | None = None,
) -> list[TransferFrame]:
    """`encode` through the generic serializer, checking every argument."""
    codec = types_or_default(types, "encode").by_class.get(type(message))
    if codec is None:
        raise argument_type_error(
            "encode", "message", "a DroneCAN message, request or response", message
        )
    if not (
        type(source_node_id) is int
        and type(transfer_id) is int
        and type(priority) is int
        and 1 <= source_node_id <= 127
        and 0 <= transfer_id <= 31
        and 0 <= priority <= 31
    ):
        _check_transport(codec, source_node_id, transfer_id, priority)
    can_id = priority << 24 | can_id_base(codec.data_type) | source_node_id
    if can_id & 0x80:
        if destination_node_id is not None and (
            not isinstance(destination_node_id, int) or isinstance(destination_node_id, bool)
        ):
            raise argument_type_error(
                "encode", "destination_node_id", "an int", destination_node_id
            )
        if destination_node_id is None or not 1 <= destination_node_id <= 127:
            raise EncodeError(
                codec.data_type.full_name, "destination_node_id", destination_node_id, "1..127"
            )
        can_id |= destination_node_id << 8
    elif destination_node_id is not None:
        raise EncodeError(
            codec.data_type.full_name, "destination_node_id", destination_node_id, "None"
        )
    payload = codec.encode(message, saturate)
    if len(payload) <= SINGLE_FRAME_MAX:
        return [TransferFrame(can_id, payload + bytes((SINGLE_FRAME | transfer_id,)))]
    crc = crc16(payload, codec.crc_seed)
    return [TransferFrame(can_id, data) for data in split_payload(payload, crc, transfer_id)]


def _check_transport(codec: TypeCodec, source: object, tid: object, priority: object) -> None:
    name = codec.data_type.full_name
    for field, value, low, high in (
        ("source_node_id", source, 1, 127),
        ("transfer_id", tid, 0, 31),
        ("priority", priority, 0, 31),
    ):
        if not isinstance(value, int) or isinstance(value, bool):
            raise argument_type_error("encode", field, "an int", value)
        if not low <= value <= high:
            raise EncodeError(name, field, value, f"an int in {low}..{high}")


_SingleRoute = tuple[Callable[[bytes], Any], TransferKind, int]
"""The single-frame route of a CAN ID: the generated frame decoder of its type, and the
kind and data type id of its transfers."""

_MultiRoute = Callable[[list[Any], float], "Transfer | None"]
"""The multi-frame route of a CAN ID: ``route(frames, timestamp)``, a list of at least two
frames to their transfer; None (or one of `DECODE_FALLBACK`) where the checked path must
decide."""


class _Routes:
    """What `decode_frames` keeps of one `TypeSet`: the routes of the CAN IDs seen so far
    (at most `_MAX_ROUTES` of each kind, then forgotten all at once; a bus of that many
    CAN IDs is not the common case)."""

    __slots__ = ("by_id", "multi", "single", "types")

    def __init__(self, types: TypeSet) -> None:
        self.types = types
        self.by_id = types.by_id
        self.single: dict[int, _SingleRoute] = {}
        self.multi: dict[int, _MultiRoute] = {}

    def codec(self, can_id: int) -> TypeCodec | None:
        """The codec of a CAN ID's type if the CAN ID is a valid one of a known type."""
        if not (0 < can_id >> 7 < 1 << 22 and can_id & 0x7F):
            return None
        if not can_id & 0x80:
            return self.by_id.get((TransferKind.MESSAGE, (can_id >> 8) & 0xFFFF))
        if not can_id & 0x7F00:
            return None
        kind = TransferKind.REQUEST if can_id & 0x8000 else TransferKind.RESPONSE
        return self.by_id.get((kind, (can_id >> 16) & 0xFF))

    def add_single(self, can_id: int) -> _SingleRoute | None:
        """The single-frame route of a CAN ID, now kept; None for a CAN ID with none."""
        codec = self.codec(can_id)
        if codec is None or codec.fast.decode_frame is None:
            return None
        if len(self.single) >= _MAX_ROUTES:
            self.single.clear()
        route = self.single[can_id] = _single_route(codec)
        return route

    def add_multi(self, can_id: int) -> _MultiRoute | None:
        """The multi-frame route of a CAN ID, now kept; None for a CAN ID with none."""
        codec = self.codec(can_id)
        if codec is None:
            return None
        if len(self.multi) >= _MAX_ROUTES:
            self.multi.clear()
        route = self.multi[can_id] = _multi_route(codec, can_id)
        return route


_MAX_ROUTES = 4096


def _single_route(codec: TypeCodec) -> _SingleRoute:
    """The single-frame route of a valid CAN ID of a type with a frame decoder."""
    decode = codec.fast.decode_frame
    assert decode is not None
    return decode, codec.data_type.kind, codec.data_type.data_type_id


def _multi_route(codec: TypeCodec, can_id: int) -> _MultiRoute:
    """The multi-frame route of a valid CAN ID of a type."""
    decode, seed = codec.fast.decode, codec.crc_seed
    most = frame_count(codec.max_payload)
    kind, data_type_id = codec.data_type.kind, codec.data_type.data_type_id

    def route(frames: list[Any], timestamp: float) -> Transfer | None:
        count = len(frames)
        if count > most:  # a longer payload than the type's largest
            return None
        chunks = []
        for frame in frames:
            if frame.__class__ is not tuple or len(frame) != 2:
                return None
            frame_id, data = frame
            if (
                frame_id.__class__ is not int
                or frame_id != can_id
                or data.__class__ is not bytes
                or len(data) > 8
            ):
                return None
            chunks.append(data)
        joined = b"".join(chunks)
        size = len(joined) - 8 * (count - 1)  # of the last frame, if the others have 8 bytes
        if not 0 < size <= len(chunks[-1]):  # then all frames have 1..8 bytes, the others 8
            return None
        tid = joined[7] & TRANSFER_ID_MASK
        tails = _TAILS[tid][count]  # of the frames before the last, and the last
        if joined[7 : 8 * count - 8 : 8] != tails[0] or joined[-1] != tails[1]:
            return None
        body = b"".join(_CHUNKS[count].unpack_from(joined)) + joined[8 * count - 8 : -1]
        payload = body[2:]
        if crc_hqx(payload, seed) != body[0] | body[1] << 8:
            return None
        return received(decode(payload), can_id, tid, timestamp, kind, data_type_id)

    return route


class _ByCount(dict[int, Any]):
    """A value per frame count, made by ``make(count)`` on first use (a route asks only
    for counts up to its type's largest transfer, `frame_count`)."""

    __slots__ = ("make",)

    def __init__(self, make: Callable[[int], Any]) -> None:
        super().__init__()
        self.make = make

    def __missing__(self, count: int) -> Any:
        value = self[count] = self.make(count)
        return value


def _tail_pair(rows: dict[int, tuple[int, ...]]) -> Callable[[int], tuple[bytes, int]]:
    return lambda count: (bytes(rows[count][:-1]), rows[count][-1])


_TAILS = tuple(_ByCount(_tail_pair(rows)) for rows in MULTI_FRAME_TAILS)
"""``_TAILS[transfer_id][frame_count]``: the tail bytes of the frames before the last, and
the last one's."""

_CHUNKS = _ByCount(lambda count: struct.Struct("7sx" * (count - 1)))
"""``_CHUNKS[frame_count]`` unpacks the payload bytes (7 each) of the frames before the last."""

_ROUTES_OF: weakref.WeakKeyDictionary[TypeSet, _Routes] = weakref.WeakKeyDictionary()
"""The routes of each type set used so far."""

_ROUTES = _ROUTES_OF[TypeSet.standard()] = _Routes(TypeSet.standard())
"""The routes of the type set used last (one object, so that a thread that reads it sees
the routes of one set)."""


def _routes_of(types: object) -> _Routes | None:
    """The routes of ``types`` (None: the default set), now `_ROUTES`; None if it is no
    `TypeSet` (the checked path then raises the error)."""
    global _ROUTES
    if types is None:
        types = _typeset.default_types()
    if not isinstance(types, TypeSet):
        return None
    routes = _ROUTES_OF.get(types)
    if routes is None:
        routes = _ROUTES_OF[types] = _Routes(types)
    _ROUTES = routes
    return routes


_FAST_ERRORS = DECODE_FALLBACK  # what the generated decoders raise
_BYTES_LIKE = (bytes, bytearray, memoryview)


def decode_frames(
    frames: Iterable[tuple[int, BytesLike]],
    timestamp: float = 0.0,
    types: TypeSet | None = None,
) -> Transfer:
    """Decode the frames of exactly one transfer, in order, checking everything.

    Checks the CAN IDs (all equal), the tail bytes (start, end, toggle, transfer id), the
    frame lengths, the CRC of a multi-frame transfer and the payload.

    Args:
        frames: ``(can_id, data)`` pairs: an int CAN ID and bytes-like data, tail byte last.
        timestamp: Returned as the transfer's timestamp.
        types: The `TypeSet` to decode with; None for the default set (the standard
            one, plus what `veronte4x.dronecan.load_dsdl` added).

    Raises:
        DecodeError: Any inconsistency in the frames.
        TypeError: ``frames`` is not an iterable of ``(int, bytes-like)`` pairs, or
            ``timestamp`` is not a number.
    """
    # Fast paths: a route per CAN ID of a known type (see `_Routes`), everything as
    # expected. On anything else the checked path below decides, and raises the precise
    # error.
    if frames.__class__ is list and timestamp.__class__ is float:
        routes: _Routes | None = _ROUTES
        if routes.types is not (_typeset._default if types is None else types):  # type: ignore[union-attr]
            routes = _routes_of(types)
        if routes is None:
            pass
        elif len(frames) == 1:
            first = frames[0]
            if first.__class__ is tuple and len(first) == 2:
                can_id, data = first
                if can_id.__class__ is int and data.__class__ is bytes and data:
                    route = routes.single.get(can_id) or routes.add_single(can_id)
                    if route is not None:
                        tail = data[-1]
                        if tail & FRAME_FLAGS == SINGLE_FRAME:
                            decode, kind, data_type_id = route
                            try:  # the frame decoder checks the frame's length
                                message = decode(data)
                            except _FAST_ERRORS:
                                pass
                            else:
                                tid = tail & TRANSFER_ID_MASK
                                return received(message, can_id, tid, timestamp, kind,
                                                data_type_id)  # fmt: skip
        elif frames:
            first = frames[0]
            if first.__class__ is tuple and len(first) == 2:
                can_id = first[0]
                if can_id.__class__ is int:
                    multi = routes.multi.get(can_id) or routes.add_multi(can_id)
                    if multi is not None:
                        try:
                            transfer = multi(frames, timestamp)
                        except _FAST_ERRORS:
                            transfer = None
                        if transfer is not None:
                            return transfer
    return _decode_frames_checked(_frame_list(frames), _check_timestamp(timestamp), types)


def _frame_list(frames: object) -> list[tuple[int, bytes]]:
    """``frames`` as a list of (int, bytes) pairs; TypeError for anything else."""
    try:
        items = list(frames)  # type: ignore[call-overload]
    except TypeError:
        raise argument_type_error(
            "decode_frames", "frames", "an iterable of (can_id, data) pairs", frames
        ) from None
    out = []
    for index, item in enumerate(items):
        if not isinstance(item, (tuple, list)) or len(item) != 2:
            raise argument_type_error(
                "decode_frames", f"frames[{index}]", "a (can_id, data) pair", item
            )
        can_id, data = item
        if not isinstance(can_id, int) or isinstance(can_id, bool):
            raise argument_type_error("decode_frames", f"frames[{index}][0]", "an int", can_id)
        if not isinstance(data, _BYTES_LIKE):
            raise argument_type_error("decode_frames", f"frames[{index}][1]", "bytes-like", data)
        out.append((can_id, bytes(data)))
    return out


def _check_timestamp(timestamp: object) -> float:
    if not isinstance(timestamp, (int, float)) or isinstance(timestamp, bool):
        raise argument_type_error("decode_frames", "timestamp", "a float", timestamp)
    return timestamp


def _decode_frames_checked(
    items: list[tuple[int, bytes]], timestamp: float, types: TypeSet | None = None
) -> Transfer:
    """`decode_frames` through the generic path, checking every field in turn."""
    if not items:
        raise DecodeError(None, "no frames", b"")
    can_id = items[0][0]
    fields = parse_can_id(can_id)
    codec = types_or_default(types, "decode_frames").by_id.get((fields.kind, fields.data_type_id))
    name = codec.data_type.full_name if codec else None
    tid = items[0][1][-1] & TRANSFER_ID_MASK if items[0][1] else 0
    count = len(items)
    for index, (frame_id, data) in enumerate(items):
        last = index == count - 1
        if frame_id != can_id:
            raise DecodeError(name, f"frame {index} has CAN ID {frame_id:#x}", data, "can_id")
        if not 1 <= len(data) <= 8 or (not last and len(data) != 8):
            raise DecodeError(name, f"frame {index} has {counted(len(data), 'byte')}", data)
        expected = tail_byte(index == 0, last, bool(index & 1), tid)
        if data[-1] != expected:
            raise DecodeError(
                name, f"frame {index} tail byte {data[-1]:#04x}, expected {expected:#04x}", data
            )
    if codec is None:
        raise DecodeError(
            None, f"no {fields.kind.name.lower()} type with id {fields.data_type_id}", b""
        )
    body = b"".join(data[:-1] for _, data in items)
    if len(items) > 1:
        payload = body[2:]
        crc = crc16(payload, codec.crc_seed)
        if crc != body[0] | body[1] << 8:
            raise DecodeError(
                name,
                f"transfer CRC {body[0] | body[1] << 8:#06x}, computed {crc:#06x}",
                body,
                "crc",
            )
    else:
        payload = body
    return received(codec.decode(payload), can_id, tid, timestamp, fields.kind,
                    codec.data_type.data_type_id)  # fmt: skip
