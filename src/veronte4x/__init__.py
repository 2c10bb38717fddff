"""veronte4x: sans-IO codecs for Veronte Autopilot 4x CAN traffic and Vertiq DroneCAN."""

from __future__ import annotations

from veronte4x.errors import (
    DecodeError,
    EncodeError,
    LayoutError,
    UnknownCommandError,
    Veronte4xError,
)


def __getattr__(name: str) -> str:
    """``__version__``, looked up in the package metadata on first use only: the lookup
    costs as much as importing the codec, which most imports never need it for."""
    if name != "__version__":
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    from importlib.metadata import PackageNotFoundError, version

    try:
        found = version("veronte4x")
    except PackageNotFoundError:  # pragma: no cover - running from a source tree
        found = "0+unknown"
    globals()["__version__"] = found
    return found


__all__ = [
    "DecodeError",
    "EncodeError",
    "LayoutError",
    "UnknownCommandError",
    "Veronte4xError",
    "__version__",
]
