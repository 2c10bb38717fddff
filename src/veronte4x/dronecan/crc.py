"""Transfer CRC of multi-frame DroneCAN transfers.

CRC-16-CCITT-FALSE: poly 0x1021, init 0xFFFF, no reflection, xorout 0, check 0x29B1 for
``b"123456789"`` (spec 4.1 "Transfer CRC"). The CRC
runs over the 8-byte little-endian data type signature and then the payload, so the
signature part is precomputed once per type as a seed.

The standard library's `crc_hqx` computes exactly this CRC (poly 0x1021,
not reflected, no final xor) from a given start value, in C.
"""

from __future__ import annotations

from binascii import crc_hqx

INITIAL = 0xFFFF
"""Initial value of the transfer CRC."""


def crc16(data: bytes, crc: int = INITIAL) -> int:
    """Continue a CRC-16-CCITT-FALSE over ``data``, starting from ``crc``."""
    return crc_hqx(data, crc)


def signature_seed(signature: int) -> int:
    """CRC after the 64-bit data type signature, fed little-endian: the per-type seed."""
    return crc_hqx(signature.to_bytes(8, "little"), INITIAL)
