"""The one error hierarchy of veronte4x.

Every error the library raises on purpose derives from :class:`Veronte4xError`.
:class:`DecodeError` and :class:`EncodeError` also derive from :class:`ValueError`, so
code written for the standard library's conventions keeps working.

Arguments of the wrong type are a caller's mistake, not bad data: every public entry point
raises :class:`TypeError` for them, naming the argument and the type expected (see
:func:`argument_type_error`). Bad bytes from a bus or a file give a :class:`DecodeError`
(or, in the reassembler, a counted problem), never a :class:`TypeError`.
"""

from __future__ import annotations

from typing import Union

BytesLike = Union[bytes, bytearray, memoryview]  # noqa: UP007  (a run-time alias on 3.10)
"""What the codecs accept as data: bytes, bytearray or memoryview."""


class Veronte4xError(Exception):
    """Base class of every error raised by veronte4x."""


class DecodeError(Veronte4xError, ValueError):
    """Bytes that do not form a valid message.

    Attributes:
        message_type: Name of the message type being decoded, or ``None`` when the
            frame could not even be attributed to a type.
        reason: What was wrong, in words.
        data: The offending bytes, exactly as received.
        field: The field that was out of range or inconsistent, if one was.
    """

    def __init__(
        self,
        message_type: str | None,
        reason: str,
        data: BytesLike,
        field: str | None = None,
    ) -> None:
        self.message_type = message_type
        self.reason = reason
        self.data = bytes(data) if isinstance(data, (bytes, bytearray, memoryview)) else b""
        self.field = field
        where = message_type or "frame"
        if field is not None:
            where = f"{where}.{field}"
        super().__init__(f"{where}: {reason} (data: {self.data.hex(' ') or 'empty'})")


class UnknownCommandError(DecodeError):
    """A Veronte frame whose command byte is reserved or unknown.

    Attributes:
        command: The command byte (byte 0) of the frame.
    """

    def __init__(self, command: int, data: BytesLike, reason: str = "") -> None:
        self.command = command
        super().__init__(
            None, reason or f"command byte {command} is reserved or unknown", data, "command"
        )


class EncodeError(Veronte4xError, ValueError):
    """A message whose fields cannot be encoded.

    Attributes:
        message_type: Name of the message type being encoded.
        field: The offending field.
        value: The offending value.
        allowed: The allowed range or kind, in words.
    """

    def __init__(self, message_type: str, field: str, value: object, allowed: str) -> None:
        self.message_type = message_type
        self.field = field
        self.value = value
        self.allowed = allowed
        super().__init__(f"{message_type}.{field} = {value!r}: expected {allowed}")


class LayoutError(Veronte4xError, ValueError):
    """A layout declaration that cannot describe a Veronte frame (too long, misplaced bytes)."""


def argument_type_error(function: str, argument: str, expected: str, value: object) -> TypeError:
    """The `TypeError` for an argument of the wrong type, in one wording everywhere.

    Examples:
        >>> str(argument_type_error("decode", "data", "bytes-like", "00ff"))
        'decode(): data must be bytes-like, not str'
    """
    return TypeError(f"{function}(): {argument} must be {expected}, not {type(value).__name__}")


def check_seconds(function: str, argument: str, value: object) -> None:
    """Raise `argument_type_error` unless ``value`` is a number of seconds (an int or a
    float, never a bool).

    Examples:
        >>> check_seconds("poll", "now", "1.5")
        Traceback (most recent call last):
        TypeError: poll(): now must be a number of seconds, not str
    """
    if value.__class__ is not float:
        check_types(function, (argument, value, (int, float), "a number of seconds"))


TypeCheck = tuple[str, object, type | tuple[type, ...], str]
"""(argument, value, the type or types it must have, what the message says is expected)."""


def check_types(function: str, *checks: TypeCheck) -> None:
    """Raise `argument_type_error` for the first argument that fails its check; a bool never
    passes for an int or a float.

    Examples:
        >>> check_types("skip", ("bits", 8, int, "an int"))
        >>> check_types("skip", ("bits", True, int, "an int"))
        Traceback (most recent call last):
        TypeError: skip(): bits must be an int, not bool
    """
    for argument, value, kind, expected in checks:
        if isinstance(value, bool) or not isinstance(value, kind):
            raise argument_type_error(function, argument, expected, value)


class SourceError(Veronte4xError, ValueError):
    """A capture that cannot be read as one: a directory, or a format veronte4x does not know.

    Its message names the path, what is wrong and what to do.
    """


class MissingExtraError(Veronte4xError, ImportError):
    """An optional dependency is not installed; the message names the extra to install.

    Attributes:
        extra: The extra to install, as in ``pip install 'veronte4x[can]'``.
    """

    def __init__(self, module: str, extra: str, needed_for: str) -> None:
        self.extra = extra
        super().__init__(
            f"{needed_for} needs the '{module}' package: pip install 'veronte4x[{extra}]'",
            name=module,
        )
