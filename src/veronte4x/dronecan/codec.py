"""Payload encoding and decoding for each of the types, fast path first.

Each top-level type gets generated fast functions (`compiled` for flat structs and
RawCommand, `compiled_tree` for everything else) and the generic `Serializer` for
everything the fast path hands over (errors, saturation, odd lengths). A shipped type's
fast functions are written ahead of time, one module of `veronte4x.dronecan.fast` each
(`veronte4x.dronecan.generate`), imported the first time the type is used; those of a type
loaded at run time are compiled then.
"""

from __future__ import annotations

import functools
import importlib
from typing import Any

from veronte4x.dronecan.can_id import TransferKind
from veronte4x.dronecan.compiled import (
    DECODE_FALLBACK,
    ENCODE_FALLBACK,
    FastPaths,
    compile_fast,
    transport_of,
)
from veronte4x.dronecan.definitions import DATA_TYPES, FAST_MODULES, DataType
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
        fast_module: The module of its fast paths written ahead of time (a shipped type),
            or None: they are compiled at first use.
    """

    def __init__(self, data_type: DataType, fast_module: str | None = None) -> None:
        self.data_type = data_type
        self.fast_module = fast_module
        self.crc_seed = data_type.crc_seed
        self.max_payload = data_type.max_payload
        self.generic = Serializer(data_type.schema)

    def __repr__(self) -> str:
        return f"TypeCodec({self.data_type.full_name} {self.data_type.kind.name.lower()})"

    @functools.cached_property
    def fast(self) -> FastPaths:
        """The generated fast paths: imported from `fast_module`, else compiled on first
        use (one type at a time: importing the package compiles nothing)."""
        if self.fast_module is not None:
            made: FastPaths = importlib.import_module(self.fast_module).FAST
            return made
        return compile_fast(self.data_type.schema, transport_of(self.data_type))

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


CODECS: tuple[TypeCodec, ...] = tuple(
    TypeCodec(t, FAST_MODULES[t.full_name, t.kind]) for t in DATA_TYPES
)
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
