"""The time text of every output (`veronte4x.times.utc_text`, `whole_micros`), in integer
arithmetic, against the exact form it replaced: ``Fraction`` for the microseconds and a
``datetime`` for the text, over every float, every `Seconds` and every microsecond of the
years 1 to 9999, and past them (both refuse the same way)."""

from __future__ import annotations

import math
from datetime import datetime, timedelta, timezone
from fractions import Fraction

import pytest
from hypothesis import example, given
from hypothesis import strategies as st

from veronte4x.capture.frames import Seconds
from veronte4x.times import END_MICROS, FIRST_MICROS, format_time, utc_text, whole_micros

EPOCH = datetime(1970, 1, 1, tzinfo=timezone.utc)
FIRST, END = FIRST_MICROS / 1e6, END_MICROS / 1e6


def old_micros(seconds: float) -> int:
    kept = getattr(seconds, "micros", None)
    return kept if isinstance(kept, int) else round(Fraction(seconds) * 1_000_000)


def old_utc_text(seconds: float) -> str:
    """The former `utc_text`, its year to four digits: glibc's ``%Y`` gives years before
    1000 unpadded (``1-01-01``), which no output reached (Unix time starts in 1973 there)."""
    moment = EPOCH + timedelta(microseconds=old_micros(seconds))
    year, rest = moment.strftime("%Y-%m-%dT%H:%M:%S.%fZ").split("-", 1)
    return f"{int(year):04d}-{rest}"


def outcome(function: object, seconds: float) -> str:
    try:
        return function(seconds)  # type: ignore[operator,no-any-return]
    except (OverflowError, ValueError) as error:
        return type(error).__name__


def received(whole: int, nanoseconds: int) -> float:
    """A receive time as python-can and the live reader make it of ``SO_TIMESTAMPNS``."""
    return float(whole + nanoseconds * 1.0e-9)


times = st.one_of(
    st.floats(FIRST - 1e6, END + 1e6),  # the whole range and past both ends
    st.floats(1.6e9, 1.9e9),  # today
    st.floats(-1e9, 1e9),  # around 1970, before it included
    st.floats(allow_nan=False),  # subnormal to infinite
    st.builds(received, st.integers(0, 2**34), st.integers(0, 999_999_999)),
    st.builds(
        lambda micros, part: (micros + part) / 1e6,  # near a half microsecond
        st.integers(FIRST_MICROS, END_MICROS),
        st.sampled_from([0.5, 0.4999, 0.5001, 0.0, 0.999]),
    ),
    st.builds(
        lambda micros: Seconds(micros / 1e6, micros), st.integers(FIRST_MICROS - 1, END_MICROS)
    ),
    st.integers(-(10**12), 10**12),
)


@given(times)
@example(0.0)
@example(-1e-7)
@example(5e-7)
@example(1.5e-6)
@example(2.5e-6)
@example(FIRST)
@example(END)
@example(Seconds(END_MICROS / 1e6, END_MICROS - 1))
@example(math.inf)
@example(math.nan)
def test_same_text_as_the_exact_form(seconds: float) -> None:
    assert outcome(whole_micros, seconds) == outcome(old_micros, seconds)
    assert outcome(utc_text, seconds) == outcome(old_utc_text, seconds)


def test_examples() -> None:
    assert utc_text(-0.0000005) == "1970-01-01T00:00:00.000000Z"  # half to even
    assert utc_text(-0.0000015) == "1969-12-31T23:59:59.999998Z"
    assert utc_text(FIRST) == "0001-01-01T00:00:00.000000Z"
    assert utc_text(Seconds(END, END_MICROS - 1)) == "9999-12-31T23:59:59.999999Z"
    with pytest.raises(OverflowError):
        utc_text(END)


def test_a_time_with_no_iso_form_is_seconds() -> None:
    """Past the year 9999 (or not finite) text gives the seconds, as JSON lines and CSV do:
    ``decode`` and ``stats`` of such a log gave a traceback."""
    assert format_time(3e11) == "300000000000.000000"
    assert format_time(math.inf) == "inf"
    assert format_time(math.nan) == "nan"
    assert format_time(Seconds(END, END_MICROS - 1)) == "9999-12-31T23:59:59.999999Z"
