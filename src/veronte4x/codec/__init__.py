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

from typing import TYPE_CHECKING, Any

from veronte4x.codec.core import Codec
from veronte4x.codec.declared import DeclaredMessage, Layout
from veronte4x.codec.fields import (
    ByteOrder,
    Field,
    Kind,
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

if TYPE_CHECKING:
    DEFAULT_CODEC = Codec()
    """The codec behind `decode` and `encode`: default PWM packing, no declared layouts."""
    decode = DEFAULT_CODEC.decode
    encode = DEFAULT_CODEC.encode


def __getattr__(name: str) -> Any:
    """Build the default codec on first use of `DEFAULT_CODEC`, `decode` or `encode`.

    Compiling its decoders takes about half of what importing the package would cost, so
    a program that never decodes with it does not pay for it. Once built, the three are
    plain module attributes: `decode` and `encode` are the codec's own bound methods, not
    wrappers, whose extra call would be measurable.
    """
    if name in ("DEFAULT_CODEC", "decode", "encode"):
        default = Codec()
        globals().update(DEFAULT_CODEC=default, decode=default.decode, encode=default.encode)
        return globals()[name]
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


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
    "JetiBecTelemetry1",
    "JetiBecTelemetry2",
    "JetiEscTelemetry",
    "JetiTemperature",
    "Kind",
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
