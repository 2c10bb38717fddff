"""The data model of DSDL types: scalars, arrays, structs and unions.

The type definitions themselves are in `definitions`; the
serializers in `serializer` and `compiled`
run from them. Bit lengths and the tail array optimisation follow spec 3 (DSDL) as libcanard and
the dronecan package implement it.
"""

from __future__ import annotations

import builtins
from dataclasses import dataclass
from functools import cached_property

from veronte4x.dronecan.can_id import TransferKind
from veronte4x.dronecan.crc import signature_seed


@dataclass(frozen=True)
class Scalar:
    """A primitive field: ``uint``, ``int``, ``float``, ``bool`` or ``void`` of ``bits`` bits.

    ``truncated`` is the DSDL cast mode ``truncated`` (the default is ``saturated``): with
    ``saturate=True`` an out-of-range value is cut to its low bits instead of clamped.
    """

    kind: str
    bits: int
    truncated: bool = False

    @property
    def dsdl(self) -> str:
        """The DSDL spelling, e.g. ``uint32``, ``int18``, ``float16``, ``bool``, ``void5``."""
        return "bool" if self.kind == "bool" else f"{self.kind}{self.bits}"

    @property
    def low(self) -> int:
        """Smallest integer value (0 for uint, bool and void)."""
        return -(1 << (self.bits - 1)) if self.kind == "int" else 0

    @property
    def high(self) -> int:
        """Largest integer value."""
        return (1 << (self.bits - 1)) - 1 if self.kind == "int" else (1 << self.bits) - 1


@dataclass(frozen=True)
class Array:
    """An array of scalars, structs or unions: fixed ``[max_size]`` or dynamic
    ``[<=max_size]``.

    Arrays of uint8 are ``bytes`` in Python, others tuples (of ints, floats, bools, struct
    instances or union values).
    """

    item: Scalar | Struct | Union
    max_size: int
    dynamic: bool

    @property
    def prefix_bits(self) -> int:
        """Bits of the length prefix: ``max_size.bit_length()`` for a dynamic array, else 0."""
        return self.max_size.bit_length() if self.dynamic else 0

    @property
    def is_bytes(self) -> bool:
        """True for uint8 arrays, held as ``bytes``."""
        return self.item == Scalar("uint", 8)

    @property
    def dsdl(self) -> str:
        """The DSDL spelling, e.g. ``uint8[<=92]``."""
        return f"{self.item.dsdl}[{'<=' if self.dynamic else ''}{self.max_size}]"


@dataclass(frozen=True)
class StructField:
    """One field of a struct: its attribute (empty for void), type, optional enum, and its
    name in the DSDL (``class`` for the attribute ``class_``; the rule is that of
    `veronte4x.dronecan.generate.attribute_names`)."""

    name: str
    type: Scalar | Array | Struct | Union
    enum: builtins.type | None = None
    dsdl_name: str = ""


@dataclass(frozen=True)
class Struct:
    """A DSDL struct (a message, a request, a response or a nested type) and its class."""

    name: str
    cls: type
    fields: tuple[StructField, ...]

    @property
    def dsdl(self) -> str:
        """The type name."""
        return self.name


@dataclass(frozen=True)
class Member:
    """One member of a union: its name (a Python keyword with ``_``), its type, the Python
    class that holds it, and its name in the DSDL.

    The class has a single field ``value`` unless the member type is a struct, in which case
    the class is that struct's own class.
    """

    name: str
    type: Scalar | Array | Struct
    cls: builtins.type
    dsdl_name: str = ""


@dataclass(frozen=True)
class Union:
    """A DSDL ``@union``: a tag of ``ceil(log2(len(members)))`` bits, then the member."""

    name: str
    members: tuple[Member, ...]

    @property
    def tag_bits(self) -> int:
        """Bits of the union tag."""
        return (len(self.members) - 1).bit_length()

    @property
    def dsdl(self) -> str:
        """The type name."""
        return self.name


def min_bits(t: Scalar | Array | Struct | Union) -> int:
    """Minimum serialized bit length of a type (dynamic arrays empty, with their prefix)."""
    return _least_bits(t, True)


def _least_bits(t: Scalar | Array | Struct | Union, prefixes: bool) -> int:
    """The least bit length of ``t``, a dynamic array counting its prefix (``prefixes``)
    or 0; each nested type shared by many fields is counted once (by id)."""
    memo: dict[int, int] = {}

    def walk(t: Scalar | Array | Struct | Union) -> int:
        found = memo.get(id(t))
        if found is not None:
            return found
        if isinstance(t, Scalar):
            found = t.bits
        elif isinstance(t, Array) and t.dynamic:
            found = t.prefix_bits if prefixes else 0
        elif isinstance(t, Array):
            found = t.max_size * walk(t.item)
        elif isinstance(t, Struct):
            found = sum(walk(f.type) for f in t.fields)
        else:
            found = t.tag_bits + min(walk(m.type) for m in t.members)
        memo[id(t)] = found
        return found

    return walk(t)


def max_bits(t: Scalar | Array | Struct | Union, tao: bool = False) -> int:
    """Maximum serialized bit length, without the length prefix dropped by TAO when ``tao``."""
    memo: dict[tuple[int, bool], int] = {}  # by id, as in `_least_bits`

    def walk(t: Scalar | Array | Struct | Union, tao: bool) -> int:
        found = memo.get((id(t), tao))
        if found is not None:
            return found
        if isinstance(t, Scalar):
            found = t.bits
        elif isinstance(t, Array):
            prefix = 0 if tao and uses_tao(t) else t.prefix_bits
            found = prefix + t.max_size * walk(t.item, False)
        elif isinstance(t, Struct):
            last = len(t.fields) - 1
            found = sum(walk(f.type, tao and i == last) for i, f in enumerate(t.fields))
        else:
            found = t.tag_bits + max(walk(m.type, tao) for m in t.members)
        memo[(id(t), tao)] = found
        return found

    return walk(t, tao)


def uses_tao(array: Array) -> bool:
    """Whether a dynamic array in tail position drops its prefix: items of 8 bits or more
    at the least (`tao_min_bits`)."""
    return array.dynamic and tao_min_bits(array.item) >= 8


def tao_min_bits(t: Scalar | Array | Struct | Union) -> int:
    """The least bit length of a type as the TAO rule counts it: dynamic arrays count 0."""
    return _least_bits(t, False)


@dataclass(frozen=True)
class DataType:
    """A top-level type: what goes on the wire for one class.

    Attributes:
        full_name: DSDL full name, e.g. ``uavcan.protocol.NodeStatus``.
        kind: Message, request or response.
        data_type_id: The default data type id.
        signature: The 64-bit data type signature (one for both halves of a service).
        schema: The struct definition.
        path: The DSDL file it was compiled from ("" if none).
    """

    full_name: str
    kind: TransferKind
    data_type_id: int
    signature: int
    schema: Struct
    path: str = ""

    @cached_property
    def crc_seed(self) -> int:
        """The transfer CRC after the signature."""
        return signature_seed(self.signature)

    @property
    def max_payload(self) -> int:
        """Largest payload in bytes, with TAO."""
        return (max_bits(self.schema, tao=True) + 7) // 8
