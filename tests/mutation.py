"""`make mutation`: a stratified, sampled mutation run over every package.

Mutants are made with ``ast`` (our own small mutator: operator, comparison and boolean
swaps, integers off by one, ``True``/``False``, ``is``/``is not``, ``in``/``not in``, ``not
x`` made ``not not x``, a string in a function (an error text) made ``None``, a return,
raise, break, continue or call statement replaced by ``pass``). mutmut 3 generates similar
mutants, but its runner selects a mutant through trampolines inside already imported
functions, after a fork; veronte4x generates its codecs' code at import, from module-level
tables that mutmut does not mutate, so every mutant here is written into a copy of the
package put first on ``PYTHONPATH`` and its tests run in a fresh interpreter (the CLI's
subprocesses inherit it). A test failure, an import error or a timeout kills a mutant.

Each mutant runs only the tests that run its statement, quickest first, as mutmut does: the
map comes from ``make coverage`` (``--coverage``: the suite under coverage, each line with
the tests that ran it, ``tests/coverage_contexts.py``), cached in ``.venv/mutation-map`` by
a hash of the sources and rebuilt when they change. A statement run at import (a module's
tables, the code generated from them) or outside any test runs its package's tests, as
``--whole`` does for every mutant; one that no test runs is ``not covered``, a survivor.

The sample is stratified: the same number of mutants from each package (``codec``,
``dronecan``, ``arbiter``, ``capture`` with ``columnar`` and ``readers``, ``client``,
``node``, ``simulator``, ``cli``, ``variables`` and the top-level modules as ``core``), drawn with a
seed, so a run is reproducible (hypothesis runs derandomized). Run from the repository
root::

    .venv/bin/python tests/mutation.py                    # 300 mutants, --random 4792
    .venv/bin/python tests/mutation.py --size 30 --jobs 2 # a quick look on two cores
    .venv/bin/python tests/mutation.py --first 5          # 5 of each package's 30
    .venv/bin/python tests/mutation.py --list             # the sample, not run
    .venv/bin/python tests/mutation.py codec/core.py:41   # some mutants by name
    .venv/bin/python tests/mutation.py --first 2 --whole  # each against its package's tests
    .venv/bin/python tests/mutation.py --coverage         # make coverage, and the test map

It prints each outcome as it comes, then the score per package and every survivor with
its diff, and writes the same to ``--report`` (Markdown).
"""

from __future__ import annotations

import argparse
import ast
import difflib
import hashlib
import json
import os
import queue
import random
import shutil
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable, Iterator
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import coverage

ROOT = Path(__file__).resolve().parent.parent
PACKAGE = ROOT / "src" / "veronte4x"
SEED = 4792
SIZE = 300
PACKAGES: tuple[str, ...] = ("codec", "dronecan", "arbiter", "capture", "client", "node")
PACKAGES += ("simulator", "cli", "variables", "core")
COMMON_TESTS: tuple[str, ...] = ("tests/test_argument_types.py", "tests/test_errors.py")
COMMON_TESTS += ("tests/test_frozen_records.py", "tests/test_mutation_survivors.py")
"""Tests of every package, run with each package's tests (a record's ``frozen`` flag is
run at import, so its mutants run their package's tests)."""
_SLOW = ("differential", "oracle", "faults", "dataset", "fleet", "notebook", "examples")
"""Test files that compare against a reference or start a cluster: run last."""
_CLI_TESTS: tuple[str, ...] = ("tests/cli",)
COVERAGE = ROOT / ".venv" / "coverage"
"""Coverage's data (``data_file`` in ``[tool.coverage.run]``) and the tests' times."""
MAPS = ROOT / ".venv" / "mutation-map"
"""The test map of each state of the sources, by hash."""
_NOT_SOURCES = ("mutation.py", "coverage_contexts.py", "test_mutation_selection.py")
KILLED = ("killed", "timeout")
"""The outcomes that kill a mutant; ``survived`` and ``not covered`` (no test runs its
line) do not."""


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
    """The ids of every node not to mutate: type annotations, ``if TYPE_CHECKING`` bodies,
    docstrings and the parts of f-strings."""
    roots: list[ast.AST] = []
    for node in ast.walk(tree):
        if isinstance(node, ast.arg | ast.AnnAssign) and node.annotation is not None:
            roots.append(node.annotation)
        elif isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef) and node.returns:
            roots.append(node.returns)
        elif isinstance(node, ast.If) and "TYPE_CHECKING" in ast.unparse(node.test):
            roots.extend(node.body)
        elif isinstance(node, ast.JoinedStr):
            roots.extend(node.values)
        elif isinstance(node, ast.Expr) and isinstance(node.value, ast.Constant):
            roots.append(node.value)  # a docstring, or a string as a statement
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


def _setter(node: ast.Constant, value: Any) -> Callable[[], None]:
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
    elif isinstance(value, str) and value:
        yield Site(node.lineno, f"{value[:20]!r} -> None", _setter(node, None))


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
    functions = {
        id(inner)
        for node in ast.walk(tree)
        if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef)
        for inner in ast.walk(node)
    }
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
        elif isinstance(node, ast.Constant) and (
            not isinstance(node.value, str) or id(node) in functions
        ):
            found.extend(_constant(node))  # strings only in functions: texts, not tables
        found.extend(site for site in swaps if site is not None)
    return found


def mutated_source(path: Path, index: int) -> str:
    """The source of the module at ``path`` with its mutation ``index`` applied."""
    tree = ast.parse(path.read_text())
    sites(tree)[index].apply()
    return ast.unparse(ast.fix_missing_locations(tree))


def package_of(module: str) -> str:
    """The package a module (a path relative to ``src/veronte4x``) is counted in."""
    return module.split("/")[0] if "/" in module else "core"


def all_mutants() -> list[Mutant]:
    """Every mutant of every module, in a fixed order."""
    mutants: list[Mutant] = []
    for path in sorted(PACKAGE.rglob("*.py")):
        module = path.relative_to(PACKAGE).as_posix()
        for index, site in enumerate(sites(ast.parse(path.read_text()))):
            mutants.append(Mutant(module, index, site.line, site.change))
    return mutants


def sample(
    seed: int = SEED, size: int = SIZE, packages: tuple[str, ...] = PACKAGES
) -> list[Mutant]:
    """The mutants drawn for a run: ``size`` split evenly over ``packages`` (a package
    with fewer mutants gives them all, the rest go to the others), in a fixed order."""
    by_package: dict[str, list[Mutant]] = {package: [] for package in packages}
    for mutant in all_mutants():
        if package_of(mutant.module) in by_package:
            by_package[package_of(mutant.module)].append(mutant)
    shares = dict.fromkeys(packages, 0)
    left = min(size, sum(len(found) for found in by_package.values()))
    while left:
        open_ = [p for p in packages if shares[p] < len(by_package[p])]
        for package in open_[:left]:
            shares[package] += 1
            left -= 1
    rng = random.Random(seed)
    chosen: list[Mutant] = []
    for package in packages:
        chosen += rng.sample(by_package[package], shares[package])
    return chosen


def first_of_each(mutants: list[Mutant], count: int) -> list[Mutant]:
    """The first ``count`` mutants of each package's share of a sample, taken in turns (the
    first of each package, then the second, ...): a smaller stratified sample, part of the
    larger one (a share is a random draw, so its start is one too), and a run stopped early
    has tried every package about as often."""
    shares: dict[str, list[Mutant]] = {}
    for mutant in mutants:
        shares.setdefault(package_of(mutant.module), []).append(mutant)
    return [share[turn] for turn in range(count) for share in shares.values() if turn < len(share)]


def sources_hash() -> str:
    """A hash of everything the test map depends on: the package, the tests (their data
    included) and the settings; not the mutation runner itself."""
    digest = hashlib.sha256()
    paths = [ROOT / "pyproject.toml", ROOT / "tests" / "conftest.py"]
    for folder in (PACKAGE, ROOT / "tests", ROOT / "docs" / "_hooks"):
        paths += sorted(
            p for p in folder.rglob("*") if p.is_file() and "__pycache__" not in p.parts
        )
    for path in paths:
        if path.name not in _NOT_SOURCES:
            digest.update(path.relative_to(ROOT).as_posix().encode() + b"\0")
            digest.update(path.read_bytes() + b"\0")
    return digest.hexdigest()[:16]


def run_coverage() -> bool:
    """Run the whole suite under coverage (``make coverage``), each line recorded with the
    tests that ran it (``tests/coverage_contexts.py``), and write the test map of the
    sources measured if the suite passed; return whether it did. The data and the tests'
    times go to ``COVERAGE``."""
    shutil.rmtree(COVERAGE, ignore_errors=True)
    COVERAGE.mkdir(parents=True)
    measured = sources_hash()
    command = [sys.executable, "-m", "coverage", "run", "-m", "pytest"]
    command += ["-p", "tests.coverage_contexts", "--hypothesis-profile=derandomized"]
    command += ["--numprocesses", "auto", "--maxprocesses", "4"]
    passed = subprocess.run(command, cwd=ROOT, check=False).returncode == 0
    subprocess.run([sys.executable, "-m", "coverage", "combine", "--quiet"], cwd=ROOT, check=True)
    if passed:
        (COVERAGE / "sources").write_text(measured)
        map_from_coverage(measured, COVERAGE, MAPS)
    return passed


def branch_table(below: float = 90.0) -> str:
    """The modules with less than ``below`` % of their branches taken in ``COVERAGE``'s data
    (coverage's own table mixes lines and branches), lowest first, in Markdown."""
    report = COVERAGE / "coverage.json"
    command = [sys.executable, "-m", "coverage", "json", "--quiet", "-o", str(report)]
    subprocess.run(command, cwd=ROOT, check=True)
    rows: list[tuple[float, str, int, int]] = []
    for name, found in json.loads(report.read_text())["files"].items():
        summary = found["summary"]
        branches, taken = summary["num_branches"], summary["covered_branches"]
        if branches and 100 * taken / branches < below:
            module = Path(name).resolve().relative_to(PACKAGE).as_posix()
            rows.append((100 * taken / branches, module, taken, branches))
    lines = [f"Modules below {below:g} % of branches:", "", "| module | branches | % |"]
    lines.append("|---|---|---|")
    for percent, module, taken, branches in sorted(rows):
        lines.append(f"| `{module}` | {taken} / {branches} | {percent:.1f} |")
    return "\n".join(lines)


def import_time_lines(tree: ast.Module) -> set[int]:
    """The lines run when the module is imported: not in the body of a function."""
    inside: set[int] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef | ast.Lambda):
            body = node.body if isinstance(node.body, list) else [node.body]
            for statement in body:
                inside.update(range(statement.lineno, (statement.end_lineno or 0) + 1))
    last = max((getattr(n, "end_lineno", 0) or 0 for n in ast.walk(tree)), default=0)
    return set(range(1, last + 1)) - inside


def node_id_of(context: str, known: set[str]) -> str:
    """The test node id of a coverage context.

    A process a test starts records the test's node id as its static context; if that
    process runs tests of its own, coverage joins the two as ``static|dynamic``. A node id
    may hold a ``|`` itself (a parameter such as a shell pipeline), so the context is cut at
    a ``|`` only where what is left is a test of the run (``known``), the longest first.
    """
    if context in known:
        return context
    head = context
    while "|" in head:
        head = head.rsplit("|", 1)[0]
        if head in known:
            return head
    return context.split("|")[0]


def map_from_coverage(measured: str, data: Path = COVERAGE, maps: Path = MAPS) -> Path:
    """Write the test map of the coverage data in ``COVERAGE``: for each module, the tests
    that ran each line (as indices into a list of node ids), the lines run outside any test
    (imports, the code generated at import), the lines run at import; and each test's time."""
    durations: dict[str, float] = {}
    for times in data.glob("durations.*.json"):
        for name, seconds in json.loads(times.read_text()).items():
            durations[name] = max(seconds, durations.get(name, 0.0))
    known = set(durations)
    lines_run = coverage.CoverageData(str(data / "data"))
    lines_run.read()
    tests: dict[str, int] = {}
    modules: dict[str, dict[str, Any]] = {}
    for measured_file in lines_run.measured_files():
        path = Path(measured_file)
        if PACKAGE not in path.parents:
            continue
        lines: dict[str, list[int]] = {}
        outside: list[int] = []
        for line, contexts in sorted((lines_run.contexts_by_lineno(measured_file) or {}).items()):
            named = sorted({node_id_of(c, known) for c in contexts if c})
            if "" in contexts:
                outside.append(line)
            if named:
                lines[str(line)] = [tests.setdefault(name, len(tests)) for name in named]
        import_time = sorted(import_time_lines(ast.parse(path.read_text())))
        module = path.relative_to(PACKAGE).as_posix()
        modules[module] = {"lines": lines, "outside": outside, "import_time": import_time}
    maps.mkdir(parents=True, exist_ok=True)
    target = maps / f"{measured}.json"
    content = {"tests": list(tests), "durations": durations, "modules": modules}
    target.write_text(json.dumps(content))
    return target


@dataclass(frozen=True)
class CoverageMap:
    """Which tests run each line of the package, and how long each test takes."""

    tests: list[str]
    durations: dict[str, float]
    modules: dict[str, dict[str, Any]]

    @classmethod
    def read(cls, path: Path) -> CoverageMap:
        """A map written by `map_from_coverage`."""
        content = json.loads(path.read_text())
        return cls(content["tests"], content["durations"], content["modules"])

    @classmethod
    def load(cls, build: bool = True) -> CoverageMap:
        """The map of the sources as they are; built by a coverage run if there is none
        (``make coverage`` leaves one too)."""
        measured = sources_hash()
        target = MAPS / f"{measured}.json"
        if not target.exists():
            stamp = COVERAGE / "sources"
            if not (stamp.exists() and stamp.read_text() == measured):
                if not build:
                    raise SystemExit("no test map for these sources: run make coverage")
                start = time.monotonic()
                print("no test map for these sources: running the suite under coverage")
                if not run_coverage():
                    raise SystemExit("the suite fails: no test map")
                print(f"the test map took {time.monotonic() - start:.0f} s", flush=True)
            else:
                map_from_coverage(measured, COVERAGE, MAPS)
        return cls.read(target)

    def select(self, mutant: Mutant, span: tuple[int, int]) -> list[str] | None:
        """The tests that run the mutated statement (lines ``span``), quickest first; ``None``
        when it runs at import or outside any test (its package's tests are run instead),
        ``[]`` when no test runs it."""
        module = self.modules.get(mutant.module)
        if module is None:
            return []
        lines = range(span[0], span[1] + 1)
        if set(lines) & set(module["import_time"]) or set(lines) & set(module["outside"]):
            return None
        indices = {index for line in lines for index in module["lines"].get(str(line), ())}
        names = {self.tests[index] for index in indices}
        return sorted(names, key=lambda name: (self.durations.get(name, 0.0), name))


def statement_span(tree: ast.Module, line: int) -> tuple[int, int]:
    """The lines of the innermost statement at ``line`` (of a compound statement, its head
    only: an ``if`` and its test, not its body)."""
    spans = [(line, line)]
    for node in ast.walk(tree):
        if isinstance(node, ast.stmt):
            bodies = [getattr(node, f, None) for f in ("body", "orelse", "finalbody", "handlers")]
            firsts = [body[0].lineno for body in bodies if isinstance(body, list) and body]
            end = max(node.lineno, min(firsts) - 1 if firsts else node.end_lineno or 0)
            if node.lineno <= line <= end:
                spans.append((node.lineno, end))
    return min(spans[1:] or spans, key=lambda span: span[1] - span[0])


def _files(patterns: tuple[str, ...]) -> list[str]:
    names: list[str] = []
    for pattern in patterns:
        path = ROOT / pattern
        found = sorted(path.glob("test_*.py")) if path.is_dir() else [path]
        names += [f.relative_to(ROOT).as_posix() for f in found]
    return names


def package_tests(package: str) -> list[str]:
    """The test files of a package, quick ones first (with ``-x`` a mutant dies at its first
    failing test)."""
    if package == "core":
        names = _files(("tests",))
    elif package == "cli":
        names = _files(_CLI_TESTS)
    elif package == "node":  # the DroneCAN node's parts, shared by the client and the ESCs
        names = _files(("tests/client", "tests/simulator"))
    else:
        names = _files((f"tests/{package}",))
    quick = [name for name in names if not any(word in name for word in _SLOW)]
    slow = [name for name in names if name not in quick]
    common = [name for name in COMMON_TESTS if name not in names]
    return [*quick, *common, *slow]


def _run(copy: Path, tests: list[str], timeout: float) -> str:
    """``killed``, ``survived``, ``timeout`` or ``not found`` (a test named is not there, or
    no test was collected): the outcome of the tests on the copy."""
    command = [sys.executable, "-m", "pytest", "-x", "-q", "-p", "no:cacheprovider"]
    command += ["-c", str(ROOT / "pyproject.toml"), "--rootdir", str(ROOT), "-n", "0"]
    command += ["--hypothesis-profile=derandomized", *tests]
    environment = dict(os.environ, PYTHONPATH=str(copy), PYTHONDONTWRITEBYTECODE="1")
    try:
        result = subprocess.run(
            command, cwd=ROOT, env=environment, capture_output=True, timeout=timeout, check=False
        )
    except subprocess.TimeoutExpired:
        return "timeout"
    if result.returncode in (4, 5):  # pytest's usage error (not found), no tests collected
        return "not found"
    return "survived" if result.returncode == 0 else "killed"


def in_copy(tests: list[str], copy: Path) -> list[str]:
    """The tests to run on ``copy``: a doctest of the package becomes its module in the copy
    (the package is imported from there)."""
    found: list[str] = []
    source = f"{PACKAGE.relative_to(ROOT).as_posix()}/"
    for name in tests:
        if name.startswith(source):
            name = str(copy / "veronte4x" / name.split("::")[0][len(source) :])
        if name not in found:
            found.append(name)
    return found


def _copy(into: Path) -> Path:
    """A copy of the package under ``into``, every module re-written by ``ast.unparse`` (as
    the mutants are, so that a survivor is never a formatting difference)."""
    shutil.copytree(PACKAGE, into / "veronte4x", ignore=shutil.ignore_patterns("__pycache__"))
    for path in (into / "veronte4x").rglob("*.py"):
        path.write_text(ast.unparse(ast.parse(path.read_text())))
    return into


def _uses_the_copy(copy: Path) -> None:
    code = "import veronte4x; print(veronte4x.__file__)"
    environment = dict(os.environ, PYTHONPATH=str(copy))
    found = subprocess.run(
        [sys.executable, "-c", code], env=environment, capture_output=True, text=True, check=True
    ).stdout.strip()
    if not found.startswith(str(copy)):
        raise SystemExit(f"the copy is not imported first: {found}")


def _baseline(copy: Path, packages: set[str]) -> dict[str, float]:
    """The time the tests of each package take on the unmutated copy; they must pass."""
    times: dict[str, float] = {}
    for package in sorted(packages):
        start = time.monotonic()
        if _run(copy, package_tests(package), timeout=3600) != "survived":
            raise SystemExit(f"the tests of {package} fail on the unmutated package")
        times[package] = time.monotonic() - start
    return times


def diff(mutant: Mutant) -> str:
    """The mutation as a unified diff of the module (both sides as ``ast.unparse`` writes)."""
    path = PACKAGE / mutant.module
    before = ast.unparse(ast.parse(path.read_text())).splitlines()
    after = mutated_source(path, mutant.index).splitlines()
    lines = difflib.unified_diff(before, after, mutant.module, mutant.module, n=1, lineterm="")
    return "\n".join(lines)


def report(results: list[tuple[Mutant, str]], seed: int) -> str:
    """The scores per package and every survivor with its diff, in Markdown."""
    lines = [f"Seed {seed}, {len(results)} mutants.", "", "| package | killed | score |"]
    lines.append("|---|---|---|")
    packages = sorted({package_of(m.module) for m, _ in results}, key=PACKAGES.index)
    for package in packages:
        outcomes = [o for m, o in results if package_of(m.module) == package]
        killed = sum(o in KILLED for o in outcomes)
        lines.append(
            f"| {package} | {killed} / {len(outcomes)} | {100 * killed / len(outcomes):.0f} % |"
        )
    killed = sum(o in KILLED for _, o in results)
    lines.append(
        f"| all | {killed} / {len(results)} | {100 * killed / max(1, len(results)):.0f} % |"
    )
    for mutant, outcome in results:
        if outcome not in KILLED:
            lines += [
                "",
                f"{outcome.capitalize()}: {mutant.name} (line {mutant.line}, {mutant.change})",
            ]
            lines += ["", "```diff", diff(mutant), "```"]
    return "\n".join(lines) + "\n"


def _seconds(tests: list[str], durations: dict[str, float]) -> float:
    """The time ``tests`` (node ids, or files for all their tests) took in the map's run."""
    total = 0.0
    for name, seconds in durations.items():
        if any(name == test or name.startswith(f"{test}::") for test in tests):
            total += seconds
    return total


@dataclass(frozen=True)
class Plan:
    """The tests a mutant runs and how long they may take."""

    tests: list[str]
    limit: float
    how: str


def _plans(mutants: list[Mutant], arguments: argparse.Namespace, copy: Path) -> dict[Mutant, Plan]:
    """Each mutant's tests: its package's (``--whole``, or a line run at import), or the
    tests that run its line (``make coverage``'s map), quickest first."""
    packages = {package_of(m.module) for m in mutants}
    plans: dict[Mutant, Plan] = {}
    if arguments.whole:
        if arguments.timeout is None:
            times = _baseline(copy, packages)
            limits = {package: 3 * times[package] + 60 for package in packages}
        else:
            limits = dict.fromkeys(packages, arguments.timeout)
        for mutant in mutants:
            package = package_of(mutant.module)
            tests = [f"src/veronte4x/{mutant.module}", *package_tests(package)]
            plans[mutant] = Plan(tests, limits[package], "package")
        return plans
    tests_map = CoverageMap.read(arguments.map) if arguments.map else CoverageMap.load()
    trees: dict[str, ast.Module] = {}
    for mutant in mutants:
        tree = trees.setdefault(mutant.module, ast.parse((PACKAGE / mutant.module).read_text()))
        chosen = tests_map.select(mutant, statement_span(tree, mutant.line))
        how = f"{len(chosen)} tests" if chosen else "not covered"
        if chosen is None:
            package = package_of(mutant.module)
            chosen, how = [f"src/veronte4x/{mutant.module}", *package_tests(package)], "package"
        limit = arguments.timeout or 3 * _seconds(chosen, tests_map.durations) + 60
        plans[mutant] = Plan(chosen, limit, how)
    return plans


def main() -> None:
    """Run the sample, or the mutants named, and print each outcome and the scores."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("names", nargs="*", help="mutants to run, as module:index")
    parser.add_argument(
        "--random", dest="seed", type=int, default=SEED, help="the random draw (a seed)"
    )
    parser.add_argument("--size", type=int, default=SIZE)
    parser.add_argument("--packages", default=",".join(PACKAGES), help="comma-separated")
    parser.add_argument(
        "--first", type=int, help="run only the first N of each package's share of the sample"
    )
    parser.add_argument("--jobs", type=int, default=1, help="mutants run at once")
    parser.add_argument("--timeout", type=float, help="seconds per mutant (no baseline run)")
    parser.add_argument("--report", type=Path, help="write the scores and survivors here")
    parser.add_argument("--list", action="store_true", help="print the sample, run nothing")
    parser.add_argument(
        "--whole", action="store_true", help="run the package's tests, not the tests of the line"
    )
    parser.add_argument("--map", type=Path, help="this test map, not the sources' own")
    parser.add_argument(
        "--coverage", action="store_true", help="make coverage: the suite under coverage, the map"
    )
    arguments = parser.parse_args()
    if arguments.coverage:
        start = time.monotonic()
        passed = run_coverage()
        print(f"the suite under coverage took {time.monotonic() - start:.0f} s", flush=True)
        subprocess.run([sys.executable, "-m", "coverage", "report", "--sort=cover"], check=False)
        print(branch_table(), flush=True)
        raise SystemExit(0 if passed else 1)
    every = all_mutants()
    if arguments.names:
        by_name = {mutant.name: mutant for mutant in every}
        mutants = [by_name[name] for name in arguments.names]
    else:
        packages = tuple(arguments.packages.split(","))
        mutants = sample(arguments.seed, arguments.size, packages)
        if arguments.first is not None:
            mutants = first_of_each(mutants, arguments.first)
    print(f"{len(mutants)} of {len(every)} mutants, seed {arguments.seed}", flush=True)
    if arguments.list:
        for mutant in mutants:
            print(f"{mutant.name}  line {mutant.line}  {mutant.change}")
        return
    with tempfile.TemporaryDirectory() as temporary:
        copies: queue.Queue[Path] = queue.Queue()
        for job in range(arguments.jobs):
            copies.put(_copy(Path(temporary) / str(job)))
        first = copies.get()
        _uses_the_copy(first)
        plans = _plans(mutants, arguments, first)
        copies.put(first)

        def run(mutant: Mutant) -> str:
            plan = plans[mutant]
            how = plan.how
            start = time.monotonic()
            if not plan.tests:
                outcome = "not covered"
            else:
                copy = copies.get()
                target = copy / "veronte4x" / mutant.module
                original = target.read_text()
                target.write_text(mutated_source(PACKAGE / mutant.module, mutant.index))
                try:
                    outcome = _run(copy, in_copy(plan.tests, copy), plan.limit)
                    if outcome == "not found":  # a test of the map is gone: the package's
                        package = package_of(mutant.module)
                        tests = in_copy([str(target), *package_tests(package)], copy)
                        outcome = _run(copy, tests, max(plan.limit, 3600))
                        how = f"package: one of its {plan.how} not found"
                finally:
                    target.write_text(original)
                    copies.put(copy)
            seconds = time.monotonic() - start
            print(
                f"{outcome:11}  {mutant.name}  line {mutant.line}  {mutant.change}"
                f"  ({how}, {seconds:.0f} s)",
                flush=True,
            )
            return outcome

        outcomes: list[str] = []
        with ThreadPoolExecutor(arguments.jobs) as pool:
            for outcome in pool.map(run, mutants):
                outcomes.append(outcome)
                if arguments.report is not None:  # so far: a run stopped early has one
                    done = list(zip(mutants, outcomes, strict=False))
                    arguments.report.write_text(report(done, arguments.seed))
    text = report(list(zip(mutants, outcomes, strict=True)), arguments.seed)
    print(text)


if __name__ == "__main__":
    main()
