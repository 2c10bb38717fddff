"""open_bus: python-can's settings from a file, arguments and options; errors in one line."""

from __future__ import annotations

from pathlib import Path

import can
import pytest

from veronte4x import codec
from veronte4x.canbus import BusOpenError, is_dronecan_frame, open_bus
from veronte4x.capture.can_messages import to_can_message


def test_a_config_file_then_arguments_then_options(tmp_path: Path) -> None:
    config = tmp_path / "can.ini"
    config.write_text("[default]\ninterface = virtual\nchannel = from_file\nbitrate = 250000\n")
    with open_bus(config_file=str(config)) as bus:
        assert bus.channel_info == "Virtual bus channel from_file"
    with open_bus(channel="given", config_file=str(config)) as bus:
        assert bus.channel_info == "Virtual bus channel given"
    options = {"channel": "option", "receive_own_messages": True}
    with open_bus("virtual", "given", options=options) as bus:
        assert bus.channel_info == "Virtual bus channel option"
        bus.send(can.Message(arbitration_id=1, data=b"\x01", is_extended_id=False))
        assert bus.recv(5.0) is not None  # receive_own_messages went through


def test_a_missing_or_unreadable_config_file_is_named(tmp_path: Path) -> None:
    missing = tmp_path / "none.ini"
    with pytest.raises(BusOpenError, match=r"^python-can configuration file '.*none\.ini' not"):
        open_bus(config_file=str(missing))
    no_section = tmp_path / "bad.ini"
    no_section.write_text("interface = virtual\n")
    with pytest.raises(BusOpenError, match=r"is not a UTF-8 INI file with a .default. section: "):
        open_bus(config_file=str(no_section))
    binary = tmp_path / "binary.ini"
    binary.write_bytes(b"[default]\ninterface = \xff\xfe\n")
    with pytest.raises(BusOpenError, match="is not a UTF-8 INI file"):
        open_bus(config_file=str(binary))


def test_a_bus_python_can_cannot_open_is_named() -> None:
    with pytest.raises(
        BusOpenError, match=r"^cannot open the CAN bus \(interface no_such, channel x\): "
    ):
        open_bus("no_such", "x")


def test_an_explicit_can_id_wins() -> None:
    message = to_can_message(codec.Ready(ready=True), can_id=0x42, timestamp=2.0, channel="c")
    assert (message.arbitration_id, message.timestamp, message.channel) == (0x42, 2.0, "c")


@pytest.mark.parametrize(
    ("kwargs", "expected"),
    [
        ({"is_extended_id": True, "data": b"\xc0"}, True),
        ({"is_extended_id": False, "data": b"\xc0"}, False),
        ({"is_extended_id": True, "is_remote_frame": True}, False),
        ({"is_extended_id": True, "is_error_frame": True, "data": b"\xc0"}, False),
        ({"is_extended_id": True, "is_fd": True, "data": b"\xc0"}, False),
        ({"is_extended_id": True, "data": b""}, False),
    ],
)
def test_what_can_be_a_dronecan_frame(kwargs: dict[str, object], expected: bool) -> None:
    assert is_dronecan_frame(can.Message(arbitration_id=0x1001, **kwargs)) is expected  # type: ignore[arg-type]
