"""The command line's python-can buses: whatever a bus raises reaches the command as
``can.CanError``, which it reports in one line.

python-can's own failures are ``can.CanError``; an interface may raise anything else
(``OSError`` from a device that went away, a driver's ``RuntimeError``). A command handles
``can.CanError`` from ``recv`` and ``send``; `open_bus` wraps the bus so that those are the
only errors they raise.
"""

from __future__ import annotations

from typing import Any

from veronte4x.extras import require


def open_bus(**settings: Any) -> Any:
    """`veronte4x.canbus.open_bus` with these settings, its ``recv`` and ``send`` raising
    ``can.CanError`` only.

    Raises:
        BusOpenError: Nothing names a bus (`NO_BUS`), or python-can could not open it.
        MissingExtraError: python-can is not installed, or msgpack for a udp_multicast bus
            (`require_bus_packages`).
    """
    require_bus_packages(settings, "a live CAN bus")
    from veronte4x.canbus import BusOpenError
    from veronte4x.canbus import open_bus as open_python_can_bus

    if not _names_a_bus(settings):
        raise BusOpenError(NO_BUS)
    return _Guarded(open_python_can_bus(**settings))


def require_bus_packages(settings: dict[str, Any], needed_for: str) -> None:
    """Check that the packages the bus of these settings needs are installed.

    python-can's ``udp_multicast`` bus (the README's ground station) needs python-can and
    msgpack, which the ``bench`` extra brings both of: its error names ``bench`` first, so
    that one install is enough. Any other bus needs the ``can`` extra.

    Raises:
        MissingExtraError: A package is missing; it names the extra to install.
    """
    if settings.get("interface") == "udp_multicast":
        require("can", "bench", "python-can's udp_multicast bus")
        require("msgpack", "bench", "python-can's udp_multicast bus")
    else:
        require("can", "can", needed_for)


NO_BUS = (
    "no CAN bus given: name one with --interface and --channel (e.g. --interface socketcan "
    "--channel can0, or --interface udp_multicast for a bus on this machine), or with "
    "--can-config FILE or python-can's configuration file ~/.canrc ([default] interface = ...)"
)
"""The error line of a command that opens a bus when nothing names one."""


def _names_a_bus(settings: dict[str, Any]) -> bool:
    """Whether the settings or python-can's own configuration (``can.rc``, ``CAN_INTERFACE``,
    its files) name an interface. A ``config_file`` counts (`veronte4x.canbus.open_bus`
    says what is wrong with it), and so does a file python-can cannot read."""
    import can

    if settings.get("interface") or settings.get("config_file") is not None:
        return True
    if "interface" in (settings.get("options") or {}):
        return True
    try:
        sources = [can.rc, can.util.load_environment_config(), can.util.load_file_config()]
    except Exception:  # a file python-can cannot read: opening the bus says why
        return True
    return any(source.get("interface") or source.get("bustype") for source in sources)


class _Guarded:
    """A python-can bus whose ``recv`` and ``send`` raise ``can.CanError`` only; every
    other attribute is the bus's, and ``__wrapped__`` the bus itself (for a reader that
    reads its socket, `veronte4x.capture.readers.live.DatagramReader`)."""

    def __init__(self, bus: Any) -> None:
        self._bus = bus
        self.__wrapped__ = bus

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
