"""The contributors' page does what it says: each change it shows, made on a scratch copy of
the package exactly as the page writes it, works (docs/contributing/index.md)."""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest
import tomli

from tests.plugin_support import install
from veronte4x.capture.frames import Frame

ROOT = Path(__file__).resolve().parent.parent
PAGE = ROOT / "docs" / "contributing" / "index.md"
_BLOCK = re.compile(r"^( *)```(?:python|toml)\n(.*?)^\1```", re.MULTILINE | re.DOTALL)
_WHERE = re.compile(r"# (\S+): (append|import|in \w+)\n")
_TIMEOUT = 600  # a hang guard, not a timed assertion


def _blocks(section: str) -> list[tuple[str, str, str]]:
    """(path, where, code) of each code block of one section of the page."""
    text = PAGE.read_text()
    start = text.index(f"## {section}\n")
    end = text.find("\n## ", start + 1)
    found = []
    for indent, code in _BLOCK.findall(text[start : end if end > 0 else None]):
        lines = code.splitlines(True)
        code = textwrap.dedent("".join(line[len(indent) :] or line for line in lines))
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
        # HOME: the scratch directory, whose vendor DSDL directories are none
        env={"PYTHONPATH": str(scratch / "src"), "PATH": "/usr/bin:/bin", "HOME": str(scratch)},
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


_LOG_FORMAT_CHECK = """
import gzip, shutil
from veronte4x import capture
from veronte4x.capture.frames import BadLine, Frame, Truncation
from veronte4x.errors import SourceError

# The frames of the frame text file are those of the same capture in candump text, and its
# comment, blank and bad lines are what the page says.
read = [f for f in capture.open_frames("capture.frames")]
same = [f for f in capture.open_frames("capture.log")]
assert [f for f in read if type(f) is Frame] == same, (len(read), len(same))
assert [f for f in read if type(f) is not Frame] == [
    BadLine(5, "1763737200.0 can0 08 00", "not TIME CHANNEL ID DATA"),
    BadLine(6, "1763737200.0 can0", "not TIME CHANNEL ID DATA"),
]
nodestatus = Frame(1763737299.25, "vcan1", 0x1001552A, bytes.fromhex("05000000000000c3"), True)
assert read[-1] == nodestatus

# Its records: those of the candump copy, and a record per bad line.
records = list(capture.read("capture.frames"))
expected = list(capture.read("capture.log"))
assert [r for r in records if r.error != "bad line"] == expected
bad = [r.detail for r in records if r.error == "bad line"]
assert bad == ["line 5: not TIME CHANNEL ID DATA: '1763737200.0 can0 08 00'",
               "line 6: not TIME CHANNEL ID DATA: '1763737200.0 can0'"], bad

# Column-wise: the tables of its records, the same tables as candump's but for the errors
# (the same schemas and rows; a dictionary column's dictionary may differ).
def same(table, other):
    return table.schema == other.schema and repr(table.to_pylist()) == repr(other.to_pylist())

tables = capture.read_tables("capture.frames")
by_records = capture.tables_from_records(records)
assert set(tables) == set(by_records), (sorted(tables), sorted(by_records))
for name, table in tables.items():
    assert same(table, by_records[name]), name
candump = capture.read_tables("capture.log")
assert set(tables) - set(candump) <= {"errors"}
for name, table in candump.items():
    if name != "errors":
        assert same(table, tables[name]), name
assert tables["errors"].column("error").to_pylist().count("bad line") == 2
frame = capture.to_dataframe("capture.frames")
assert len(frame) == len(records)

# Recognised by its content under another name, gzipped or not; cut gzip data ends in a
# Truncation; its suffix is in the error for a file in no known format.
shutil.copy("capture.frames", "capture.bin")
assert capture.resolve("capture.bin").format == "frametext"
assert list(capture.read("capture.bin")) == records
with open("capture.frames", "rb") as plain, gzip.open("capture.frames.gz", "wb") as packed:
    shutil.copyfileobj(plain, packed)
assert list(capture.read("capture.frames.gz")) == records
data = open("capture.frames.gz", "rb").read()
open("cut.frames", "wb").write(data[: len(data) // 2])
cut = list(capture.open_frames("cut.frames"))
assert type(cut[-1]) is Truncation and 0 < len(cut) < len(read), cut[-1]
open("notes.md", "w").write("# notes\\n")
try:
    capture.read("notes.md")
except SourceError as error:
    assert ".frames" in str(error), error
else:
    raise AssertionError("notes.md was read")
print("ok")
"""


def _frame_text(frame: object) -> str:
    """One frame of examples/capture.log as a line of the page's frame text."""
    from veronte4x.capture.frames import Frame

    assert type(frame) is Frame and frame.timestamp is not None
    can_id = f"{frame.can_id:08X}" if frame.extended else f"{frame.can_id:03X}"
    data = " ".join(f"{byte:02X}" for byte in frame.data)
    return f"{frame.timestamp:.6f} {frame.channel} {can_id} {data}".rstrip() + "\n"


def test_adding_a_log_format(scratch: Path) -> None:
    import duckdb

    from veronte4x import capture

    for path, where, code in _blocks("Adding a log format"):
        _apply(scratch, path, where, code)
    example = ROOT / "examples" / "capture.log"
    last = "(1763737299.250000) vcan1 1001552A#05000000000000C3\n"
    (scratch / "capture.log").write_text(example.read_text() + last)
    lines = [_frame_text(f) for f in capture.open_frames(scratch / "capture.log")]
    lines[2:2] = [
        "# the arbiter's and the autopilots' first frames\n",
        "\n",
        "1763737200.0 can0 08 00  # a CAN ID of 2 digits\n",
        "1763737200.0 can0\n",
    ]
    (scratch / "capture.frames").write_text("".join(lines))
    (scratch / "check.py").write_text(_LOG_FORMAT_CHECK)
    done = _run(scratch, "check.py")
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip().endswith("ok")

    # The command line: converted into a Parquet dataset, read back with DuckDB.
    out = scratch / "out"
    converted = _run(scratch, "-m", "veronte4x", "convert", "capture.frames", "--to", "parquet",
                     str(out))  # fmt: skip
    assert converted.returncode == 0, converted.stderr
    tables = capture.read_tables(scratch / "capture.log")
    assert {"Ready", "Score", "NodeStatus", "errors"} <= set(tables)
    for name, table in tables.items():
        rows = (
            duckdb.connect()
            .execute(f"SELECT count(*) FROM read_parquet('{out}/capture=*/{name}.parquet')")
            .fetchone()
        )
        assert rows == (table.num_rows + 2 * (name == "errors"),), name
    bad = (
        duckdb.connect()
        .execute(
            f"SELECT count(*) FROM read_parquet('{out}/capture=*/errors.parquet') "
            "WHERE error = 'bad line'"
        )
        .fetchone()
    )
    assert bad == (2,)
    decoded = _run(scratch, "-m", "veronte4x", "decode", "capture.frames")
    assert decoded.returncode == 0, decoded.stderr
    same = _run(scratch, "-m", "veronte4x", "decode", "capture.log")
    assert decoded.stdout == same.stdout  # bad lines are counted, not shown
    assert "NodeStatus" in decoded.stdout and "3 bad" in decoded.stderr


_THIRD_PARTY_CHECK = """
from veronte4x import capture

# By content: the bench log is benchlog's, the other .csv files are read as before.
formats = {name: capture.resolve(name).format for name in ("bench.csv", "gvret.csv", "can.csv")}
assert formats == {"bench.csv": "benchlog", "gvret.csv": "gvret", "can.csv": "python-can"}
records = list(capture.read("bench.csv"))
same = [r for r in capture.read("capture.log") if r.error != "bad line"]
assert [r for r in records if r.error != "bad line"] == same
bad = [r.detail for r in records if r.error == "bad line"]
assert bad == ["line 3: not time,bus,id,data: '1763737200.0,can0,08,00'"], bad
tables = capture.read_tables("bench.csv")
candump = capture.read_tables("capture.log")
assert set(tables) == set(candump) | {"errors"}, (sorted(tables), sorted(candump))
for name, table in candump.items():
    if name != "errors":
        assert table.equals(tables[name]), name
print("ok")
"""


def test_adding_a_log_format_from_another_package(tmp_path: Path) -> None:
    """The package of the page, installed as pip installs it (its module and a dist-info
    with the entry points of its pyproject.toml), reads its files by content among the
    other ``.csv`` formats, through the library and the command line."""
    from veronte4x import capture

    section = "Adding a log format from another package"
    for path, where, code in _blocks(section):
        _apply(tmp_path, path, where, code)
    text = PAGE.read_text()
    assert "    pip install ./benchlog\n" in text[text.index(f"## {section}\n") :]
    package = tmp_path / "benchlog"
    pyproject = tomli.loads((package / "pyproject.toml").read_text())
    project, modules = pyproject["project"], pyproject["tool"]["setuptools"]["py-modules"]
    sources = {f"{module}.py": (package / f"{module}.py").read_text() for module in modules}
    install(tmp_path / "site", project["name"], project["version"], sources,
            project["entry-points"])  # fmt: skip

    work = tmp_path / "work"
    work.mkdir()
    example = ROOT / "examples" / "capture.log"
    (work / "capture.log").write_text(example.read_text())
    lines = [_bench_line(f) for f in capture.open_frames(example) if type(f) is Frame]
    lines[1:1] = ["1763737200.0,can0,08,00\n", "\n"]
    (work / "bench.csv").write_text("time,bus,id,data\n" + "".join(lines))
    (work / "gvret.csv").write_text(
        "Time Stamp,ID,Extended,Dir,Bus,LEN,D1,D2\n1,0FF,false,Rx,0,1,01,\n"
    )
    (work / "can.csv").write_text("timestamp,arbitration_id,extended,remote,error,dlc,data\n")
    (work / "check.py").write_text(_THIRD_PARTY_CHECK)
    path = os.pathsep.join([str(tmp_path / "site"), str(ROOT / "src")])
    env = {"PYTHONPATH": path, "PATH": "/usr/bin:/bin", "HOME": str(tmp_path)}

    def run(*args: str) -> subprocess.CompletedProcess[str]:
        return subprocess.run([sys.executable, *args], cwd=work, env=env, capture_output=True,
                              text=True, timeout=_TIMEOUT, check=False)  # fmt: skip

    checked = run("check.py")
    assert (checked.returncode, checked.stdout, checked.stderr) == (0, "ok\n", "")
    decoded = run("-m", "veronte4x", "decode", "bench.csv")
    same = run("-m", "veronte4x", "decode", "capture.log")
    assert decoded.returncode == 0, decoded.stderr
    assert decoded.stdout == same.stdout and "Ready" in decoded.stdout


def _bench_line(frame: Frame) -> str:
    """One frame as a line of the page's bench log."""
    assert frame.timestamp is not None
    can_id = f"{frame.can_id:08X}" if frame.extended else f"{frame.can_id:03X}"
    return f"{frame.timestamp:.6f},{frame.channel},{can_id},{frame.data.hex().upper()}\n"


_DSDL_BLOCK = re.compile(r"^( *)```text\n *# (\S+): new file\n(.*?)^\1```", re.M | re.S)

_DRONECAN_TYPE_CHECK = """
import dataclasses, importlib, sys
from veronte4x import dronecan
from veronte4x.dronecan import codec, compiled

types = dronecan.default_types()
Beat = types["ardupilot.example.Beat"]
assert Beat.__name__ == "Beat" and Beat._FLOAT16_FIELDS_ == {"voltage"}
assert Beat._TEXT_FIELDS_ == {"name"}
beat = Beat(counter=7, voltage=12.5, name=b"pump")
found = types.by_class[Beat]
assert found.fast_module == "veronte4x.dronecan.fast.ardupilot_example_Beat"
assert found.data_type.data_type_id == 20990
assert types.units[Beat] == {"voltage": "Volt"}
frames = dronecan.encode(beat, source_node_id=9, transfer_id=3)
assert dronecan.decode_frames(frames).message == beat
assert sys.modules[found.fast_module]  # the generated fast paths, compiled by nobody
print("ok")
"""


def test_adding_a_dronecan_type(scratch: Path) -> None:
    text = PAGE.read_text()
    start = text.index("## Adding a DroneCAN type\n")
    section = text[start : text.index("\n## ", start + 1)]
    (indent, path, code), *more = _DSDL_BLOCK.findall(section)
    assert not more
    target = scratch / path
    target.parent.mkdir(parents=True)
    target.write_text(
        textwrap.dedent("".join(line[len(indent) :] for line in code.splitlines(True)))
    )
    assert "    python -m veronte4x.dronecan.generate\n" in section
    generated = _run(scratch, "-m", "veronte4x.dronecan.generate")
    assert generated.returncode == 0, generated.stderr
    assert "fast/ardupilot_example_Beat.py" in generated.stdout
    checked = _run(scratch, "-c", _DRONECAN_TYPE_CHECK)
    assert (checked.returncode, checked.stdout, checked.stderr) == (0, "ok\n", "")


def test_every_block_says_where_it_goes() -> None:
    sections = [
        "Adding a frame type",
        "Adding a command",
        "Adding a log format",
        "Adding a log format from another package",
    ]
    assert all(_blocks(section) for section in sections)
