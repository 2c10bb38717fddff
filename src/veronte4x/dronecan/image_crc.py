"""CRC-64-WE, the checksum of a firmware image in ``SoftwareVersion.image_crc``.

The same CRC as the DSDL data type signature; its one home is `veronte4x.dronecan.crc`,
re-exported here where the firmware tools import it.
"""

from __future__ import annotations

from veronte4x.dronecan.crc import CRC64_POLYNOMIAL as POLYNOMIAL
from veronte4x.dronecan.crc import crc64we

__all__ = ["POLYNOMIAL", "crc64we"]
