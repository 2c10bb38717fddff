"""Timestamps as people read them: ISO 8601 for Unix time, seconds otherwise or relative."""

from __future__ import annotations

import datetime as _dt
from typing import Literal

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
        ISO 8601 in UTC for Unix time (see `EPOCH_THRESHOLD`) and seconds otherwise.

    Examples:
        >>> format_time(1763737200.01)
        '2025-11-21T15:00:00.010000Z'
        >>> format_time(1763737200.01, start=1763737200.0)
        '0.010000'
    """
    if seconds is None:
        return "-"
    if start is not None:
        return f"{seconds - start:.6f}"
    if seconds < EPOCH_THRESHOLD:
        return f"{seconds:.6f}"
    return _moment(seconds).strftime("%Y-%m-%dT%H:%M:%S.%fZ")


_EPOCH = _dt.datetime(1970, 1, 1, tzinfo=_dt.timezone.utc)


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
    """Unix time as a UTC datetime, rounded to the microsecond."""
    return _EPOCH + _dt.timedelta(microseconds=round(seconds * 1_000_000))


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
