"""The command line's python-can buses: whatever a bus raises reaches the command as
``can.CanError``, which it reports in one line.

python-can's own failures are ``can.CanError``; an interface may raise anything else
(``OSError`` from a device that went away, a driver's ``RuntimeError``). A command handles
``can.CanError`` from ``recv`` and ``send``; `open_bus` wraps the bus so that those are the
only errors they raise.
"""

from __future__ import annotations

from typing import Any


def open_bus(**settings: Any) -> Any:
    """`veronte4x.canbus.open_bus` with these settings, its ``recv`` and ``send`` raising
    ``can.CanError`` only.

    Raises:
        BusOpenError: python-can could not open it.
    """
    from veronte4x.canbus import open_bus as open_python_can_bus

    return _Guarded(open_python_can_bus(**settings))


class _Guarded:
    """A python-can bus whose ``recv`` and ``send`` raise ``can.CanError`` only; every
    other attribute is the bus's."""

    def __init__(self, bus: Any) -> None:
        self._bus = bus

    def __getattr__(self, name: str) -> Any:
        return getattr(self._bus, name)

    def recv(self, timeout: float | None = None) -> Any:
        try:
            return self._bus.recv(timeout=timeout)
        except Exception as error:
            raise _as_can_error(error) from error

    def send(self, message: Any, timeout: float | None = None) -> None:
        try:
            self._bus.send(message, timeout=timeout)
        except Exception as error:
            raise _as_can_error(error) from error


def _as_can_error(error: Exception) -> Exception:
    """``error`` if python-can's, else a ``can.CanOperationError`` naming it in words."""
    import can

    if isinstance(error, can.CanError):
        return error
    if isinstance(error, OSError) and error.strerror:
        return can.CanOperationError(error.strerror)
    reason = str(error)
    return can.CanOperationError(
        f"{type(error).__name__}: {reason}" if reason else type(error).__name__
    )
