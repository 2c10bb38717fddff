"""A sampled mutation run over the codec and DroneCAN modules.

Every mutant of ``src/veronte4x/codec`` and ``src/veronte4x/dronecan`` is enumerated
with ``ast`` (operator, comparison and boolean swaps, integers off by one,
``True``/``False``, ``is``/``is not``, ``in``/``not in``, ``not x`` made ``not not x``, a
return, raise, break, continue or call statement replaced by ``pass``); 222 of them are
drawn with seed 4792. Each mutant is written into a copy of the package put first on
``PYTHONPATH``, and its tests (the module's doctests, then its package's tests) run in a
fresh interpreter, since the package generates layouts and fast paths at import. A test
failure, an import error or a timeout kills it. Run from the repository root::

    .venv/bin/python tests/mutation_sample.py            # the whole sample
    .venv/bin/python tests/mutation_sample.py --list     # the sample, not run
    .venv/bin/python tests/mutation_sample.py dronecan/reassembler.py:41  # some mutants

Hypothesis runs derandomized, so a run is reproducible.
"""

from __future__ import annotations

import argparse
import ast
import os
import random
import shutil
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PACKAGE = ROOT / "src" / "veronte4x"
PACKAGES = ("codec", "dronecan")
SEED = 4792
SIZE = 222
COMMON_TESTS = ("tests/test_argument_types.py", "tests/test_errors.py")
_SLOW = ("differential", "oracle")
"""Test files that compare against a reference implementation: most of the time."""

_OPERATORS: dict[type[ast.AST], type[ast.AST]] = {
    ast.Add: ast.Sub,
    ast.Sub: ast.Add,
    ast.Mult: ast.FloorDiv,
    ast.FloorDiv: ast.Mult,
    ast.Div: ast.Mult,
    ast.Mod: ast.FloorDiv,
    ast.LShift: ast.RShift,
    ast.RShift: ast.LShift,
    ast.BitAnd: ast.BitOr,
    ast.BitOr: ast.BitAnd,
    ast.BitXor: ast.BitOr,
    ast.Eq: ast.NotEq,
    ast.NotEq: ast.Eq,
    ast.Lt: ast.LtE,
    ast.LtE: ast.Lt,
    ast.Gt: ast.GtE,
    ast.GtE: ast.Gt,
    ast.Is: ast.IsNot,
    ast.IsNot: ast.Is,
    ast.In: ast.NotIn,
    ast.NotIn: ast.In,
    ast.And: ast.Or,
    ast.Or: ast.And,
}

_REMOVABLE = (ast.Return, ast.Raise, ast.Break, ast.Continue)


@dataclass(frozen=True)
class Site:
    """One place a module can be mutated, and how."""

    line: int
    change: str
    apply: Callable[[], None]


@dataclass(frozen=True)
class Mutant:
    """One mutant: the module (relative to the package), its site's index and its line."""

    module: str
    index: int
    line: int
    change: str

    @property
    def name(self) -> str:
        """The name that selects this mutant on the command line."""
        return f"{self.module}:{self.index}"


def _annotations(tree: ast.AST) -> set[int]:
    """The ids of every node inside a type annotation or the body of ``if TYPE_CHECKING``."""
    roots: list[ast.AST] = []
    for node in ast.walk(tree):
        if isinstance(node, ast.arg | ast.AnnAssign) and node.annotation is not None:
            roots.append(node.annotation)
        elif isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef) and node.returns:
            roots.append(node.returns)
        elif isinstance(node, ast.If) and "TYPE_CHECKING" in ast.unparse(node.test):
            roots.extend(node.body)
    return {id(inner) for root in roots for inner in ast.walk(root)}


def _swap(holder: ast.AST, field: str, position: int | None) -> Site | None:
    """The site that swaps the operator held in ``holder.field`` (or its item)."""
    old = getattr(holder, field) if position is None else getattr(holder, field)[position]
    new = _OPERATORS.get(type(old))
    if new is None:
        return None

    def apply() -> None:
        if position is None:
            setattr(holder, field, new())
        else:
            getattr(holder, field)[position] = new()

    line = getattr(holder, "lineno", 0)
    return Site(line, f"{type(old).__name__} -> {new.__name__}", apply)


def _setter(node: ast.Constant, value: int) -> Callable[[], None]:
    """A function that sets the value of a constant."""

    def apply() -> None:
        node.value = value

    return apply


def _constant(node: ast.Constant) -> Iterator[Site]:
    """The sites that change an integer by one or swap ``True`` and ``False``."""
    value = node.value
    if isinstance(value, bool):
        yield Site(node.lineno, f"{value} -> {not value}", _setter(node, not value))
    elif isinstance(value, int):
        for new in (value + 1, value - 1):
            yield Site(node.lineno, f"{value} -> {new}", _setter(node, new))


def _removals(node: ast.AST) -> Iterator[Site]:
    """The sites that replace one statement of a body by ``pass``."""
    for field in ("body", "orelse", "finalbody"):
        statements = getattr(node, field, None)
        if not isinstance(statements, list):
            continue
        for position, statement in enumerate(statements):
            call = isinstance(statement, ast.Expr) and isinstance(statement.value, ast.Call)
            if isinstance(statement, _REMOVABLE) or call:

                def apply(
                    statements: list[ast.stmt] = statements, position: int = position
                ) -> None:
                    statements[position] = ast.copy_location(ast.Pass(), statements[position])

                change = f"{type(statement).__name__} -> pass"
                yield Site(statement.lineno, change, apply)


def sites(tree: ast.Module) -> list[Site]:
    """Every mutation site of a module, in an order fixed by its source."""
    skipped = _annotations(tree)
    found: list[Site] = []
    for node in ast.walk(tree):
        if id(node) in skipped:
            continue
        found.extend(_removals(node))
        swaps: list[Site | None] = []
        if isinstance(node, ast.BinOp | ast.AugAssign | ast.BoolOp):
            swaps.append(_swap(node, "op", None))
        elif isinstance(node, ast.Compare):
            swaps.extend(_swap(node, "ops", position) for position in range(len(node.ops)))
        elif isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.Not):

            def apply(node: ast.UnaryOp = node) -> None:
                node.operand = ast.UnaryOp(ast.Not(), node.operand)

            swaps.append(Site(node.lineno, "not x -> not not x", apply))
        elif isinstance(node, ast.Constant):
            found.extend(_constant(node))
        found.extend(site for site in swaps if site is not None)
    return found


def mutated_source(path: Path, index: int) -> str:
    """The source of the module at ``path`` with its mutation ``index`` applied."""
    tree = ast.parse(path.read_text())
    sites(tree)[index].apply()
    return ast.unparse(ast.fix_missing_locations(tree))


def all_mutants() -> list[Mutant]:
    """Every mutant of the modules under test, in a fixed order."""
    mutants: list[Mutant] = []
    for package in PACKAGES:
        for path in sorted((PACKAGE / package).glob("*.py")):
            module = path.relative_to(PACKAGE).as_posix()
            for index, site in enumerate(sites(ast.parse(path.read_text()))):
                mutants.append(Mutant(module, index, site.line, site.change))
    return mutants


def sample(seed: int = SEED, size: int = SIZE) -> list[Mutant]:
    """The mutants drawn for a run, in the order of :func:`all_mutants`."""
    mutants = all_mutants()
    chosen = set(random.Random(seed).sample(range(len(mutants)), size))
    return [mutant for position, mutant in enumerate(mutants) if position in chosen]


def _tests(copy: Path, target: str) -> list[str]:
    """What the mutants of ``target`` (a module, or a package for all) are run against.

    First the doctests of the target's copy, then the package's test files with the slow
    comparisons last: with ``-x`` a mutant dies at its first failing test.
    """
    files = sorted((ROOT / "tests" / target.split("/")[0]).glob("test_*.py"))
    names = [path.relative_to(ROOT).as_posix() for path in files]
    quick = [name for name in names if not any(word in name for word in _SLOW)]
    slow = [name for name in names if name not in quick]
    return [str(copy / "veronte4x" / target), *quick, *COMMON_TESTS, *slow]


def _run(copy: Path, tests: list[str], timeout: float) -> str:
    """``killed``, ``survived`` or ``timeout``: the outcome of the tests on the copy."""
    command = [sys.executable, "-m", "pytest", "-x", "-q", "-p", "no:cacheprovider"]
    command += ["-c", str(ROOT / "pyproject.toml"), "--rootdir", str(ROOT)]
    command += ["--hypothesis-profile=derandomized", *tests]
    environment = dict(os.environ, PYTHONPATH=str(copy), PYTHONDONTWRITEBYTECODE="1")
    try:
        result = subprocess.run(
            command, cwd=ROOT, env=environment, capture_output=True, timeout=timeout, check=False
        )
    except subprocess.TimeoutExpired:
        return "timeout"
    return "survived" if result.returncode == 0 else "killed"


def _baseline(copy: Path) -> dict[str, float]:
    """The time each test group takes on every module re-written by ``ast.unparse``."""
    for package in PACKAGES:
        for path in (copy / "veronte4x" / package).glob("*.py"):
            path.write_text(ast.unparse(ast.parse(path.read_text())))
    times: dict[str, float] = {}
    for package in PACKAGES:
        start = time.monotonic()
        if _run(copy, _tests(copy, package), timeout=600) != "survived":
            raise SystemExit(f"the tests of {package} fail on the unmutated package")
        times[package] = time.monotonic() - start
    return times


def main() -> None:
    """Run the sample, or the mutants named, and print each outcome and the kill rate."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("names", nargs="*", help="mutants to run, as module:index")
    parser.add_argument("--seed", type=int, default=SEED)
    parser.add_argument("--size", type=int, default=SIZE)
    parser.add_argument("--list", action="store_true", help="print the sample, run nothing")
    arguments = parser.parse_args()
    every = all_mutants()
    if arguments.names:
        by_name = {mutant.name: mutant for mutant in every}
        mutants = [by_name[name] for name in arguments.names]
    else:
        mutants = sample(arguments.seed, arguments.size)
    print(f"{len(mutants)} of {len(every)} mutants", flush=True)
    if arguments.list:
        for mutant in mutants:
            print(f"{mutant.name}  line {mutant.line}  {mutant.change}")
        return
    with tempfile.TemporaryDirectory() as temporary:
        copy = Path(temporary)
        shutil.copytree(PACKAGE, copy / "veronte4x", ignore=shutil.ignore_patterns("__pycache__"))
        times = _baseline(copy)
        killed = 0
        for mutant in mutants:
            target = copy / "veronte4x" / mutant.module
            original = target.read_text()
            target.write_text(mutated_source(PACKAGE / mutant.module, mutant.index))
            package = mutant.module.split("/")[0]
            try:
                outcome = _run(copy, _tests(copy, mutant.module), timeout=3 * times[package] + 30)
            finally:
                target.write_text(original)
            killed += outcome != "survived"
            print(f"{outcome:8}  {mutant.name}  line {mutant.line}  {mutant.change}", flush=True)
    print(f"killed {killed} of {len(mutants)}: {100 * killed / len(mutants):.1f} %")


if __name__ == "__main__":
    main()
