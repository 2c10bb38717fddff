"""Every Python snippet of the docs runs as pasted (issue 39, item 7): each fenced
``python`` block of docs/**/*.md, alone in a fresh namespace (so it imports what it uses),
in a directory with the examples and a demo flight as ``flight.log`` and
``examples/flight.log``.

A block that is not meant to run alone says so on the line before its fence, with a reason
a reader sees in the page's source:

- ``<!-- snippet: raises NAME -->``: it shows an error; it must raise ``NAME``;
- ``<!-- snippet: not run: REASON -->``: it needs what a test cannot give (a CAN interface,
  a Dask cluster, a frame of the reader's own) or continues the block before it.

Pages whose blocks run as one session have a test of their own (`PAGE_TESTS`)."""

from __future__ import annotations

import re
import runpy
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


def _snippets() -> list[tuple[str, str | None, str]]:
    """(page#index, marker, code) of every Python block outside `PAGE_TESTS`."""
    found = []
    for page in sorted(DOCS.rglob("*.md")):
        name = page.relative_to(DOCS).as_posix()
        if name in PAGE_TESTS or name.startswith("_"):
            continue
        blocks = BLOCK.findall(page.read_text(encoding="utf-8"))
        for index, (marker, kind, code) in enumerate(blocks):
            if kind == "python":
                found.append((f"{name}#{index}", marker or None, code))
    return found


SNIPPETS = _snippets()


def test_the_pages_with_tests_of_their_own_exist() -> None:
    for page, test in PAGE_TESTS.items():
        assert (DOCS / page).exists()
        assert test == "no code to run" or (ROOT / test).exists()


def test_every_marker_is_one_the_rule_knows() -> None:
    for where, marker, _ in SNIPPETS:
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
    return root


@pytest.mark.parametrize(
    ("where", "marker", "code"),
    [s for s in SNIPPETS if not (s[1] or "").startswith("not run")],
    ids=[s[0] for s in SNIPPETS if not (s[1] or "").startswith("not run")],
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
