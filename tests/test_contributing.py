"""The contributors' page does what it says: each change it shows, made on a scratch copy of
the package exactly as the page writes it, works (docs/contributing/index.md)."""

from __future__ import annotations

import json
import re
import shutil
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
PAGE = ROOT / "docs" / "contributing" / "index.md"
_BLOCK = re.compile(r"^( *)```python\n(.*?)^\1```", re.MULTILINE | re.DOTALL)
_WHERE = re.compile(r"# (\S+): (append|import|in \w+)\n")
_TIMEOUT = 600  # a hang guard, not a timed assertion


def _blocks(section: str) -> list[tuple[str, str, str]]:
    """(path, where, code) of each code block of one section of the page."""
    text = PAGE.read_text()
    start = text.index(f"## {section}\n")
    end = text.find("\n## ", start + 1)
    found = []
    for indent, code in _BLOCK.findall(text[start : end if end > 0 else None]):
        code = textwrap.dedent("".join(line[len(indent) :] for line in code.splitlines(True)))
        where = _WHERE.match(code)
        assert where is not None, f"a block of {section!r} does not say where it goes"
        found.append((where.group(1), where.group(2), code[where.end() :]))
    return found


def _apply(root: Path, path: str, where: str, code: str) -> None:
    """Make one change of the page in the scratch copy under ``root``."""
    target = root / path
    text = target.read_text() if target.exists() else ""
    if where == "append":
        text += code
    elif where == "import":
        head = "from __future__ import annotations\n"
        assert head in text, path
        text = text.replace(head, head + code, 1)
    else:
        name = where.removeprefix("in ")
        opening = re.search(rf"^{name}\b[^\n]*= [(\[]\n", text, re.MULTILINE)
        assert opening is not None, (path, name)
        closing = re.compile(r"^[)\]]", re.MULTILINE).search(text, opening.end())
        assert closing is not None, (path, name)
        text = text[: closing.start()] + code + text[closing.start() :]
    target.parent.mkdir(parents=True, exist_ok=True)
    target.write_text(text)


@pytest.fixture
def scratch(tmp_path: Path) -> Path:
    """A scratch copy of the package's sources."""
    shutil.copytree(
        ROOT / "src" / "veronte4x",
        tmp_path / "src" / "veronte4x",
        ignore=shutil.ignore_patterns("__pycache__"),
    )
    return tmp_path


def _run(scratch: Path, *args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, *args],
        cwd=scratch,
        env={"PYTHONPATH": str(scratch / "src"), "PATH": "/usr/bin:/bin"},
        capture_output=True,
        text=True,
        timeout=_TIMEOUT,
        check=False,
    )


_FRAME_TYPE_CHECK = """
import sys
from veronte4x import capture, codec
from veronte4x.codec import Sender
AP, ARB = Sender.AUTOPILOT, Sender.ARBITER

GOLDEN = [
{golden}]
assert len(GOLDEN) >= 2
for hex_data, sender, message in GOLDEN:
    data = bytes.fromhex(hex_data)
    assert codec.decode(data, sender=sender) == message, hex_data
    assert codec.DEFAULT_CODEC._checked(data, sender=sender) == message, hex_data
    assert codec.encode(message) == data, hex_data

# The fast path decodes it without the checked decoder.
def refuse(*args, **kwargs):
    raise AssertionError("the checked decoder was called")
codec.decode.__globals__["_checked"] = refuse
assert codec.decode(bytes.fromhex(GOLDEN[0][0]), sender=AP) == GOLDEN[0][2]
codec.decode.__globals__["_checked"] = codec.DEFAULT_CODEC._checked

# Its command can no longer be declared: its layout is public.
try:
    codec.Layout(20, "Mine", [codec.unsigned("x", 8)])
    codec.Codec(layouts=[codec.Layout(20, "Mine", [codec.unsigned("x", 8)])])
except codec.LayoutError as error:
    assert "command 20 has a public layout" in str(error), error
else:
    raise AssertionError("a layout declared for command 20 was taken")

# The column-wise decoder: a table of its own, equal to the records decoded one by one.
with open("capture.log", "w") as log:
    for number, (hex_data, sender, _) in enumerate(GOLDEN):
        can_id = "0FF" if sender is ARB else "008"
        log.write(f"({{number}}.000000) can0 {{can_id}}#{{hex_data.upper()}}\\n")
    log.write("(9.000000) can0 008#00FF01\\n")
tables = capture.read_tables("capture.log")
assert tables["Heartbeat"].num_rows == len(GOLDEN), tables.keys()
assert tables["Heartbeat"].column("counter").to_pylist() == [m.counter for _, _, m in GOLDEN]
records = capture.tables_from_records(capture.read("capture.log"))
assert set(records) == set(tables)
for name, table in tables.items():
    assert table.equals(records[name]), name

# The protocol reference's message-type table.
sys.path.insert(0, sys.argv[1])
from docgen import codec as docs
assert "| 20 | `Heartbeat` | 6 bytes |" in docs.command_table()
assert "| 21-255 | unknown |" in docs.command_table()
print("ok")
"""


def test_adding_a_frame_type(scratch: Path) -> None:
    blocks = _blocks("Adding a frame type")
    golden = ""
    for path, where, code in blocks:
        if path.startswith("tests/"):
            golden += code
        else:
            _apply(scratch, path, where, code)
    (scratch / "check.py").write_text(_FRAME_TYPE_CHECK.format(golden=golden))
    done = _run(scratch, "check.py", str(ROOT / "docs" / "_hooks"))
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip().endswith("ok")
    listed = _run(scratch, "-m", "veronte4x", "list", "--json")
    assert listed.returncode == 0, listed.stderr
    messages = json.loads(listed.stdout)["veronte"]["messages"]
    heartbeat = [m for m in messages if m["message"] == "Heartbeat"]
    assert heartbeat == [
        {
            "message": "Heartbeat",
            "command": 20,
            "from": "any Veronte ID",
            "bytes": "6",
            "fields": ["command", "counter", "load"],
            "source": "an example of the contributors' page, not a message of the manual",
        }
    ]


def test_adding_a_command(scratch: Path) -> None:
    for path, where, code in _blocks("Adding a command"):
        _apply(scratch, path, where, code)
    (scratch / "capture.log").write_text(
        "(0.000000) can0 008#00FF01\n(0.100000) can0 009#00FF00\n(0.200000) can0 0FF#0109\n"
    )
    done = _run(scratch, "-m", "veronte4x", "count", "capture.log")
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines() == ["Ready 2", "VersionResponse 1"]
    missing = _run(scratch, "-m", "veronte4x", "count", "missing.log")
    assert missing.returncode == 2
    assert missing.stderr.count("\n") == 1 and "missing.log" in missing.stderr
    helped = _run(scratch, "-m", "veronte4x", "--help")
    assert "count" in helped.stdout


def test_every_block_says_where_it_goes() -> None:
    sections = ["Adding a frame type", "Adding a command"]
    assert all(_blocks(section) for section in sections)
    assert "## Adding a log format" in PAGE.read_text()
