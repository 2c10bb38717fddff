"""Every ``>>>`` example of the API reference renders as code: it sits in a Google-style
``Examples:`` section (mkdocstrings renders a singular ``Example:`` as prose, which garbles
``>>>`` into nested quotes and ``[...]`` into broken cross-references). pytest runs them all
as doctests (``--doctest-modules`` over src)."""

from __future__ import annotations

import ast
from pathlib import Path

SRC = Path(__file__).resolve().parent.parent / "src" / "veronte4x"


def _docstrings(path: Path) -> list[tuple[str, str]]:
    tree = ast.parse(path.read_text())
    nodes = [tree, *(n for n in ast.walk(tree) if isinstance(n, (ast.ClassDef, ast.FunctionDef)))]
    found = []
    for node in nodes:
        text = ast.get_docstring(node)
        if text:
            found.append((getattr(node, "name", path.stem), text))
    return found


def test_every_example_is_in_an_examples_section() -> None:
    misplaced = []
    for path in sorted(SRC.rglob("*.py")):
        for name, text in _docstrings(path):
            lines = text.splitlines()
            prompts = [i for i, line in enumerate(lines) if line.lstrip().startswith(">>>")]
            if not prompts:
                continue
            headers = [i for i, line in enumerate(lines) if line.strip() == "Examples:"]
            if not headers or headers[0] > prompts[0]:
                misplaced.append(f"{path.relative_to(SRC)}: {name}")
    assert misplaced == []
