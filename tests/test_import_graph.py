"""The package layering: no upward import and no circle between packages, at module level or
inside functions (every ``import`` statement of every module under ``src/veronte4x``, read
with `ast`), and the modules a message's HTML view loads.

The layers, bottom to top (a package or a module directly under ``veronte4x``):

1. Modules that import nothing of the library: words, numbers, times, units, files, codegen,
   sockets.
2. ``errors`` (its messages count with ``words``).
3. What every protocol may use: the root package (it re-exports the errors), ``extras`` (the
   optional dependencies), ``values`` (a field's value as machines and people read it).
4. ``progress`` (needs ``extras``) and ``display`` (the HTML table builders, needs ``values``).
5. The two protocols and the manual's data, independent of each other: ``codec`` (Veronte),
   ``dronecan`` (DroneCAN), ``variables``.
6. ``mcastbus``: the ``mcast:`` bus of pydronecan and ArduPilot SITL, on ``dronecan``'s
   datagram, a python-can bus that ``canbus`` opens.
7. What is built on one protocol: ``arbiter`` (the Veronte arbiter, on ``codec``), ``node``
   (what every DroneCAN node does, on ``dronecan``), ``canbus`` (CAN bus I/O for DroneCAN
   frames).
8. The applications, independent of one another: ``capture`` (logs and live captures of
   both protocols), ``client`` (the ground station: ESCs, parameters, firmware), ``simulator``
   (a simulated ESC). A broken capture module cannot break the ESC tool, and the client and
   the simulated ESC share only ``node``.
9. ``cli``, then ``__main__``.

An import may only point to a lower layer; two packages of one layer never import each
other. Imports by name (`importlib.import_module`) are outside this test: the codec's fast
paths and the reader registry load modules of their own package that way.
"""

from __future__ import annotations

import ast
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

SOURCE = Path(__file__).resolve().parent.parent / "src" / "veronte4x"

LAYERS: tuple[tuple[str, ...], ...] = (
    ("words", "numbers", "times", "units", "files", "codegen", "sockets"),
    ("errors",),
    ("veronte4x", "extras", "values"),
    ("progress", "display"),
    ("codec", "dronecan", "variables"),
    ("mcastbus",),
    ("arbiter", "node", "canbus"),
    ("capture", "client", "simulator"),
    ("cli",),
    ("__main__",),
)
"""Bottom to top; the module docstring says why."""

LEVEL = {name: level for level, names in enumerate(LAYERS) for name in names}


def _module_name(path: Path) -> str:
    parts = list(path.relative_to(SOURCE.parent).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


MODULES = {_module_name(path): path for path in sorted(SOURCE.rglob("*.py"))}


def _unit(module: str) -> str:
    """The package (or module directly under ``veronte4x``) a module belongs to."""
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else parts[0]


def _known(name: str) -> str | None:
    """The module of the library an imported name is, or is in; None outside the library."""
    while name not in MODULES:
        if "." not in name:
            return None
        name = name.rsplit(".", 1)[0]
    return name


def _imports(module: str) -> Iterator[tuple[int, str]]:
    """Line and module of the library of every import in ``module``, wherever it stands."""
    path = MODULES[module]
    package = module if path.name == "__init__.py" else module.rsplit(".", 1)[0]
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"), str(path))):
        if isinstance(node, ast.Import):
            names = [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                anchor = package.split(".")[: len(package.split(".")) - node.level + 1]
                base = ".".join([*anchor, *([base] if base else [])])
            # ``from veronte4x import codec`` imports the module veronte4x.codec
            names = [
                f"{base}.{a.name}" if f"{base}.{a.name}" in MODULES else base for a in node.names
            ]
        else:
            continue
        for name in names:
            found = _known(name)
            if found is not None and found != module:
                yield node.lineno, found


ARROWS = [
    (module, line, target)
    for module in MODULES
    for line, target in _imports(module)
    if _unit(module) != _unit(target)
]
"""Every import from one package to another: (importing module, line, imported module)."""


def test_every_package_has_a_layer() -> None:
    assert sorted({_unit(m) for m in MODULES} - set(LEVEL)) == []
    assert sorted(set(LEVEL) - {_unit(m) for m in MODULES}) == []  # no stale names


def test_imports_are_read_wherever_they_stand() -> None:
    """At module level, under ``if TYPE_CHECKING:`` and inside a method alike."""
    assert {"veronte4x.display", "veronte4x.times", "veronte4x.dronecan.transfer"} <= {
        target for _, target in _imports("veronte4x.dronecan.view")
    }
    assert "veronte4x.dronecan.view" in {t for _, t in _imports("veronte4x.dronecan.transfer")}


def test_no_import_points_up_or_sideways() -> None:
    wrong = [
        f"{source}:{line} -> {target} ({_unit(source)} is layer {LEVEL[_unit(source)]}, "
        f"{_unit(target)} layer {LEVEL[_unit(target)]})"
        for source, line, target in ARROWS
        if LEVEL[_unit(target)] >= LEVEL[_unit(source)]
    ]
    assert wrong == []


def test_no_circle_between_packages() -> None:
    graph: dict[str, set[str]] = {}
    for source, _, target in ARROWS:
        graph.setdefault(_unit(source), set()).add(_unit(target))
    done: set[str] = set()

    def circle(unit: str, path: tuple[str, ...]) -> tuple[str, ...] | None:
        if unit in path:
            return (*path[path.index(unit) :], unit)
        if unit in done:
            return None
        for target in sorted(graph.get(unit, ())):
            found = circle(target, (*path, unit))
            if found is not None:
                return found
        done.add(unit)
        return None

    assert [c for unit in sorted(graph) if (c := circle(unit, ())) is not None] == []


_SHOW = """
import sys
{setup}
html = message._repr_html_()
assert html.startswith('<table class="dataframe veronte4x">'), html
print(" ".join(sorted(name for name in sys.modules if name.startswith("veronte4x."))))
"""


@pytest.mark.parametrize(
    ("setup", "packages"),
    [
        pytest.param(
            "from veronte4x import codec\n"
            "message = codec.decode(bytes.fromhex('0000cdcccc3d'), sender=codec.Sender.AUTOPILOT)",
            ("dronecan", "capture", "client", "canbus", "node", "arbiter"),
            id="veronte",
        ),
        pytest.param(
            "from veronte4x import dronecan\n"
            "message = dronecan.EscStatus(0, 16.203125, 2.5, 310.25, 1200, 40, 2)",
            ("codec", "capture", "client", "canbus", "node"),
            id="dronecan",
        ),
    ],
)
def test_showing_a_message_loads_only_its_protocol(setup: str, packages: tuple[str, ...]) -> None:
    """A fresh interpreter: one message's HTML view (Jupyter's ``_repr_html_``) loads the
    message's protocol and the display, nothing of the other protocol or the applications."""
    script = _SHOW.format(setup=setup)
    run = subprocess.run(
        [sys.executable, "-c", script], capture_output=True, text=True, check=False, timeout=300
    )
    assert run.returncode == 0, run.stderr
    loaded = run.stdout.split()
    assert "veronte4x.display" in loaded
    assert [m for m in loaded if _unit(m) in packages] == []
