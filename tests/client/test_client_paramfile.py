"""Parameter files: written by our own TOML writer, read back by tomllib, planned."""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from veronte4x.client.paramfile import (
    NodeParameters,
    ParameterFileError,
    dumps,
    loads,
    plan,
)
from veronte4x.client.params import ParameterInfo
from veronte4x.dronecan.messages import (
    BooleanValue,
    Empty,
    IntegerValue,
    RealValue,
    StringValue,
    Value,
)


def _node(*parameters: ParameterInfo, node_id: int = 21) -> NodeParameters:
    return NodeParameters(node_id, "iq_motion.esc", "00" * 16, "1.0", None, parameters)


def _int(name: str, value: int, low: int = 0, high: int = 19) -> ParameterInfo:
    return ParameterInfo(
        name, IntegerValue(value), IntegerValue(0), IntegerValue(low), IntegerValue(high)
    )


def test_the_written_text() -> None:
    text = dumps([_node(_int("esc_index", 2))], "saved")
    assert text == (
        "# saved\n"
        'format = "veronte4x-esc-parameters/1"\n'
        "\n"
        "[[node]]\n"
        "node_id = 21\n"
        'name = "iq_motion.esc"\n'
        'unique_id = "00000000000000000000000000000000"\n'
        'software_version = "1.0"\n'
        "\n"
        "[node.parameters]\n"
        'esc_index = { type = "integer", value = 2, default = 0, min = 0, max = 19 }\n'
    )


KINDS: dict[type, st.SearchStrategy[Value]] = {
    IntegerValue: st.integers(-(2**63), 2**63 - 1).map(IntegerValue),
    RealValue: st.floats(allow_nan=False, width=32).map(RealValue),
    BooleanValue: st.booleans().map(lambda b: BooleanValue(int(b))),
    StringValue: st.text(max_size=20).map(lambda t: StringValue(t.encode("utf-8"))),
    Empty: st.just(Empty()),
}
values = st.one_of(*(KINDS[kind] for kind in (IntegerValue, RealValue, BooleanValue, StringValue)))


@given(st.dictionaries(st.text(min_size=1, max_size=12), values, max_size=6))
def test_any_parameters_round_trip(parameters: dict[str, Value]) -> None:
    node = _node(
        *(
            ParameterInfo(name, value, Empty(), Empty(), Empty())
            for name, value in parameters.items()
        )
    )
    (back,) = loads(dumps([node]))
    assert back == node


@st.composite
def parameters(draw: st.DrawFn) -> ParameterInfo:
    """A parameter of any value type, Empty included (a name the node has no value for),
    with a default and a range of its type or Empty, as GetSet gives them."""
    name = draw(st.text(max_size=12))
    value = draw(st.one_of(*KINDS.values()))
    like = st.one_of(st.just(Empty()), KINDS[type(value)])
    numeric = isinstance(value, (IntegerValue, RealValue))
    low, high = (draw(like) if numeric else Empty() for _ in range(2))
    return ParameterInfo(name, value, draw(like), low, high)  # type: ignore[arg-type]


@given(st.lists(parameters(), max_size=6, unique_by=lambda p: p.name))
def test_a_saved_file_always_loads_without_the_parameters_that_do_not_exist(
    saved: list[ParameterInfo],
) -> None:
    """An empty value or name names no parameter (DSDL param.GetSet): left out of the file;
    every other parameter reads back as it was. It was written as type "empty", which
    `loads` refused."""
    (back,) = loads(dumps([_node(*saved)]))
    assert back == _node(*(p for p in saved if p.exists))


def test_an_entry_of_type_empty_names_no_parameter() -> None:
    ghost = ParameterInfo("ghost", Empty(), IntegerValue(3), Empty(), Empty())
    text = dumps([_node(_int("esc_index", 2), ghost)])
    assert "ghost" not in text
    old = text + 'ghost = { type = "empty", value = "" }\n'  # as a file written before
    assert loads(old) == loads(text) == [_node(_int("esc_index", 2))]


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("not toml = = 1", "not a TOML file: "),
        ('format = "other"', "not a veronte4x parameter file"),
        ('format = "veronte4x-esc-parameters/1"', "the file holds no [[node]] table"),
        (
            'format = "veronte4x-esc-parameters/1"\n[[node]]\nnode_id = 200',
            "node table 1: node_id 200 is not a node id (1..127)",
        ),
        (
            'format = "veronte4x-esc-parameters/1"\n[[node]]\nnode_id = 21\n'
            '[node.parameters]\nesc_index = { type = "integer", value = "two" }',
            "node 21, esc_index: 'two' is not a value of type integer",
        ),
        (
            'format = "veronte4x-esc-parameters/1"\n[[node]]\nnode_id = 21\n'
            '[node.parameters]\nesc_index = { type = "int", value = 2 }',
            "node 21, esc_index: type 'int' is not integer, real, boolean or string",
        ),
    ],
)
def test_bad_files_are_one_line_errors(text: str, message: str) -> None:
    with pytest.raises(ParameterFileError) as error:
        loads(text)
    assert str(error.value).startswith(message)
    assert "\n" not in str(error.value)


def test_plan_sets_what_differs_and_refuses_what_cannot_be_set() -> None:
    current = [
        _int("uavcan_node_id", 23, 1, 127),
        _int("esc_index", 2),
        _int("zero_behavior", 0, 0, 2),
    ]
    saved = _node(
        _int("uavcan_node_id", 21, 1, 127), _int("esc_index", 2), _int("zero_behavior", 1, 0, 2)
    )
    changes = plan(23, saved, current)
    assert [(c.name, c.current, c.wanted) for c in changes] == [
        ("zero_behavior", 0, IntegerValue(1))
    ]
    with pytest.raises(ParameterFileError, match=r"^node 23: 5 is out of range for zero_behavior"):
        plan(23, _node(_int("zero_behavior", 5, 0, 9)), current)
    with pytest.raises(ParameterFileError, match=r"^node 23 has no parameter 'rpm_max'$"):
        plan(23, _node(_int("rpm_max", 5)), current)
    real = ParameterInfo("esc_index", RealValue(1.5), Empty(), Empty(), Empty())
    with pytest.raises(ParameterFileError, match=r"^node 23: esc_index takes an integer, not 1.5$"):
        plan(23, _node(real), current)
