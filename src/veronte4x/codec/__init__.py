"""Encode and decode the Veronte 4x CAN messages.

The messages are those of the Veronte Autopilot 4x Software Manual, section 3 "CAN Bus
protocol".

Examples:
    >>> from veronte4x import codec
    >>> codec.decode(b"\\x00\\xff\\x01", sender=codec.Sender.AUTOPILOT)
    Ready(ready=True)
    >>> codec.encode(codec.Ready(ready=True))
    b'\\x00\\xff\\x01'
"""

from __future__ import annotations

from veronte4x.codec.core import Codec
from veronte4x.codec.declared import DeclaredMessage, Layout
from veronte4x.codec.fields import (
    ByteOrder,
    Field,
    FieldKind,
    Linear,
    constant,
    float32,
    signed,
    skip,
    unsigned,
)
from veronte4x.codec.messages import (
    ArbitrationVariable,
    JetiBecTelemetry1,
    JetiBecTelemetry2,
    JetiEscTelemetry,
    JetiTemperature,
    MaintenanceCommand,
    McuCommand,
    McuTelemetry1,
    McuTelemetry2,
    Message,
    OpaqueMessage,
    PwmSet,
    Ready,
    Score,
    ScorpionEscTelemetry,
    Sender,
    Status,
    StickSelection,
    VersionRequest,
    VersionResponse,
)
from veronte4x.codec.pwm import PWM_MAX, PwmPacking, from_microseconds, to_microseconds
from veronte4x.errors import (
    DecodeError,
    EncodeError,
    LayoutError,
    UnknownCommandError,
    Veronte4xError,
)

DEFAULT_CODEC = Codec()
"""The codec behind `decode` and `encode`: default PWM packing, no declared layouts.

It is built at import (about 11 ms). A module-level ``__getattr__`` could defer that, but
CPython does not specialise attribute lookups on a module that has one: every
``codec.decode`` call would pay 10-25 ns more, up to a twelfth of a frame's decode.
"""
decode = DEFAULT_CODEC.decode
"""Decode one Veronte frame's data bytes with `DEFAULT_CODEC`:
``decode(data, *, sender, allow_excess=False)``, as `Codec.decode` does (its arguments,
result and errors)."""
decode.__module__, decode.__qualname__ = __name__, "decode"  # where it imports from
encode = DEFAULT_CODEC.encode


__all__ = [
    "DEFAULT_CODEC",
    "PWM_MAX",
    "ArbitrationVariable",
    "ByteOrder",
    "Codec",
    "DeclaredMessage",
    "DecodeError",
    "EncodeError",
    "Field",
    "FieldKind",
    "JetiBecTelemetry1",
    "JetiBecTelemetry2",
    "JetiEscTelemetry",
    "JetiTemperature",
    "Layout",
    "LayoutError",
    "Linear",
    "MaintenanceCommand",
    "McuCommand",
    "McuTelemetry1",
    "McuTelemetry2",
    "Message",
    "OpaqueMessage",
    "PwmPacking",
    "PwmSet",
    "Ready",
    "Score",
    "ScorpionEscTelemetry",
    "Sender",
    "Status",
    "StickSelection",
    "UnknownCommandError",
    "Veronte4xError",
    "VersionRequest",
    "VersionResponse",
    "constant",
    "decode",
    "encode",
    "float32",
    "from_microseconds",
    "signed",
    "skip",
    "to_microseconds",
    "unsigned",
]
