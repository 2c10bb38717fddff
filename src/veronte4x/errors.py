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

import numbers
import operator
import os
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


class DsdlError(Veronte4xError, ValueError):
    """A DSDL definition that cannot be used (`veronte4x.dronecan.TypeSet.with_dsdl`):
    ``<file>:<line>: <problem>``.

    Attributes:
        path: The file of the definition.
        line: The line (1-based), or None for a problem of the whole file.
        problem: What is wrong, in words.
    """

    def __init__(self, path: str | os.PathLike[str], line: int | None, problem: str) -> None:
        self.path = str(path)
        self.line = line
        self.problem = problem
        where = self.path if line is None else f"{self.path}:{line}"
        super().__init__(_printable(f"{where}: {problem}"))


def _printable(text: str) -> str:
    """``text`` with each unprintable character escaped (``\\n``, ``\\x00``; a byte of a
    name that is not UTF-8, kept by Python as a lone surrogate, as ``\\xff``): one line."""
    if text.isprintable():
        return text
    return "".join(
        char
        if char.isprintable()
        else f"\\x{ord(char) - 0xDC00:02x}"
        if 0xDC80 <= ord(char) <= 0xDCFF
        else repr(char)[1:-1]
        for char in text
    )


class LayoutError(Veronte4xError, ValueError):
    """A layout declaration that cannot describe a Veronte frame (too long, misplaced bytes)."""


def argument_type_error(function: str, argument: str, expected: str, value: object) -> TypeError:
    """The `TypeError` for an argument of the wrong type, in one wording everywhere.

    Examples:
        >>> str(argument_type_error("decode", "data", "bytes-like", "00ff"))
        'decode(): data must be bytes-like, not str'
    """
    return TypeError(f"{function}(): {argument} must be {expected}, not {type(value).__name__}")


def _is_numpy_bool(value: object) -> bool:
    """Whether ``value`` is a NumPy bool (``numpy.bool_``), told by its type's module and
    name so that NumPy is never imported."""
    kind = value.__class__
    return kind.__module__ == "numpy" and kind.__name__ in ("bool_", "bool")


def integer(value: object) -> int | None:
    """``value`` as a Python int if it is an integer, else None: the one rule for every place
    that takes an int (codec and DroneCAN encoders, argument checks).

    An int, a NumPy integer or any object whose ``__index__`` gives its exact value (told
    with `operator.index`, so NumPy is never imported) is an integer; a bool or a NumPy
    bool is not, nor is a float, even ``1.0``: a value is never narrowed.

    Examples:
        >>> integer(7), integer(True), integer(1.0), integer("1")
        (7, None, None, None)
    """
    if value.__class__ is int:
        return value
    if isinstance(value, bool) or _is_numpy_bool(value):
        return None
    try:
        return operator.index(value)  # type: ignore[arg-type]
    except TypeError:
        return None


def real(value: object) -> int | float | None:
    """``value`` as a Python int or float if it is a real number that converts exactly, else
    None: the one rule for every place that takes a float.

    Integers are taken as `integer` takes them (and stay ints). A float, or any
    `numbers.Real` (NumPy's float16, float32 and float64 register themselves, so NumPy is
    never imported) whose ``float()`` equals it, gives that float; a NaN gives its NaN. A
    value ``float()`` would round (a ``longdouble`` beyond float64, ``Fraction(1, 3)``) is
    refused: a value is never narrowed silently. Bools are not numbers here.

    Examples:
        >>> real(0.5), real(2), real(False), real("0.5")
        (0.5, 2, None, None)
    """
    if value.__class__ is float:
        return value
    whole = integer(value)
    if whole is not None:
        return whole
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        return None
    converted = float(value)
    if converted == value or converted != converted:
        return converted
    return None


def boolean(value: object) -> bool | None:
    """``value`` as a Python bool if it is a bool or a NumPy bool, else None (never 0 or 1).

    Examples:
        >>> boolean(True), boolean(1)
        (True, None)
    """
    if value is True or value is False:
        return value
    if _is_numpy_bool(value):
        return bool(value)
    return None


def int_argument(function: str, argument: str, value: object, expected: str = "an int") -> int:
    """``value`` as a Python int by the rule of `integer`; else raise `argument_type_error`."""
    whole = integer(value)
    if whole is None:
        raise argument_type_error(function, argument, expected, value)
    return whole


def real_argument(function: str, argument: str, value: object, expected: str = "a float") -> float:
    """``value`` as a Python int or float by the rule of `real`; else raise
    `argument_type_error`."""
    number = real(value)
    if number is None:
        raise argument_type_error(function, argument, expected, value)
    return number


def check_seconds(function: str, argument: str, value: object) -> float:
    """``value`` as a number of seconds (an int or a float, Python's or NumPy's, see `real`;
    never a bool); else raise `argument_type_error`.

    Examples:
        >>> check_seconds("poll", "now", "1.5")
        Traceback (most recent call last):
        TypeError: poll(): now must be a number of seconds, not str
    """
    if value.__class__ is float:
        return value
    return real_argument(function, argument, value, "a number of seconds")


TypeCheck = tuple[str, object, type | tuple[type, ...], str]
"""(argument, value, the type or types it must have, what the message says is expected)."""


def check_types(function: str, *checks: TypeCheck) -> None:
    """Raise `argument_type_error` for the first argument that fails its check.

    A bool never passes for an int or a float; where an int passes, so does any integer
    `integer` takes (a NumPy integer), and where a float passes, any real `real` takes (a
    NumPy float). The value is not converted: a caller that keeps or computes with it
    converts it with `integer` or `real`.

    Examples:
        >>> check_types("skip", ("bits", 8, int, "an int"))
        >>> check_types("skip", ("bits", True, int, "an int"))
        Traceback (most recent call last):
        TypeError: skip(): bits must be an int, not bool
    """
    for argument, value, kind, expected in checks:
        kinds = kind if isinstance(kind, tuple) else (kind,)
        if isinstance(value, bool) or _is_numpy_bool(value):
            fits = False
        elif isinstance(value, kinds):
            fits = True
        elif float in kinds:
            fits = real(value) is not None
        else:
            fits = int in kinds and integer(value) is not None
        if not fits:
            raise argument_type_error(function, argument, expected, value)


class SourceError(Veronte4xError, ValueError):
    """A capture that cannot be read as one: a directory, or a format veronte4x does not know.

    Its message names the path, what is wrong and what to do.
    """


class NotACaptureError(SourceError):
    """A file whose lines are all bad: none is a CAN frame, so it is no capture at all.

    Every command that reads a capture file refuses one the same way (exit code 2).

    Attributes:
        path: The file's name as given (``standard input`` for ``-``).
        lines: Its lines, none of them a CAN frame.
    """

    def __init__(self, path: str, lines: int) -> None:
        from veronte4x.words import counted

        self.path = path
        self.lines = lines
        super().__init__(
            f"{path} is not a capture of any known format: none of its "
            f"{counted(lines, 'line')} is a CAN frame; give candump text or a log "
            "python-can reads"
        )


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
