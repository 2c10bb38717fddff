"""The page "Using veronte4x with other tools" runs: its bash blocks as commands, its Python
blocks in order in one namespace, in a directory of their own (``sh`` blocks are shown
only: they need a CAN interface)."""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
PAGE = ROOT / "docs" / "other-tools.md"
BLOCK = re.compile(r"^```(\w+)\n(.*?)^```", re.MULTILINE | re.DOTALL)


def test_every_block_runs(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    (tmp_path / "examples").symlink_to(ROOT / "examples")
    (tmp_path / "bus.toml").write_text('[veronte]\npwm_packing = "msb_first"\n')
    (tmp_path / "payload.dbc").write_bytes((ROOT / "tests/capture/data/payload.dbc").read_bytes())
    bin_dir = Path(sys.executable).parent
    environment = {**os.environ, "PATH": f"{bin_dir}{os.pathsep}{os.environ['PATH']}"}
    monkeypatch.chdir(tmp_path)
    namespace: dict[str, object] = {}
    blocks = BLOCK.findall(PAGE.read_text())
    assert [kind for kind, _ in blocks].count("bash") >= 5
    for kind, code in blocks:
        if kind == "bash":
            for line in code.splitlines():
                done = subprocess.run(
                    ["bash", "-c", line.replace("python ", f"{sys.executable} ", 1)],
                    capture_output=True,
                    text=True,
                    env=environment,
                    check=False,
                )
                assert done.returncode == 0, (line, done.stderr)
        elif kind == "python":
            exec(compile(code, str(PAGE), "exec"), namespace)
    assert (tmp_path / "veronte.dbc").exists()
    assert (tmp_path / "installation.dbc").read_text() != (tmp_path / "veronte.dbc").read_text()
    assert (tmp_path / "flight.csv").read_text().startswith('"time",')


def test_the_page_says_where_the_files_its_blocks_use_are() -> None:
    """``--dbc payload.dbc`` is runnable only where the reader finds the file: the page
    names the one the test above copies, and it is there."""
    text = PAGE.read_text()
    assert "`tests/capture/data/payload.dbc`" in text
    assert text.index("`tests/capture/data/payload.dbc`") < text.index("--dbc payload.dbc")
    assert (ROOT / "tests/capture/data/payload.dbc").is_file()
