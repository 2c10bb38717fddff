"""The physical units of message fields, where the protocol gives them.

Keys are message class names and field names as `veronte4x.capture.fields` flattens them
(nested structures with dots). A field that is not listed has no unit: a count, an index,
an enum, a flag, or a value whose unit the vehicle's configuration decides (an arbitration
variable's value, a score, a PWM value).

Sources: the DroneCAN DSDL definitions (``uavcan.equipment.esc.Status``: voltage in volt,
current in ampere, temperature in kelvin, rpm, power rating in percent;
``uavcan.equipment.device.Temperature``: kelvin; ``uavcan.protocol.NodeStatus``: uptime in
seconds).

Examples:
    >>> unit("EscStatus", "voltage")
    'V'
    >>> unit("GetNodeInfoResponse", "status.uptime_sec")
    's'
    >>> unit("Score", "score") is None
    True
"""

from __future__ import annotations

from collections.abc import Mapping
from types import MappingProxyType

_NODE_STATUS = {"uptime_sec": "s"}

UNITS: Mapping[str, Mapping[str, str]] = MappingProxyType(
    {
        "EscStatus": MappingProxyType(
            {
                "voltage": "V",
                "current": "A",
                "temperature": "K",
                "rpm": "rpm",
                "power_rating_pct": "%",
            }
        ),
        "Temperature": MappingProxyType({"temperature": "K"}),
        "NodeStatus": MappingProxyType(_NODE_STATUS),
        "GetNodeInfoResponse": MappingProxyType(
            {f"status.{name}": symbol for name, symbol in _NODE_STATUS.items()}
        ),
    }
)
"""Message class name -> field name -> unit symbol (``V``, ``A``, ``K``, ``rpm``, ``%``, ``s``)."""

UNIT_NAMES: Mapping[str, str] = MappingProxyType(
    {
        "V": "volt",
        "A": "ampere",
        "K": "kelvin",
        "rpm": "revolutions per minute",
        "%": "percent",
        "s": "second",
    }
)
"""Each unit symbol of `UNITS` in words."""


def unit(message_type: str, field: str) -> str | None:
    """The unit symbol of a field, or None where the protocol gives none."""
    return UNITS.get(message_type, {}).get(field)
