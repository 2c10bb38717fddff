"""The soak run, ``make soak``: the tests marked ``soak``, too long for the suite (which
deselects them, ``addopts`` in ``pyproject.toml``), and the differential tests, each with
`FACTOR` times its examples under the hypothesis profile ``soak`` (``tests/conftest.py``)."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, TypeVar

import pytest
from hypothesis import settings

FACTOR = 10
"""How many times its examples a differential test runs in the soak run."""

Test = TypeVar("Test", bound=Callable[..., Any])


def differential(count: int, **options: Any) -> Callable[[Test], Test]:
    """The hypothesis settings of a differential test (a fast path against the exact one):
    ``count`` examples in the suite, `FACTOR` times as many under the ``soak`` profile, and
    the other settings ``options``; with the ``differential`` mark, which the soak run
    selects."""
    if settings.get_current_profile_name() == "soak":
        count *= FACTOR

    def apply(test: Test) -> Test:
        marked: Test = pytest.mark.differential(settings(max_examples=count, **options)(test))
        return marked

    return apply
