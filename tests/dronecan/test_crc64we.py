"""CRC-64-WE has one home (`veronte4x.dronecan.crc`) and two users: the DSDL data type
signature and the firmware image CRC; both still give the known values."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from veronte4x.client.firmware import image_crc
from veronte4x.dronecan import crc, parser
from veronte4x.dronecan import image_crc as image_crc_module
from veronte4x.dronecan.types import standard_definitions

SAMPLE = Path(__file__).parent / "data" / "dronecan_sample.jsonl"
CHECK = 0x62EC59E3F1A4F00A
"""CRC-64-WE of ``b"123456789"``, its check value (catalogue of parametrised CRC
algorithms, "CRC-64/WE")."""


def _known_signatures() -> dict[str, int]:
    """The signatures the `dronecan` package gives, as recorded in the sample."""
    known: dict[str, int] = {}
    for line in SAMPLE.read_text().splitlines():
        entry = json.loads(line)
        known[entry["type"]] = int(entry["signature"], 16)
    return known


def test_one_home() -> None:
    assert vars(parser)["crc64we"] is crc.crc64we  # the signature computes with it
    assert image_crc_module.crc64we is crc.crc64we
    assert image_crc_module.POLYNOMIAL == crc.CRC64_POLYNOMIAL == 0x42F0E1EBA9EA3693


@pytest.mark.parametrize(("name", "expected"), sorted(_known_signatures().items()))
def test_signatures_are_the_known_ones(name: str, expected: int) -> None:
    assert parser.signature(name, standard_definitions()) == expected


def test_signatures_cover_nested_types() -> None:
    # GetNodeInfo's response nests NodeStatus, SoftwareVersion and HardwareVersion
    assert _known_signatures()["uavcan.protocol.GetNodeInfo"] == 0xEE468A8121C46A9E


def test_image_crc_is_the_check_value() -> None:
    assert crc.crc64we(b"123456789") == CHECK
    assert image_crc_module.crc64we(b"123456789") == CHECK
    assert image_crc(b"123456789") == CHECK
    assert crc.crc64we(b"6789", crc.crc64we(b"12345")) == CHECK
    assert crc.crc64we(b"") == 0
