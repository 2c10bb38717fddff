"""CRC-64-WE, the checksum of a firmware image in ``SoftwareVersion.image_crc``.

The DSDL of ``uavcan.protocol.SoftwareVersion`` names the algorithm: CRC-64-WE, that is
polynomial 0x42F0E1EBA9EA3693, initial value and final XOR 0xFFFFFFFFFFFFFFFF, no bit
reflection; its check value (the CRC of ``b"123456789"``) is 0x62EC59E3F1A4F00A.
"""

from __future__ import annotations

POLYNOMIAL = 0x42F0E1EBA9EA3693
_MASK = (1 << 64) - 1


def _table() -> tuple[int, ...]:
    table = []
    for byte in range(256):
        crc = byte << 56
        for _ in range(8):
            crc = ((crc << 1) ^ POLYNOMIAL) & _MASK if crc & (1 << 63) else (crc << 1) & _MASK
        table.append(crc)
    return tuple(table)


_TABLE = _table()


def crc64we(data: bytes, crc: int = 0) -> int:
    """CRC-64-WE of ``data``; pass a previous result as ``crc`` to continue over more data.

    Examples:
        >>> hex(crc64we(b"123456789"))
        '0x62ec59e3f1a4f00a'
        >>> crc64we(b"6789", crc64we(b"12345")) == crc64we(b"123456789")
        True
    """
    value = crc ^ _MASK
    table = _TABLE
    for byte in data:
        value = table[((value >> 56) ^ byte) & 0xFF] ^ ((value << 8) & _MASK)
    return value ^ _MASK
