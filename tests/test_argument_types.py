"""One policy for arguments of the wrong type, at every public entry point of the codecs:
a TypeError naming the function, the argument and the type expected. Bad bytes stay the
library's own errors (or counted problems in the reassembler)."""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import Any

import pytest

from veronte4x import codec, dronecan
from veronte4x.dronecan import TransferKind, vertiq
from veronte4x.errors import BytesLike

AP = codec.Sender.AUTOPILOT
STATUS = dronecan.NodeStatus(1, dronecan.Health.OK, dronecan.Mode.OPERATIONAL, 0, 0)
NODE_STATUS_ID = dronecan.message_can_id(16, 341, 5)
LAYOUT = codec.Layout(20, "Declared", [codec.unsigned("a", 8)])
SCALE = codec.Linear(0, 255, 0.0, 1.0)
GET_SET = dronecan.GetSetResponse(value=dronecan.IntegerValue(2), name=b"esc_index")


def _call(function: Callable[..., Any], *args: Any, **kwargs: Any) -> Callable[[], Any]:
    return lambda: function(*args, **kwargs)


CASES: list[tuple[str, Callable[[], Any], str]] = [
    # veronte4x.codec
    (
        "decode str",
        _call(codec.decode, "", sender=AP),
        "decode(): data must be bytes-like, not str",
    ),
    ("decode int", _call(codec.decode, 7, sender=AP), "decode(): data must be bytes-like, not int"),
    (
        "decode list",
        _call(codec.decode, [0, 255, 1], sender=AP),
        "data must be bytes-like, not list",
    ),
    ("decode list pwm", _call(codec.decode, [2, 0, 0, 0, 0, 0, 0], sender=AP), "not list"),
    ("decode sender", _call(codec.decode, b"\x00\xff\x01", sender="ap"), "sender must be a Sender"),
    ("decode sender pwm", _call(codec.decode, bytes(7), sender=None), "sender must be a Sender"),
    ("encode", _call(codec.encode, "x"), "encode(): message must be a Veronte message, not str"),
    (
        "Codec packing",
        _call(codec.Codec, pwm_packing="lsb_first"),
        "pwm_packing must be a PwmPacking",
    ),
    ("Codec layouts", _call(codec.Codec, layouts=[5]), "layouts must be Layout objects, not int"),
    (
        "decoder",
        _call(codec.DEFAULT_CODEC.decoder, "arbiter"),
        "decoder(): sender must be a Sender",
    ),
    (
        "Layout command",
        _call(codec.Layout, "5", "X", []),
        "Layout(): command must be an int, not str",
    ),
    ("Layout name", _call(codec.Layout, 5, 5, []), "Layout(): name must be a str, not int"),
    ("Layout fields", _call(codec.Layout, 5, "X", ["a"]), "fields must be Field objects, not str"),
    ("Layout order", _call(codec.Layout, 5, "X", [], "little"), "byte_order must be a ByteOrder"),
    ("Layout.decode", _call(LAYOUT.decode, "14"), "Layout.decode(): data must be bytes-like"),
    (
        "Layout.encode",
        _call(LAYOUT.encode, codec.Ready(True)),
        "message must be a Declared, not Ready",
    ),
    ("to_microseconds", _call(codec.to_microseconds, 1.5), "value must be an int, not float"),
    ("to_microseconds bound", _call(codec.to_microseconds, 1, "900"), "min_us must be a number"),
    (
        "from_microseconds",
        _call(codec.from_microseconds, "1500"),
        "pulse_us must be a number, not str",
    ),
    # veronte4x.codec fields
    ("constant value", _call(codec.constant, 1.0), "constant(): value must be an int, not float"),
    (
        "constant value bool",
        _call(codec.constant, True),
        "constant(): value must be an int, not bool",
    ),
    ("constant bits", _call(codec.constant, 1, "8"), "constant(): bits must be an int, not str"),
    (
        "constant description",
        _call(codec.constant, 1, 8, None),
        "constant(): description must be a str, not NoneType",
    ),
    (
        "constant name",
        _call(codec.constant, 1, 8, "", 3),
        "constant(): name must be a str, not int",
    ),
    ("skip bits", _call(codec.skip, 8.0), "skip(): bits must be an int, not float"),
    ("skip bits bool", _call(codec.skip, False), "skip(): bits must be an int, not bool"),
    ("unsigned name", _call(codec.unsigned, b"a", 8), "unsigned(): name must be a str, not bytes"),
    ("unsigned bits", _call(codec.unsigned, "a", "8"), "unsigned(): bits must be an int, not str"),
    (
        "unsigned scale",
        _call(codec.unsigned, "a", 8, (0, 255, 0.0, 1.0)),
        "unsigned(): scale must be a Linear or None, not tuple",
    ),
    (
        "unsigned description",
        _call(codec.unsigned, "a", 8, SCALE, 1),
        "unsigned(): description must be a str, not int",
    ),
    ("signed name", _call(codec.signed, None, 8), "signed(): name must be a str, not NoneType"),
    ("signed bits", _call(codec.signed, "a", True), "signed(): bits must be an int, not bool"),
    ("signed scale", _call(codec.signed, "a", 8, 2.0), "signed(): scale must be a Linear or None"),
    (
        "signed description",
        _call(codec.signed, "a", 8, None, ["x"]),
        "signed(): description must be a str, not list",
    ),
    ("float32 name", _call(codec.float32, 1), "float32(): name must be a str, not int"),
    (
        "float32 description",
        _call(codec.float32, "a", b""),
        "float32(): description must be a str, not bytes",
    ),
    (
        "Linear encoded_min",
        _call(codec.Linear, 0.0, 255, 0.0, 1.0),
        "Linear(): encoded_min must be an int, not float",
    ),
    (
        "Linear encoded_max",
        _call(codec.Linear, 0, "255", 0.0, 1.0),
        "Linear(): encoded_max must be an int, not str",
    ),
    (
        "Linear decoded_min",
        _call(codec.Linear, 0, 255, False, 1.0),
        "Linear(): decoded_min must be a number, not bool",
    ),
    (
        "Linear decoded_max",
        _call(codec.Linear, 0, 255, 0.0, "1"),
        "Linear(): decoded_max must be a number, not str",
    ),
    ("Field kind", _call(codec.Field, "unsigned", 8), "Field(): kind must be a FieldKind, not str"),
    (
        "Field bits",
        _call(codec.Field, codec.FieldKind.UNSIGNED, 8.0),
        "Field(): bits must be an int",
    ),
    (
        "Field attr",
        _call(codec.Field, codec.FieldKind.UNSIGNED, 8, 1),
        "Field(): attr must be a str or None, not int",
    ),
    (
        "Field index",
        _call(codec.Field, codec.FieldKind.UNSIGNED, 8, "a", "0"),
        "Field(): index must be an int or None, not str",
    ),
    (
        "Field value",
        _call(codec.Field, codec.FieldKind.CONSTANT, 8, value=True),
        "Field(): value must be an int, not bool",
    ),
    (
        "Field maximum",
        _call(codec.Field, codec.FieldKind.UNSIGNED, 8, "a", maximum=9.0),
        "Field(): maximum must be an int or None, not float",
    ),
    (
        "Field scale",
        _call(codec.Field, codec.FieldKind.UNSIGNED, 8, "a", scale=1),
        "Field(): scale must be a Linear or None, not int",
    ),
    (
        "Field description",
        _call(codec.Field, codec.FieldKind.UNSIGNED, 8, "a", description=None),
        "Field(): description must be a str, not NoneType",
    ),
    (
        "Field name",
        _call(codec.Field, codec.FieldKind.PADDING, 8, name=None),
        "Field(): name must be a str, not NoneType",
    ),
    (
        "Field mapping",
        _call(codec.Field, codec.FieldKind.MAPPED, 8, "a", mapping=[(0, "x")]),
        "Field(): mapping must be a tuple of (wire value, value) pairs, not list",
    ),
    # veronte4x.dronecan
    (
        "decode_payload payload",
        _call(dronecan.decode_payload, TransferKind.MESSAGE, 341, 7),
        "decode_payload(): payload must be bytes-like, not int",
    ),
    (
        "decode_payload kind",
        _call(dronecan.decode_payload, 0, 341, bytes(7)),
        "kind must be a TransferKind, not int",
    ),
    (
        "decode_payload id",
        _call(dronecan.decode_payload, TransferKind.MESSAGE, "341", bytes(7)),
        "data_type_id must be an int, not str",
    ),
    (
        "decode_frames id",
        _call(dronecan.decode_frames, [("1", b"\xc0")]),
        "decode_frames(): frames[0][0] must be an int, not str",
    ),
    (
        "decode_frames data",
        _call(dronecan.decode_frames, [(NODE_STATUS_ID, 7)]),
        "frames[0][1] must be bytes-like, not int",
    ),
    (
        "decode_frames pair",
        _call(dronecan.decode_frames, [NODE_STATUS_ID]),
        "frames[0] must be a (can_id, data) pair, not int",
    ),
    (
        "decode_frames frames",
        _call(dronecan.decode_frames, 5),
        "frames must be an iterable of (can_id, data) pairs, not int",
    ),
    (
        "decode_frames timestamp",
        _call(dronecan.decode_frames, [(NODE_STATUS_ID, bytes(7) + b"\xc0")], "0"),
        "timestamp must be a float, not str",
    ),
    (
        "encode message",
        _call(dronecan.encode, object(), source_node_id=1, transfer_id=0),
        "encode(): message must be a DroneCAN message",
    ),
    (
        "encode source",
        _call(dronecan.encode, STATUS, source_node_id=1.0, transfer_id=0),
        "source_node_id must be an int, not float",
    ),
    (
        "encode tid",
        _call(dronecan.encode, STATUS, source_node_id=1, transfer_id="0"),
        "transfer_id must be an int, not str",
    ),
    (
        "encode priority",
        _call(dronecan.encode, STATUS, source_node_id=1, transfer_id=0, priority=None),
        "priority must be an int, not NoneType",
    ),
    (
        "encode destination",
        _call(
            dronecan.encode,
            dronecan.GetNodeInfoRequest(),
            source_node_id=1,
            transfer_id=0,
            destination_node_id="2",
        ),
        "destination_node_id must be an int, not str",
    ),
    (
        "message_can_id",
        _call(dronecan.message_can_id, 0, 341.0, 1),
        "message_can_id(): data_type_id must be an int, not float",
    ),
    (
        "anonymous_can_id",
        _call(dronecan.anonymous_can_id, True, 1, 1),
        "anonymous_can_id(): priority must be an int, not bool",
    ),
    (
        "service_can_id request",
        _call(dronecan.service_can_id, 0, 1, 1, 1, 2),
        "service_can_id(): request must be a bool, not int",
    ),
    (
        "parse_can_id",
        _call(dronecan.parse_can_id, 1.0),
        "parse_can_id(): can_id must be an int, not float",
    ),
    (
        "feed data",
        _call(dronecan.Reassembler().feed, NODE_STATUS_ID, "x", 0.0),
        "Reassembler.feed(): data must be bytes-like, not str",
    ),
    (
        "feed can_id",
        _call(dronecan.Reassembler().feed, 1.5, b"\xc0", 0.0),
        "Reassembler.feed(): can_id must be an int, not float",
    ),
    (
        "feed timestamp",
        _call(dronecan.Reassembler().feed, NODE_STATUS_ID, b"\xc0", "0"),
        "timestamp must be a float, not str",
    ),
    (
        "expire",
        _call(dronecan.Reassembler().expire, None),
        "Reassembler.expire(): timestamp must be a float",
    ),
    (
        "Reassembler",
        _call(dronecan.Reassembler, max_sessions=1.5),
        "Reassembler(): max_sessions must be an int",
    ),
    (
        "from_builtin cls",
        _call(dronecan.from_builtin, ["NodeStatus"], {}),
        "from_builtin(): cls must be a DroneCAN message class, not list",
    ),
    (
        "from_builtin cls not DroneCAN",
        _call(dronecan.from_builtin, codec.Ready, {}),
        "from_builtin(): cls must be a DroneCAN message class, not type",
    ),
    (
        "from_builtin data",
        _call(dronecan.from_builtin, dronecan.NodeStatus, [1]),
        "from_builtin(): data must be a dict, not list",
    ),
    # veronte4x.dronecan.vertiq
    (
        "get_parameter name",
        _call(vertiq.get_parameter, b"esc_index"),
        "get_parameter(): name must be a str or Parameter, not bytes",
    ),
    (
        "set_parameter name",
        _call(vertiq.set_parameter, 3, 1),
        "set_parameter(): name must be a str or Parameter, not int",
    ),
    (
        "set_parameter value",
        _call(vertiq.set_parameter, "esc_index", [1]),
        "set_parameter(): value must be an int, float, bool, str, bytes or param.Value, not list",
    ),
    (
        "get_parameter_by_index index",
        _call(vertiq.get_parameter_by_index, True),
        "get_parameter_by_index(): index must be an int, not bool",
    ),
    (
        "is_end_of_parameters response",
        _call(vertiq.is_end_of_parameters, dronecan.GetSetRequest()),
        "is_end_of_parameters(): response must be a GetSetResponse, not GetSetRequest",
    ),
    (
        "discovered_parameters responses",
        _call(vertiq.discovered_parameters, None),
        "discovered_parameters(): responses must be a sequence of GetSetResponse, not NoneType",
    ),
    (
        "discovered_parameters responses[1]",
        _call(vertiq.discovered_parameters, [GET_SET, "x"]),
        "discovered_parameters(): responses[1] must be a GetSetResponse, not str",
    ),
    (
        "restart bootloader",
        _call(vertiq.restart, 1),
        "restart(): bootloader must be a bool, not int",
    ),
    (
        "throttle_to_raw str",
        _call(vertiq.throttle_to_raw, "0.5"),
        "throttle_to_raw(): throttle must be a float, not str",
    ),
    (
        "throttle_to_raw bool",
        _call(vertiq.throttle_to_raw, True),
        "throttle_to_raw(): throttle must be a float, not bool",
    ),
    (
        "raw_to_throttle raw",
        _call(vertiq.raw_to_throttle, 8191.0),
        "raw_to_throttle(): raw must be an int, not float",
    ),
    (
        "raw_command throttles",
        _call(vertiq.raw_command, 0.5),
        "raw_command(): throttles must be a sequence or mapping of floats, not float",
    ),
    (
        "raw_command throttles[1]",
        _call(vertiq.raw_command, [0.5, "0.5"]),
        "raw_command(): throttles[1] must be a float, not str",
    ),
    (
        "raw_command throttles value",
        _call(vertiq.raw_command, {3: None}),
        "raw_command(): throttles[3] must be a float, not NoneType",
    ),
    (
        "raw_command throttles keys",
        _call(vertiq.raw_command, {"3": 0.5}),
        "raw_command(): throttles keys must be ints, not str",
    ),
    (
        "raw_command throttles keys bool",
        _call(vertiq.raw_command, {True: 0.5}),
        "raw_command(): throttles keys must be ints, not bool",
    ),
    (
        "throttles command",
        _call(vertiq.throttles, (8191,)),
        "throttles(): command must be a RawCommand, not tuple",
    ),
]


@pytest.mark.parametrize(("name", "call", "message"), CASES, ids=[c[0] for c in CASES])
def test_wrong_type_is_a_type_error_naming_the_argument(
    name: str, call: Callable[[], Any], message: str
) -> None:
    with pytest.raises(TypeError, match=re.escape(message)):
        call()


def test_feed_with_a_known_session_refuses_wrong_types_too() -> None:
    r = dronecan.Reassembler()
    (frame,) = dronecan.encode(STATUS, source_node_id=5, transfer_id=0)
    assert r.feed(frame.can_id, frame.data, 0.0) is not None  # the session now exists
    (frame,) = dronecan.encode(STATUS, source_node_id=5, transfer_id=1)
    with pytest.raises(TypeError, match=r"timestamp must be a float, not str"):
        r.feed(frame.can_id, frame.data, "0.1")  # type: ignore[arg-type]
    with pytest.raises(TypeError, match=r"data must be bytes-like, not list"):
        r.feed(frame.can_id, list(frame.data), 0.1)  # type: ignore[arg-type]
    assert sum(r.counts.values()) == 0
    assert r.feed(frame.can_id, frame.data, 0.1) is not None


def test_bytes_like_data_is_accepted_everywhere() -> None:
    frames = dronecan.encode(dronecan.RawCommand(tuple(range(8))), source_node_id=5, transfer_id=0)
    kinds: tuple[Callable[[bytes], BytesLike], ...] = (bytes, bytearray, memoryview)
    for kind in kinds:
        assert codec.decode(kind(b"\x00\xff\x01"), sender=AP) == codec.Ready(True)
        assert dronecan.decode_frames([(f.can_id, kind(f.data)) for f in frames]).message.cmd == (
            tuple(range(8))
        )
        r = dronecan.Reassembler()
        out = [r.feed(f.can_id, kind(f.data), 0.0) for f in frames]
        assert out[-1] is not None
        assert out[-1].message.cmd == tuple(range(8))
        assert dronecan.decode_payload(TransferKind.MESSAGE, 341, kind(bytes(7))).uptime_sec == 0


def test_a_decode_error_on_odd_data_never_fails_itself() -> None:
    error = codec.DecodeError(None, "reason", "not bytes")  # type: ignore[arg-type]
    assert error.data == b""
    assert str(error) == "frame: reason (data: empty)"
