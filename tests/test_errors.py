"""The error hierarchy: one base, and ValueError for decode and encode errors."""

import veronte4x
from veronte4x import DecodeError, EncodeError, UnknownCommandError, Veronte4xError, codec


def test_hierarchy() -> None:
    assert issubclass(DecodeError, Veronte4xError)
    assert issubclass(DecodeError, ValueError)
    assert issubclass(EncodeError, Veronte4xError)
    assert issubclass(EncodeError, ValueError)
    assert issubclass(UnknownCommandError, DecodeError)
    assert codec.DecodeError is DecodeError
    assert codec.EncodeError is EncodeError


def test_messages_name_type_field_and_bytes() -> None:
    err = DecodeError(
        "Status", "selected autopilot 5 out of range 0..3", b"\x00\xff\x05\x00", "selected"
    )
    assert str(err) == (
        "Status.selected: selected autopilot 5 out of range 0..3 (data: 00 ff 05 00)"
    )
    assert err.data == b"\x00\xff\x05\x00"
    enc = EncodeError("Score", "autopilot", 7, "an int in 0..3")
    assert str(enc) == "Score.autopilot = 7: expected an int in 0..3"
    unknown = UnknownCommandError(4, b"\x04\x01")
    assert unknown.command == 4
    assert unknown.data == b"\x04\x01"


def test_version_is_package_metadata() -> None:
    assert veronte4x.__version__ == "0.1.0"
