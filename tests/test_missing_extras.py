"""Every public module and a representative set of public functions, in a process where only
the core and one extra are installed: each works, or raises `MissingExtraError` naming an
extra that brings what is missing, never a bare ``ModuleNotFoundError``.

The other packages are hidden, not uninstalled: the process starts with a finder in front
of ``sys.meta_path`` that raises ``ModuleNotFoundError`` for each top-level module of every
installed distribution the extra does not bring, as Python does for one that is not there.
"""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from functools import cache
from importlib import metadata

import pytest

from tests.extras_support import EXTRAS, ROOT, modules

SOURCE = ROOT / "src" / "veronte4x"
PUBLIC_MODULES = sorted(
    ".".join(("veronte4x", *path.relative_to(SOURCE).with_suffix("").parts)).removesuffix(
        ".__init__"
    )
    for path in SOURCE.rglob("*.py")
    if not any(
        part.startswith("_") and part != "__init__.py" for part in path.relative_to(SOURCE).parts
    )
)
"""Every module of the package whose path has no part starting with ``_``."""

DBC = 'VERSION ""\nBU_: A\nBO_ 1 M: 1 A\n SG_ s : 0|8@1+ (1,0) [0|255] "" A\n'
"""A DBC file of one message (CAN ID 1)."""

CALLS: dict[str, set[str]] = {
    "from veronte4x import codec; "
    "codec.decode(b'\\x00\\xff\\x01', sender=codec.Sender.AUTOPILOT)": set(),
    "from veronte4x import capture; list(capture.read('capture.log'))": set(),
    "from veronte4x import capture; capture.stats(capture.read('capture.log'))": set(),
    "from veronte4x import dronecan; dronecan.TypeSet.standard()": set(),
    "from veronte4x import capture; capture.read_tables('capture.log')": {"pyarrow", "numpy"},
    "from veronte4x import capture; capture.tables_from_records(capture.read('capture.log'))": {
        "pyarrow",
        "numpy",
    },
    "from veronte4x import capture; capture.to_dataframe(capture.read('capture.log'))": {
        "pandas",
        "pyarrow",
        "numpy",
    },
    "from veronte4x import capture; capture.to_parquet(['capture.log'], 'dataset')": {
        "pyarrow",
        "numpy",
    },
    "from veronte4x import capture; from veronte4x.capture.plot import arbitration_timeline; "
    "arbitration_timeline(capture.read('capture.log'))": {"matplotlib"},
    "from veronte4x import capture; from veronte4x.capture.esc_plot import esc_telemetry; "
    "esc_telemetry(capture.read('capture.log'))": {"matplotlib"},
    "from veronte4x import capture; list(capture.read('capture.log', dbc=['one.dbc']))": {
        "cantools"
    },
    "from veronte4x import capture; list(capture.read('one.mf4'))": {"can", "asammdf"},
    "from veronte4x import canbus; canbus.open_bus(interface='virtual').shutdown()": {"can"},
    "from veronte4x.client.bus import BusClient": {"can"},
    "from veronte4x.cli.buses import open_bus; open_bus(interface='udp_multicast', "
    "channel='239.74.163.2').shutdown()": {"can", "msgpack"},
    "from veronte4x.simulator.can_node import EscBus": {"can"},
}
"""Representative calls, each with the top-level modules it needs."""

PROBE = r"""
import importlib, importlib.abc, json, sys, traceback
blocked, names, calls = json.loads(sys.stdin.read())
blocked = set(blocked)

class NotInstalled(importlib.abc.MetaPathFinder):
    def find_spec(self, name, path=None, target=None):
        if name.partition(".")[0] in blocked:
            raise ModuleNotFoundError(f"No module named {name!r}", name=name)
        return None

sys.meta_path.insert(0, NotInstalled())
from veronte4x.errors import MissingExtraError

def outcome(run):
    try:
        run()
        return ["ok"]
    except MissingExtraError as error:
        return ["missing", error.name, error.extra, str(error)]
    except BaseException as error:
        return ["error", f"{type(error).__name__}: {error}", traceback.format_exc()]

print(json.dumps({
    "modules": {name: outcome(lambda: importlib.import_module(name)) for name in names},
    "calls": {code: outcome(lambda: exec(code, {})) for code in calls},
}))
"""

ENVIRONMENTS = ["core", *sorted(name for name in EXTRAS if name != "dev")]
"""The core alone, and each extra alone (``dev`` is the environment the tests run in)."""


def _allowed(environment: str) -> set[str]:
    return set(modules([] if environment == "core" else [environment]))


def _hidden(environment: str) -> list[str]:
    """The top-level modules of the installed distributions the environment does not bring."""
    allowed = _allowed(environment)
    return sorted(
        name
        for name in metadata.packages_distributions()
        if name not in allowed
        and name not in sys.stdlib_module_names
        and name.isidentifier()
        and not name.startswith("_")
    )


@cache
def _results(environment: str, directory: str) -> dict[str, dict[str, list[str]]]:
    found = subprocess.run(
        [sys.executable, "-c", PROBE],
        input=json.dumps([_hidden(environment), PUBLIC_MODULES, list(CALLS)]),
        cwd=directory,
        capture_output=True,
        text=True,
        check=False,
    )
    assert found.returncode == 0, found.stderr
    results: dict[str, dict[str, list[str]]] = json.loads(found.stdout)
    return results


@pytest.fixture(scope="module")
def workdir(tmp_path_factory: pytest.TempPathFactory) -> str:
    """A directory with a capture, an MF4 file and a DBC file, where each probe runs."""
    directory = tmp_path_factory.mktemp("extras")
    shutil.copy(ROOT / "examples" / "capture.log", directory)
    (directory / "one.dbc").write_text(DBC)
    import can

    with can.Logger(str(directory / "one.mf4")) as logger:  # python-can writes it with asammdf
        logger(can.Message(timestamp=1.0, arbitration_id=8, is_extended_id=False, data=b"\0"))
    return str(directory)


def _problem(outcome: list[str], allowed: set[str], what: str) -> str | None:
    """What is wrong with an outcome that is not ``ok``: None when it is a
    `MissingExtraError` naming an extra that brings the missing module, which is hidden."""
    if outcome[0] != "missing":
        return f"{what}: {outcome[1]}"
    _, module, extra, _message = outcome
    top = module.partition(".")[0]
    if top in allowed:
        return f"{what}: {module} is installed, yet: {outcome[3]}"
    if extra not in EXTRAS or top not in modules([extra]):
        return f"{what}: names the {extra!r} extra, which does not bring {module}"
    return None


@pytest.mark.parametrize("environment", ENVIRONMENTS)
def test_every_public_module_imports_or_names_the_extra(environment: str, workdir: str) -> None:
    allowed = _allowed(environment)
    results = _results(environment, workdir)["modules"]
    assert sorted(results) == PUBLIC_MODULES
    problems = []
    for name, outcome in results.items():
        if outcome[0] == "ok":
            continue
        problem = _problem(outcome, allowed, name)
        if problem is None and outcome[2] in ENVIRONMENTS:
            # where the named extra is installed, the module is not what the import misses
            there = _results(outcome[2], workdir)["modules"][name]
            if there[0] != "ok" and there[0] == "missing" and there[1] == outcome[1]:
                problem = f"{name}: misses {outcome[1]} with the {outcome[2]} extra too"
        if problem is not None:
            problems.append(problem)
    assert problems == []


@pytest.mark.parametrize("environment", ENVIRONMENTS)
def test_public_functions_work_or_name_the_extra(environment: str, workdir: str) -> None:
    allowed = _allowed(environment)
    problems = []
    for code, outcome in _results(environment, workdir)["calls"].items():
        if CALLS[code] <= allowed:
            if outcome != ["ok"]:
                problems.append(f"{code}: {outcome[1]}")
        elif (problem := _problem(outcome, allowed, code)) is not None:
            problems.append(problem)
        elif outcome[1].partition(".")[0] not in CALLS[code]:
            problems.append(f"{code}: misses {outcome[1]}, not one of {sorted(CALLS[code])}")
    assert problems == []


def test_the_probe_hides_what_the_environment_does_not_bring(workdir: str) -> None:
    hidden = _hidden("arrow")
    assert {"pandas", "can", "matplotlib", "cantools"} <= set(hidden)
    assert not {"pyarrow", "numpy", "veronte4x"} & set(hidden)
    assert set(CALLS) and all(isinstance(needs, set) for needs in CALLS.values())
