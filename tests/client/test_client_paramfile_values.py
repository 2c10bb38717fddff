"""Parameter files: the real values TOML writes in words (nan, inf), a node's image CRC,
and a parameter entry that is not a table with a type and a value."""

from __future__ import annotations

import math

import pytest

from veronte4x.client.paramfile import NodeParameters, ParameterFileError, dumps, loads
from veronte4x.client.params import ParameterInfo
from veronte4x.dronecan.messages import Empty, RealValue


def _real(name: str, value: float) -> ParameterInfo:
    return ParameterInfo(name, RealValue(value), Empty(), Empty(), Empty())


def test_nan_and_infinities_and_the_image_crc_are_written_and_read_back() -> None:
    node = NodeParameters(
        21,
        "iq_motion.esc",
        "ab" * 16,
        "1.2",
        "0x0123456789abcdef",
        (_real("up", math.inf), _real("down", -math.inf), _real("unset", math.nan)),
    )
    text = dumps([node])
    assert text.splitlines()[3:] == [
        "node_id = 21",
        'name = "iq_motion.esc"',
        f'unique_id = "{"ab" * 16}"',
        'software_version = "1.2"',
        'image_crc = "0x0123456789abcdef"',
        "",
        "[node.parameters]",
        'up = { type = "real", value = inf }',
        'down = { type = "real", value = -inf }',
        'unset = { type = "real", value = nan }',
    ]
    (back,) = loads(text)
    assert back.image_crc == "0x0123456789abcdef"
    up, down, unset = (p.value for p in back.parameters)
    assert (up, down) == (RealValue(math.inf), RealValue(-math.inf))
    assert isinstance(unset, RealValue) and math.isnan(unset.value)


@pytest.mark.parametrize(
    "entry", ["esc_index = 2", "esc_index = { value = 2 }", 'esc_index = { type = "integer" }']
)
def test_a_parameter_that_is_not_a_table_with_type_and_value_is_refused(entry: str) -> None:
    text = (
        f'format = "veronte4x-esc-parameters/1"\n[[node]]\nnode_id = 21\n[node.parameters]\n{entry}'
    )
    with pytest.raises(ParameterFileError) as error:
        loads(text)
    assert str(error.value) == "node 21, esc_index: a table with type and value expected"
