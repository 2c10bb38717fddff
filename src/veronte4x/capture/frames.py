"""The raw CAN frame that readers produce and the capture decoder consumes."""

from __future__ import annotations

from typing import NamedTuple


class Frame(NamedTuple):
    """One CAN frame as captured.

    A named tuple rather than a dataclass: readers make one per line, and a tuple is the
    cheapest immutable record Python builds.

    Attributes:
        timestamp: Seconds (the capture's clock), or None when the capture has no time.
        channel: Interface name, such as ``can0``.
        can_id: 11-bit or 29-bit identifier.
        data: Data bytes (empty for a remote frame).
        extended: 29-bit identifier.
        remote: Remote transmission request.
        fd: CAN FD frame.
        error: Error frame (its ``data`` holds the error details).
    """

    timestamp: float | None
    channel: str
    can_id: int
    data: bytes
    extended: bool = False
    remote: bool = False
    fd: bool = False
    error: bool = False


class BadLine(NamedTuple):
    """A line of a capture that is not a frame, kept so that it can be counted and shown.

    Attributes:
        line_number: 1-based line number in the capture.
        text: The line, without its line break.
        reason: Why it is not a frame.
    """

    line_number: int
    text: str
    reason: str


class Truncation(BadLine):
    """Input that ends early, such as a truncated gzip file: the last item of its stream.

    A `BadLine` of its own kind, so that a reader counts it (error ``truncated``) and a
    person is told: the frames before it were read.
    """

    __slots__ = ()
