"""NumPy scalars in the DroneCAN encoders: what is expected of them, and what holds today.

The rule is the codec's (`veronte4x.errors.integer`, `real`, `boolean`): a NumPy integer
where an int is expected, a NumPy bool where a bool is, a NumPy float or integer where a
float is, each giving exactly the bytes of the Python value; a float where an int is
expected (even ``np.float64(3.0)``) and a NumPy bool where an int is are refused with an
`EncodeError`. ``ACCEPTED`` holds the first kind, ``REFUSED`` the second. The generated
fast paths hand every value that is not a Python int to the generic serializer: NumPy
arithmetic wraps at the scalar's own width, which once gave wrong bytes for an esc.Status
of NumPy integers ("esc.Status every field").
"""

from __future__ import annotations

from typing import Any

import pytest

from veronte4x import dronecan as d
from veronte4x.errors import EncodeError

np = pytest.importorskip("numpy")

H, M = d.Health.OK, d.Mode.OPERATIONAL
_ESC: dict[str, Any] = {
    "error_count": 1,
    "voltage": 12.5,
    "current": 1.5,
    "temperature": 300.0,
    "rpm": 1000,
}
_ESC |= {"power_rating_pct": 50, "esc_index": 2}

# (name, message with NumPy scalars, the same with Python values)
ACCEPTED: list[tuple[str, Any, Any]] = [
    (
        "NodeStatus integers",
        d.NodeStatus(np.uint32(5), H, M, np.uint8(1), np.uint16(7)),
        d.NodeStatus(5, H, M, 1, 7),
    ),
    ("RawCommand integers", d.RawCommand((np.int16(5), np.int64(-3))), d.RawCommand((5, -3))),
    (
        "Temperature integers and float32",
        d.Temperature(np.uint16(1), np.float32(300.5), np.uint8(0)),
        d.Temperature(1, 300.5, 0),
    ),
    *[
        (f"esc.Status {field} alone", d.EscStatus(**(_ESC | {field: value})), d.EscStatus(**_ESC))
        for field, value in [
            ("error_count", np.uint32(1)),
            ("voltage", np.float32(12.5)),
            ("current", np.float64(1.5)),
            ("temperature", np.float16(300.0)),
            ("rpm", np.int32(1000)),
        ]
    ],
    (
        "param.Value real float64",
        d.GetSetRequest(value=d.RealValue(np.float64(0.5)), name=b"x"),
        d.GetSetRequest(value=d.RealValue(0.5), name=b"x"),
    ),
    # A NumPy integer in a field narrower than a byte, in a union member, in a request.
    (
        "esc.Status power_rating_pct",
        d.EscStatus(**(_ESC | {"power_rating_pct": np.uint8(50)})),
        d.EscStatus(**_ESC),
    ),
    (
        "esc.Status esc_index",
        d.EscStatus(**(_ESC | {"esc_index": np.uint8(2)})),
        d.EscStatus(**_ESC),
    ),
    ("GetSet index", d.GetSetRequest(index=np.int64(3)), d.GetSetRequest(index=3)),
    (
        "param.Value integer",
        d.GetSetRequest(value=d.IntegerValue(np.int64(3)), name=b"x"),
        d.GetSetRequest(value=d.IntegerValue(3), name=b"x"),
    ),
    (
        "param.Value real float32",
        d.GetSetRequest(value=d.RealValue(np.float32(0.5)), name=b"x"),
        d.GetSetRequest(value=d.RealValue(0.5), name=b"x"),
    ),
    (
        "param.Value boolean",
        d.GetSetRequest(value=d.BooleanValue(np.uint8(1)), name=b"x"),
        d.GetSetRequest(value=d.BooleanValue(1), name=b"x"),
    ),
    ("RestartNode ok bool", d.RestartNodeResponse(np.bool_(True)), d.RestartNodeResponse(True)),
    # A uint40 (a NumPy uint64 has no to_bytes: the generic serializer takes it).
    (
        "RestartNode magic uint64",
        d.RestartNodeRequest(np.uint64(0xACCE551B1E)),
        d.RestartNodeRequest(0xACCE551B1E),
    ),
    # NumPy integers side by side in bit-packed bytes (their arithmetic would wrap).
    (
        "esc.Status every field",
        d.EscStatus(
            np.uint32(1),
            np.float32(12.5),
            np.float64(1.5),
            np.float16(300.0),
            np.int32(1000),
            np.uint8(50),
            np.uint8(2),
        ),
        d.EscStatus(**_ESC),
    ),
]

# (name, message with a value that would be narrowed)
REFUSED: list[tuple[str, Any]] = [
    ("NodeStatus uptime float", d.NodeStatus(np.float64(5.0), H, M, 0, 0)),
    ("RawCommand float", d.RawCommand((np.float64(5.5),))),
    ("RawCommand NumPy bool", d.RawCommand((np.bool_(True),))),
    ("GetSet index float", d.GetSetRequest(index=np.float64(3.0))),
    ("param.Value integer float", d.GetSetRequest(value=d.IntegerValue(np.float64(3.5)))),
]


def _encode(message: Any) -> list[Any]:
    service = not isinstance(message, (d.NodeStatus, d.RawCommand, d.Temperature, d.EscStatus))
    destination = 22 if service else None
    return d.encode(message, source_node_id=21, transfer_id=3, destination_node_id=destination)


@pytest.mark.parametrize(("name", "numpy", "python"), ACCEPTED, ids=[c[0] for c in ACCEPTED])
def test_numpy_scalars_give_the_bytes_of_python_values(name: str, numpy: Any, python: Any) -> None:
    assert _encode(numpy) == _encode(python)


@pytest.mark.parametrize(("name", "message"), REFUSED, ids=[c[0] for c in REFUSED])
def test_a_value_that_would_be_narrowed_is_refused(name: str, message: Any) -> None:
    with pytest.raises(EncodeError):
        _encode(message)
