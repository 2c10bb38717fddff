"""examples/esc_asyncio.py runs the asyncio client against simulated ESCs and exits 0."""

from __future__ import annotations

import runpy
from pathlib import Path

import pytest

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "esc_asyncio.py"

EXPECTED = """\
nodes: [21, 22, 23, 24]
esc_index: {21: 0, 22: 1, 23: 2, 24: 3}
node 21: updated True, image CRC 0x4b98d46f9508cd65
node 22: updated True, image CRC 0x4b98d46f9508cd65
node 21 again: updated False
"""


def test_example_output(capsys: pytest.CaptureFixture[str]) -> None:
    module = runpy.run_path(str(EXAMPLE))
    assert module["main"](channel="test-esc-asyncio") == 0
    assert capsys.readouterr().out == EXPECTED
