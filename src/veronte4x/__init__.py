"""veronte4x: sans-IO codecs for Veronte Autopilot 4x CAN traffic and Vertiq DroneCAN."""

from __future__ import annotations

from importlib.metadata import PackageNotFoundError, version

from veronte4x.errors import (
    DecodeError,
    EncodeError,
    LayoutError,
    UnknownCommandError,
    Veronte4xError,
)

try:
    __version__ = version("veronte4x")
except PackageNotFoundError:  # pragma: no cover - running from a source tree
    __version__ = "0+unknown"

__all__ = [
    "DecodeError",
    "EncodeError",
    "LayoutError",
    "UnknownCommandError",
    "Veronte4xError",
    "__version__",
]
