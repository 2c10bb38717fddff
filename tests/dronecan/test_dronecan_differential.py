"""Differential property tests against the ``dronecan`` package (the reference).

Random instances of every type, within their DSDL ranges, are encoded by both libraries:
the frames must be identical, and each library must decode the other's frames to equal
values. Infinity is left out: the ``dronecan`` package clamps it, the spec keeps it
(tested in test_dronecan_float16.py).
"""

from __future__ import annotations

from typing import Any

import pytest
from dronecan_oracle import (
    CLASS_OF,
    reference_builtin,
    reference_decode,
    reference_frames,
    reference_object,
)
from hypothesis import given
from hypothesis import strategies as st
from tests.plain_data import same
from tests.soak import differential

from veronte4x import dronecan
from veronte4x.dronecan.codec import BY_CLASS
from veronte4x.dronecan.definitions import DATA_TYPES
from veronte4x.dronecan.schema import Array, Struct, Union

K = dronecan.TransferKind


def _u(bits: int) -> st.SearchStrategy[int]:
    return st.integers(0, (1 << bits) - 1)


def _i(bits: int) -> st.SearchStrategy[int]:
    return st.integers(-(1 << (bits - 1)), (1 << (bits - 1)) - 1)


def _bytes(max_size: int) -> st.SearchStrategy[list[int]]:
    return st.lists(_u(8), max_size=max_size)


_F16 = st.one_of(
    st.floats(allow_infinity=False, width=64),
    st.floats(-70000, 70000),
    st.integers(-2048, 2048).map(lambda n: n / 8),
)
_F32 = st.floats(allow_infinity=False, allow_nan=False)


def _value(numeric: bool) -> st.SearchStrategy[dict[str, Any]]:
    members: list[st.SearchStrategy[dict[str, Any]]] = [
        st.just({"empty": {}}),
        _i(64).map(lambda v: {"integer_value": v}),
        _F32.map(lambda v: {"real_value": v}),
    ]
    if not numeric:
        members.append(_u(8).map(lambda v: {"boolean_value": v}))
        members.append(_bytes(128).map(lambda v: {"string_value": v}))
    return st.one_of(members)


_NODE_STATUS = st.fixed_dictionaries(
    {
        "uptime_sec": _u(32),
        "health": _u(2),
        "mode": _u(3),
        "sub_mode": _u(3),
        "vendor_specific_status_code": _u(16),
    }
)

STRATEGIES: dict[tuple[str, dronecan.TransferKind], st.SearchStrategy[dict[str, Any]]] = {
    ("uavcan.protocol.NodeStatus", K.MESSAGE): _NODE_STATUS,
    ("uavcan.equipment.esc.Status", K.MESSAGE): st.fixed_dictionaries(
        {
            "error_count": _u(32),
            "voltage": _F16,
            "current": _F16,
            "temperature": _F16,
            "rpm": _i(18),
            "power_rating_pct": _u(7),
            "esc_index": _u(5),
        }
    ),
    ("uavcan.equipment.device.Temperature", K.MESSAGE): st.fixed_dictionaries(
        {"device_id": _u(16), "temperature": _F16, "error_flags": _u(8)}
    ),
    ("uavcan.equipment.esc.RawCommand", K.MESSAGE): st.fixed_dictionaries(
        {"cmd": st.lists(_i(14), max_size=20)}
    ),
    ("uavcan.protocol.GetNodeInfo", K.REQUEST): st.just({}),
    ("uavcan.protocol.GetNodeInfo", K.RESPONSE): st.fixed_dictionaries(
        {
            "status": _NODE_STATUS,
            "software_version": st.fixed_dictionaries(
                {
                    "major": _u(8),
                    "minor": _u(8),
                    "optional_field_flags": _u(8),
                    "vcs_commit": _u(32),
                    "image_crc": _u(64),
                }
            ),
            "hardware_version": st.fixed_dictionaries(
                {
                    "major": _u(8),
                    "minor": _u(8),
                    "unique_id": st.lists(_u(8), min_size=16, max_size=16),
                    "certificate_of_authenticity": _bytes(255),
                }
            ),
            "name": _bytes(80),
        }
    ),
    ("uavcan.protocol.param.GetSet", K.REQUEST): st.fixed_dictionaries(
        {"index": _u(13), "value": _value(False), "name": _bytes(92)}
    ),
    ("uavcan.protocol.param.GetSet", K.RESPONSE): st.fixed_dictionaries(
        {
            "value": _value(False),
            "default_value": _value(False),
            "max_value": _value(True),
            "min_value": _value(True),
            "name": _bytes(92),
        }
    ),
    ("uavcan.protocol.RestartNode", K.REQUEST): st.fixed_dictionaries({"magic_number": _u(40)}),
    ("uavcan.protocol.RestartNode", K.RESPONSE): st.fixed_dictionaries({"ok": st.booleans()}),
    ("uavcan.protocol.file.BeginFirmwareUpdate", K.REQUEST): st.fixed_dictionaries(
        {
            "source_node_id": _u(8),
            "image_file_remote_path": st.fixed_dictionaries({"path": _bytes(200)}),
        }
    ),
    ("uavcan.protocol.file.BeginFirmwareUpdate", K.RESPONSE): st.fixed_dictionaries(
        {"error": _u(8), "optional_error_message": _bytes(127)}
    ),
    ("uavcan.protocol.param.ExecuteOpcode", K.REQUEST): st.fixed_dictionaries(
        {"opcode": _u(8), "argument": _i(48)}
    ),
    ("uavcan.protocol.param.ExecuteOpcode", K.RESPONSE): st.fixed_dictionaries(
        {"argument": _i(48), "ok": st.booleans()}
    ),
    ("uavcan.protocol.file.GetInfo", K.REQUEST): st.fixed_dictionaries(
        {"path": st.fixed_dictionaries({"path": _bytes(200)})}
    ),
    ("uavcan.protocol.file.GetInfo", K.RESPONSE): st.fixed_dictionaries(
        {
            "size": _u(40),
            "error": st.fixed_dictionaries({"value": _i(16)}),
            "entry_type": st.fixed_dictionaries({"flags": _u(8)}),
        }
    ),
    ("uavcan.protocol.file.Read", K.REQUEST): st.fixed_dictionaries(
        {"offset": _u(40), "path": st.fixed_dictionaries({"path": _bytes(200)})}
    ),
    ("uavcan.protocol.file.Read", K.RESPONSE): st.fixed_dictionaries(
        {"error": st.fixed_dictionaries({"value": _i(16)}), "data": _bytes(256)}
    ),
}


def _ends(low: int, high: int) -> st.SearchStrategy[int]:
    """Any int in range, with both ends drawn often."""
    return st.one_of(st.sampled_from((low, high)), st.integers(low, high))


def _list(item: st.SearchStrategy[Any], size: int, dynamic: bool) -> st.SearchStrategy[Any]:
    """Arrays empty, full or in between (exactly ``size`` items when static)."""
    if not dynamic:
        return st.lists(item, min_size=size, max_size=size)
    return st.one_of(
        st.just([]),
        st.lists(item, min_size=size, max_size=size),
        st.lists(item, max_size=size),
    )


def _member(name: str, values: st.SearchStrategy[Any]) -> st.SearchStrategy[dict[str, Any]]:
    return values.map(lambda v: {name: v})


def schema_strategy(t: Any) -> st.SearchStrategy[Any]:
    """Plain data (as `to_builtin` gives it) of any type, from its schema alone."""
    if isinstance(t, Struct):
        return st.fixed_dictionaries({f.name: schema_strategy(f.type) for f in t.fields if f.name})
    if isinstance(t, Union):
        return st.one_of([_member(m.name, schema_strategy(m.type)) for m in t.members])
    if isinstance(t, Array):
        return _list(schema_strategy(t.item), t.max_size, t.dynamic)
    if t.kind == "float":
        return {16: _F16, 32: _F32, 64: st.floats(allow_infinity=False)}[t.bits]
    if t.kind == "bool":
        return st.booleans()
    return _ends(t.low, t.high)


for _t in DATA_TYPES:
    STRATEGIES.setdefault((_t.full_name, _t.kind), schema_strategy(_t.schema))


def test_every_type_has_a_strategy() -> None:
    assert set(STRATEGIES) == set(CLASS_OF)


@pytest.mark.parametrize("key", list(STRATEGIES), ids=[f"{n}-{k.name}" for n, k in STRATEGIES])
@differential(150)
@given(data=st.data())
def test_frames_identical_and_cross_decoded(
    key: tuple[str, dronecan.TransferKind], data: st.DataObject
) -> None:
    name, kind = key
    fields = data.draw(STRATEGIES[key], label="fields")
    source = data.draw(st.integers(1, 127), label="source")
    destination = None if kind is K.MESSAGE else data.draw(st.integers(1, 127), label="dst")
    transfer_id = data.draw(st.integers(0, 31), label="transfer_id")
    priority = data.draw(st.integers(0, 31), label="priority")

    message: Any = dronecan.from_builtin(CLASS_OF[key], fields)
    ours = [
        (f.can_id, f.data)
        for f in dronecan.encode(
            message,
            source_node_id=source,
            destination_node_id=destination,
            transfer_id=transfer_id,
            priority=priority,
        )
    ]
    theirs = reference_frames(
        reference_object(name, kind, fields), source, destination, transfer_id, priority, kind
    )
    assert ours == theirs
    # Through the generated code of every type, which never hands valid values over.
    fast = BY_CLASS[type(message)].fast
    frames = fast.frames(message, source, transfer_id, priority, destination)
    assert [(f.can_id, f.data) for f in frames] == theirs
    assert same(
        dronecan.to_builtin(fast.decode(fast.payload(message))),
        reference_builtin(reference_decode(ours)),
    )

    # Each decodes the other's frames (identical here) to equal values.
    reassembler = dronecan.Reassembler()
    results = [reassembler.feed(can_id, d, timestamp=0.0) for can_id, d in theirs]
    transfer = results[-1]
    assert transfer is not None
    assert same(dronecan.to_builtin(transfer.message), reference_builtin(reference_decode(ours)))
    again = dronecan.encode(
        transfer.message,
        source_node_id=source,
        destination_node_id=destination,
        transfer_id=transfer_id,
        priority=priority,
    )
    assert [(f.can_id, f.data) for f in again] == ours
