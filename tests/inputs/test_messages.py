"""Error lines of the command line in the user's words, not the code's: the file and key the
user wrote, one line, the documented exit code."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.inputs.support import EXAMPLES, run

CONFIGS = [
    (
        '[arbiter]\nmethod = "best"\n',
        "[arbiter] method = 'best': expected one of 'always best', 'change if worst', "
        "'round robin', 'fixed 0', 'fixed 1', 'fixed 2', 'fixed while ok'",
    ),
    ("[arbiter]\nholding_time = -1\n", "[arbiter] holding_time = -1: expected a finite number"),
    ("[arbiter]\nfoo = 1\n", "[arbiter] foo is not a setting of the arbiter"),
    ("x = [", "not TOML: Invalid value (at end of document)"),
    ("[other]\n", "tables other are not read: only [arbiter] is"),
    ("[arbiter]\nautopilot_ids = [1, 2]\n", "[arbiter] autopilot_ids = [1, 2]: expected four"),
    (
        "[arbiter]\nvariables = [{weight = 1.0, foo = 2}]\n",
        "[arbiter] variables[0]: foo are not settings of a variable (expected weight, absolute, "
        "max_error)",
    ),
    ("arbiter = 1\n", "not an arbiter configuration"),
    ("[arbiter]\nvariables = 1\n", "not an arbiter configuration"),
]


@pytest.mark.parametrize(("text", "what"), CONFIGS)
def test_a_bad_arbiter_configuration(tmp_path: Path, text: str, what: str) -> None:
    path = tmp_path / "arbiter.toml"
    path.write_text(text)
    result = run("replay", str(EXAMPLES / "capture.log"), "--config", str(path))
    assert result.returncode == 2
    [line] = result.stderr.splitlines()
    assert line.startswith(f"veronte4x: {path}: {what}")
    assert line.endswith("; fix the arbiter configuration (see the Replay docs)")
    assert "ArbiterConfig" not in line and "(file)" not in line
    assert result.stdout == ""
