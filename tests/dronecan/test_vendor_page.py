"""The page "Vendor namespaces" runs: its Python blocks in order in one namespace, then its
bash blocks as commands, in a directory of their own (``text`` blocks are shown only)."""

from __future__ import annotations

import os
import re
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pyarrow.parquet as pq
import pytest

from veronte4x import capture, dronecan

ROOT = Path(__file__).resolve().parents[2]
PAGE = ROOT / "docs" / "dronecan" / "vendor.md"
BLOCK = re.compile(r"^```(\w+)\n(.*?)^```", re.MULTILINE | re.DOTALL)


@pytest.fixture
def default_types() -> Iterator[None]:
    yield
    dronecan.set_default_types(dronecan.TypeSet.standard())


@pytest.mark.usefixtures("default_types")
def test_every_block_runs(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    (tmp_path / "examples").symlink_to(ROOT / "examples")
    bin_dir = Path(sys.executable).parent
    environment = {**os.environ, "PATH": f"{bin_dir}{os.pathsep}{os.environ['PATH']}"}
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("HOME", str(tmp_path))  # find_roots: no user's roots
    monkeypatch.delenv("VERONTE4X_DSDL_PATH", raising=False)
    namespace: dict[str, object] = {}
    blocks = BLOCK.findall(PAGE.read_text())
    assert [kind for kind, _ in blocks].count("python") == 4
    outputs = []
    for kind, code in blocks:
        if kind == "python":
            exec(compile(code, str(PAGE), "exec"), namespace)
        elif kind == "bash":
            for line in code.splitlines():
                done = subprocess.run(
                    ["bash", "-c", line], capture_output=True, text=True, env=environment,
                    check=False,
                )  # fmt: skip
                assert done.returncode == 0, (line, done.stderr)
                outputs.append(done.stdout)
    assert dronecan.default_types() is dronecan.TypeSet.standard()
    shown = next(code for kind, code in blocks if kind == "text" and "can0" in code)
    first, second = shown.splitlines()
    assert outputs[0].startswith(first.removesuffix("..."))
    assert outputs[0].splitlines()[1] == second
    table = pq.read_table(capture.dataset_files(tmp_path / "vendor-dataset", "Telemetry"))
    assert table.column("name").to_pylist() == ["front left"]  # text: a string
