"""The tail byte and the cutting of a payload into frames (spec 4.1 "Payload").

Tail byte, the last data byte of every frame: bit 7 start of transfer, bit 6 end of
transfer, bit 5 toggle, bits 4..0 transfer id. A payload of at most 7 bytes goes in one
frame with tail ``0xC0 | transfer_id``. A longer payload is prefixed with the transfer CRC
(little-endian) and cut into 7-byte chunks; the toggle starts at 0 and alternates.
"""

from __future__ import annotations

START_OF_TRANSFER = 0x80
END_OF_TRANSFER = 0x40
TOGGLE = 0x20
TRANSFER_ID_MASK = 0x1F
FRAME_FLAGS = START_OF_TRANSFER | END_OF_TRANSFER | TOGGLE
"""The tail bits above the transfer id."""
SINGLE_FRAME = START_OF_TRANSFER | END_OF_TRANSFER
"""The tail bits of a transfer in one frame (its toggle is 0)."""

SINGLE_FRAME_MAX = 7
"""Largest payload that fits in one classic CAN frame next to the tail byte."""


def tail_byte(start: bool, end: bool, toggle: bool, transfer_id: int) -> int:
    """Build a tail byte."""
    return (
        (START_OF_TRANSFER if start else 0)
        | (END_OF_TRANSFER if end else 0)
        | (TOGGLE if toggle else 0)
        | (transfer_id & TRANSFER_ID_MASK)
    )


class TailRows(dict[int, tuple[int, ...]]):
    """The tail bytes of every multi-frame length for one transfer id: ``rows[count]`` is
    the tail byte of each of ``count`` frames, made on first use.

    A transfer has as many frames as its payload needs (the type's largest payload bounds
    it): libcanard's ``payload_len`` is a ``uint16_t`` and the ``dronecan`` package cuts and
    joins any number of frames, so no frame count is refused here.
    """

    __slots__ = ("transfer_id",)

    def __init__(self, transfer_id: int) -> None:
        super().__init__()
        self.transfer_id = transfer_id

    def __missing__(self, count: int) -> tuple[int, ...]:
        if not isinstance(count, int) or count < 0:
            raise KeyError(count)
        tid = self.transfer_id
        row = self[count] = tuple(
            tail_byte(i == 0, i == count - 1, bool(i & 1), tid) for i in range(count)
        )
        return row


MULTI_FRAME_TAILS = tuple(TailRows(tid) for tid in range(32))
"""``MULTI_FRAME_TAILS[transfer_id][frame_count]``: the tail byte of each frame."""


def frame_count(size: int) -> int:
    """Frames of a transfer of ``size`` payload bytes (the CRC's two bytes added past 7).

    Examples:
        >>> frame_count(7), frame_count(8), frame_count(12), frame_count(13)
        (1, 2, 2, 3)
    """
    return 1 if size <= SINGLE_FRAME_MAX else (size + 8) // 7


def split_payload(payload: bytes, crc: int, transfer_id: int) -> list[bytes]:
    """Cut a payload longer than 7 bytes into frame data (CRC first, tail bytes added)."""
    body = bytes((crc & 0xFF, crc >> 8)) + payload
    count = frame_count(len(payload))
    tails = MULTI_FRAME_TAILS[transfer_id][count]
    return [body[i * 7 : i * 7 + 7] + bytes((tails[i],)) for i in range(count)]
