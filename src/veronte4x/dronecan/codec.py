"""Payload encoding and decoding for each of the types, fast path first.

Each top-level type gets generated fast functions (`compiled` for flat structs and
RawCommand, `compiled_tree` for everything else), compiled the first time the type is
used, and the generic `Serializer` for everything the fast path hands over (errors,
saturation, odd lengths).
"""

from __future__ import annotations

import functools
from typing import Any

from veronte4x.dronecan.can_id import TransferKind
from veronte4x.dronecan.compiled import (
    DECODE_FALLBACK,
    ENCODE_FALLBACK,
    FastPaths,
    Transport,
    compile_int_array,
    compile_struct,
)
from veronte4x.dronecan.compiled_tree import compile_tree
from veronte4x.dronecan.definitions import DATA_TYPES, DataType
from veronte4x.dronecan.frame import TransferFrame
from veronte4x.dronecan.serializer import Serializer
from veronte4x.errors import BytesLike, DecodeError, argument_type_error


class TypeCodec:
    """The payload functions of one top-level DroneCAN type (the Veronte messages' codec is
    `veronte4x.codec.Codec`).

    Attributes:
        data_type: The type definition.
        crc_seed: The transfer CRC after the type's signature.
        max_payload: Largest payload in bytes.
        generic: The generic serializer of the type.
    """

    def __init__(self, data_type: DataType) -> None:
        self.data_type = data_type
        self.crc_seed = data_type.crc_seed
        self.max_payload = data_type.max_payload
        self.generic = Serializer(data_type.schema)

    def __repr__(self) -> str:
        return f"TypeCodec({self.data_type.full_name} {self.data_type.kind.name.lower()})"

    @functools.cached_property
    def fast(self) -> FastPaths:
        """The generated fast paths, compiled on first use (one type at a time: importing
        the package compiles nothing)."""
        data_type = self.data_type
        transport = Transport(
            TransferFrame,
            can_id_base(data_type),
            data_type.kind is not TransferKind.MESSAGE,
            data_type.crc_seed,
        )
        schema = data_type.schema
        return (
            compile_struct(schema, transport)
            or compile_int_array(schema, transport)
            or compile_tree(schema, transport)
        )

    def encode(self, message: Any, saturate: bool = False) -> bytes:
        """Serialize ``message``; raise EncodeError for any value the type cannot hold."""
        if not saturate:
            try:
                return self.fast.payload(message)
            except ENCODE_FALLBACK:
                pass
        return self.generic.encode(message, saturate)

    def decode(self, payload: bytes) -> Any:
        """Deserialize a whole payload; raise DecodeError if it does not fit the type."""
        try:
            return self.fast.decode(payload)
        except DECODE_FALLBACK:
            return self.generic.decode(payload)


def can_id_base(data_type: DataType) -> int:
    """The CAN ID bits fixed by the type: type id, request bit and service bit."""
    if data_type.kind is TransferKind.MESSAGE:
        return data_type.data_type_id << 8
    request = 0x8000 if data_type.kind is TransferKind.REQUEST else 0
    return data_type.data_type_id << 16 | request | 0x80


CODECS: tuple[TypeCodec, ...] = tuple(TypeCodec(t) for t in DATA_TYPES)
"""One `TypeCodec` per top-level type, in the order of `DATA_TYPES`."""

BY_CLASS: dict[type, TypeCodec] = {c.data_type.schema.cls: c for c in CODECS}
"""The `TypeCodec` of each message, request and response class."""

BY_ID: dict[tuple[TransferKind, int], TypeCodec] = {
    (c.data_type.kind, c.data_type.data_type_id): c for c in CODECS
}
"""The `TypeCodec` of each (kind, data type id)."""


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
