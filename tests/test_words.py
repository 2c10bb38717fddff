"""Counts with their noun in the right number."""

from __future__ import annotations

from hypothesis import given
from hypothesis import strategies as st

from veronte4x.words import counted


def test_one_is_singular_and_every_other_count_plural() -> None:
    assert counted(1, "file") == "1 file"
    assert counted(0, "file") == "0 files"
    assert counted(2, "bad frame") == "2 bad frames"
    assert counted(1, "entry", "entries") == "1 entry"
    assert counted(5, "entry", "entries") == "5 entries"


@given(st.integers(min_value=0))
def test_the_count_comes_first_as_digits(count: int) -> None:
    text = counted(count, "node")
    assert text.split(" ")[0] == str(count)
    assert text.endswith("node" if count == 1 else "nodes")
