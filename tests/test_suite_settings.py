"""The suite's shared settings hold for every test: no hypothesis deadline anywhere, no
shared DuckDB connection, and the soak run's long tests left out of it (``tests/soak.py``)."""

import re
import shlex
from pathlib import Path

import tomli
from hypothesis import given, settings
from hypothesis import strategies as st

from tests.soak import FACTOR, differential

TESTS = Path(__file__).resolve().parent
ROOT = TESTS.parent


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


def _recipe(target: str) -> str:
    """The commands of one target of the Makefile."""
    found = re.search(rf"^{target}:.*\n((?:\t.*\n)+)", (ROOT / "Makefile").read_text(), re.M)
    assert found is not None, target
    return found.group(1)


def test_the_suite_deselects_the_soak_tests_and_make_soak_selects_them() -> None:
    options = tomli.loads((ROOT / "pyproject.toml").read_text())["tool"]["pytest"]
    assert shlex.split(options["ini_options"]["addopts"])[-2:] == ["-m", "not soak"]
    assert " -m " not in _recipe("test").partition(" pytest ")[2]
    assert '-m "soak or differential" --hypothesis-profile=soak --timeout 3600' in _recipe("soak")


def test_the_soak_profile_draws_anew_with_no_deadline() -> None:
    soak = settings.get_profile("soak")
    assert (soak.deadline, soak.derandomize) == (None, False)
    assert soak.max_examples == settings.get_profile("default").max_examples * FACTOR


def _calls(count: int) -> int:
    """How many examples a test of ``differential(count)`` runs under the loaded profile."""
    calls = []

    @differential(count)
    @given(st.integers())
    def test(value: int) -> None:
        calls.append(value)

    test()
    return len(calls)


def test_a_differential_test_runs_factor_times_its_examples_in_the_soak_run_only() -> None:
    assert _calls(3) == 3
    settings.load_profile("soak")
    try:
        assert _calls(3) == 3 * FACTOR
    finally:
        settings.load_profile("veronte4x")
