"""Golden vectors, both ways: bytes to message and message to bytes."""

import pytest

from veronte4x import codec
from veronte4x.codec import Sender, layouts
from veronte4x.codec.compiler import FrameLayout

ARB, AP = Sender.ARBITER, Sender.AUTOPILOT

STATUS_4X_ALL_OK = codec.Status(
    selected=1,
    arbitrating=True,
    alive=(True, True, True, False),
    ready=(True, True, True, False),
    **{name: True for name in codec.Status.__dataclass_fields__ if name.endswith("_ok")},
    normal_mode=True,
)

GOLDEN = [
    # Embention's 1x template (notes/veronte-protocol.md, test vectors).
    ("00ff01", AP, codec.Ready(ready=True)),
    ("00ff00", AP, codec.Ready(ready=False)),
    ("0000cdcccc3d", AP, codec.ArbitrationVariable(number=0, value=0.10000000149011612)),
    ("001f0000c0bf", AP, codec.ArbitrationVariable(number=31, value=-1.5)),
    ("000200000000", ARB, codec.Score(autopilot=2, score=0.0)),
    ("00030000803f", ARB, codec.Score(autopilot=3, score=1.0)),
    ("00ff8177ffff", ARB, STATUS_4X_ALL_OK),
    (
        "00ff0200",
        ARB,
        codec.Status(selected=2, arbitrating=False, alive=(False,) * 4, ready=(False,) * 4),
    ),
    ("01", ARB, codec.VersionRequest()),
    ("01", AP, codec.VersionRequest()),
    ("0109", AP, codec.VersionResponse(application_code=9)),
    ("010906010203", AP, codec.VersionResponse(application_code=9, rest=b"\x06\x01\x02\x03")),
    ("0223614589c7ab", ARB, codec.PwmSet(0, (0x123, 0x456, 0x789, 0xABC))),
    ("0dffffffffffff", AP, codec.PwmSet(16, (4095, 4095, 4095, 4095))),
    ("0b000000000000", AP, codec.PwmSet(8, (0, 0, 0, 0))),
    ("05", AP, codec.ScorpionEscTelemetry(payload=b"")),
    ("06" + "01" * 7, AP, codec.JetiEscTelemetry(payload=b"\x01" * 7)),
    ("07aa", AP, codec.JetiBecTelemetry1(payload=b"\xaa")),
    ("08aabb", AP, codec.JetiBecTelemetry2(payload=b"\xaa\xbb")),
    ("09000102", AP, codec.JetiTemperature(payload=b"\x00\x01\x02")),
    ("0a10", ARB, codec.McuCommand(payload=b"\x10")),
    ("10", ARB, codec.MaintenanceCommand(payload=b"")),
    ("1101", ARB, codec.StickSelection(payload=b"\x01")),
    ("12ffffffffffffff", AP, codec.McuTelemetry1(payload=b"\xff" * 7)),
    ("1300", AP, codec.McuTelemetry2(payload=b"\x00")),
]


@pytest.mark.parametrize(("hex_data", "sender", "message"), GOLDEN)
def test_decode(hex_data: str, sender: Sender, message: codec.Message) -> None:
    assert codec.decode(bytes.fromhex(hex_data), sender=sender) == message


@pytest.mark.parametrize(("hex_data", "sender", "message"), GOLDEN)
def test_encode(hex_data: str, sender: Sender, message: codec.Message) -> None:
    assert codec.encode(message) == bytes.fromhex(hex_data)


def test_issue_examples() -> None:
    msg = codec.decode(b"\x00\xff\x01", sender=codec.Sender.AUTOPILOT)
    assert msg == codec.Ready(ready=True)
    assert codec.encode(msg) == b"\x00\xff\x01"
    var = codec.decode(bytes.fromhex("0000cdcccc3d"), sender=codec.Sender.AUTOPILOT)
    assert var == codec.ArbitrationVariable(number=0, value=0.10000000149011612)
    assert codec.encode(codec.ArbitrationVariable(number=0, value=0.1)) == bytes.fromhex(
        "0000cdcccc3d"
    )


def test_same_bytes_differ_by_sender() -> None:
    data = bytes.fromhex("00010000803f")
    assert codec.decode(data, sender=ARB) == codec.Score(autopilot=1, score=1.0)
    assert codec.decode(data, sender=AP) == codec.ArbitrationVariable(number=1, value=1.0)


def test_unique_commands_ignore_sender() -> None:
    for hex_data, _, message in GOLDEN:
        data = bytes.fromhex(hex_data)
        if data[0] != 0:
            assert codec.decode(data, sender=ARB) == codec.decode(data, sender=AP) == message


def test_messages_are_frozen_slotted_and_hashable() -> None:
    msg = codec.Score(autopilot=1, score=0.5)
    with pytest.raises(AttributeError):
        msg.score = 1.0  # type: ignore[misc]
    assert not hasattr(msg, "__dict__")
    assert {msg, codec.Score(autopilot=1, score=0.5)} == {msg}
    assert all(isinstance(m, codec.Message) for _, _, m in GOLDEN)


FIXED_LAYOUTS = [
    layouts.READY,
    layouts.SCORE,
    layouts.STATUS_4X,
    layouts.STATUS_CEX,
    layouts.ARBITRATION_VARIABLE,
    layouts.VERSION_REQUEST,
    layouts.VERSION_RESPONSE,
    *layouts.OPAQUE.values(),
]


@pytest.mark.parametrize("layout", FIXED_LAYOUTS, ids=lambda layout: layout.name)
def test_each_message_class_is_frozen_and_its_command_is_its_layouts(layout: FrameLayout) -> None:
    cls = layout.message
    assert cls.__dataclass_params__.frozen  # type: ignore[attr-defined]
    assert layout.fields[0].label == "command"
    assert layout.fields[0].value == cls.COMMAND
