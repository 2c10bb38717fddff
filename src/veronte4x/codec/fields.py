"""The field model that every Veronte layout is written in, built-in or declared.

It follows Veronte's own model for custom CAN messages (the 4x PDI
Builder's custom messages): an ordered list of fields, each a constant ("matcher"), a skip
(padding), an unsigned or signed integer of N bits with an optional linear compression,
or a float32, laid out one after the other in little or big endian. Built-in layouts add
booleans and a trailing run of raw bytes.

Positions are sequential. In a little-endian layout the frame is read as one
little-endian integer and the first field takes its least significant bits (bit 0 is the
LSB of byte 0, as the manual numbers bits). In a big-endian layout the frame is read as one
big-endian integer and the first field takes its most significant bits.
"""

from __future__ import annotations

import enum
from dataclasses import dataclass
from typing import Any

from veronte4x.errors import check_types, integer, real

_NUMBER = (int, float)
_OPTIONAL_INT = (int, type(None))


class ByteOrder(enum.Enum):
    """How the bytes of a frame form the integer its fields are cut from."""

    LITTLE = "little"
    BIG = "big"


class FieldKind(enum.Enum):
    """What a field holds on the wire."""

    CONSTANT = "constant"
    PADDING = "padding"
    UNSIGNED = "unsigned"
    SIGNED = "signed"
    BOOL = "bool"
    FLOAT32 = "float32"
    BYTES = "bytes"
    MAPPED = "mapped"


@dataclass(frozen=True, slots=True)
class Linear:
    """A linear compression: wire values encoded_min..encoded_max map to decoded_min..decoded_max.

    Attributes:
        encoded_min: Wire value that stands for decoded_min.
        encoded_max: Wire value that stands for decoded_max.
        decoded_min: Physical value at encoded_min.
        decoded_max: Physical value at encoded_max.
    """

    encoded_min: int
    encoded_max: int
    decoded_min: float
    decoded_max: float

    def __post_init__(self) -> None:
        check_types(
            "Linear",
            ("encoded_min", self.encoded_min, int, "an int"),
            ("encoded_max", self.encoded_max, int, "an int"),
            ("decoded_min", self.decoded_min, _NUMBER, "a number"),
            ("decoded_max", self.decoded_max, _NUMBER, "a number"),
        )
        for attribute in ("encoded_min", "encoded_max"):  # a NumPy integer as a Python int
            object.__setattr__(self, attribute, integer(getattr(self, attribute)))
        for attribute in ("decoded_min", "decoded_max"):
            object.__setattr__(self, attribute, real(getattr(self, attribute)))

    @property
    def factor(self) -> float:
        """Physical units per wire step."""
        return (self.decoded_max - self.decoded_min) / (self.encoded_max - self.encoded_min)

    @property
    def offset(self) -> float:
        """Physical value of wire value 0."""
        return self.decoded_min - self.encoded_min * self.factor


@dataclass(frozen=True, slots=True)
class Field:
    """One field of a layout.

    Attributes:
        kind: What the field holds.
        bits: Width in bits (for BYTES, the most bytes times 8).
        attr: Message attribute the field fills; None for constants and padding.
        index: Position inside a tuple attribute, or None for a plain attribute.
        value: The constant's value (CONSTANT only).
        maximum: Largest wire value allowed, when smaller than the width allows.
        scale: Linear compression of an integer field, if any.
        description: What the field means, from the source.
        name: Name of a constant or padding field, for errors and docs.
        mapping: For a MAPPED field, (wire value, attribute value) pairs: the only values
            the field may take.
    """

    kind: FieldKind
    bits: int
    attr: str | None = None
    index: int | None = None
    value: int = 0
    maximum: int | None = None
    scale: Linear | None = None
    description: str = ""
    name: str = ""
    mapping: tuple[tuple[int, Any], ...] = ()

    def __post_init__(self) -> None:
        check_types(
            "Field",
            ("kind", self.kind, FieldKind, "a FieldKind"),
            ("bits", self.bits, int, "an int"),
            ("attr", self.attr, (str, type(None)), "a str or None"),
            ("index", self.index, _OPTIONAL_INT, "an int or None"),
            ("value", self.value, int, "an int"),
            ("maximum", self.maximum, _OPTIONAL_INT, "an int or None"),
            ("scale", self.scale, (Linear, type(None)), "a Linear or None"),
            ("description", self.description, str, "a str"),
            ("name", self.name, str, "a str"),
            ("mapping", self.mapping, tuple, "a tuple of (wire value, value) pairs"),
        )
        for attribute in ("bits", "index", "value", "maximum"):  # NumPy integers as ints
            number = getattr(self, attribute)
            if number is not None:
                object.__setattr__(self, attribute, integer(number))

    @property
    def label(self) -> str:
        """The field's name as errors and docs show it."""
        if self.attr is None:
            return self.name or self.kind.value
        return self.attr if self.index is None else f"{self.attr}[{self.index}]"


def constant(value: int, bits: int = 8, description: str = "", name: str = "constant") -> Field:
    """A matcher: a fixed value that a frame must carry.

    Raises:
        TypeError: An argument of the wrong type.
    """
    check_types(
        "constant",
        ("value", value, int, "an int"),
        ("bits", bits, int, "an int"),
        ("description", description, str, "a str"),
        ("name", name, str, "a str"),
    )
    return Field(FieldKind.CONSTANT, bits, value=value, description=description, name=name)


def skip(bits: int) -> Field:
    """Padding: ignored when decoding, sent as zeros.

    Raises:
        TypeError: ``bits`` is not an int.
    """
    check_types("skip", ("bits", bits, int, "an int"))
    return Field(FieldKind.PADDING, bits, description="ignored, sent as zeros", name="padding")


def _check_integer(
    function: str, name: object, bits: object, scale: object, description: object
) -> None:
    check_types(
        function,
        ("name", name, str, "a str"),
        ("bits", bits, int, "an int"),
        ("scale", scale, (Linear, type(None)), "a Linear or None"),
        ("description", description, str, "a str"),
    )


def unsigned(name: str, bits: int, scale: Linear | None = None, description: str = "") -> Field:
    """An unsigned integer of `bits` bits, optionally linearly compressed.

    Raises:
        TypeError: An argument of the wrong type.
    """
    _check_integer("unsigned", name, bits, scale, description)
    return Field(FieldKind.UNSIGNED, bits, name, scale=scale, description=description)


def signed(name: str, bits: int, scale: Linear | None = None, description: str = "") -> Field:
    """A two's complement integer of `bits` bits, optionally linearly compressed.

    Raises:
        TypeError: An argument of the wrong type.
    """
    _check_integer("signed", name, bits, scale, description)
    return Field(FieldKind.SIGNED, bits, name, scale=scale, description=description)


def float32(name: str, description: str = "") -> Field:
    """An IEEE-754 binary32 value.

    Raises:
        TypeError: An argument of the wrong type.
    """
    check_types("float32", ("name", name, str, "a str"), ("description", description, str, "a str"))
    return Field(FieldKind.FLOAT32, 32, name, description=description)
