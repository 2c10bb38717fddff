"""The single-frame fast path of `decode_frames` (a route per CAN ID seen before) against
the checked path, on every type with a frame decoder.

Each case is decoded twice, so that the second call takes the route the first one left
(the route of a valid CAN ID is kept whatever its frame held), and both results must be
the checked path's: the same transfer, or the same error. Frames are drawn from valid
payloads and faults: payloads cut, extended or changed, arbitrary tail bytes, CAN IDs with
a bit flipped or node id 0, data as bytearray, timestamps that are not floats.
"""

from __future__ import annotations

import weakref
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from test_dronecan_compiled import _payloads, _same

from veronte4x import dronecan
from veronte4x.dronecan import transfer as transfer_module
from veronte4x.dronecan.can_id import TransferKind
from veronte4x.dronecan.codec import BY_CLASS, CODECS, TypeCodec
from veronte4x.dronecan.compiled import can_id_base
from veronte4x.dronecan.typeset import TypeSet

SINGLE = [c for c in CODECS if c.fast.decode_frame is not None]
_IDS = [f"{c.data_type.full_name}-{c.data_type.kind.name}" for c in SINGLE]


def _outcome(function: Any, *args: Any) -> Any:
    try:
        return function(*args)
    except (dronecan.DecodeError, TypeError) as error:
        return type(error), str(error)


def _checked(frames: Any, timestamp: Any) -> Any:
    return _outcome(
        lambda: transfer_module._decode_frames_checked(
            transfer_module._frame_list(frames), transfer_module._check_timestamp(timestamp)
        )
    )


@st.composite
def _frame(draw: st.DrawFn, codec: TypeCodec) -> tuple[int, Any, Any]:
    payload = draw(_payloads(codec))[:8]
    tail = draw(st.one_of(st.integers(0, 31).map(lambda t: 0xC0 | t), st.integers(0, 255)))
    data: Any = payload[:7] + bytes([tail]) if draw(st.integers(0, 9)) else payload
    can_id = draw(st.integers(0, 31)) << 24 | can_id_base(codec.data_type)
    can_id |= draw(st.integers(0, 127) if draw(st.integers(0, 9)) else st.just(0))
    if codec.data_type.kind is not TransferKind.MESSAGE:
        can_id |= draw(st.integers(0, 127)) << 8
    if not draw(st.integers(0, 9)):
        can_id ^= 1 << draw(st.integers(0, 31))
    if not draw(st.integers(0, 9)):
        data = bytearray(data)
    timestamp = draw(st.sampled_from([0.0, 1.5, 1.7e9, 2, None]))
    return can_id, data, timestamp


@pytest.mark.parametrize("codec", SINGLE, ids=_IDS)
@settings(max_examples=40)
@given(data=st.data())
def test_the_route_of_a_can_id_decodes_as_the_checked_path(
    codec: TypeCodec, data: st.DataObject
) -> None:
    can_id, payload, timestamp = data.draw(_frame(codec), label="frame")
    frames = [(can_id, payload)]
    expected = _checked(frames, timestamp)
    for _ in range(2):  # the first call may leave a route that the second one takes
        assert _same(_outcome(dronecan.decode_frames, frames, timestamp), expected)


def _fresh_routes(monkeypatch: pytest.MonkeyPatch) -> None:
    """Start from no routes; every route global is put back after the test."""
    monkeypatch.setattr(transfer_module, "_ROUTES_OF", weakref.WeakKeyDictionary())
    monkeypatch.setattr(transfer_module, "_ROUTES", transfer_module._Routes(TypeSet.standard()))


def test_the_routes_stay_bounded(monkeypatch: pytest.MonkeyPatch) -> None:
    """Past the bound every route is forgotten; decoding goes on the same."""
    monkeypatch.setattr(transfer_module, "_MAX_ROUTES", 3)
    _fresh_routes(monkeypatch)
    for source in range(1, 40):
        ((can_id, data),) = [
            (f.can_id, f.data)
            for f in dronecan.encode(
                dronecan.NodeStatus(source, dronecan.Health.OK, dronecan.Mode.OPERATIONAL, 0, 0),
                source_node_id=source,
                transfer_id=source % 32,
            )
        ]
        for _ in range(2):
            transfer = dronecan.decode_frames([(can_id, data)], 1.0)
            assert transfer == transfer_module._decode_frames_checked([(can_id, data)], 1.0)
        assert 1 <= len(transfer_module._ROUTES.single) <= 3


def test_a_known_can_id_takes_the_route(monkeypatch: pytest.MonkeyPatch) -> None:
    """Once a CAN ID was seen, its single frames decode without the type lookup."""
    _fresh_routes(monkeypatch)
    ((can_id, data),) = [
        (f.can_id, f.data)
        for f in dronecan.encode(
            dronecan.GetNodeInfoRequest(), source_node_id=9, destination_node_id=3, transfer_id=4
        )
    ]
    first = dronecan.decode_frames([(can_id, data)], 2.0)
    assert can_id in transfer_module._ROUTES.single

    def refuse(self: Any, can_id: int) -> None:
        raise AssertionError("looked the type up again")

    monkeypatch.setattr(transfer_module._Routes, "codec", refuse)
    assert dronecan.decode_frames([(can_id, data)], 2.0) == first
    assert first == (dronecan.GetNodeInfoRequest(), 9, 3, 16, 4, 2.0, TransferKind.REQUEST, 1)


def _without(kind: TransferKind, data_type_id: int) -> TypeSet:
    """The standard set less one type."""
    codecs = tuple(
        c for c in CODECS if (c.data_type.kind, c.data_type.data_type_id) != (kind, data_type_id)
    )
    standard = TypeSet.standard()
    return TypeSet(
        codecs,
        standard.classes,
        standard._enums,
        standard._members,
        standard.definitions,
        (),
        standard._names,
        standard.units,
    )


@pytest.mark.parametrize("frames_of", ["NodeStatus", "esc.Status"])
def test_an_explicit_type_set_is_not_decoded_with_the_routes_of_another(frames_of: str) -> None:
    """The routes of the default set are not used for a set that lacks the type, nor for a
    ``types=`` that is no set; each set decodes as the checked path does with it."""
    if frames_of == "NodeStatus":
        message: Any = dronecan.NodeStatus(5, dronecan.Health.OK, dronecan.Mode.OPERATIONAL, 0, 0)
    else:
        message = dronecan.EscStatus(3, 24.5, 12.25, 310.0, 4321, 55, 2)
    frames = [(f.can_id, f.data) for f in dronecan.encode(message, source_node_id=9, transfer_id=1)]
    codec = BY_CLASS[type(message)]
    lacking = _without(codec.data_type.kind, codec.data_type.data_type_id)
    for _ in range(2):  # the routes of each set, made by the first round, used by the second
        assert dronecan.decode_frames(frames, 1.0).message == message
        with pytest.raises(dronecan.DecodeError, match="no message type with id"):
            dronecan.decode_frames(frames, 1.0, types=lacking)
        assert dronecan.decode_frames(frames, 1.0, types=TypeSet.standard()).message == message
        with pytest.raises(TypeError, match="types"):
            dronecan.decode_frames(frames, 1.0, types="uavcan")  # type: ignore[arg-type]


def test_an_explicit_type_set_encodes_only_its_own_types() -> None:
    """``encode(types=...)`` takes the class from that set, as the checked path does: a set
    that lacks it refuses it, and a ``types=`` that is no set is a TypeError."""
    message = dronecan.EscStatus(3, 24.5, 12.25, 310.0, 4321, 55, 2)
    codec = BY_CLASS[type(message)]
    lacking = _without(codec.data_type.kind, codec.data_type.data_type_id)
    expected = dronecan.encode(message, source_node_id=9, transfer_id=1)
    for _ in range(2):  # the default set's fast function made by the first round
        assert dronecan.encode(message, source_node_id=9, transfer_id=1) == expected
        got = dronecan.encode(message, source_node_id=9, transfer_id=1, types=TypeSet.standard())
        assert got == expected
        with pytest.raises(TypeError, match="message"):
            dronecan.encode(message, source_node_id=9, transfer_id=1, types=lacking)
        with pytest.raises(TypeError, match="types"):
            dronecan.encode(message, source_node_id=9, transfer_id=1, types="uavcan")  # type: ignore[arg-type]


@pytest.mark.parametrize("index", [0, 1, 2])
@pytest.mark.parametrize("kind", [float, bool])
def test_a_frame_id_that_is_no_int_is_refused_in_any_frame(index: int, kind: type) -> None:
    """Equal is not enough: a CAN ID of another type (1234.0 == 1234) is the checked
    path's TypeError in every frame, the first or a later one."""
    message = dronecan.EscStatus(3, 24.5, 12.25, 310.0, 4321, 55, 2)
    frames: list[Any] = [
        (f.can_id, f.data) for f in dronecan.encode(message, source_node_id=9, transfer_id=1)
    ]
    assert len(frames) == 3
    for _ in range(2):  # the second time along the route of the CAN ID
        assert dronecan.decode_frames(frames, 1.0).message == message
        can_id, data = frames[index]
        changed = list(frames)
        changed[index] = (kind(can_id) if kind is float else True, data)
        with pytest.raises(TypeError, match=rf"frames\[{index}\]\[0\]"):
            dronecan.decode_frames(changed, 1.0)
