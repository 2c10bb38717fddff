"""The five configuration parameters of the simulated ESC and its GetSet replies.

Names, types and order are those of Vertiq's DroneCAN support document, section 3 (all integers;
the index of a
parameter is its position in that section, which is what a discovery walk by index sees).
The document gives no minimum or maximum for any of them; the ranges below are the simulator's
own and are documented on the "Simulated ESC" page:

- ``uavcan_node_id``: 1..127, the node ids DroneCAN allows a named node.
- ``bit_rate``: 10000..1000000 bit/s, the classic CAN range.
- ``esc_index``: 0..19, the entries a RawCommand can hold (Vertiq's DroneCAN support, 1.4: up to
20).
- ``zero_behavior``: 0..2, the values of `ZeroBehavior` (3.4).
- ``telem_frequency``: 0..1000 Hz, 0 turning telemetry off (3.5).
"""

from __future__ import annotations

from dataclasses import dataclass

from veronte4x.dronecan.messages import Empty, GetSetRequest, GetSetResponse, IntegerValue
from veronte4x.dronecan.vertiq import MAX_ESCS, Parameter


@dataclass(frozen=True, slots=True)
class ParameterRange:
    """The allowed values of one parameter and when a new value takes effect.

    Attributes:
        parameter: Which parameter.
        minimum: Smallest accepted value.
        maximum: Largest accepted value.
        takes_effect: When a set value is used, in words (for the docs).
    """

    parameter: Parameter
    minimum: int
    maximum: int
    takes_effect: str


PARAMETERS: tuple[ParameterRange, ...] = (
    ParameterRange(
        Parameter.UAVCAN_NODE_ID,
        1,
        127,
        "after a restart (Vertiq document, 3.1)",
    ),
    ParameterRange(
        Parameter.BIT_RATE, 10_000, 1_000_000, "at once, stored only: the simulator has no wire"
    ),
    ParameterRange(Parameter.ESC_INDEX, 0, MAX_ESCS - 1, "at once: the next RawCommand"),
    ParameterRange(Parameter.ZERO_BEHAVIOR, 0, 2, "at once: the next zero setpoint"),
    ParameterRange(Parameter.TELEM_FREQUENCY, 0, 1000, "at once: the schedule restarts"),
)
"""The parameters in discovery order: index i is ``PARAMETERS[i]``."""

_BY_NAME: dict[bytes, int] = {r.parameter.value.encode(): i for i, r in enumerate(PARAMETERS)}


def find(request: GetSetRequest) -> int | None:
    """The index of the parameter a GetSet request names, or None if there is none.

    A non-empty ``name`` selects by name and the index is ignored (DSDL GetSet).
    """
    if request.name:
        return _BY_NAME.get(request.name)
    return request.index if request.index < len(PARAMETERS) else None


def new_value(index: int, request: GetSetRequest) -> int | None:
    """The value a GetSet request sets, or None if it reads or asks for a value out of range.

    Only an ``integer_value`` sets a parameter (they are all integers, Vertiq's DroneCAN support,
    3); any
    other member or an out-of-range integer leaves it unchanged, and the reply then shows
    the unchanged value (the DSDL's "actual value after the set").
    """
    value = request.value
    if not isinstance(value, IntegerValue):
        return None
    allowed = PARAMETERS[index]
    return value.value if allowed.minimum <= value.value <= allowed.maximum else None


def response(index: int, value: int, default: int) -> GetSetResponse:
    """The GetSet reply for parameter ``index``: value, default, maximum, minimum, name."""
    allowed = PARAMETERS[index]
    return GetSetResponse(
        value=IntegerValue(value),
        default_value=IntegerValue(default),
        max_value=IntegerValue(allowed.maximum),
        min_value=IntegerValue(allowed.minimum),
        name=allowed.parameter.value.encode(),
    )


NO_PARAMETER = GetSetResponse(Empty(), Empty(), Empty(), Empty(), b"")
"""The empty reply to an unknown name or an index past the last: it ends discovery."""
