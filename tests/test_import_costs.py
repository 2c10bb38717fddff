"""What starting costs: importing a public module, or a call that does not need an optional
package, leaves the heavy optional packages unimported (issue 36, "lazy where laziness is
free"). Each check runs in a fresh interpreter and compares sets of module names, never a
time (the times are `benchmarks/bench_cold.py`'s)."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from tests.dsdl_support import write_namespace

ROOT = Path(__file__).resolve().parent.parent
CAPTURE = ROOT / "examples" / "capture.log"

HEAVY = frozenset(
    {
        "asammdf",
        "asyncio",
        "can",  # python-can, which itself imports asyncio, pandas, polars and asammdf
        "cantools",
        "distributed",
        "dronecan",  # the dronecan package (pydronecan), not veronte4x.dronecan
        "matplotlib",
        "msgpack",
        "numpy",
        "pandas",
        "polars",
        "pyarrow",
        "pyarrow.dataset",
        "rich",
        "tqdm",
    }
)
"""Optional packages that cost tens to hundreds of milliseconds to import."""

PUBLIC = (
    "veronte4x",
    "veronte4x.codec",
    "veronte4x.dronecan",
    "veronte4x.capture",
    "veronte4x.client",
    "veronte4x.arbiter",
    "veronte4x.node",
    "veronte4x.simulator",
    "veronte4x.variables",
    "veronte4x.cli",
)

PROBE = """
import json, sys
heavy = set(json.loads(sys.argv[1]))
steps = json.loads(sys.argv[2])
found = {}
for name, code in steps:
    exec(code, {})
    found[name] = sorted(heavy & set(sys.modules))
print(json.dumps(found))
"""


def heavy_after(
    steps: list[tuple[str, str]],
    heavy: frozenset[str] = HEAVY,
    environ: dict[str, str] | None = None,
) -> dict[str, set[str]]:
    """Run ``steps`` (name, code) in turn in one fresh interpreter (with ``environ`` for
    its environment if given); the ``heavy`` modules loaded after each. Importing is
    monotonic: a module that a step alone would import is loaded after that step here
    too, so a step that adds nothing proves its code alone imports none."""
    done = subprocess.run(
        [sys.executable, "-c", PROBE, json.dumps(sorted(heavy)), json.dumps(steps)],
        capture_output=True,
        text=True,
        cwd=ROOT,
        timeout=300,
        env=environ,
    )
    assert done.returncode == 0, done.stderr[-2000:]
    found: dict[str, list[str]] = json.loads(done.stdout.splitlines()[-1])
    return {name: set(modules) for name, modules in found.items()}


def test_importing_a_public_module_imports_no_heavy_package() -> None:
    found = heavy_after([(module, f"import {module}") for module in PUBLIC])
    assert found == {module: set() for module in PUBLIC}


def test_decoding_a_candump_file_per_frame_imports_no_heavy_package() -> None:
    found = heavy_after(
        [
            (
                "capture.read",
                f"from veronte4x import capture; list(capture.read({str(CAPTURE)!r}))",
            ),
            (
                "veronte4x decode",
                "import contextlib, io; from veronte4x.cli import main\n"
                "with contextlib.redirect_stdout(io.StringIO()):\n"
                f"    main(['decode', {str(CAPTURE)!r}])",
            ),
        ]
    )
    assert found == {"capture.read": set(), "veronte4x decode": set()}


@pytest.mark.parametrize("call", ["read_tables", "to_parquet"])
def test_arrow_calls_import_only_what_they_need(call: str, tmp_path: Path) -> None:
    arguments = f"{str(CAPTURE)!r}" + (
        f", {str(tmp_path / 'out')!r}" if call == "to_parquet" else ""
    )
    found = heavy_after([(call, f"from veronte4x import capture; capture.{call}({arguments})")])
    # pandas is pyarrow's: pyarrow (pandas-shim.pxi) imports it, when it is installed, on
    # building its first array in a process; nothing of veronte4x asks for it.
    assert found[call] - {"pandas"} == {"numpy", "pyarrow"}


DSDL_COMPILER = frozenset(
    {"veronte4x.dronecan.generate", "veronte4x.dronecan.parser", "veronte4x.dronecan.types"}
)
"""What parses DSDL and turns it into classes and schemas: needed for the user's DSDL only,
the first time it is loaded (every shipped type was generated ahead of time; a load from
the disk cache runs what it stored)."""


def test_the_dsdl_compiler_loads_for_user_dsdl_only(tmp_path: Path) -> None:
    root = write_namespace(tmp_path, "com", {"20990.Ping": "uint8 count\n"})
    environ = {
        **os.environ,
        "HOME": str(tmp_path),  # no vendor root of the user's own home directory
        "VERONTE4X_CACHE_DIR": "off",
    }
    environ.pop("VERONTE4X_DSDL_PATH", None)
    decode = (
        "import contextlib, io; from veronte4x.cli import main\n"
        "with contextlib.redirect_stdout(io.StringIO()):\n"
        f"    main(['decode', {str(CAPTURE)!r}])"
    )
    found = heavy_after(
        [
            ("imports", "; ".join(f"import {module}" for module in PUBLIC)),
            ("default set", "from veronte4x import dronecan; dronecan.default_types()"),
            ("veronte4x decode", decode),
            ("load_dsdl", f"from veronte4x import dronecan; dronecan.load_dsdl({str(root)!r})"),
        ],
        DSDL_COMPILER,
        environ,
    )
    assert found == {
        "imports": set(),
        "default set": set(),
        "veronte4x decode": set(),
        "load_dsdl": DSDL_COMPILER,
    }


def test_a_load_from_the_cache_parses_and_generates_nothing(tmp_path: Path) -> None:
    root = write_namespace(tmp_path, "com", {"20990.Ping": "uint8[<4] counts\n"})
    environ = {**os.environ, "HOME": str(tmp_path), "VERONTE4X_CACHE_DIR": str(tmp_path)}
    environ.pop("VERONTE4X_DSDL_PATH", None)
    load_and_use = (
        "from veronte4x import dronecan\n"
        f"types = dronecan.TypeSet.standard().with_dsdl({str(root)!r})\n"
        "assert types.by_class[types['com.Ping']].decode(b'\\x07').counts == b'\\x07'"
    )
    steps = [("load and use", load_and_use)]
    assert heavy_after(steps, DSDL_COMPILER, environ) == {"load and use": DSDL_COMPILER}
    assert heavy_after(steps, DSDL_COMPILER, environ) == {"load and use": set()}  # cached


def test_a_command_imports_its_own_module_only() -> None:
    others = frozenset(
        {"veronte4x.cli.esc", "veronte4x.cli.simulate", "veronte4x.client", "veronte4x.arbiter"}
    )
    decode = (
        "import contextlib, io; from veronte4x.cli import main\n"
        "with contextlib.redirect_stdout(io.StringIO()):\n"
        f"    main(['decode', {str(CAPTURE)!r}])"
    )
    found = heavy_after([("veronte4x decode", decode)], others | {"veronte4x.cli.decode"})
    assert found == {"veronte4x decode": {"veronte4x.cli.decode"}}


def test_the_capture_package_loads_the_arbiter_for_a_replay_only() -> None:
    config = str(ROOT / "examples" / "arbiter.toml")
    found = heavy_after(
        [
            ("import", "import veronte4x.capture"),
            (
                "replay",
                f"from veronte4x import capture; capture.replay({str(CAPTURE)!r}, {config!r})",
            ),
        ],
        frozenset({"veronte4x.arbiter"}),
    )
    assert found == {"import": set(), "replay": {"veronte4x.arbiter"}}


def test_a_file_a_built_in_format_recognises_scans_no_installed_package() -> None:
    """The readers of other packages (entry points) come after the built-in ones: a file
    that one of these claims and recognises is read without importlib.metadata."""
    read = f"from veronte4x import capture; list(capture.read({str(CAPTURE)!r}))"
    found = heavy_after([("capture.read", read)], frozenset({"importlib.metadata"}))
    assert found == {"capture.read": set()}
