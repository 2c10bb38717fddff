"""The CAN frame of a DroneCAN transfer, as `encode` returns it (a captured frame, with its
time and channel, is `veronte4x.capture.Frame`)."""

from __future__ import annotations

from typing import NamedTuple


class TransferFrame(NamedTuple):
    """One classic CAN frame: a 29-bit extended ``can_id`` and up to 8 data bytes.

    ``data`` ends with the tail byte (spec 4.1 "Payload").
    """

    can_id: int
    data: bytes
