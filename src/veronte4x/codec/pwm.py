"""PWM set frames: the open packing order, and the value/microsecond helpers.

The Software Manual's CAN table gives commands 2, 3, 11, 12, 13 (t_pwm_0_3_set .. t_pwm_16_19_set);
Embention's manuals give four 12-bit normalised values 0..4095 per frame. The order in which the
four fields are packed
is not public, hence `PwmPacking`. The microsecond mapping lives in the receiving device
(template default 900..2100 us), so it is a helper, not part of the wire format.
"""

from __future__ import annotations

import enum

from veronte4x.errors import EncodeError, argument_type_error, integer, real

PWM_MAX = 4095
"""The largest normalised PWM value: "12 bits all with ones"."""

DEFAULT_MIN_US = 900.0
DEFAULT_MAX_US = 2100.0

PWM_COMMANDS: dict[int, int] = {0: 2, 4: 3, 8: 11, 12: 12, 16: 13}
"""First channel to command byte (Software Manual, section 3, message-type table)."""


class PwmPacking(enum.Enum):
    """How the four 12-bit values fill bytes 1-6 of a PWM set frame (an open point).

    Attributes:
        LSB_FIRST: Default. Bytes 1-6 read as a little-endian 48-bit word; the first
            channel takes bits 0-11, the next bits 12-23, and so on.
        MSB_FIRST: Bytes 1-6 read as a big-endian 48-bit word; the first channel takes
            the 12 most significant bits (byte 1 and the high nibble of byte 2).
    """

    LSB_FIRST = "lsb_first"
    MSB_FIRST = "msb_first"


def _number(function: str, argument: str, value: object) -> float:
    """``value`` as a Python number (a NumPy one too, see `veronte4x.errors.real`)."""
    number = real(value)
    if number is None:
        raise argument_type_error(function, argument, "a number", value)
    return number


def to_microseconds(
    value: int, min_us: float = DEFAULT_MIN_US, max_us: float = DEFAULT_MAX_US
) -> float:
    """Convert a normalised PWM value (0..4095) to a pulse width in microseconds.

    Raises:
        EncodeError: ``value`` out of 0..4095.
        TypeError: ``value`` not an int, or a bound not a number.
    """
    min_us = _number("to_microseconds", "min_us", min_us)
    max_us = _number("to_microseconds", "max_us", max_us)
    whole = integer(value)
    if whole is None:
        raise argument_type_error("to_microseconds", "value", "an int", value)
    value = whole
    if not 0 <= value <= PWM_MAX:
        raise EncodeError("PwmSet", "values", value, f"an int in 0..{PWM_MAX}")
    return min_us + (max_us - min_us) * value / PWM_MAX


def from_microseconds(
    pulse_us: float, min_us: float = DEFAULT_MIN_US, max_us: float = DEFAULT_MAX_US
) -> int:
    """Convert a pulse width in microseconds to the nearest normalised PWM value.

    Raises:
        EncodeError: The pulse lies outside min_us..max_us.
        TypeError: An argument that is not a number.
    """
    pulse_us = _number("from_microseconds", "pulse_us", pulse_us)
    min_us = _number("from_microseconds", "min_us", min_us)
    max_us = _number("from_microseconds", "max_us", max_us)
    low, high = sorted((min_us, max_us))
    if not low <= pulse_us <= high:
        raise EncodeError("PwmSet", "values", pulse_us, f"a pulse in {low}..{high} us")
    return round((pulse_us - min_us) / (max_us - min_us) * PWM_MAX)
