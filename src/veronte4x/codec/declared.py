"""Layouts that a user declares for the commands whose payload layout is not public.

No public source gives the payload of commands 5-10 and 16-19 (not in Embention's
public manuals); the layout comes from each installation's PDI configuration. A user who
knows it declares it in Veronte's own terms (ordered constants, skips, integers with an
optional linear compression, float32; little or big endian) and gets a frozen dataclass
with named fields, which encodes as well as it decodes.
"""

from __future__ import annotations

import dataclasses
import keyword
from collections.abc import Sequence
from typing import Any

from veronte4x.codec.compiler import FrameLayout
from veronte4x.codec.fields import ByteOrder, Field, FieldKind, constant
from veronte4x.codec.messages import Message
from veronte4x.errors import BytesLike, LayoutError, argument_type_error, check_types, integer

_DECLARABLE = frozenset(
    {FieldKind.CONSTANT, FieldKind.PADDING, FieldKind.UNSIGNED, FieldKind.SIGNED, FieldKind.FLOAT32}
)


class DeclaredMessage(Message):
    """Base class of the message classes that `Layout` generates (frozen dataclasses)."""

    __slots__ = ()


class Layout:
    """A declared payload layout for one command byte.

    Args:
        command: The command byte (byte 0) the layout applies to.
        name: Name of the generated message class, a Python identifier.
        fields: The payload fields after the command byte, in order: `constant`, `skip`,
            `unsigned`, `signed` and `float32` from `veronte4x.codec`.
        byte_order: Little endian (first field in the low bits, the default) or big endian
            (first field in the high bits).

    Examples:
        >>> from veronte4x import codec
        >>> esc = codec.Layout(5, "EscTelemetry", [
        ...     codec.unsigned("rpm", 16),
        ...     codec.signed("current", 16, scale=codec.Linear(-32768, 32767, -327.68, 327.67)),
        ... ])
        >>> msg = esc.decode(bytes.fromhex("05e803f6ff"))
        >>> msg.rpm, round(msg.current, 2)
        (1000, -0.1)
    """

    def __init__(
        self,
        command: int,
        name: str,
        fields: Sequence[Field],
        byte_order: ByteOrder = ByteOrder.LITTLE,
    ) -> None:
        """See the class docstring.

        Raises:
            LayoutError: A layout that cannot describe a Veronte frame.
            TypeError: An argument of the wrong type.
        """
        check_types(
            "Layout",
            ("command", command, int, "an int"),
            ("name", name, str, "a str"),
            ("byte_order", byte_order, ByteOrder, "a ByteOrder"),
        )
        whole = integer(command)  # a NumPy integer as a Python int
        assert whole is not None
        command = whole
        fields = tuple(fields)
        for f in fields:
            if not isinstance(f, Field):
                raise argument_type_error("Layout", "fields", "Field objects", f)
        if not 0 <= command <= 255:
            raise LayoutError(f"{name}: command {command!r} is not a byte")
        if not name.isidentifier() or keyword.iskeyword(name):
            raise LayoutError(f"{name!r} is not a valid class name")
        self.command = command
        self.name = name
        self.fields = tuple(fields)
        self.byte_order = byte_order
        self.message_class: type[Any] = self._make_class()
        self.frame = FrameLayout(
            self.message_class,
            (constant(command, 8, "message type", "command"), *self.fields),
            byte_order,
            source="declared by the user (installation PDI configuration)",
            title=name,
        )
        self.frame.check()

    def _make_class(self) -> type[Message]:
        annotations: list[tuple[str, Any]] = []
        for f in self.fields:
            if f.kind not in _DECLARABLE or f.index is not None:
                raise LayoutError(f"{self.name}: field {f.label} cannot be declared")
            if f.attr is None:
                continue
            if not f.attr.isidentifier() or keyword.iskeyword(f.attr) or f.attr.startswith("_"):
                raise LayoutError(f"{self.name}: {f.attr!r} is not a valid field name")
            if any(name == f.attr for name, _ in annotations):
                raise LayoutError(f"{self.name}: field {f.attr!r} is declared twice")
            numeric = f.kind is FieldKind.FLOAT32 or f.scale is not None
            annotations.append((f.attr, float if numeric else int))
        cls = dataclasses.make_dataclass(
            self.name,
            annotations,
            bases=(DeclaredMessage,),
            namespace={"COMMAND": self.command, "__module__": __name__},
            frozen=True,
            slots=True,
        )
        return cls

    def decode(self, data: BytesLike, allow_excess: bool = False) -> Any:
        """Decode one frame (command byte included) with this layout.

        Returns:
            An instance of `message_class` (typed Any: its fields are declared at run time).

        Raises:
            DecodeError: Wrong length, wrong command byte or constant.
            TypeError: ``data`` is not bytes-like.
        """
        if data.__class__ is not bytes:
            if not isinstance(data, (bytearray, memoryview)):
                raise argument_type_error("Layout.decode", "data", "bytes-like", data)
            data = bytes(data)
        return self.frame.decode(data, allow_excess)

    def encode(self, message: Message) -> bytes:
        """Encode a message of this layout's class into a frame's data bytes.

        Raises:
            EncodeError: A field is out of range or of the wrong kind.
            TypeError: ``message`` is not an instance of this layout's class.
        """
        if not isinstance(message, self.message_class):
            raise argument_type_error(
                "Layout.encode", "message", f"a {self.message_class.__name__}", message
            )
        return self.frame.encode(message)

    def __repr__(self) -> str:
        return f"Layout(command={self.command}, name={self.name!r}, fields={len(self.fields)})"
