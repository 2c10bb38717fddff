"""Every snippet of the docs runs as pasted (issue 39, item 7): each fenced ``python``
block of docs/**/*.md alone in a fresh namespace (so it imports what it uses), each
``bash`` or ``sh`` block line by line in bash (exit code 0), in a directory with the
examples, the demo vehicle's ``arbiter.toml`` and a demo flight as ``flight.log`` and
``examples/flight.log``.

A block that is not meant to run alone says so on the line before its fence, with a reason
a reader sees in the page's source:

- ``<!-- snippet: raises NAME -->``: it shows an error; it must raise ``NAME``;
- ``<!-- snippet: not run: REASON -->``: it needs what a test cannot give (a CAN interface,
  a Dask cluster, a frame of the reader's own) or continues the block before it.

Pages whose blocks run as one session have a test of their own (`PAGE_TESTS`)."""

from __future__ import annotations

import os
import re
import runpy
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
DOCS = ROOT / "docs"
BLOCK = re.compile(r"^(?:<!-- snippet: (.*?) -->\n)?```(\w+)\n(.*?)^```", re.MULTILINE | re.DOTALL)
PAGE_TESTS = {
    "other-tools.md": "tests/test_other_tools_page.py",
    "fleet.md": "tests/test_fleet_page.py",
    "dronecan/vendor.md": "tests/dronecan/test_vendor_page.py",
    "changelog.md": "no code to run",
}
"""Pages run by a test of their own, which runs their blocks in order, in one session."""


SHELLS = ("bash", "sh")
"""The fence names of shell blocks."""


def _snippets(kinds: tuple[str, ...]) -> list[tuple[str, str | None, str]]:
    """(page#index, marker, code) of every block of these kinds outside `PAGE_TESTS`."""
    found = []
    for page in sorted(DOCS.rglob("*.md")):
        name = page.relative_to(DOCS).as_posix()
        if name in PAGE_TESTS or name.startswith("_"):
            continue
        blocks = BLOCK.findall(page.read_text(encoding="utf-8"))
        for index, (marker, kind, code) in enumerate(blocks):
            if kind in kinds:
                found.append((f"{name}#{index}", marker or None, code))
    return found


SNIPPETS = _snippets(("python",))
SHELL_SNIPPETS = _snippets(SHELLS)


def _run(snippets: list[tuple[str, str | None, str]]) -> list[tuple[str, str | None, str]]:
    return [s for s in snippets if not (s[1] or "").startswith("not run")]


def test_the_pages_with_tests_of_their_own_exist() -> None:
    for page, test in PAGE_TESTS.items():
        assert (DOCS / page).exists()
        assert test == "no code to run" or (ROOT / test).exists()


def test_every_marker_is_one_the_rule_knows() -> None:
    for where, marker, _ in SNIPPETS + SHELL_SNIPPETS:
        assert marker is None or re.fullmatch(r"raises \w+|not run: .+", marker), where


@pytest.fixture(scope="module")
def demo(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A directory as `make demo` leaves the checkout: the examples and a demo flight (30
    s, the selected autopilot failing at 15 s)."""
    root = tmp_path_factory.mktemp("docs")
    examples = root / "examples"
    examples.mkdir()
    for item in (ROOT / "examples").iterdir():
        (examples / item.name).symlink_to(item)
    make = runpy.run_path(str(ROOT / "examples" / "make_capture.py"))
    make["generate"](0.5, 15.0, 4).write(root / "flight.log")
    (examples / "flight.log").symlink_to(root / "flight.log")
    (root / "arbiter.toml").symlink_to(ROOT / "examples" / "arbiter.toml")
    return root


@pytest.mark.parametrize(
    ("where", "marker", "code"), _run(SNIPPETS), ids=[s[0] for s in _run(SNIPPETS)]
)
def test_a_snippet_runs_alone(
    where: str, marker: str | None, code: str, demo: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(demo)
    compiled = compile(code, where, "exec")
    if marker is None:
        exec(compiled, {"__name__": "__snippet__"})
        return
    expected = marker.removeprefix("raises ")
    with pytest.raises(Exception) as raised:
        exec(compiled, {"__name__": "__snippet__"})
    assert type(raised.value).__name__ == expected, where


@pytest.mark.parametrize(
    ("where", "marker", "code"), _run(SHELL_SNIPPETS), ids=[s[0] for s in _run(SHELL_SNIPPETS)]
)
def test_a_shell_snippet_runs_line_by_line(
    where: str, marker: str | None, code: str, demo: Path
) -> None:
    assert marker is None, f"{where}: a shell block is run or not run"
    environment = {
        **os.environ,
        "PATH": f"{Path(sys.executable).parent}{os.pathsep}{os.environ['PATH']}",
    }
    for line in code.splitlines():
        done = subprocess.run(
            ["bash", "-c", re.sub(r"^python ", f"{sys.executable} ", line)],
            cwd=demo,
            capture_output=True,
            text=True,
            env=environment,
            check=False,
        )
        assert done.returncode == 0, (where, line, done.stderr)
