"""The raw CAN frame that readers produce and the capture decoder consumes."""

from __future__ import annotations

import math
from fractions import Fraction
from typing import NamedTuple

from veronte4x.times import END_MICROS, FIRST_MICROS, whole_micros


class Frame(NamedTuple):
    """One CAN frame as captured.

    A named tuple rather than a dataclass: readers make one per line, and a tuple is the
    cheapest immutable record Python builds.

    Attributes:
        timestamp: Seconds (the capture's clock), or None when the capture has no time; a
            `Seconds` where the float alone does not hold the log's microseconds.
        channel: Interface name, such as ``can0``.
        can_id: 11-bit or 29-bit identifier.
        data: Data bytes (empty for a remote frame).
        extended: 29-bit identifier.
        remote: Remote transmission request.
        fd: CAN FD frame.
        error: Error frame (its ``data`` holds the error details).
        brs: CAN FD bit rate switch: the data phase at the data bit rate.
        esi: CAN FD error state indicator: the sender is error passive.
        dlc: A remote frame's DLC as given (the length it asks for); 0 for other frames,
            whose length is their data's.
    """

    timestamp: float | None
    channel: str
    can_id: int
    data: bytes
    extended: bool = False
    remote: bool = False
    fd: bool = False
    error: bool = False
    brs: bool = False
    esi: bool = False
    dlc: int = 0


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


_SAFE = 8_589_934_592.0
"""2**33 seconds (year 2242): below, a float of at most six decimals gives them back."""


class Seconds(float):
    """A timestamp in seconds (the float a reader gives) that also holds the log's time in
    whole microseconds, made only where the float cannot give them back: a text with more
    than six decimals, or a time after 2242. Equal to, and used as, the float."""

    __slots__ = ("micros",)
    micros: int

    def __new__(cls, seconds: float, micros: int) -> Seconds:
        self = super().__new__(cls, seconds)
        self.micros = micros
        return self

    def __reduce__(self) -> tuple[type[Seconds], tuple[float, int]]:
        return Seconds, (float(self), self.micros)


def micros(seconds: float) -> int | None:
    """A timestamp in whole microseconds since the epoch: those a `Seconds` holds, else the
    nearest to the float (half to even); None when it is not finite or outside the years
    1 to 9999."""
    if not math.isfinite(seconds):
        return None
    exact = whole_micros(seconds)
    return exact if FIRST_MICROS <= exact < END_MICROS else None


def micros_seconds(count: int) -> float:
    """The timestamp of a log's whole count of microseconds: ``count / 1e6``, as a `Seconds`
    holding ``count`` where the float alone would not give it back (after 2242)."""
    seconds = count / 1_000_000
    return seconds if -_SAFE < seconds < _SAFE else Seconds(seconds, count)


def text_seconds(text: str, seconds: float | None = None) -> float:
    """The timestamp of a log's decimal text: ``float(text)``, as a `Seconds` with the
    text's microseconds (rounded half to even past the sixth decimal) where the float alone
    would not give them (``seconds``: ``float(text)``, if the caller has it)."""
    if seconds is None:
        seconds = float(text)
    if (-_SAFE < seconds < _SAFE and _plain(text)) or not math.isfinite(seconds):
        return seconds
    exact = round(Fraction(text) * 1_000_000)
    return seconds if micros(seconds) == exact else Seconds(seconds, exact)


def _plain(text: str) -> bool:
    """Decimal digits with at most six after the point."""
    dot = text.find(".")
    return (dot < 0 or len(text) - dot <= 7) and text.replace(".", "", 1).lstrip("+-").isdigit()
