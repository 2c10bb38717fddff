"""Timestamps as people and text formats read them: ISO 8601 for Unix time, seconds
otherwise or relative.

The one rule for a time in text (``decode``'s text, JSON lines and CSV, ``convert --to
csv``): Unix time as ISO 8601 in UTC to the microsecond (`utc_text`), the log's own
microseconds, as the tables' ``timestamp[us, tz=UTC]`` hold it; a capture's own clock
(below `EPOCH_THRESHOLD`: time since a device booted or a log started) as its seconds,
never as a time of 1970.
"""

from __future__ import annotations

import datetime as _dt
import functools
from typing import Literal

FIRST_MICROS = -62_135_596_800_000_000
"""0001-01-01 00:00:00 UTC in microseconds since the epoch: the first time a table holds,
and the first with an ISO 8601 form."""
END_MICROS = 253_402_300_800_000_000
"""10000-01-01 00:00:00 UTC in microseconds: times from here on have no table value and no
ISO 8601 form."""
EPOCH_THRESHOLD = 1e8
"""Timestamps at or above this many seconds (March 1973) are read as Unix time, printed as
ISO 8601 in UTC; smaller ones are a capture's own clock (seconds since its start), printed
as seconds."""


def format_time(seconds: float | None, start: float | None = None) -> str:
    """A timestamp as people read it.

    Args:
        seconds: The timestamp (None: the capture has no time).
        start: Print the time relative to this one (the first frame's), in seconds.

    Returns:
        ``-`` without a time; seconds since `start` with microseconds when given; else
        ISO 8601 in UTC for Unix time (see `EPOCH_THRESHOLD`) and seconds otherwise (a
        capture's own clock, a time past the year 9999).

    Examples:
        >>> format_time(1763737200.01)
        '2025-11-21T15:00:00.010000Z'
        >>> format_time(1763737200.01, start=1763737200.0)
        '0.010000'
    """
    if seconds is None:
        return "-"
    if start is not None:
        return f"{relative_seconds(seconds, start):.6f}"
    if seconds < EPOCH_THRESHOLD:
        return f"{seconds:.6f}"
    try:
        return utc_text(seconds)
    except (OverflowError, ValueError):  # past the year 9999, or not finite: no ISO 8601
        return f"{seconds:.6f}"


def relative_seconds(seconds: float, start: float) -> float:
    """Seconds from ``start`` to ``seconds``, from their whole microseconds (`whole_micros`),
    so that a difference of logged times is the logged difference.

    Examples:
        >>> relative_seconds(1763737200.3, 1763737200.0000005)
        0.3
        >>> 1763737200.3 - 1763737200.0000005  # the floats' difference
        0.299999475479126
    """
    return (whole_micros(seconds) - whole_micros(start)) / 1_000_000


def utc_text(seconds: float) -> str:
    """Unix time as ISO 8601 in UTC to the microsecond, the form of text outputs.

    The microseconds are the log's (`whole_micros`): a float of python-can's readers that
    holds less than a microsecond more is rounded to the nearest, as the tables are;
    ``decode --time seconds`` writes that float itself. In integer arithmetic: a full bus
    writes thousands a second.

    Raises:
        OverflowError: The time is outside the years 1 to 9999.

    Examples:
        >>> utc_text(1763737200.123456)
        '2025-11-21T15:00:00.123456Z'
    """
    micros = whole_micros(seconds)
    if not FIRST_MICROS <= micros < END_MICROS:
        raise OverflowError("date value out of range")
    days, micros = divmod(micros, 86_400_000_000)
    second, micro = divmod(micros, 1_000_000)
    minute, second = divmod(second, 60)
    hour, minute = divmod(minute, 60)
    return f"{_date_text(days)}T{hour:02d}:{minute:02d}:{second:02d}.{micro:06d}Z"


@functools.lru_cache(maxsize=16)
def _date_text(days: int) -> str:
    """The date ``days`` after 1970-01-01 as ISO 8601 (``YYYY-MM-DD``), kept for the few
    days a capture spans."""
    day = _dt.date.fromordinal(_EPOCH_ORDINAL + days)
    return f"{day.year:04d}-{day.month:02d}-{day.day:02d}"


def whole_micros(seconds: float) -> int:
    """A finite timestamp in whole microseconds: those the log wrote where the reader kept
    them beside the float (`veronte4x.capture.frames.Seconds`), else the nearest to the
    float, half to even (from the float's exact ratio of integers).

    Examples:
        >>> whole_micros(1763737200.0000005), whole_micros(12.5)
        (1763737200000000, 12500000)
    """
    if type(seconds) is not float:
        kept = getattr(seconds, "micros", None)
        if isinstance(kept, int):
            return kept
    numerator, denominator = seconds.as_integer_ratio()  # exact; the denominator is 2**k
    whole, rest = divmod(numerator * 1_000_000, denominator)
    return whole + (2 * rest > denominator or (2 * rest == denominator and whole % 2 == 1))


_EPOCH = _dt.datetime(1970, 1, 1, tzinfo=_dt.timezone.utc)
_EPOCH_ORDINAL = _EPOCH.toordinal()


def utc_datetime(seconds: float) -> _dt.datetime | None:
    """Unix time as a UTC datetime, to the microsecond (as the tables hold it).

    Returns:
        None for a capture's own clock (below `EPOCH_THRESHOLD`), a time that is not
        finite, or one past year 9999.

    Examples:
        >>> utc_datetime(1763737200.01)
        datetime.datetime(2025, 11, 21, 15, 0, 0, 10000, tzinfo=datetime.timezone.utc)
        >>> utc_datetime(12.5) is None
        True
    """
    if not EPOCH_THRESHOLD <= seconds < _MAX_SECONDS:
        return None
    return _moment(seconds)


def _moment(seconds: float) -> _dt.datetime:
    """Unix time as a UTC datetime, to the microsecond (`whole_micros`)."""
    return _EPOCH + _dt.timedelta(microseconds=whole_micros(seconds))


_MAX_SECONDS = (
    _dt.datetime(9999, 12, 31, 23, 59, 59, tzinfo=_dt.timezone.utc) - _EPOCH
).total_seconds()


TimeForm = Literal["timestamp", "relative", "seconds"]
"""How tables, DataFrames and datasets give a capture's time (their ``time`` option):
``timestamp``, an Arrow ``timestamp[us, tz=UTC]`` exact to the log (the default);
``relative``, float seconds from the capture's first timestamped frame; ``seconds``, float
seconds as logged (Unix time for candump)."""
TIME_FORMS: tuple[TimeForm, ...] = ("timestamp", "relative", "seconds")


def check_time_form(time: str) -> TimeForm:
    """The ``time`` option, checked.

    Raises:
        ValueError: It is none of `TIME_FORMS`.
    """
    if time not in TIME_FORMS:
        raise ValueError(
            f"time={time!r}: give 'timestamp' (UTC, the default), 'relative' (seconds from "
            "the first frame) or 'seconds' (seconds as logged)"
        )
    return time
