"""The mutation run's test selection (``tests/mutation.py``): which lines count as run at
import, which statement a mutated line belongs to, and which tests a mutant runs."""

import ast
from pathlib import Path

from tests.mutation import (
    PACKAGE,
    CoverageMap,
    Mutant,
    import_time_lines,
    in_copy,
    node_id_of,
    statement_span,
)

SOURCE = """\
TABLE = {
    "a": 1,
}


class Layout:
    size = 2

    def width(self, bits: int) -> int:
        if bits > 8 and (
            bits < 64
        ):
            return bits // 8
        return 0


def generate(name: str = "x") -> str:
    return name * 2
"""


def _map() -> CoverageMap:
    tests = ["tests/t.py::test_quick", "tests/t.py::test_slow", "src/veronte4x/m.py::m.f"]
    lines = {"10": [1, 0], "11": [1], "13": [2], "18": [1]}
    module = {"lines": lines, "outside": [1, 2, 3, 17], "import_time": []}
    durations = {tests[0]: 0.1, tests[1]: 9.0, tests[2]: 0.5}
    return CoverageMap(tests, durations, {"m.py": module})


def test_a_statement_is_its_own_lines_or_a_compound_statement_its_head() -> None:
    tree = ast.parse(SOURCE)
    assert statement_span(tree, 2) == (1, 3)
    assert statement_span(tree, 11) == (10, 12)  # the if's test, not its body
    assert statement_span(tree, 13) == (13, 13)
    assert statement_span(tree, 7) == (7, 7)
    assert statement_span(tree, 18) == (18, 18)


def test_a_mutant_runs_the_tests_of_its_statement_quickest_first() -> None:
    tests = _map()
    assert tests.select(Mutant("m.py", 0, 11, "Lt -> LtE"), (10, 12)) == [
        "tests/t.py::test_quick",
        "tests/t.py::test_slow",
    ]
    assert tests.select(Mutant("m.py", 1, 13, "Return -> pass"), (13, 13)) == [
        "src/veronte4x/m.py::m.f"
    ]


def test_a_line_run_outside_any_test_runs_the_package_and_an_unrun_line_nothing() -> None:
    tests = _map()
    assert tests.select(Mutant("m.py", 0, 2, "1 -> 2"), (1, 3)) is None
    assert tests.select(Mutant("m.py", 0, 14, "0 -> 1"), (14, 14)) == []
    assert tests.select(Mutant("other.py", 0, 1, "0 -> 1"), (1, 1)) == []


def test_the_lines_run_at_import_are_outside_function_bodies() -> None:
    assert sorted(import_time_lines(ast.parse(SOURCE))) == [
        *range(1, 10),
        *range(15, 18),
    ]


def test_a_doctest_of_the_package_runs_from_the_copy(tmp_path: Path) -> None:
    names = ["tests/t.py::test_quick", "src/veronte4x/codec/core.py::veronte4x.codec.core.f"]
    names.append("src/veronte4x/codec/core.py::veronte4x.codec.core.g")
    copied = str(tmp_path / "veronte4x" / "codec" / "core.py")
    assert in_copy(names, tmp_path) == ["tests/t.py::test_quick", copied]
    assert PACKAGE.name == "veronte4x"


def test_a_context_is_its_test_even_with_a_pipe_in_the_node_id() -> None:
    """A node id holding ``|`` (a shell pipeline as a parameter) was cut there: the map
    named a test that does not exist, and its mutants ran another folder's tests."""
    piped = "tests/test_readme.py::test_runs[cat flight.log | veronte4x decode -]"
    outer = "tests/test_m.py::test_runner"
    known = {piped, outer, "tests/t.py::test_quick"}
    assert node_id_of(piped, known) == piped
    assert node_id_of(f"{outer}|tests/t.py::test_quick", known) == outer
    assert node_id_of(f"{piped}|tests/t.py::test_quick", known) == piped
    assert node_id_of("tests/gone.py::test_x|inner", known) == "tests/gone.py::test_x"
