"""The CAN frame type that `encode` returns."""

from __future__ import annotations

from typing import NamedTuple


class TransferFrame(NamedTuple):
    """One classic CAN frame: a 29-bit extended ``can_id`` and up to 8 data bytes.

    ``data`` ends with the tail byte (spec 4.1 "Payload").
    """

    can_id: int
    data: bytes
