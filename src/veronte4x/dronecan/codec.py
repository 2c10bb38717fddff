"""Payload encoding and decoding for each of the types, fast path first.

Each top-level type gets the generated fast functions of
`compiled` where its layout allows, and the generic
`Serializer` otherwise and for everything the fast
path hands over (errors, saturation, odd lengths).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from veronte4x.dronecan.can_id import TransferKind
from veronte4x.dronecan.compiled import (
    ENCODE_FALLBACK,
    FastPaths,
    SlowPath,
    Transport,
    compile_int_array,
    compile_struct,
)
from veronte4x.dronecan.definitions import DATA_TYPES, DataType
from veronte4x.dronecan.frame import Frame
from veronte4x.dronecan.serializer import Serializer
from veronte4x.errors import BytesLike, DecodeError, argument_type_error


@dataclass(frozen=True)
class Codec:
    """The payload functions of one top-level type.

    Attributes:
        data_type: The type definition.
        encode: ``encode(message, saturate) -> payload bytes``; raises EncodeError.
        decode: ``decode(payload) -> message``; raises DecodeError.
        crc_seed: The transfer CRC after the type's signature.
        max_payload: Largest payload in bytes.
        fast: The generated fast paths, or None for types that only use the generic
            serializer (GetNodeInfo response, GetSet, BeginFirmwareUpdate).
    """

    data_type: DataType
    encode: Callable[[Any, bool], bytes]
    decode: Callable[[bytes], Any]
    crc_seed: int
    max_payload: int
    fast: FastPaths | None


def can_id_base(data_type: DataType) -> int:
    """The CAN ID bits fixed by the type: type id, request bit and service bit."""
    if data_type.kind is TransferKind.MESSAGE:
        return data_type.data_type_id << 8
    request = 0x8000 if data_type.kind is TransferKind.REQUEST else 0
    return data_type.data_type_id << 16 | request | 0x80


def _codec(data_type: DataType) -> Codec:
    generic = Serializer(data_type.schema)
    transport = Transport(
        Frame,
        can_id_base(data_type),
        data_type.kind is not TransferKind.MESSAGE,
        data_type.crc_seed,
    )
    fast = compile_struct(data_type.schema, transport) or compile_int_array(
        data_type.schema, transport
    )
    if fast is None:
        encode: Callable[[Any, bool], bytes] = generic.encode
        decode: Callable[[bytes], Any] = generic.decode
    else:
        fast_payload, fast_decode = fast.payload, fast.decode

        def encode(message: Any, saturate: bool = False) -> bytes:
            if not saturate:
                try:
                    return fast_payload(message)
                except ENCODE_FALLBACK:
                    pass
            return generic.encode(message, saturate)

        def decode(payload: bytes) -> Any:
            try:
                return fast_decode(payload)
            except SlowPath:
                return generic.decode(payload)

    return Codec(data_type, encode, decode, data_type.crc_seed, data_type.max_payload, fast)


CODECS: tuple[Codec, ...] = tuple(_codec(t) for t in DATA_TYPES)
"""One codec per top-level type, in the order of `DATA_TYPES`."""

BY_CLASS: dict[type, Codec] = {c.data_type.schema.cls: c for c in CODECS}
"""Codec of each message, request and response class."""

BY_ID: dict[tuple[TransferKind, int], Codec] = {
    (c.data_type.kind, c.data_type.data_type_id): c for c in CODECS
}
"""Codec of each (kind, data type id)."""


def decode_payload(kind: TransferKind, data_type_id: int, payload: BytesLike) -> Any:
    """Decode the payload of one complete transfer (without CRC and tail bytes).

    Raises:
        DecodeError: Unknown (kind, type id), or a payload that does not fit the type.
        TypeError: ``kind`` not a `TransferKind`, ``data_type_id`` not an int, or
            ``payload`` not bytes-like.
    """
    if not isinstance(kind, TransferKind):
        raise argument_type_error("decode_payload", "kind", "a TransferKind", kind)
    if not isinstance(data_type_id, int) or isinstance(data_type_id, bool):
        raise argument_type_error("decode_payload", "data_type_id", "an int", data_type_id)
    if not isinstance(payload, (bytes, bytearray, memoryview)):
        raise argument_type_error("decode_payload", "payload", "bytes-like", payload)
    codec = BY_ID.get((kind, data_type_id))
    if codec is None:
        raise DecodeError(
            None, f"no {kind.name.lower()} type with id {data_type_id}", payload, "data_type_id"
        )
    return codec.decode(bytes(payload))
