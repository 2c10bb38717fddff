"""The CRCs of DroneCAN: the transfer CRC and CRC-64-WE.

Transfer CRC of multi-frame DroneCAN transfers: CRC-16-CCITT-FALSE, poly 0x1021, init
0xFFFF, no reflection, xorout 0, check 0x29B1 for ``b"123456789"`` (spec 4.1 "Transfer
CRC"). The CRC runs over the 8-byte little-endian data type signature and then the payload,
so the signature part is computed once per type as a seed. The standard library's
`crc_hqx` computes exactly this CRC (poly 0x1021, not reflected, no final xor) from a given
start value, in C.

CRC-64-WE (`crc64we`) is both the data type signature of a DSDL definition (the
specification's section "Data type signature"; `veronte4x.dronecan.parser.signature`) and
the checksum of a firmware image in ``SoftwareVersion.image_crc`` (named by the DSDL of
``uavcan.protocol.SoftwareVersion``): polynomial 0x42F0E1EBA9EA3693, initial value and
final XOR 0xFFFFFFFFFFFFFFFF, no bit reflection; its check value (the CRC of
``b"123456789"``) is 0x62EC59E3F1A4F00A.
"""

from __future__ import annotations

from binascii import crc_hqx

INITIAL = 0xFFFF
"""Initial value of the transfer CRC."""


def crc16(data: bytes, crc: int = INITIAL) -> int:
    """Continue a CRC-16-CCITT-FALSE over ``data``, starting from ``crc``."""
    return crc_hqx(data, crc)


def crc16_table() -> tuple[int, ...]:
    """The transfer CRC's byte table, for engines that feed a byte at a time: from register
    ``c`` and byte ``b``, the next is ``(c << 8 & 0xFFFF) ^ table[(c >> 8) ^ b]``."""
    return tuple(crc16(bytes((byte,)), 0) for byte in range(256))


def signature_seed(signature: int) -> int:
    """CRC after the 64-bit data type signature, fed little-endian: the per-type seed."""
    return crc_hqx(signature.to_bytes(8, "little"), INITIAL)


CRC64_POLYNOMIAL = 0x42F0E1EBA9EA3693
"""The polynomial of CRC-64-WE."""
_MASK64 = (1 << 64) - 1


def _crc64_table() -> tuple[int, ...]:
    table = []
    for byte in range(256):
        crc = byte << 56
        for _ in range(8):
            crc = ((crc << 1) ^ CRC64_POLYNOMIAL) & _MASK64 if crc >> 63 else (crc << 1) & _MASK64
        table.append(crc)
    return tuple(table)


_CRC64_TABLE = _crc64_table()


def crc64we(data: bytes, crc: int = 0) -> int:
    """CRC-64-WE of ``data``; pass a previous result as ``crc`` to continue over more data.

    Examples:
        >>> hex(crc64we(b"123456789"))
        '0x62ec59e3f1a4f00a'
        >>> crc64we(b"6789", crc64we(b"12345")) == crc64we(b"123456789")
        True
    """
    value = crc ^ _MASK64
    table = _CRC64_TABLE
    for byte in data:
        value = table[(value >> 56) ^ byte] ^ ((value << 8) & _MASK64)
    return value ^ _MASK64
