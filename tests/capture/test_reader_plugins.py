"""The reader registry settles a suffix two formats share by content (``.csv``: python-can's
CSV and SavvyCAN's GVRET CSV), and reads formats installed by other packages through the
entry point group ``veronte4x.readers``."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from tests.plugin_support import install
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


BROKEN = '''\
"""A third party's module whose entry points name no Reader of theirs."""

from veronte4x.capture.readers.registry import Reader

CANDUMP = Reader("candump", (".mine",), "broken_plugin:frames")
NOT_A_READER = "a string"
'''

CHECK = """
import warnings
from veronte4x import capture
from veronte4x.capture.readers import registry

with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    assert [r.name for r in registry.claimants("capture.log")] == ["candump"]
assert sorted(str(w.message) for w in caught) == [
    "veronte4x: the reader 'missing' of the entry point group veronte4x.readers is left out: "
    "No module named 'no_such_module'; fix or uninstall its package",
    "veronte4x: the reader 'wrong' of the entry point group veronte4x.readers is left out: "
    "broken_plugin:NOT_A_READER is no Reader named 'wrong'; fix or uninstall its package",
], caught
assert registry.READERS["candump"].suffixes == (".log", ".txt", ".candump")
assert "wrong" not in registry.READERS and "missing" not in registry.READERS
assert sum(r.error is None for r in capture.read("capture.log")) == 38  # all but one
print("ok")
"""


def test_entry_points_that_name_no_reader_are_left_out_with_a_warning(tmp_path: Path) -> None:
    """An entry point that fails to load or names no `Reader` is left out with a warning
    that names it, and the other formats are read; one named as a registered format is
    not loaded (the registered format is kept). Installing a reader that works is the
    contributors' page's recipe (tests/test_contributing.py)."""
    site = tmp_path / "site"
    points = {
        "candump": "broken_plugin:CANDUMP",
        "wrong": "broken_plugin:NOT_A_READER",
        "missing": "no_such_module:READER",
    }
    install(site, "broken-plugin", "1.0", {"broken_plugin.py": BROKEN},
            {registry.ENTRY_POINT_GROUP: points})  # fmt: skip
    (tmp_path / "capture.log").write_text(EXAMPLE.read_text())
    (tmp_path / "check.py").write_text(CHECK)
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(site), str(ROOT / "src")])}
    done = subprocess.run(
        [sys.executable, "check.py"], cwd=tmp_path, env=env, capture_output=True, text=True,
        timeout=_TIMEOUT, check=False,
    )  # fmt: skip
    assert (done.returncode, done.stdout.strip()) == (0, "ok"), done.stderr
