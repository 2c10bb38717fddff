"""The DroneCAN GUI tool's ``.parm`` parameter files: read, typed by the node, planned.

The golden file below is written by hand in the exact shape of the GUI tool's writer
(``dronecan/gui_tool``, ``dronecan_gui_tool/widgets/node_properties.py`` at 4eda5d8,
``ConfigParams._do_save_to_file`` lines 806-821 and ``param_as_string`` lines 784-804):
``name value`` and a newline per parameter, integers and reals as Python's ``str``, booleans
``True``/``False``, strings as they are, empty strings left out.
"""

from __future__ import annotations

import struct

import pytest
from hypothesis import given
from hypothesis import strategies as st

from veronte4x.client.paramfile import ParameterFileError, plan
from veronte4x.client.params import ParameterInfo
from veronte4x.client.parmfile import ParmLine, is_parm, loads, typed
from veronte4x.dronecan.messages import (
    BooleanValue,
    Empty,
    IntegerValue,
    RealValue,
    StringValue,
    Value,
)

GUI_TOOL_FILE = (
    "uavcan_node_id 23\n"
    "bit_rate 1000000\n"
    "esc_index 2\n"
    "zero_behavior 1\n"
    "telem_frequency 50\n"
    "max_current 12.5\n"
    "throttle_slew 0.10000000149011612\n"
    "reverse True\n"
    "log_enabled False\n"
    "label front left\n"
)
"""What the GUI tool saves for a node with these ten parameters (a float32 0.1 decoded to a
Python float is ``0.10000000149011612``; the string ``front left`` is written as it is)."""


NONE = Empty()


def _info(name: str, value: Value, low: Value = NONE, high: Value = NONE) -> ParameterInfo:
    return ParameterInfo(name, value, NONE, low, high)  # type: ignore[arg-type]


CURRENT = [
    _info("uavcan_node_id", IntegerValue(23), IntegerValue(1), IntegerValue(127)),
    _info("bit_rate", IntegerValue(1_000_000), IntegerValue(10_000), IntegerValue(1_000_000)),
    _info("esc_index", IntegerValue(2), IntegerValue(0), IntegerValue(19)),
    _info("zero_behavior", IntegerValue(0), IntegerValue(0), IntegerValue(2)),
    _info("telem_frequency", IntegerValue(10), IntegerValue(0), IntegerValue(1000)),
    _info("max_current", RealValue(10.0), RealValue(0.0), RealValue(40.0)),
    _info("throttle_slew", RealValue(0.5)),
    _info("reverse", BooleanValue(0)),
    _info("log_enabled", BooleanValue(0)),
    _info("label", StringValue(b"")),
]
"""A node's parameters now, as GetSet reports them."""


def test_the_gui_tools_file_read_and_typed_by_the_node() -> None:
    lines = loads(GUI_TOOL_FILE)
    assert lines[0] == ParmLine(1, "uavcan_node_id", "23")
    assert lines[-1] == ParmLine(10, "label", "front left")
    saved = typed(lines, 23, CURRENT)
    assert saved.node_id == 23
    assert [(p.name, p.value) for p in saved.parameters] == [
        ("uavcan_node_id", IntegerValue(23)),
        ("bit_rate", IntegerValue(1_000_000)),
        ("esc_index", IntegerValue(2)),
        ("zero_behavior", IntegerValue(1)),
        ("telem_frequency", IntegerValue(50)),
        ("max_current", RealValue(12.5)),
        ("throttle_slew", RealValue(struct.unpack("<f", struct.pack("<f", 0.1))[0])),
        ("reverse", BooleanValue(1)),
        ("log_enabled", BooleanValue(0)),
        ("label", StringValue(b"front left")),
    ]
    changes = plan(23, saved, CURRENT)
    assert [(c.name, c.current, c.wanted) for c in changes] == [
        ("zero_behavior", 0, IntegerValue(1)),
        ("telem_frequency", 10, IntegerValue(50)),
        ("max_current", 10.0, RealValue(12.5)),
        ("throttle_slew", 0.5, RealValue(0.10000000149011612)),
        ("reverse", False, BooleanValue(1)),
        ("label", "", StringValue(b"front left")),
    ]


def test_mission_planner_lines_comments_and_windows_line_ends() -> None:
    text = "# Note: saved by Mission Planner\r\nesc_index,3\r\n\r\ntelem_frequency , 20\r\n"
    saved = typed(loads(text), 23, CURRENT)
    assert [(p.name, p.value) for p in saved.parameters] == [
        ("esc_index", IntegerValue(3)),
        ("telem_frequency", IntegerValue(20)),
    ]


@pytest.mark.parametrize("string", [",", ",0", " , x", "a,b"])
def test_a_string_keeps_a_comma_after_the_space(string: str) -> None:
    """The GUI tool writes ``NAME VALUE`` and reads the value after the first space."""
    current = [_info("s", StringValue(b""))]
    (back,) = typed(loads(f"s {string}\n"), 21, current).parameters
    assert back.value == StringValue(string.encode("utf-8"))


def test_a_string_that_is_no_utf8_is_refused() -> None:
    current = [_info("s", StringValue(b""))]
    with pytest.raises(ParameterFileError, match="line 1: s: the value is not UTF-8 text"):
        typed(loads("s \ud800\n"), 21, current)


def test_a_real_is_what_the_bus_carries() -> None:
    (back,) = typed(loads("throttle_slew 0.1\n"), 23, CURRENT).parameters
    assert back.value == RealValue(0.10000000149011612)  # float32, as read back
    assert plan(23, typed(loads("throttle_slew 0.1\n"), 23, CURRENT), [back]) == []


float32 = st.floats(width=32, allow_nan=False, allow_infinity=False)
# Text a file read as UTF-8 can hold: no line end, no lone surrogate.
texts = st.text(st.characters(blacklist_characters="\n\r", codec="utf-8"), min_size=1, max_size=20)


@given(
    st.integers(-(2**63), 2**63 - 1),
    float32,
    st.booleans(),
    texts,
)
def test_anything_the_gui_tool_writes_reads_back(
    integer: int, real: float, boolean: bool, string: str
) -> None:
    """Each value written as the GUI tool writes it comes back as that value."""
    text = f"i {integer}\nr {real}\nb {boolean}\ns {string}\n"
    current = [
        _info("i", IntegerValue(0)),
        _info("r", RealValue(0.0)),
        _info("b", BooleanValue(0)),
        _info("s", StringValue(b"")),
    ]
    values = [p.value for p in typed(loads(text), 21, current).parameters]
    assert values == [
        IntegerValue(integer),
        RealValue(real),
        BooleanValue(int(boolean)),
        StringValue(string.encode("utf-8")),
    ]


@given(st.text(max_size=60))
def test_any_text_gives_lines_or_a_file_error(text: str) -> None:
    try:
        lines = loads(text)
    except ParameterFileError as error:
        assert "\n" not in str(error)
        return
    try:
        typed(lines, 21, CURRENT)
    except ParameterFileError as error:
        assert "\n" not in str(error)


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("", "the .parm file holds no parameter line (NAME VALUE)"),
        ("# only a comment\n\n", "the .parm file holds no parameter line (NAME VALUE)"),
        ("esc_index\n", "line 1: 'esc_index' is not a parameter line (NAME VALUE)"),
        ("esc_index 2\nesc_index,3\n", "line 2: esc_index is given twice (also on line 1)"),
        ("esc_index 1.0\n", "line 1: esc_index takes an integer, not '1.0'"),
        ("esc_index 2 # front\n", "line 1: esc_index takes an integer, not '2 # front'"),
        ("max_current 1_0\n", "line 1: max_current takes a finite number, not '1_0'"),
        ("max_current nan\n", "line 1: max_current takes a finite number, not 'nan'"),
        (
            "esc_index 9223372036854775808\n",
            "line 1: esc_index: 9223372036854775808 is beyond the range of an int64",
        ),
        ("esc_index \n", "line 1: 'esc_index' is not a parameter line (NAME VALUE)"),
        ("esc_index  \n", "line 1: esc_index takes an integer, not ''"),
        ("max_current 1e39\n", "line 1: max_current: 1e39 is beyond the range of a float32"),
        ("reverse maybe\n", "line 1: reverse takes True or False, not 'maybe'"),
        ("rpm_max 5\n", "line 1: node 23 has no parameter 'rpm_max'"),
    ],
)
def test_what_the_gui_tool_would_guess_is_refused(text: str, message: str) -> None:
    with pytest.raises(ParameterFileError) as error:
        typed(loads(text), 23, CURRENT)
    assert str(error.value) == message


def test_an_am32_melody_in_the_gui_tools_own_form_is_refused() -> None:
    current = [_info("STARTUP_TUNE", StringValue(b"\x01\x02"))]
    with pytest.raises(ParameterFileError, match=r"^line 1: STARTUP_TUNE is saved by the GUI"):
        typed(loads("STARTUP_TUNE Melody:b=100,o=4,d=1:c\n"), 23, current)


def test_a_parameter_without_a_value_is_refused() -> None:
    with pytest.raises(ParameterFileError, match=r"^line 1: odd has no value on the node"):
        typed(loads("odd 1\n"), 23, [_info("odd", Empty())])


@pytest.mark.parametrize(
    ("path", "text", "parm"),
    [
        ("esc23.parm", 'format = "veronte4x-esc-parameters/1"\n', True),
        ("esc23.param", "", True),
        ("vehicle.toml", "esc_index 2\n", False),
        ("vehicle", '# saved\nformat = "veronte4x-esc-parameters/1"\n', False),
        ("vehicle.txt", "[[node]]\n", False),
        ("esc23.txt", "# GUI tool\nesc_index 2\n", True),
        ("esc23", "esc_index,2\n", True),
        ("empty", "", False),
    ],
)
def test_the_format_is_told_by_suffix_then_content(path: str, text: str, parm: bool) -> None:
    assert is_parm(path, text) is parm
