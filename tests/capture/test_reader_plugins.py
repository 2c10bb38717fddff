"""The reader registry settles a suffix two formats share by content (``.csv``: python-can's
CSV and SavvyCAN's GVRET CSV), and reads formats installed by other packages through the
entry point group ``veronte4x.readers``."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from veronte4x import capture
from veronte4x.capture.frames import BadLine, Frame
from veronte4x.capture.readers import registry

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "capture.log"
_TIMEOUT = 600  # a hang guard, not a timed assertion


def _frames(path: Path | str) -> list[Frame]:
    return [f for f in capture.open_frames(path) if isinstance(f, Frame)]


def _gvret(frames: list[Frame], version: int = 2) -> str:
    """The frames in SavvyCAN's GVRET CSV, as its ``saveNativeCSVFile`` writes them (the
    data padded with ``00`` to 8 bytes, a comma after each)."""
    header = (
        "Time Stamp,ID,Extended,Dir,Bus,LEN," if version == 2 else "Time Stamp,ID,Extended,Bus,LEN,"
    )
    lines = [header + "D1,D2,D3,D4,D5,D6,D7,D8\n"]
    for frame in frames:
        assert frame.timestamp is not None
        data = "".join(f"{b:02X}," for b in frame.data.ljust(8, b"\0"))
        direction = "Rx," if version == 2 else ""
        lines.append(
            f"{round(frame.timestamp * 1e6)},{frame.can_id:08X},{str(frame.extended).lower()},"
            f"{direction}{frame.channel.removeprefix('can')},{len(frame.data)},{data}\n"
        )
    return "".join(lines)


@pytest.mark.parametrize("version", [1, 2])
def test_gvret_csv_is_told_from_python_can_csv_by_content(tmp_path: Path, version: int) -> None:
    """Both are ``.csv``: GVRET's header settles it; python-can reads every other ``.csv``.
    The GVRET file gives the records of the same frames in candump form, bus 0 as can0."""
    can = pytest.importorskip("can")
    frames = _frames(EXAMPLE)
    gvret = tmp_path / "flight.csv"
    gvret.write_text(_gvret(frames, version).replace("\n", "\n\n", 3) + "1,2\n")
    assert capture.source.resolve(gvret).format == "gvret"
    read = list(capture.open_frames(gvret))
    assert read[-1] == BadLine(len(frames) + 5, "1,2", f"fewer than {version + 4} columns")
    assert read[:-1] == frames
    records = list(capture.read(gvret))
    assert records[:-1] == [r for r in capture.read(EXAMPLE) if r.error != "bad line"]

    other = tmp_path / "other.csv"
    with can.CSVWriter(str(other)) as writer:
        for frame in frames:
            writer.on_message_received(
                can.Message(timestamp=frame.timestamp, arbitration_id=frame.can_id,
                            data=frame.data, is_extended_id=frame.extended)
            )  # fmt: skip
    assert capture.source.resolve(other).format == "python-can"
    assert [f[2:5] for f in _frames(other)] == [f[2:5] for f in frames]


def test_a_suffix_shared_needs_a_sniff_and_the_sniffless_claimant_reads_the_rest(
    tmp_path: Path,
) -> None:
    with pytest.raises(ValueError, match=r"\.csv already read as python-can: a second format"):
        registry.register(registry.Reader("plain", (".csv",), "toy:frames"))
    toy = registry.register(
        registry.Reader("toy", (".csv",), "toy:frames", sniff=lambda head: head.startswith(b"toy"))
    )
    try:
        assert registry.claimants("a.CSV.gz") == [
            registry.READERS["python-can"],
            registry.READERS["gvret"],
            toy,
        ]
        assert registry.pick("a.csv", b"toy,1\n") is toy
        assert registry.pick("a.csv", b"Time Stamp,ID,Extended,Bus,LEN,D1\n").name == "gvret"  # type: ignore[union-attr]
        assert registry.pick("a.csv", b"timestamp,arbitration_id\n").name == "python-can"  # type: ignore[union-attr]
        assert registry.pick("a.csv", None).name == "python-can"  # type: ignore[union-attr]
    finally:
        registry.unregister("toy")
    # A suffix whose only claimant sniffs and does not recognise the file: its content
    # decides (candump text saved as .csv is no GVRET file), else that claimant reads it.
    registry.register(registry.Reader("sniffed", (".snf",), "toy:frames", sniff=lambda head: False))
    try:
        assert registry.pick("a.snf", EXAMPLE.read_bytes()).name == "candump"  # type: ignore[union-attr]
        assert registry.pick("a.snf", b"\0\1\2").name == "sniffed"  # type: ignore[union-attr]
    finally:
        registry.unregister("sniffed")


PLUGIN = '''\
"""A third party's log format, ``id,data,time`` lines (hex CAN ID, hex data, seconds)."""

from veronte4x.capture.frames import BadLine, Frame
from veronte4x.capture.readers.registry import Reader


def frames(source):
    with open(source.path, encoding="utf-8") as file:
        for number, line in enumerate(file, 1):
            try:
                ident, data, time = line.strip().split(",")
                yield Frame(float(time), "can0", int(ident, 16), bytes.fromhex(data),
                            len(ident) == 8)
            except ValueError as error:
                yield BadLine(number, line.rstrip("\\n"), f"not id,data,time: {error}")


def sniff(head):
    return head.startswith(b"#toy")


READER = Reader("toy", (".toy", ".csv"), "toy_plugin:frames", sniff="toy_plugin:sniff")
NOT_A_READER = "a string"
'''

ENTRY_POINTS = """\
[veronte4x.readers]
toy = toy_plugin:READER
wrong = toy_plugin:NOT_A_READER
"""

CHECK = """\
import warnings
from veronte4x import capture
from veronte4x.capture.readers import registry

with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    assert capture.source.resolve("capture.toy").format == "toy"
assert capture.source.resolve("shared.csv").format == "toy"  # by its first bytes
assert [str(w.message) for w in caught] == [
    "veronte4x: the reader 'wrong' of the entry point group veronte4x.readers is left out: "
    "toy_plugin:NOT_A_READER is no Reader named 'wrong'; fix or uninstall its package"
], caught
records = list(capture.read("capture.toy"))
same = list(capture.read("same.log"))
assert [r for r in records if r.error is None] == [r for r in same if r.error is None]
assert capture.read_tables("capture.toy")["Ready"].equals(capture.read_tables("same.log")["Ready"])
print("ok")
"""


def _lines(frames: list[Frame]) -> str:
    text = ""
    for frame in frames:
        width = 8 if frame.extended else 3
        text += f"{frame.can_id:0{width}X},{frame.data.hex()},{frame.timestamp!r}\n"
    return text


def test_a_reader_installed_from_another_package(tmp_path: Path) -> None:
    """A distribution on the path (its module and a dist-info with entry_points.txt, as pip
    installs it) adds its format to the library and the command line; an entry point that
    names no Reader is left out with a warning that names it."""
    site = tmp_path / "site"
    info = site / "toy_plugin-1.0.dist-info"
    info.mkdir(parents=True)
    (site / "toy_plugin.py").write_text(PLUGIN)
    (info / "METADATA").write_text("Metadata-Version: 2.1\nName: toy-plugin\nVersion: 1.0\n")
    (info / "entry_points.txt").write_text(ENTRY_POINTS)
    work = tmp_path / "work"
    work.mkdir()
    frames = _frames(EXAMPLE)
    (work / "capture.toy").write_text(_lines(frames))
    (work / "shared.csv").write_text("#toy\n" + _lines(frames))
    (work / "same.log").write_text(EXAMPLE.read_text())
    (work / "check.py").write_text(CHECK)
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(site), str(ROOT / "src")])}

    def run(*args: str) -> subprocess.CompletedProcess[str]:
        return subprocess.run(
            [sys.executable, *args], cwd=work, env=env, capture_output=True, text=True,
            timeout=_TIMEOUT, check=False,
        )  # fmt: skip

    done = run("check.py")
    assert (done.returncode, done.stdout.strip()) == (0, "ok"), done.stderr
    decoded = run("-W", "ignore::RuntimeWarning", "-m", "veronte4x", "decode", "capture.toy")
    same = run("-m", "veronte4x", "decode", "same.log")
    assert decoded.returncode == 0, decoded.stderr
    assert decoded.stdout == same.stdout and "Ready" in decoded.stdout
