"""The suite's shared settings hold for every test: no hypothesis deadline anywhere, no
shared DuckDB connection."""

import re
from pathlib import Path

from hypothesis import given, settings
from hypothesis import strategies as st

TESTS = Path(__file__).resolve().parent


def test_the_loaded_profile_has_no_deadline() -> None:
    assert settings().deadline is None


@settings(max_examples=5)
@given(st.integers())
def test_a_test_with_settings_of_its_own_inherits_no_deadline(value: int) -> None:
    assert settings().deadline is None


def test_no_test_file_sets_a_deadline() -> None:
    pattern = re.compile(r"\bdeadline\s*=")
    offenders = [
        f"{path.relative_to(TESTS)}:{number}"
        for path in sorted(TESTS.rglob("*.py"))
        if path.name != "conftest.py"
        for number, line in enumerate(path.read_text().splitlines(), 1)
        if pattern.search(line)
    ]
    assert offenders == []


def test_no_test_file_queries_duckdbs_shared_connection() -> None:
    """``duckdb.execute``/``duckdb.sql`` use one connection per process; a result one test
    leaves unfinished (``fetchone``) makes the next test's query on it fail, depending on
    the order xdist gives. Tests open their own (``duckdb.connect()``); docs pages and
    notebooks may use the shared one, as users do."""
    pattern = re.compile(r"\bduckdb\.(execute|sql|query)\(")
    offenders = [
        f"{path.relative_to(TESTS)}:{number}"
        for path in sorted(TESTS.rglob("*.py"))
        for number, line in enumerate(path.read_text().splitlines(), 1)
        if pattern.search(line)
    ]
    assert offenders == []
