"""The 29-bit CAN ID of DroneCAN frames: build and parse.

Layouts (spec 4.1 "ID field"), bit 28 first:

- message:   priority(5) | type id(16) | service=0 (1) | source node(7), source 1..127
- anonymous: priority(5) | discriminator(14) | type id low bits(2) | service=0 | source=0
- service:   priority(5) | type id(8) | request(1) | destination(7) | service=1 | source(7)
"""

from __future__ import annotations

import enum
from typing import NamedTuple

from veronte4x.errors import DecodeError, EncodeError, argument_type_error

CAN_ID_MASK = 0x1FFFFFFF
"""The 29 bits of an extended CAN ID."""

LAYOUTS: dict[str, tuple[tuple[str, int, str], ...]] = {
    "message": (
        ("priority", 5, "0..31, 0 highest"),
        ("message type id", 16, "0..65535"),
        ("service not message", 1, "0"),
        ("source node id", 7, "1..127"),
    ),
    "anonymous message": (
        ("priority", 5, "0..31"),
        ("discriminator", 14, "any, e.g. from the payload CRC"),
        ("message type id, low 2 bits", 2, "type ids 0..3"),
        ("service not message", 1, "0"),
        ("source node id", 7, "0"),
    ),
    "service": (
        ("priority", 5, "0..31; a response normally copies the request's"),
        ("service type id", 8, "0..255"),
        ("request not response", 1, "1 request, 0 response"),
        ("destination node id", 7, "1..127"),
        ("service not message", 1, "1"),
        ("source node id", 7, "1..127"),
    ),
}
"""Field name, width and allowed values of each CAN ID layout, bit 28 first (spec 4.1)."""


class TransferKind(enum.IntEnum):
    """What a transfer carries: a message, a service request or a service response."""

    MESSAGE = 0
    REQUEST = 1
    RESPONSE = 2


class CanId(NamedTuple):
    """The fields of a DroneCAN CAN ID.

    Attributes:
        priority: 0 (highest) to 31.
        kind: Message, request or response.
        data_type_id: Message type id (0..65535; only the low 2 bits for anonymous
            messages) or service type id (0..255).
        source_node_id: 1..127, or 0 for an anonymous message.
        destination_node_id: 1..127 for services, ``None`` for messages.
        discriminator: The 14-bit discriminator of an anonymous message, else ``None``.
    """

    priority: int
    kind: TransferKind
    data_type_id: int
    source_node_id: int
    destination_node_id: int | None
    discriminator: int | None


def _check(function: str, name: str, value: int, low: int, high: int) -> None:
    if not isinstance(value, int) or isinstance(value, bool):
        raise argument_type_error(function, name, "an int", value)
    if not low <= value <= high:
        raise EncodeError("CanId", name, value, f"an int in {low}..{high}")


def message_can_id(priority: int, data_type_id: int, source_node_id: int) -> int:
    """CAN ID of a message frame from node ``source_node_id`` (1..127).

    Raises:
        EncodeError: A value out of range.
        TypeError: An argument that is not an int.
    """
    _check("message_can_id", "priority", priority, 0, 31)
    _check("message_can_id", "data_type_id", data_type_id, 0, 0xFFFF)
    _check("message_can_id", "source_node_id", source_node_id, 1, 127)
    return priority << 24 | data_type_id << 8 | source_node_id


def anonymous_can_id(priority: int, data_type_id: int, discriminator: int) -> int:
    """CAN ID of an anonymous message frame (type ids 0..3, single frame only).

    Raises:
        EncodeError: A value out of range.
        TypeError: An argument that is not an int.
    """
    _check("anonymous_can_id", "priority", priority, 0, 31)
    _check("anonymous_can_id", "data_type_id", data_type_id, 0, 3)
    _check("anonymous_can_id", "discriminator", discriminator, 0, 0x3FFF)
    return priority << 24 | discriminator << 10 | data_type_id << 8


def service_can_id(
    priority: int,
    data_type_id: int,
    request: bool,
    source_node_id: int,
    destination_node_id: int,
) -> int:
    """CAN ID of a service request (``request=True``) or response frame.

    Raises:
        EncodeError: A value out of range.
        TypeError: ``request`` not a bool, or another argument that is not an int.
    """
    _check("service_can_id", "priority", priority, 0, 31)
    _check("service_can_id", "data_type_id", data_type_id, 0, 0xFF)
    if not isinstance(request, bool):
        raise argument_type_error("service_can_id", "request", "a bool", request)
    _check("service_can_id", "source_node_id", source_node_id, 1, 127)
    _check("service_can_id", "destination_node_id", destination_node_id, 1, 127)
    return (
        priority << 24
        | data_type_id << 16
        | request << 15
        | destination_node_id << 8
        | 0x80
        | source_node_id
    )


def service_destination(can_id: int) -> int | None:
    """The destination node id of a service frame's CAN ID, or None for a message's (spec
    4.1): a node's quick test of whether a frame is for it, without `parse_can_id`'s checks.

    Examples:
        >>> service_destination(0x1E0B95FF), service_destination(0x10015514) is None
        (21, True)
    """
    return (can_id >> 8) & 0x7F if can_id & 0x80 else None


def parse_can_id(can_id: int) -> CanId:
    """Split a 29-bit CAN ID into its DroneCAN fields.

    Raises:
        DecodeError: ``can_id`` is not a 29-bit value.
        TypeError: ``can_id`` is not an int.
    """
    if not isinstance(can_id, int) or isinstance(can_id, bool):
        raise argument_type_error("parse_can_id", "can_id", "an int", can_id)
    if not 0 <= can_id <= CAN_ID_MASK:
        raise DecodeError("CanId", f"CAN ID {can_id!r} is not a 29-bit value", b"", "can_id")
    priority = can_id >> 24
    source = can_id & 0x7F
    if can_id & 0x80:
        kind = TransferKind.REQUEST if can_id & 0x8000 else TransferKind.RESPONSE
        return CanId(priority, kind, (can_id >> 16) & 0xFF, source, (can_id >> 8) & 0x7F, None)
    if source == 0:
        return CanId(
            priority, TransferKind.MESSAGE, (can_id >> 8) & 3, 0, None, (can_id >> 10) & 0x3FFF
        )
    return CanId(priority, TransferKind.MESSAGE, (can_id >> 8) & 0xFFFF, source, None, None)
