"""The reassembler's and the codecs' less travelled paths, each pinned to exact outcomes,
and proof that the generated fast paths are the ones taken for ordinary input."""

from __future__ import annotations

import dataclasses
from binascii import crc_hqx
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from tests.dsdl_support import write_namespace

import dronecan as reference
from veronte4x import dronecan
from veronte4x.dronecan import Problem, TransferKind
from veronte4x.dronecan import codec as dronecan_codec
from veronte4x.dronecan import messages as dronecan_messages
from veronte4x.dronecan import transfer as transfer_module
from veronte4x.dronecan.crc import crc16
from veronte4x.dronecan.definitions import DATA_TYPES, NESTED_SIGNATURES
from veronte4x.dronecan.float16 import float16_bits
from veronte4x.dronecan.serializer import Serializer
from veronte4x.dronecan.tail import split_payload

OK = dronecan.Health.OK
OPERATIONAL = dronecan.Mode.OPERATIONAL
ESC = dronecan.EscStatus(3, 24.5, 12.25, 310.0, 4321, 55, 2)


def _frames(message: Any, source: int = 10, tid: int = 0, **kwargs: Any) -> list[tuple[int, bytes]]:
    return [
        (f.can_id, f.data)
        for f in dronecan.encode(message, source_node_id=source, transfer_id=tid, **kwargs)
    ]


def _lost(r: dronecan.Reassembler) -> int:
    return sum(r.counts[p] for p in dronecan.TRANSFER_PROBLEMS)


def test_a_short_first_frame_loses_its_transfer_once() -> None:
    r = dronecan.Reassembler(strict=True)
    (c, first), *rest = _frames(ESC)
    assert r.feed(c, first[:5] + first[-1:], 0.0) is None
    assert [r.feed(c, d, 0.0) for c, d in rest] == [None, None]  # silent, not MISSED_START
    assert r.counts[Problem.MALFORMED_FRAME] == 1
    assert _lost(r) == 0
    assert r.problems[-1].detail == "short first frame"
    assert r.feed(*_frames(ESC, tid=1)[0], 0.1) is None  # the next transfer is fine
    assert [r.feed(c, d, 0.1) for c, d in _frames(ESC, tid=1)[1:]][-1] is not None


def test_a_short_middle_frame_loses_its_transfer_once() -> None:
    r = dronecan.Reassembler(strict=True)
    frames = _frames(ESC)
    c, middle = frames[1]
    assert r.feed(*frames[0], 0.0) is None
    assert r.feed(c, middle[:3] + middle[-1:], 0.0) is None
    assert r.feed(*frames[2], 0.0) is None
    assert r.counts[Problem.MALFORMED_FRAME] == 1
    assert sum(r.counts.values()) == 1


@pytest.mark.parametrize("size", [9, 10])
def test_a_last_frame_of_more_than_8_bytes_is_refused(size: int) -> None:
    r = dronecan.Reassembler()
    frames = _frames(ESC)
    c, last = frames[-1]
    for frame in frames[:-1]:
        assert r.feed(*frame, 0.0) is None
    long_last = last[:-1] + bytes(size - len(last)) + last[-1:]
    assert r.feed(c, long_last, 0.0) is None
    assert r.counts[Problem.MALFORMED_FRAME] == 1
    assert r.transfers == 0


def test_a_first_frame_interrupts_the_transfer_in_progress() -> None:
    r = dronecan.Reassembler()
    first = _frames(ESC, tid=4)
    second = _frames(dronecan.EscStatus(1, 1.0, 2.0, 3.0, 4, 5, 6), tid=5)
    assert r.feed(*first[0], 0.0) is None
    assert r.feed(*first[1], 0.0) is None
    out = [r.feed(c, d, 0.01) for c, d in second]
    assert r.counts[Problem.INTERRUPTED] == 1
    assert r.problems[-1].detail == "transfer id 4"
    assert out[-1] is not None
    assert out[-1].message.error_count == 1
    assert out[-1].timestamp == 0.01


def test_the_checked_path_delivers_exactly_like_the_fast_one() -> None:
    """bytearray frames take the full state update for every frame."""
    slow, fast = dronecan.Reassembler(), dronecan.Reassembler()
    for tid in range(40):
        for c, d in _frames(ESC, tid=tid % 32) + _frames(
            dronecan.RawCommand(tuple(range(tid % 20))), tid=tid % 32
        ):
            a = slow.feed(c, bytearray(d), tid * 0.01)
            b = fast.feed(c, d, tid * 0.01)
            assert a == b
    assert slow.transfers == fast.transfers == 80
    assert sum(slow.counts.values()) == 0


def test_a_payload_the_generated_decoder_refuses_goes_to_the_checked_decoder() -> None:
    """A 3-frame transfer of esc.Status one byte short: the checked decoder decides."""
    codec = dronecan_codec.BY_CLASS[dronecan.EscStatus]
    payload = codec.encode(ESC, False)[:-1]
    can_id = dronecan.message_can_id(16, 1034, 10)
    datas = split_payload(payload, crc_hqx(payload, codec.crc_seed), 0)
    r = dronecan.Reassembler()
    assert [r.feed(can_id, d, 0.0) for d in datas] == [None] * len(datas)
    assert r.counts[Problem.BAD_PAYLOAD] == 1
    with pytest.raises(dronecan.DecodeError) as error:
        dronecan.decode_payload(TransferKind.MESSAGE, 1034, payload)
    assert r.problems[-1].detail == str(error.value)


def test_the_session_whose_latest_transfer_began_first_is_evicted() -> None:
    r = dronecan.Reassembler(max_sessions=2)
    a, b, c = (_frames(ESC, source=s) for s in (1, 2, 3))
    assert r.feed(*a[0], 0.0) is None
    assert r.feed(*b[0], 0.1) is None
    a_next = _frames(ESC, source=1, tid=1)
    assert r.feed(*a_next[0], 0.2) is None  # interrupts a's transfer 0: a is now the newer
    assert r.counts[Problem.INTERRUPTED] == 1
    assert r.feed(*c[0], 0.3) is None  # the table is full: b goes
    assert r.counts[Problem.EVICTED] == 1
    assert r.problems[-1].can_id == b[0][0] & 0xFFFFFF
    assert [r.feed(cid, d, 0.3) for cid, d in a_next[1:]][-1] is not None
    assert [r.feed(cid, d, 0.3) for cid, d in c[1:]][-1] is not None
    assert r.session_count == 2


def test_a_timed_out_session_is_dropped_before_an_active_one_and_counted_as_timeout() -> None:
    r = dronecan.Reassembler(max_sessions=2)
    old, fresh, new = (_frames(ESC, source=s) for s in (1, 2, 3))
    r.feed(*old[0], 0.0)
    r.feed(*fresh[0], 2.5)
    r.feed(*new[0], 3.0)  # old (idle since 0.0) goes, as a timeout
    assert r.counts[Problem.TIMEOUT] == 1
    assert r.counts[Problem.EVICTED] == 0
    assert [r.feed(c, d, 3.0) for c, d in fresh[1:]][-1] is not None


def test_anonymous_can_id_refuses_priority_32() -> None:
    assert dronecan.anonymous_can_id(31, 3, 0x3FFF) == 0x1FFFFF00
    with pytest.raises(dronecan.EncodeError):
        dronecan.anonymous_can_id(32, 0, 0)
    for args in ((0, 4, 0), (0, 0, 1 << 14), (-1, 0, 0)):
        with pytest.raises(dronecan.EncodeError):
            dronecan.anonymous_can_id(*args)


@pytest.mark.parametrize("priority", [0, 7, 31])
def test_decode_frames_returns_source_destination_and_priority(priority: int) -> None:
    for message, destination in (
        (dronecan.NodeStatus(1, OK, OPERATIONAL, 0, 0), None),
        (ESC, None),
        (dronecan.GetNodeInfoRequest(), 99),
        (dronecan.GetSetRequest(name=b"x" * 20), 98),
    ):
        frames = _frames(
            message, source=77, tid=9, priority=priority, destination_node_id=destination
        )
        t = dronecan.decode_frames(frames, timestamp=1.5)
        assert t.message == message
        assert t.source_node_id == 77
        assert t.destination_node_id == destination
        assert t.priority == priority
        assert t.transfer_id == 9
        assert t.timestamp == 1.5
        checked = transfer_module._decode_frames_checked(frames, 1.5)
        assert t == checked


@pytest.mark.parametrize(
    ("units", "bits"),
    [
        (2.5, 0x0003),  # a tie rounds away from zero
        (2.5 - 2**-16, 0x0002),  # just below the tie rounds down
        (3.5 - 2**-16, 0x0003),
        (0.5, 0x0001),  # half the smallest subnormal rounds up
        (0.5 - 2**-16, 0x0000),  # just below it underflows
        (1023.5 - 2**-12, 0x03FF),  # the largest subnormal, just below the tie
        (1023.5, 0x0400),  # the tie rounds up into the normal range
    ],
)
def test_float16_subnormals_round_just_below_a_tie(units: float, bits: int) -> None:
    value = units * 2**-24
    assert float16_bits(value) == bits
    assert float16_bits(-value) == bits | 0x8000
    # The generated encoder of Temperature gives the same bits.
    message = dronecan.Temperature(1, value, 0)
    ((_, data),) = _frames(message)
    assert int.from_bytes(data[2:4], "little") == bits


def _refuse(*args: Any, **kwargs: Any) -> Any:
    raise AssertionError("the checked path was called")


FAST_MESSAGES = [
    dronecan.NodeStatus(123456, OK, OPERATIONAL, 0, 0),
    ESC,
    dronecan.Temperature(3, 301.5, 0),
    dronecan.RawCommand((1000, -2000, 8191, 0)),
    dronecan.RawCommand(tuple(range(20))),
    dronecan.EscStatus(3, 24.5, -12.25, 310.0, -4321, 55, 2),  # negative: masked, not refused
]


@pytest.mark.parametrize("message", FAST_MESSAGES, ids=lambda m: type(m).__name__)
def test_ordinary_messages_take_the_fast_paths(
    message: Any, monkeypatch: pytest.MonkeyPatch
) -> None:
    frames = _frames(message)
    r = dronecan.Reassembler()
    first = [r.feed(c, d, 0.0) for c, d in frames]  # opens the session
    assert first[-1] is not None
    monkeypatch.setattr(transfer_module, "_encode_checked", _refuse)
    monkeypatch.setattr(transfer_module, "_decode_frames_checked", _refuse)
    monkeypatch.setattr(Serializer, "decode", _refuse)
    monkeypatch.setattr(Serializer, "encode", _refuse)
    monkeypatch.setattr(r, "_feed", _refuse)
    frames = _frames(message, tid=1)
    assert dronecan.decode_frames(frames).message == message
    out = [r.feed(c, d, 0.1) for c, d in frames]
    assert out[-1] is not None
    assert out[-1].message == message


@pytest.mark.parametrize("epoch", [0.0, 1.7e9])
@pytest.mark.parametrize("kind", [bytes, bytearray], ids=["fast", "checked"])
def test_timeouts_at_any_epoch(epoch: float, kind: type) -> None:
    """Capture timestamps are often seconds since 1970: only differences may count."""
    r = dronecan.Reassembler(strict=True)
    frames = _frames(ESC, tid=3)
    assert [r.feed(c, kind(d), epoch + 0.5 * i) for i, (c, d) in enumerate(frames)][-1]
    late = _frames(ESC, tid=4)
    assert r.feed(late[0][0], kind(late[0][1]), epoch + 10.0) is None
    assert r.feed(late[1][0], kind(late[1][1]), epoch + 11.9) is None
    assert r.feed(late[2][0], kind(late[2][1]), epoch + 12.1) is None  # 2.1 s after its start
    assert r.counts[Problem.TIMEOUT] == 1
    assert r.expire(epoch + 14.0) == 0  # the timed-out frame silences its transfer until then
    assert r.expire(epoch + 14.2) == 1
    again = _frames(ESC, tid=4)  # the same transfer id, long after: accepted
    out = [r.feed(c, kind(d), epoch + 20.0) for c, d in again]
    assert out[-1] is not None
    assert out[-1].timestamp == epoch + 20.0
    assert sum(r.counts.values()) == 1


_TRANSFERS = st.sampled_from(
    [
        dronecan.NodeStatus(1, OK, OPERATIONAL, 0, 7),
        ESC,
        dronecan.Temperature(3, 301.5, 0),
        dronecan.RawCommand((1, -2, 3)),
        dronecan.RawCommand(tuple(range(12))),
        dronecan.GetNodeInfoRequest(),
        dronecan.RestartNodeRequest(0xACCE551B1E),
        dronecan.GetSetRequest(name=b"abc"),
    ]
)


@st.composite
def _damaged(draw: st.DrawFn) -> tuple[list[tuple[int, bytes]], float]:
    """The frames of one transfer, perhaps with a changed CAN ID, tail, length or order."""
    message = draw(_TRANSFERS)
    service = not isinstance(
        message,
        (dronecan.NodeStatus, dronecan.EscStatus, dronecan.Temperature, dronecan.RawCommand),
    )
    frames = _frames(
        message,
        source=draw(st.integers(1, 127)),
        tid=draw(st.integers(0, 31)),
        priority=draw(st.integers(0, 31)),
        destination_node_id=draw(st.integers(1, 127)) if service else None,
    )
    for _ in range(draw(st.integers(0, 2))):
        index = draw(st.integers(0, len(frames) - 1))
        can_id, data = frames[index]
        change = draw(st.sampled_from(["id", "tail", "bit", "cut", "grow", "drop", "swap"]))
        if change == "id":
            can_id ^= 1 << draw(st.integers(0, 30))
        elif change == "tail":
            data = data[:-1] + bytes([draw(st.integers(0, 255))])
        elif change == "bit" and data:
            bit = draw(st.integers(0, 8 * len(data) - 1))
            data = bytes(b ^ (1 << bit % 8) if i == bit // 8 else b for i, b in enumerate(data))
        elif change == "cut":
            data = data[1:]
        elif change == "grow":
            data = b"\x00" + data
        elif change == "drop" and len(frames) > 1:
            del frames[index]
            continue
        elif change == "swap" and index + 1 < len(frames):
            frames[index], frames[index + 1] = frames[index + 1], frames[index]
            continue
        frames[index] = (can_id, data)
    return frames, draw(st.sampled_from([0.0, 1.5, 1.7e9]))


def _decoded(function: Any, frames: Any, timestamp: float) -> Any:
    try:
        return function(frames, timestamp)
    except dronecan.DecodeError as error:
        return str(error)


@settings(max_examples=500)
@given(case=_damaged())
def test_decode_frames_fast_path_agrees_with_the_checked_path(
    case: tuple[list[tuple[int, bytes]], float],
) -> None:
    frames, timestamp = case
    fast = _decoded(dronecan.decode_frames, frames, timestamp)
    checked = _decoded(transfer_module._decode_frames_checked, frames, timestamp)
    assert fast == checked


@pytest.mark.parametrize("extra", [1 << 29, 1 << 30, 1 << 31, -(1 << 29)])
@pytest.mark.parametrize("message", [ESC, dronecan.NodeStatus(1, OK, OPERATIONAL, 0, 7)])
def test_decode_frames_refuses_can_ids_beyond_29_bits(extra: int, message: Any) -> None:
    frames = [(can_id + extra, data) for can_id, data in _frames(message)]
    with pytest.raises(dronecan.DecodeError, match="is not a 29-bit value"):
        dronecan.decode_frames(frames)


def test_the_generic_serializer_takes_bools_only_for_bool_fields() -> None:
    """saturate=True goes through the generic serializer, as do the types without fast paths."""
    for saturate in (False, True):
        for ok, wire in ((True, "80c4"), (False, "00c4")):
            frames = dronecan.encode(
                dronecan.RestartNodeResponse(ok),
                source_node_id=2,
                destination_node_id=1,
                transfer_id=4,
                saturate=saturate,
            )
            assert frames[0].data == bytes.fromhex(wire)
        with pytest.raises(dronecan.EncodeError, match="an int for"):
            dronecan.encode(
                dronecan.NodeStatus(True, OK, OPERATIONAL, 0, 0),
                source_node_id=1,
                transfer_id=0,
                saturate=saturate,
            )
    with pytest.raises(dronecan.EncodeError, match="an int for"):
        dronecan.encode(
            dronecan.GetSetRequest(index=True),
            source_node_id=1,
            destination_node_id=2,
            transfer_id=0,
        )


def test_can_id_layouts_have_29_bits() -> None:
    for name, fields in dronecan.can_id.LAYOUTS.items():
        assert sum(width for _, width, _ in fields) == 29, name


def test_signatures_and_crc_seeds_match_the_dronecan_package() -> None:
    """Every type's signature, including those whose transfers always fit one frame."""
    for data_type in DATA_TYPES:
        theirs = reference.TYPENAMES[data_type.full_name]
        assert data_type.signature == theirs.get_data_type_signature(), data_type.full_name
        assert data_type.crc_seed == theirs.base_crc, data_type.full_name
        seed = crc16(data_type.signature.to_bytes(8, "little"), 0xFFFF)
        assert data_type.crc_seed == seed, data_type.full_name


@pytest.mark.parametrize(
    ("message", "destination"),
    [
        (dronecan.NodeStatus(1, OK, OPERATIONAL, 0, 7), None),
        (dronecan.GetNodeInfoRequest(), 42),
        (dronecan.RestartNodeResponse(True), 43),
    ],
)
def test_a_frame_that_opens_a_session_takes_the_lean_path(
    message: Any, destination: int | None, monkeypatch: pytest.MonkeyPatch
) -> None:
    r = dronecan.Reassembler(max_sessions=1)
    monkeypatch.setattr(r, "_feed", _refuse)
    for source in (5, 6, 7):  # each one opens a session and evicts the previous one
        ((can_id, data),) = _frames(message, source=source, tid=3, destination_node_id=destination)
        t = r.feed(can_id, data, 0.0)
        assert t is not None
        assert (t.message, t.source_node_id, t.destination_node_id) == (
            message,
            source,
            destination,
        )
        assert (t.priority, t.transfer_id) == (16, 3)
    assert r.session_count == 1


_VALUES = st.one_of(
    st.none(),
    st.booleans(),
    st.integers(-(2**40), 2**40),
    st.integers(-20000, 70000),
    st.floats(),
    st.floats(-70000, 70000, width=32),
    st.text(max_size=2),
    st.lists(st.integers(-9000, 9000), max_size=21).map(tuple),
    st.lists(st.booleans(), max_size=3).map(tuple),
)
_FAST_MESSAGES = [
    dronecan.NodeStatus(5, OK, OPERATIONAL, 0, 7),
    ESC,
    dronecan.Temperature(3, 301.5, 0),
    dronecan.RawCommand((1, -2, 3)),
    dronecan.RestartNodeRequest(0xACCE551B1E),
    dronecan.RestartNodeResponse(True),
]


@pytest.mark.parametrize("valid", _FAST_MESSAGES, ids=lambda m: type(m).__name__)
@settings(max_examples=150)
@given(data=st.data())
def test_generated_encoders_agree_with_the_generic_serializer(valid: Any, data: Any) -> None:
    """A valid message with one field replaced by anything."""
    cls = type(valid)
    field = data.draw(st.sampled_from([f.name for f in dataclasses.fields(cls)]))
    message = dataclasses.replace(valid, **{field: data.draw(_VALUES, label=field)})
    codec = dronecan_codec.BY_CLASS[cls]
    generic = Serializer(codec.data_type.schema)

    def outcome(encode: Any) -> Any:
        try:
            return encode(message, False)
        except dronecan.EncodeError as error:
            return str(error)

    assert outcome(codec.encode) == outcome(generic.encode)


def test_can_id_zero_parses() -> None:
    assert dronecan.parse_can_id(0) == dronecan.CanId(0, TransferKind.MESSAGE, 0, 0, None, 0)
    assert dronecan.parse_can_id(0x1FFFFFFF).priority == 31


def test_enum_values_are_the_dsdl_constants() -> None:
    status = reference.uavcan.protocol.NodeStatus()
    for member in dronecan.Health:
        assert member.value == getattr(status, f"HEALTH_{member.name}")
    for mode in dronecan.Mode:
        assert mode.value == getattr(status, f"MODE_{mode.name}")


def test_the_defaults() -> None:
    r = dronecan.Reassembler()
    assert (r.timeout, r.max_sessions, r.problems.maxlen) == (2.0, 1024, 256)


@pytest.mark.parametrize("kind", [bytes, bytearray], ids=["fast", "checked"])
def test_a_transfer_repeated_at_exactly_the_timeout_is_still_a_repeat(kind: type) -> None:
    r = dronecan.Reassembler(strict=True)
    ((can_id, frame),) = _frames(dronecan.NodeStatus(1, OK, OPERATIONAL, 0, 7))
    data = kind(frame)
    assert r.feed(can_id, data, 10.0) is not None
    assert r.feed(can_id, data, 11.0) is None
    assert r.feed(can_id, data, 12.0) is None
    assert r.counts[Problem.DUPLICATE_FRAME] == 2
    out = r.feed(can_id, data, 12.5)  # past the timeout: a new transfer
    assert out is not None
    assert out.timestamp == 12.5


def test_an_active_session_evicted_late_in_time_counts_as_evicted() -> None:
    r = dronecan.Reassembler(max_sessions=1)
    assert r.feed(*_frames(ESC, source=1)[0], 100.0) is None
    assert r.feed(*_frames(ESC, source=2)[0], 100.5) is None
    assert r.counts[Problem.EVICTED] == 1
    assert sum(r.counts.values()) == 1


@pytest.mark.parametrize("kind", [bytes, bytearray], ids=["fast", "checked"])
def test_a_payload_one_byte_too_long_is_refused_at_its_last_frame(kind: type) -> None:
    """NodeStatus has 7 bytes: 8 with a good CRC are PAYLOAD_TOO_LONG, not BAD_PAYLOAD."""
    payload = bytes(range(8))
    seed = dronecan_codec.BY_CLASS[dronecan.NodeStatus].crc_seed
    first, last = split_payload(payload, crc_hqx(payload, seed), 0)
    can_id = dronecan.message_can_id(16, 341, 10)
    r = dronecan.Reassembler()
    assert r.feed(can_id, kind(first), 0.0) is None
    assert r.feed(can_id, kind(last), 0.0) is None
    assert r.counts[Problem.PAYLOAD_TOO_LONG] == 1
    assert sum(r.counts.values()) == r.reported == 1
    assert r.problems[-1].data == last


_MESSAGE_CLASSES = [
    cls
    for cls in vars(dronecan_messages).values()
    if isinstance(cls, type)
    and dataclasses.is_dataclass(cls)
    and cls.__module__ == dronecan_messages.__name__
]


@pytest.mark.parametrize("cls", _MESSAGE_CLASSES, ids=lambda cls: cls.__name__)
def test_every_message_class_is_a_frozen_slotted_dataclass(cls: type) -> None:
    assert cls.__dataclass_params__.frozen  # type: ignore[attr-defined]
    assert "__slots__" in vars(cls)


def test_nested_signatures_match_the_dronecan_package() -> None:
    for name, signature in NESTED_SIGNATURES.items():
        assert reference.TYPENAMES[name].get_data_type_signature() == signature, name


_PROTOCOL = "uavcan.protocol."


@pytest.mark.parametrize(
    ("enum", "type_name", "part", "prefix"),
    [
        (
            dronecan.FirmwareUpdateError,
            _PROTOCOL + "file.BeginFirmwareUpdate",
            "response_constants",
            "ERROR_",
        ),
        (dronecan_messages.FileError, _PROTOCOL + "file.Error", "constants", ""),
        (
            dronecan_messages.Opcode,
            _PROTOCOL + "param.ExecuteOpcode",
            "request_constants",
            "OPCODE_",
        ),
        (dronecan_messages.EntryTypeFlag, _PROTOCOL + "file.EntryType", "constants", "FLAG_"),
        (
            dronecan_messages.TemperatureErrorFlag,
            "uavcan.equipment.device.Temperature",
            "constants",
            "ERROR_FLAG_",
        ),
        (
            dronecan_messages.SoftwareVersionFlag,
            _PROTOCOL + "SoftwareVersion",
            "constants",
            "OPTIONAL_FIELD_FLAG_",
        ),
    ],
    ids=lambda value: getattr(value, "__name__", None),
)
def test_more_enum_values_are_the_dsdl_constants(
    enum: Any, type_name: str, part: str, prefix: str
) -> None:
    constants = getattr(reference.TYPENAMES[type_name], part)
    ours = {prefix + member.name: member.value for member in enum}
    assert ours == {constant.name: constant.value for constant in constants}


_CONSTANTS_PARTS = {
    TransferKind.MESSAGE: "constants",
    TransferKind.REQUEST: "request_constants",
    TransferKind.RESPONSE: "response_constants",
}
_CONSTANT_HOLDERS = [
    *((t.schema.cls, t.full_name, _CONSTANTS_PARTS[t.kind]) for t in DATA_TYPES),
    (dronecan_messages.SoftwareVersion, "uavcan.protocol.SoftwareVersion", "constants"),
    (dronecan_messages.Path, "uavcan.protocol.file.Path", "constants"),
]


@pytest.mark.parametrize(
    ("cls", "type_name", "part"),
    _CONSTANT_HOLDERS,
    ids=lambda value: getattr(value, "__name__", None),
)
def test_class_constants_are_the_dsdl_constants(cls: type, type_name: str, part: str) -> None:
    ours = {name: value for name, value in vars(cls).items() if name.isupper()}
    theirs = {c.name: c.value for c in getattr(reference.TYPENAMES[type_name], part)}
    shared = ours.keys() & theirs.keys()  # file.Read's MAX_DATA is this package's own
    assert {name: ours[name] for name in shared} == {name: theirs[name] for name in shared}


def test_a_trailing_array_with_a_partial_item_is_refused() -> None:
    with pytest.raises(dronecan.DecodeError) as error:
        dronecan.decode_payload(TransferKind.MESSAGE, 1030, bytes(3))
    assert str(error.value) == (
        "uavcan.equipment.esc.RawCommand.cmd: 24 bits left, not a whole int14 (data: 00 00 00)"
    )


def test_a_union_value_of_no_member_type_is_refused() -> None:
    with pytest.raises(dronecan.EncodeError) as error:
        dronecan.encode(
            dronecan.GetSetRequest(value=3),  # type: ignore[arg-type]
            source_node_id=1,
            destination_node_id=2,
            transfer_id=0,
        )
    assert str(error.value) == (
        "uavcan.protocol.param.GetSet.Request.value = 3: "
        "expected one of Empty, IntegerValue, RealValue, BooleanValue, StringValue"
    )


def test_an_anonymous_frame_is_no_message_of_the_type_its_bits_resemble() -> None:
    """The fast path skips node id 0: anonymous type ids have two bits (here 341 & 3, the
    id of ``dynamic_node_id.Allocation``, which is what the frame decodes to)."""
    ((_, data),) = _frames(dronecan.NodeStatus(1, OK, OPERATIONAL, 0, 7))
    can_id = dronecan.anonymous_can_id(16, 341 & 3, 341 >> 2)
    transfer = dronecan.decode_frames([(can_id, data)])
    assert type(transfer.message).__name__ == "Allocation"


def test_valid_transport_values_skip_their_full_check(monkeypatch: pytest.MonkeyPatch) -> None:
    """The checked path (saturate=True) tests the common case inline first."""
    monkeypatch.setattr(transfer_module, "_check_transport", _refuse)
    for source, tid, priority in ((1, 0, 0), (127, 31, 31)):
        frames = dronecan.encode(
            ESC, source_node_id=source, transfer_id=tid, priority=priority, saturate=True
        )
        transfer = dronecan.decode_frames([(f.can_id, f.data) for f in frames])
        assert transfer.message == ESC
        assert (transfer.source_node_id, transfer.transfer_id, transfer.priority) == (
            source,
            tid,
            priority,
        )


def _decode_error(frames: list[tuple[int, bytes]]) -> str:
    with pytest.raises(dronecan.DecodeError) as error:
        dronecan.decode_frames(frames)
    return str(error.value)


def test_decode_frames_names_what_is_wrong() -> None:
    """The checked path's messages, exactly: a 9-byte last frame, a toggled tail, a CRC."""
    *head, (can_id, last) = _frames(ESC)
    (first_id, first), *rest = _frames(ESC)
    name = "uavcan.equipment.esc.Status"
    long_last = last[:-1] + bytes(9 - len(last)) + last[-1:]
    assert _decode_error([*head, (can_id, long_last)]) == (
        f"{name}: frame 2 has 9 bytes (data: 1b 88 00 00 00 00 00 00 40)"
    )
    assert _decode_error([*head, (can_id, last[:-1] + bytes([last[-1] ^ 0x20]))]) == (
        f"{name}: frame 2 tail byte 0x60, expected 0x40 (data: 1b 88 60)"
    )
    assert _decode_error([(first_id, bytes([first[0] ^ 1]) + first[1:]), *rest]) == (
        f"{name}.crc: transfer CRC 0x2254, computed 0x2255 "
        "(data: 54 22 03 00 00 00 20 4e 20 4a d8 5c e1 10 1b 88)"
    )
    assert _decode_error([]) == "frame: no frames (data: empty)"  # any count past 0 is taken
    assert _decode_error([(first_id, first[-1:]), *rest]) == (
        f"{name}: frame 0 has 1 byte (data: {first[-1]:02x})"
    )


def test_a_tail_array_of_at_most_one_struct_counts_one_item(tmp_path: Path) -> None:
    root = write_namespace(tmp_path, "tao", {"P": "uint8 k\n", "20950.One": "P[<=1] ps\n"})
    types = dronecan.TypeSet.standard().with_dsdl(root)
    codec = types.by_class[types["tao.One"]]
    assert codec.decode(b"\x01") == types["tao.One"](ps=(types["tao.P"](k=1),))
    with pytest.raises(dronecan.DecodeError) as error:
        codec.decode(b"\x01\x02")
    assert str(error.value) == "tao.One.ps: more than 1 item (tao.P[<=1]) (data: 01 02)"


def test_one_byte_too_many_is_one_byte() -> None:
    with pytest.raises(dronecan.DecodeError) as error:
        dronecan.decode_payload(TransferKind.MESSAGE, 341, bytes(8))
    assert str(error.value) == (
        "uavcan.protocol.NodeStatus: 1 byte left after the last field "
        "(data: 00 00 00 00 00 00 00 00)"
    )


def test_a_bool_field_takes_the_ints_0_and_1_only() -> None:
    """The fast encoder sends an int for a bool field to the generic serializer, which
    takes 0 and 1 as False and True."""
    datas = []
    for ok in (0, 1):
        frames = dronecan.encode(
            dronecan.RestartNodeResponse(ok),  # type: ignore[arg-type]
            source_node_id=2,
            destination_node_id=1,
            transfer_id=4,
        )
        datas.append(frames[0].data)
    assert datas == [bytes.fromhex("00c4"), bytes.fromhex("80c4")]
    with pytest.raises(dronecan.EncodeError) as error:
        dronecan.encode(
            dronecan.RestartNodeResponse(2),  # type: ignore[arg-type]
            source_node_id=2,
            destination_node_id=1,
            transfer_id=4,
        )
    assert str(error.value) == "uavcan.protocol.RestartNode.Response.ok = 2: expected a bool"
