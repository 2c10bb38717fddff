"""NumPy scalars are taken wherever Python's numbers and bools are, and never narrowed.

The rule lives in `veronte4x.errors` (`integer`, `real`, `boolean`): a NumPy integer
where an int is expected, a NumPy bool where a bool is, a NumPy float (or integer) where a
float is; a float where an int is expected is refused, even ``np.float64(1.0)``, as Python's
``1.0`` is; a value that ``float()`` would round is refused. numpy is a test dependency
only: the library recognises its scalars without importing it.
"""

from __future__ import annotations

import dataclasses
import fractions
import subprocess
import sys
from typing import Any

import pytest
from hypothesis import given
from hypothesis import strategies as st

from tests.codec.strategies import MESSAGES
from veronte4x import codec, dronecan
from veronte4x.arbiter import Arbiter, ArbiterConfig, VariableConfig
from veronte4x.codec import Linear
from veronte4x.dronecan import vertiq
from veronte4x.errors import EncodeError, boolean, check_seconds, check_types, integer, real

np = pytest.importorskip("numpy")

INTEGER_TYPES = [np.int8, np.int16, np.int32, np.int64, np.uint8, np.uint16, np.uint32, np.uint64]
FLOAT_TYPES = [np.float16, np.float32, np.float64]


def test_the_core_never_imports_numpy() -> None:
    code = (
        "import sys, veronte4x.codec, veronte4x.dronecan, veronte4x.arbiter, veronte4x.errors;"
        "print('numpy' in sys.modules)"
    )
    result = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True
    )
    assert result.stdout == "False\n"


@pytest.mark.parametrize("kind", INTEGER_TYPES)
def test_numpy_integers_are_integers(kind: Any) -> None:
    top = int(np.iinfo(kind).max)
    for value in (0, 1, top):
        converted = integer(kind(value))
        assert converted == value and converted.__class__ is int
        assert real(kind(value)) == value and real(kind(value)).__class__ is int
    assert boolean(kind(1)) is None


@pytest.mark.parametrize("kind", FLOAT_TYPES)
def test_numpy_floats_are_reals_exactly_and_never_integers(kind: Any) -> None:
    for value in (kind(0.1), kind(-1.5), kind(1.0), kind("inf")):
        converted = real(value)
        assert converted.__class__ is float and converted == value
        assert integer(value) is None
        assert boolean(value) is None
    nan = real(kind("nan"))
    assert nan is not None and nan != nan


def test_bools_are_bools_and_nothing_else() -> None:
    for flag in (np.bool_(True), np.bool_(False), True, False):
        assert boolean(flag) is bool(flag) and integer(flag) is None and real(flag) is None
    assert [boolean(v) for v in (1, 0, np.int64(1), 1.0, "True", None)] == [None] * 6


def test_a_value_that_float_would_round_is_refused() -> None:
    assert real(fractions.Fraction(1, 3)) is None
    assert real(fractions.Fraction(1, 2)) == 0.5
    third = np.longdouble(1) / 3
    assert (real(third) is None) is bool(float(third) != third)  # longdouble wider than float64


def test_argument_checks_take_numpy_scalars() -> None:
    check_types("f", ("n", np.int64(3), int, "an int"), ("x", np.float32(0.5), float, "a float"))
    check_types("f", ("x", np.int16(3), (int, float), "a number"))
    for value, kind in ((np.float64(1.0), int), (np.bool_(True), int), (np.bool_(True), float)):
        with pytest.raises(TypeError, match="must be"):
            check_types("f", ("n", value, kind, "it"))
    seconds = check_seconds("poll", "now", np.float32(0.25))
    assert seconds == 0.25 and seconds.__class__ is float
    assert check_seconds("poll", "now", np.int64(3)).__class__ is int
    with pytest.raises(TypeError, match=r"poll\(\): now must be a number of seconds, not bool"):
        check_seconds("poll", "now", np.bool_(True))


def _numpy(value: Any, kinds: Any) -> Any:
    """``value`` with every number and bool replaced by a NumPy scalar of the same value."""
    if isinstance(value, bool):
        return np.bool_(value)
    if isinstance(value, int):
        fitting = [k for k in INTEGER_TYPES if np.iinfo(k).min <= value <= np.iinfo(k).max]
        return kinds(st.sampled_from(fitting))(value)
    if isinstance(value, float):
        with np.errstate(over="ignore"):  # float16(1e6) is inf: not fitting
            fitting = [k for k in FLOAT_TYPES if value != value or float(k(value)) == value]
        return kinds(st.sampled_from(fitting))(value)
    if isinstance(value, tuple):
        return tuple(_numpy(item, kinds) for item in value)
    return value


def _with_numpy(message: Any, draw: Any) -> Any:
    changes = {f.name: _numpy(getattr(message, f.name), draw) for f in dataclasses.fields(message)}
    return dataclasses.replace(message, **changes)


ESC = codec.Layout(
    5,
    "EscTelemetry",
    [
        codec.unsigned("throttle", 8, scale=Linear(0, 200, 0.0, 100.0)),
        codec.skip(4),
        codec.signed("current", 12),
        codec.float32("voltage"),
    ],
)
DECLARED = codec.Codec(layouts=[ESC])
ESC_MESSAGES = st.builds(
    ESC.message_class,
    throttle=st.integers(0, 200).map(lambda step: step * 0.5),
    current=st.integers(-2048, 2047),
    voltage=st.floats(width=32, allow_nan=False),
)


@given(message=st.one_of(*MESSAGES.values(), ESC_MESSAGES), data=st.data())
def test_codec_encoders_take_numpy_scalars_and_give_the_same_bytes(
    message: codec.Message, data: st.DataObject
) -> None:
    assert DECLARED.encode(_with_numpy(message, data.draw)) == DECLARED.encode(message)


@given(message=st.one_of(*MESSAGES.values(), ESC_MESSAGES), data=st.data())
def test_codec_encoders_refuse_a_float_or_bool_for_an_int(
    message: Any, data: st.DataObject
) -> None:
    names = [
        f.name for f in dataclasses.fields(message) if getattr(message, f.name).__class__ is int
    ]
    if not names:
        return
    name = data.draw(st.sampled_from(names))
    value = getattr(message, name)
    wrong = data.draw(
        st.sampled_from([np.float64(value), np.float64(value + 0.5), np.float32(value), True])
    )
    with pytest.raises(EncodeError, match=rf"\.{name} = "):
        DECLARED.encode(dataclasses.replace(message, **{name: wrong}))


def test_the_issue_cases() -> None:
    pwm = codec.PwmSet(first_channel=np.int64(4), values=(np.int64(1), 2, 3, 4))
    assert codec.encode(pwm) == codec.encode(codec.PwmSet(4, (1, 2, 3, 4)))
    for wrong in (np.float64(1.5), np.float64(1.0), np.bool_(True)):
        with pytest.raises(EncodeError, match=r"PwmSet\.values\[0\]"):
            codec.encode(codec.PwmSet(first_channel=4, values=(wrong, 2, 3, 4)))
    with pytest.raises(EncodeError, match=r"PwmSet\.first_channel = True"):
        codec.encode(codec.PwmSet(first_channel=True, values=(1, 2, 3, 4)))
    with pytest.raises(EncodeError, match=r"PwmSet\.first_channel = 4\.0"):
        codec.encode(codec.PwmSet(first_channel=4.0, values=(1, 2, 3, 4)))  # type: ignore[arg-type]
    assert codec.encode(codec.Ready(ready=np.bool_(True))) == b"\x00\xff\x01"
    score = codec.Score(autopilot=np.uint8(2), score=np.float32(0.1))
    assert codec.encode(score) == codec.encode(codec.Score(2, float(np.float32(0.1))))
    assert codec.to_microseconds(np.int64(4095), np.float32(1000), 2000) == 2000.0
    assert codec.from_microseconds(np.float64(1500.0)) == codec.from_microseconds(1500.0)


def test_layout_declarations_keep_python_numbers() -> None:
    field = codec.unsigned("rpm", np.int64(8), scale=Linear(np.int64(0), 255, 0, np.float32(5.5)))
    assert field.bits.__class__ is int
    assert field.scale is not None and field.scale.encoded_min.__class__ is int
    assert field.scale.decoded_max.__class__ is float
    layout = codec.Layout(np.uint8(6), "Rpm", [field])
    assert layout.command.__class__ is int
    assert layout.encode(layout.message_class(rpm=np.float32(5.5))) == b"\x06\xff"


def test_vertiq_helpers_take_numpy_scalars() -> None:
    assert vertiq.throttle_to_raw(np.float32(0.5)) == vertiq.throttle_to_raw(0.5)
    assert vertiq.raw_to_throttle(np.int16(8191)) == 1.0
    assert vertiq.raw_command([np.float32(0.5), np.float64(-1.0)]) == vertiq.raw_command(
        [0.5, -1.0]
    )
    assert vertiq.raw_command({np.int64(1): np.float32(0.25)}) == vertiq.raw_command({1: 0.25})
    assert vertiq.get_parameter_by_index(np.int64(3)).index.__class__ is int
    assert vertiq.restart(np.bool_(True)) == vertiq.restart(True)
    for value, python in ((np.int64(5), 5), (np.float32(0.5), 0.5), (np.bool_(True), True)):
        assert vertiq.set_parameter("x", value) == vertiq.set_parameter("x", python)
    set_int = vertiq.set_parameter("x", np.uint32(7))
    assert type(set_int.value.value) is int  # type: ignore[union-attr]
    with pytest.raises(TypeError, match=r"raw_to_throttle\(\): raw must be an int"):
        vertiq.raw_to_throttle(np.float64(1.0))
    with pytest.raises(TypeError, match=r"restart\(\): bootloader must be a bool"):
        vertiq.restart(np.int64(1))


def test_the_arbiter_takes_numpy_scalars() -> None:
    config = ArbiterConfig(
        variables=[VariableConfig(weight=np.float32(0.5), absolute=np.bool_(False))],
        preferred=np.int64(1),
        status_period=np.float32(0.25),
    )
    assert config.status_period.__class__ is float and config.preferred.__class__ is int
    assert config.variables[0].absolute is False
    python = Arbiter(ArbiterConfig(variables=[VariableConfig(weight=0.5)], preferred=1))
    arb = Arbiter(config)
    start = 1_763_737_200.0  # an epoch time: float32 arithmetic would be 128 s off
    for offset in (0.0, 0.25, 0.5):
        assert arb.poll(np.float64(start + offset)) == python.poll(start + offset)
    assert arb.receive(np.int64(8), b"\x00\xff\x01", np.float64(start + 1.0)) is not None
    arb.set_fts(np.float64(start + 2), np.int64(0), np.bool_(False))
    with pytest.raises(TypeError, match=r"set_fts\(\): autopilot must be an int"):
        arb.set_fts(start + 3, np.float64(0.0), True)


def test_dronecan_encoders_take_numpy_scalars_already() -> None:
    """What the DroneCAN encoders accept today: its own checks (replaced by the DSDL compiler
    on another branch, which calls `veronte4x.errors.integer`, `real` and `boolean`)."""
    status = dronecan.NodeStatus(np.uint32(5), dronecan.Health.OK, dronecan.Mode.OPERATIONAL, 0, 0)
    python = dronecan.NodeStatus(5, dronecan.Health.OK, dronecan.Mode.OPERATIONAL, 0, 0)
    frames = dronecan.encode(status, source_node_id=21, transfer_id=0)
    assert frames == dronecan.encode(python, source_node_id=21, transfer_id=0)
