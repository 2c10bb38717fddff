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


def _tail_sequences() -> tuple[tuple[tuple[int, ...], ...], ...]:
    """Tail bytes of every multi-frame length, indexed by transfer id then frame count."""
    rows: list[tuple[int, ...]] = [()]  # transfer id 0; the others add their id to each byte
    for count in range(1, 64):
        rows.append(tuple(tail_byte(i == 0, i == count - 1, bool(i & 1), 0) for i in range(count)))
    return tuple(tuple(tuple(map(tid.__or__, row)) for row in rows) for tid in range(32))


MULTI_FRAME_TAILS = _tail_sequences()
"""``MULTI_FRAME_TAILS[transfer_id][frame_count]``: the tail byte of each frame."""


def split_payload(payload: bytes, crc: int, transfer_id: int) -> list[bytes]:
    """Cut a payload longer than 7 bytes into frame data (CRC first, tail bytes added)."""
    body = bytes((crc & 0xFF, crc >> 8)) + payload
    count = (len(body) + 6) // 7
    tails = MULTI_FRAME_TAILS[transfer_id][count]
    return [body[i * 7 : i * 7 + 7] + bytes((tails[i],)) for i in range(count)]
