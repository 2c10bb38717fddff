"""Parameters as a ground station shows them: name, value, default and range."""

from __future__ import annotations

import math
from dataclasses import dataclass

from veronte4x.client.errors import InvalidRequestError
from veronte4x.dronecan import vertiq
from veronte4x.dronecan.messages import (
    BooleanValue,
    Empty,
    GetSetRequest,
    GetSetResponse,
    IntegerValue,
    NumericValue,
    RealValue,
    StringValue,
    Value,
)

Plain = int | float | bool | str | None
"""A parameter value as plain Python: None for an empty value."""


def plain(value: Value | NumericValue) -> Plain:
    """The Python value of a ``param.Value`` member (bool for ``boolean_value``)."""
    if isinstance(value, Empty):
        return None
    if isinstance(value, BooleanValue):
        return bool(value.value)
    if isinstance(value, StringValue):
        return value.value.decode("utf-8", "replace")
    return value.value


def parameter_request(name: str | None, index: int | None = None) -> GetSetRequest:
    """The GetSet request reading one parameter by name, or by index when only ``index`` is
    given.

    DroneCAN's GetSet reads by index when the name is empty (DSDL ``param.GetSet``), and
    index 0 of a Vertiq module is ``uavcan_node_id``: so an empty name is refused rather
    than taken for index 0, and by-index access needs ``index`` said explicitly.

    Raises:
        InvalidRequestError: An empty name, both a name and an index, or neither.
        TypeError: A name that is not a str or an index that is not an int.
    """
    if name is not None and index is not None:
        raise InvalidRequestError(
            f"give a parameter name ({name!r}) or an index ({index}), not both"
        )
    if index is not None:
        return vertiq.get_parameter_by_index(index)
    if name is None:
        raise InvalidRequestError("give a parameter name, or an index to read by index")
    if not isinstance(name, str):
        raise TypeError(f"a parameter name is a str, not {name!r}; to read by index, give index=")
    if not name:
        raise InvalidRequestError(
            "an empty parameter name is refused (DroneCAN would read index 0, uavcan_node_id); "
            "give the name, or the index explicitly"
        )
    return vertiq.get_parameter(name)


@dataclass(frozen=True, slots=True)
class ParameterInfo:
    """One parameter of a node, from a GetSet response.

    Attributes:
        name: Its name.
        value: Its value.
        default: Its default value (`Empty` when the node gives none).
        minimum: Its smallest value (`Empty` when the node gives none).
        maximum: Its largest value (`Empty` when the node gives none).
        index: Its index, when it was read by index (discovery).
    """

    name: str
    value: Value
    default: Value
    minimum: NumericValue
    maximum: NumericValue
    index: int | None = None

    @classmethod
    def from_response(cls, response: GetSetResponse, index: int | None = None) -> ParameterInfo:
        """The parameter a non-empty GetSet response describes."""
        return cls(
            response.name.decode("utf-8", "replace"),
            response.value,
            response.default_value,
            response.min_value,
            response.max_value,
            index,
        )

    def as_dict(self) -> dict[str, Plain]:
        """Plain data for JSON: name, value, default, min, max, index."""
        return {
            "name": self.name,
            "value": plain(self.value),
            "default": plain(self.default),
            "min": plain(self.minimum),
            "max": plain(self.maximum),
            "index": self.index,
        }

    @property
    def exists(self) -> bool:
        """Whether the node has this parameter. The DroneCAN specification
        (``uavcan.protocol.param.GetSet``, the response): an Empty value (and/or an empty
        name) indicates that there is no such parameter."""
        return bool(self.name) and not isinstance(self.value, Empty)

    def _missing(self) -> str:
        return f"{self.name or 'the parameter'} does not exist on the node (its value is empty)"

    def check(self, value: Value) -> str | None:
        """Why ``value`` cannot be set here (no such parameter, wrong type, out of range), or
        None if it can."""
        if not self.exists:
            return self._missing()
        if type(value) is not type(self.value):
            return f"{self.name} takes {_KINDS[type(self.value)]}, not {plain(value)!r}"
        if isinstance(value, (IntegerValue, RealValue)):
            low, high = plain(self.minimum), plain(self.maximum)
            number = value.value
            if (isinstance(low, (int, float)) and number < low) or (
                isinstance(high, (int, float)) and number > high
            ):
                return f"{number} is out of range for {self.name}: {low}..{high}"
        return None

    def parse(self, text: str) -> Value:
        """A value of this parameter's type from text (as typed on a command line).

        Raises:
            ValueError: The text is not a value of that type, or the parameter does not
                exist (`exists`).
        """
        if not self.exists:
            raise ValueError(self._missing())
        value = self.value
        if isinstance(value, IntegerValue):
            try:
                return IntegerValue(int(text, 0))
            except ValueError:
                raise ValueError(f"{self.name} takes an integer, not {text!r}") from None
        if isinstance(value, RealValue):
            try:
                number = float(text)
            except ValueError:
                raise ValueError(f"{self.name} takes a number, not {text!r}") from None
            if not math.isfinite(number):
                raise ValueError(f"{self.name} takes a finite number, not {text!r}")
            return RealValue(number)
        if isinstance(value, BooleanValue):
            words = {"1": 1, "true": 1, "yes": 1, "on": 1, "0": 0, "false": 0, "no": 0, "off": 0}
            if text.lower() not in words:
                raise ValueError(f"{self.name} takes true or false, not {text!r}")
            return BooleanValue(words[text.lower()])
        return StringValue(text.encode("utf-8"))


_KINDS: dict[type, str] = {
    IntegerValue: "an integer",
    RealValue: "a number",
    BooleanValue: "true or false",
    StringValue: "text",
}
"""What a parameter of each value type takes, in words."""
