"""An update timeout that is not a finite number of seconds above 0 is refused before
anything is sent: a NaN one never gave a stalled update up (the node stayed in its
bootloader and the tool waited for ever), an infinite one neither, and 0 or less gave up
at once."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import can
import pytest

from veronte4x import dronecan
from veronte4x.client import FirmwareOptions, FirmwareUpdate, InvalidRequestError
from veronte4x.client.bus import BusClient
from veronte4x.client.files import FileRead

from .cli_support import bus_args, free_port, veronte4x

BAD = [math.nan, math.inf, -math.inf, 0, -1.0, True, "5", None]


@pytest.mark.parametrize("name", ["start_timeout", "read_timeout", "restart_timeout"])
@pytest.mark.parametrize("value", BAD)
def test_a_timeout_that_never_ends_or_ends_at_once_is_refused(name: str, value: Any) -> None:
    text = (
        f"the firmware update's {name} is {value!r}, not a finite number of seconds above 0; "
        "nothing was sent"
    )
    with pytest.raises(InvalidRequestError) as error:
        FirmwareOptions(**{name: value})
    assert str(error.value) == text
    with pytest.raises(InvalidRequestError) as error:
        FirmwareUpdate(21, b"fw", 600, 0.0, **{name: value})
    assert str(error.value) == text


def test_the_smallest_and_largest_timeouts_are_taken() -> None:
    tiny, huge = 2**-30, 1e300
    update = FirmwareUpdate(21, b"fw", 600, 0.0, start_timeout=tiny, read_timeout=huge)
    update.accepted(dronecan.BeginFirmwareUpdateResponse(0), 1.0)
    update.served(21, FileRead(b"fw", 0, 256, 600), 2.0)
    assert update.poll(1e299).phase.value == "reading"
    assert FirmwareOptions(tiny, tiny, tiny).restart_timeout == tiny


def test_a_client_refuses_a_nan_timeout_before_sending_anything() -> None:
    with (
        can.Bus(interface="virtual", channel="test-update-timeouts") as bus,
        can.Bus(interface="virtual", channel="test-update-timeouts") as spy,
    ):
        client = BusClient(bus)
        with pytest.raises(InvalidRequestError, match=r"^the firmware update's read_timeout"):
            client.update_firmware(21, b"image", read_timeout=math.nan)
        assert spy.recv(0.0) is None
        assert client.protocol.next_deadline() is None


def test_the_command_line_refuses_a_nan_read_timeout(tmp_path: Path) -> None:
    firmware = tmp_path / "esc.bin"
    firmware.write_bytes(bytes(2000))
    result = veronte4x(
        "esc", "update", "21", str(firmware), *bus_args(free_port()), "--read-timeout", "nan"
    )
    assert (result.returncode, result.stdout) == (2, "")
    assert result.stderr == (
        "veronte4x: the firmware update's read_timeout is nan, not a finite number of seconds "
        "above 0; nothing was sent\n"
    )
