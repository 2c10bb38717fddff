"""Parameters as a ground station shows them: plain values, requests, checks, parsing."""

from __future__ import annotations

import pytest

from veronte4x.client import InvalidRequestError
from veronte4x.client.params import ParameterInfo, parameter_request, plain
from veronte4x.dronecan import (
    BooleanValue,
    Empty,
    GetSetRequest,
    GetSetResponse,
    IntegerValue,
    RealValue,
    StringValue,
)


def _info(value: object, low: object = None, high: object = None) -> ParameterInfo:
    response = GetSetResponse(
        value=value,  # type: ignore[arg-type]
        default_value=value,  # type: ignore[arg-type]
        min_value=Empty() if low is None else low,  # type: ignore[arg-type]
        max_value=Empty() if high is None else high,  # type: ignore[arg-type]
        name=b"velocity_kp",
    )
    return ParameterInfo.from_response(response)


def test_plain_values() -> None:
    assert plain(Empty()) is None
    assert plain(BooleanValue(1)) is True
    assert plain(BooleanValue(0)) is False
    assert plain(StringValue(b"caf\xc3\xa9 \xff")) == "café \ufffd"
    assert plain(IntegerValue(-3)) == -3
    assert plain(RealValue(0.5)) == 0.5


def test_requests_by_name_or_by_index_said_explicitly() -> None:
    assert parameter_request("velocity_kp") == GetSetRequest(name=b"velocity_kp")
    assert parameter_request(None, 0) == GetSetRequest(index=0)
    with pytest.raises(InvalidRequestError, match=r"^give a parameter name \('a'\) or an index"):
        parameter_request("a", 3)
    with pytest.raises(InvalidRequestError, match=r"^give a parameter name, or an index"):
        parameter_request(None)
    with pytest.raises(InvalidRequestError, match=r"^an empty parameter name is refused"):
        parameter_request("")
    with pytest.raises(TypeError, match=r"^a parameter name is a str, not b'a'"):
        parameter_request(b"a")  # type: ignore[arg-type]


def test_info_as_plain_data() -> None:
    info = ParameterInfo.from_response(
        GetSetResponse(
            value=IntegerValue(5),
            default_value=Empty(),
            min_value=IntegerValue(0),
            max_value=IntegerValue(9),
            name=b"esc_index",
        ),
        index=4,
    )
    assert info.as_dict() == {
        "name": "esc_index",
        "value": 5,
        "default": None,
        "min": 0,
        "max": 9,
        "index": 4,
    }


def test_check_type_and_range() -> None:
    integer = _info(IntegerValue(5), IntegerValue(0), IntegerValue(9))
    assert integer.check(IntegerValue(0)) is None
    assert integer.check(IntegerValue(9)) is None
    assert integer.check(IntegerValue(10)) == "10 is out of range for velocity_kp: 0..9"
    assert integer.check(IntegerValue(-1)) == "-1 is out of range for velocity_kp: 0..9"
    assert integer.check(RealValue(1.0)) == "velocity_kp takes an integer, not 1.0"
    real = _info(RealValue(0.5), None, RealValue(1.0))  # no minimum
    assert real.check(RealValue(-1e9)) is None
    assert real.check(RealValue(1.5)) == "1.5 is out of range for velocity_kp: None..1.0"
    assert (
        _info(BooleanValue(1)).check(StringValue(b"x"))
        == "velocity_kp takes true or false, not 'x'"
    )
    assert _info(StringValue(b"a")).check(StringValue(b"b")) is None
    missing = "velocity_kp does not exist on the node (its value is empty)"
    assert _info(Empty()).check(IntegerValue(1)) == missing


def test_parse_by_type() -> None:
    assert _info(IntegerValue(0)).parse("0x10") == IntegerValue(16)
    assert _info(RealValue(0.0)).parse("2.5") == RealValue(2.5)
    assert _info(BooleanValue(0)).parse("On") == BooleanValue(1)
    assert _info(BooleanValue(1)).parse("no") == BooleanValue(0)
    assert _info(StringValue(b"")).parse("café") == StringValue("café".encode())
    with pytest.raises(ValueError, match=r"^velocity_kp does not exist on the node"):
        _info(Empty()).parse("7")  # an Empty value: no such parameter, not a string
    with pytest.raises(ValueError, match=r"^velocity_kp takes an integer, not '1\.5'$"):
        _info(IntegerValue(0)).parse("1.5")
    with pytest.raises(ValueError, match=r"^velocity_kp takes a number, not 'x'$"):
        _info(RealValue(0.0)).parse("x")
    with pytest.raises(ValueError, match=r"^velocity_kp takes a finite number, not 'nan'$"):
        _info(RealValue(0.0)).parse("nan")
    with pytest.raises(ValueError, match=r"^velocity_kp takes true or false, not 'maybe'$"):
        _info(BooleanValue(0)).parse("maybe")


def test_a_parameter_answered_with_an_empty_value_does_not_exist() -> None:
    """DroneCAN GetSet: an Empty value means there is no such parameter; setting it and
    applying a saved set to it are refused in words."""
    from veronte4x.client import ParameterError
    from veronte4x.client.operations import wanted_value
    from veronte4x.client.paramfile import NodeParameters, ParameterFileError, plan

    missing = _info(Empty())
    assert not missing.exists
    assert _info(IntegerValue(0)).exists
    for value in ("7", 7, IntegerValue(7)):
        with pytest.raises(ParameterError, match=r"^node 23 has no parameter 'velocity_kp'$"):
            wanted_value(23, missing, value)
    saved = NodeParameters(23, "", "", "", None, (_info(IntegerValue(7)),))
    with pytest.raises(
        ParameterFileError,
        match=r"^node 23: velocity_kp does not exist on the node \(its value is empty\)$",
    ):
        plan(23, saved, [missing])
