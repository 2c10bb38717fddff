"""Bus maps: the defaults, roles, and TOML overrides with declared layouts."""

import re
from pathlib import Path

import pytest

from veronte4x import codec
from veronte4x.capture.busmap import BusMap, BusMapError, Role


def test_defaults_are_embentions_template_ids() -> None:
    bus = BusMap()
    assert bus.role(255, False) == (Role.ARBITER, None)
    assert [bus.role(i, False) for i in (8, 9, 10, 11)] == [
        (Role.AUTOPILOT, 0), (Role.AUTOPILOT, 1), (Role.AUTOPILOT, 2), (Role.AUTOPILOT, 3)
    ]  # fmt: skip
    assert bus.role(255, True) == (Role.DRONECAN, None)
    assert bus.role(12, False) == (Role.UNKNOWN, None)
    assert BusMap(dronecan=False).role(0x1004D42A, True) == (Role.UNKNOWN, None)


def test_toml_overrides(tmp_path: Path) -> None:
    path = tmp_path / "bus.toml"
    path.write_text(
        """
[veronte]
arbiter_id = 0x100
autopilot_ids = [0x101, 0x102, 0x103, 0x104]
pwm_packing = "msb_first"
allow_excess = true

[[veronte.layouts]]
command = 9
name = "CellTemperature"
byte_order = "big"
fields = [
    { kind = "unsigned", name = "sensor", bits = 4 },
    { kind = "signed", name = "celsius", bits = 12, scale = [-2048, 2047, -204.8, 204.7] },
    { kind = "constant", value = 0x81, bits = 8 },
]

[dronecan]
enabled = false
text = "binary"
strict_transfers = true
"""
    )
    bus = BusMap.from_toml(str(path))
    assert bus.arbiter_id == 0x100
    assert bus.role(0x102, False) == (Role.AUTOPILOT, 1)
    assert bus.pwm_packing is codec.PwmPacking.MSB_FIRST
    assert bus.allow_excess is True
    assert bus.dronecan is False
    assert bus.dronecan_text == "binary"
    assert bus.strict_transfers is True
    message = bus.codec().decode(bytes.fromhex("093ff681"), sender=codec.Sender.AUTOPILOT)
    assert type(message).__name__ == "CellTemperature"
    assert (message.sensor, round(message.celsius, 1)) == (3, -1.0)  # type: ignore[attr-defined]


@pytest.mark.parametrize(
    ("text", "error"),
    [
        ("[veronte]\nunknown = 1\n", "unknown key(s) in [veronte]: unknown"),
        ("[veronte]\narbiter_id = 'x'\n", "arbiter_id: 'x' is not a CAN ID"),
        ("[veronte]\nautopilot_ids = [1, 2]\n", "autopilot_ids needs 4 IDs"),
        ("[veronte]\nautopilot_ids = [1, 2, 3, 255]\n", "CAN ID 255 is given to two"),
        ("[veronte]\nextended = 1\n", "extended: 1 is not true or false"),
        ("[veronte]\npwm_packing = 'sideways'\n", "'sideways' is not one of lsb_first"),
        ("[[veronte.layouts]]\ncommand = 2\nname = 'X'\n", "command 2 has a public layout"),
        ("[dronecan]\ntext = 'utf-16'\n", "[dronecan] text: 'utf-16' is not one of string"),
        ("[dronecan]\ntext = 1\n", "[dronecan] text: 1 is not one of string, binary"),
        ("[dronecan]\nstrict_transfers = 1\n", "[dronecan] strict_transfers: 1 is not true"),
        ("x = [", "bus.toml"),
    ],
)
def test_bad_bus_maps(tmp_path: Path, text: str, error: str) -> None:
    path = tmp_path / "bus.toml"
    path.write_text(text)
    with pytest.raises(BusMapError, match=re.escape(error)):
        BusMap.from_toml(str(path)).codec()
