"""A node given twice in one parameter file is refused, naming both tables, rather than its
second entry being ignored (issue 41, item 6); a ``.parm`` name given twice names both lines."""

from __future__ import annotations

import pytest

from veronte4x.client import paramfile, parmfile
from veronte4x.client.params import plain

_TABLE = """[[node]]{comment}
node_id = {node}
unique_id = "{unique}"

[node.parameters]
esc_index = {{ type = "integer", value = {index} }}
"""


def _file(*tables: tuple[int, str, int], comment: str = "") -> str:
    head = f'format = "{paramfile.FORMAT}"\n\n'
    return head + "\n".join(
        _TABLE.format(node=n, unique=u, index=i, comment=comment) for n, u, i in tables
    )


def test_a_node_id_given_twice_names_both_tables_by_line() -> None:
    text = _file((21, "aa", 0), (22, "bb", 1), (21, "cc", 3), comment="  # saved")
    assert text.splitlines()[2] == "[[node]]  # saved"
    with pytest.raises(paramfile.ParameterFileError) as refused:
        paramfile.loads(text)
    assert str(refused.value) == (
        "node_id 21 is given twice (lines 3 and 17): one would be ignored; keep one table per node"
    )


def test_a_unique_id_given_twice_is_refused_too() -> None:
    with pytest.raises(paramfile.ParameterFileError) as refused:
        paramfile.loads(_file((21, "aa", 0), (22, "aa", 1)))
    assert str(refused.value) == (
        "unique_id aa is given twice (lines 3 and 10): one would be ignored; keep one table "
        "per node"
    )


def test_tables_without_headers_are_named_by_position() -> None:
    text = (
        f'format = "{paramfile.FORMAT}"\n'
        "node = [{ node_id = 21, parameters = {} }, { node_id = 21, parameters = {} }]\n"
    )
    with pytest.raises(paramfile.ParameterFileError) as refused:
        paramfile.loads(text)
    assert str(refused.value) == (
        "node_id 21 is given twice (node tables 1 and 2): one would be ignored; keep one "
        "table per node"
    )


def test_distinct_nodes_and_empty_unique_ids_load() -> None:
    loaded = paramfile.loads(_file((21, "", 0), (22, "", 1)))
    assert [(n.node_id, n.unique_id, plain(n.parameters[0].value)) for n in loaded] == [
        (21, "", 0),
        (22, "", 1),
    ]
    # what dumps writes loads back whole
    assert paramfile.loads(paramfile.dumps(loaded)) == loaded


def test_a_parm_name_given_twice_names_both_lines() -> None:
    with pytest.raises(paramfile.ParameterFileError) as refused:
        parmfile.loads("esc_index 1\n# note\nzero_behavior 0\nesc_index 2\n")
    assert str(refused.value) == "line 4: esc_index is given twice (also on line 1)"
