"""Frames and transfers: `encode` a message, `decode_frames` one transfer.

A transfer of at most 7 payload bytes is one frame; a longer one is prefixed with the
transfer CRC seeded with the type signature and cut into 7-byte chunks (spec 4.1). The stateful
receiver for a stream of frames is
`Reassembler`.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any, NamedTuple

from veronte4x.dronecan.can_id import TransferKind, parse_can_id
from veronte4x.dronecan.codec import BY_CLASS, BY_ID, Codec, can_id_base
from veronte4x.dronecan.crc import crc16
from veronte4x.dronecan.frame import Frame
from veronte4x.dronecan.tail import MULTI_FRAME_TAILS, SINGLE_FRAME_MAX, split_payload
from veronte4x.errors import DecodeError, EncodeError

DEFAULT_PRIORITY = 16
"""Priority used when none is given: the middle of 0 (highest) to 31, libcanard's
``CANARD_TRANSFER_PRIORITY_MEDIUM``. The spec sets no default."""


class Transfer(NamedTuple):
    """A complete, checked transfer.

    Attributes:
        message: The decoded message, request or response.
        source_node_id: Sender, 1..127.
        destination_node_id: Receiver of a service transfer, ``None`` for a message.
        priority: 0 (highest) to 31.
        transfer_id: 0..31.
        timestamp: The timestamp given with the transfer's first frame.
        kind: Message, request or response.
        data_type_id: The data type id of the CAN ID.
    """

    message: Any
    source_node_id: int
    destination_node_id: int | None
    priority: int
    transfer_id: int
    timestamp: float
    kind: TransferKind
    data_type_id: int


_FAST = {cls: codec.fast.frames for cls, codec in BY_CLASS.items() if codec.fast is not None}


def encode(
    message: Any,
    *,
    source_node_id: int,
    transfer_id: int,
    priority: int = DEFAULT_PRIORITY,
    destination_node_id: int | None = None,
    saturate: bool = False,
) -> list[Frame]:
    """Encode a message, request or response into the frames of one transfer.

    Args:
        message: An instance of one of the message, request or response classes.
        source_node_id: The sender, 1..127 (anonymous messages are not supported: none of
            the eight types may be sent anonymously).
        transfer_id: 0..31.
        priority: 0 (highest) to 31.
        destination_node_id: The receiver, 1..127; required for requests and responses,
            must be None for messages.
        saturate: Clamp out-of-range integers to their DSDL range (the spec's saturated
            cast) instead of raising.

    Raises:
        EncodeError: Unknown class, a field the type cannot hold, or bad transport fields.
    """
    if not saturate:
        # Generated fast path; on anything unusual the checked path raises the precise error.
        try:
            return _FAST[message.__class__](
                message, source_node_id, transfer_id, priority, destination_node_id
            )
        except Exception:
            pass
    return _encode_checked(
        message, source_node_id, transfer_id, priority, destination_node_id, saturate
    )


def _encode_checked(
    message: Any,
    source_node_id: int,
    transfer_id: int,
    priority: int,
    destination_node_id: int | None,
    saturate: bool,
) -> list[Frame]:
    """`encode` through the generic serializer, checking every argument."""
    codec = BY_CLASS.get(type(message))
    if codec is None:
        raise EncodeError("encode", "message", message, "a DroneCAN message class")
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
        if type(destination_node_id) is not int or not 1 <= destination_node_id <= 127:
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
        return [Frame(can_id, payload + bytes((0xC0 | transfer_id,)))]
    crc = crc16(payload, codec.crc_seed)
    return [Frame(can_id, data) for data in split_payload(payload, crc, transfer_id)]


def _check_transport(codec: Codec, source: object, tid: object, priority: object) -> None:
    name = codec.data_type.full_name
    for field, value, low, high in (
        ("source_node_id", source, 1, 127),
        ("transfer_id", tid, 0, 31),
        ("priority", priority, 0, 31),
    ):
        if type(value) is not int or not low <= value <= high:
            raise EncodeError(name, field, value, f"an int in {low}..{high}")


def decode_frames(frames: Iterable[tuple[int, bytes]], timestamp: float = 0.0) -> Transfer:
    """Decode the frames of exactly one transfer, in order, checking everything.

    Checks the CAN IDs (all equal), the tail bytes (start, end, toggle, transfer id), the
    frame lengths, the CRC of a multi-frame transfer and the payload.

    Raises:
        DecodeError: Any inconsistency.
    """
    items = [(can_id, bytes(data)) for can_id, data in frames]
    if not 0 < len(items) < len(MULTI_FRAME_TAILS[0]):
        raise DecodeError(None, f"{len(items)} frames, not 1..{len(MULTI_FRAME_TAILS[0]) - 1}", b"")
    can_id = items[0][0]
    fields = parse_can_id(can_id)
    codec = BY_ID.get((fields.kind, fields.data_type_id))
    name = codec.data_type.full_name if codec else None
    tid = items[0][1][-1] & 0x1F if items[0][1] else 0
    for index, (frame_id, data) in enumerate(items):
        last = index == len(items) - 1
        if frame_id != can_id:
            raise DecodeError(name, f"frame {index} has CAN ID {frame_id:#x}", data, "can_id")
        if not 1 <= len(data) <= 8 or (not last and len(data) != 8):
            raise DecodeError(name, f"frame {index} has {len(data)} bytes", data)
        expected = MULTI_FRAME_TAILS[tid][len(items)][index] if len(items) > 1 else 0xC0 | tid
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
    return Transfer(
        codec.decode(payload),
        fields.source_node_id,
        fields.destination_node_id,
        fields.priority,
        tid,
        timestamp,
        fields.kind,
        fields.data_type_id,
    )
