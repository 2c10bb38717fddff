"""The reader registry: a format added as one module and one entry is read by every entry
point (`capture.read`, `read_tables`, `open_frames`, the CLI), and standard input's gzip is
recognised by the columnar path too."""

from __future__ import annotations

import gzip
import importlib
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

from tests.capture.columnar_support import assert_same_tables
from veronte4x import capture
from veronte4x.capture.frames import Frame
from veronte4x.capture.readers import registry
from veronte4x.errors import SourceError

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "capture.log"

TOY_MODULE = '''\
"""A toy log format: lines of ``id,data,time`` (hex CAN ID, hex data, seconds)."""

from veronte4x.capture.frames import BadLine, Frame
from veronte4x.capture.readers.registry import Reader, register


def frames(source):
    with open(source.path, encoding="utf-8") as file:
        for number, line in enumerate(file, 1):
            try:
                ident, data, time = line.strip().split(",")
                frame = Frame(float(time), "can0", int(ident, 16), bytes.fromhex(data),
                              len(ident) == 8)
            except ValueError as error:
                yield BadLine(number, line.rstrip("\\n"), f"not id,data,time: {error}")
            else:
                yield frame


register(Reader("toy", (".toy",), frames))
'''


@pytest.fixture
def toy(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[Path]:
    """The toy format registered from its module, and the example capture in it (with one
    line that is no frame) next to it, as ``capture.toy``."""
    (tmp_path / "toy_reader.py").write_text(TOY_MODULE)
    monkeypatch.syspath_prepend(str(tmp_path))
    importlib.import_module("toy_reader")
    lines = []
    for frame in capture.open_frames(EXAMPLE):
        assert isinstance(frame, Frame) and frame.timestamp is not None
        width = 8 if frame.extended else 3
        lines.append(f"{frame.can_id:0{width}X},{frame.data.hex()},{frame.timestamp!r}\n")
    lines.insert(5, "not a frame\n")
    path = tmp_path / "capture.toy"
    path.write_text("".join(lines))
    try:
        yield path
    finally:
        registry.unregister("toy")
        sys.modules.pop("toy_reader", None)


def _as_candump(tmp_path: Path) -> Path:
    """The example capture with the same bad line as the toy file's, in candump text."""
    lines = EXAMPLE.read_text().splitlines(keepends=True)
    lines.insert(5, "not a frame\n")
    path = tmp_path / "same.log"
    path.write_text("".join(lines))
    return path


def test_a_registered_format_is_read_by_every_entry_point(toy: Path, tmp_path: Path) -> None:
    same = _as_candump(tmp_path)
    records = list(capture.read(toy))
    expected = list(capture.read(same))
    assert [r[:-2] + r[-1:] for r in records if r.error is None] == [
        r[:-2] + r[-1:] for r in expected if r.error is None
    ]
    assert [r.error for r in records] == [r.error for r in expected]
    assert [f for f in capture.open_frames(toy) if isinstance(f, Frame)] == [
        f for f in capture.open_frames(same) if isinstance(f, Frame)
    ]
    assert_same_tables(capture.read_tables(toy), capture.tables_from_records(records))
    assert capture.read_tables(toy)["Ready"].equals(capture.read_tables(same)["Ready"])


def test_a_registered_format_in_the_command_line(toy: Path, tmp_path: Path) -> None:
    script = "import sys, toy_reader\nfrom veronte4x.cli import main\nsys.exit(main())"
    done = subprocess.run(
        [sys.executable, "-c", script, "decode", str(toy)],
        capture_output=True,
        text=True,
        cwd=toy.parent,
        check=False,
    )
    same = subprocess.run(
        [sys.executable, "-m", "veronte4x", "decode", str(_as_candump(tmp_path))],
        capture_output=True,
        text=True,
        check=False,
    )
    assert (done.returncode, done.stderr) == (
        same.returncode,
        same.stderr.replace("same.log", "capture.toy"),
    )
    assert done.stdout == same.stdout
    assert "Ready" in done.stdout


def test_suffixes_are_claimed_once_and_the_unknown_are_named(toy: Path, tmp_path: Path) -> None:
    with pytest.raises(ValueError, match=r"\.toy already read as toy"):
        registry.register(registry.Reader("other", (".toy",), "toy_reader:frames"))
    with pytest.raises(ValueError, match="standard input is already read as candump"):
        registry.register(registry.Reader("piped", (".pipe",), "toy_reader:frames", streams=True))
    other = tmp_path / "notes.md"
    other.write_text("# not a capture\n")
    with pytest.raises(SourceError, match=r"\.mf4, \.toy, \.trc; rename it"):
        capture.read(other)
    assert capture.source.resolve(toy).format == "toy"


def test_the_unknown_name_every_format_tried_by_content(tmp_path: Path) -> None:
    """A format with a sniffer is named among those tried; one without is not."""
    sniffer = registry.Reader(
        "sniffed", (".sniffed",), "toy_reader:frames", sniff=lambda head: False
    )
    registry.register(sniffer)
    try:
        other = tmp_path / "notes.md"
        other.write_text("# not a capture\n")
        with pytest.raises(SourceError) as raised:
            capture.source.resolve(other)
    finally:
        registry.unregister("sniffed")
    assert str(raised.value) == (
        f"{other}: in no format veronte4x knows: its content is not candump or gvret or "
        "dataflash or pydronecan or sniffed, and its suffix is none of .log, .txt, .candump, "
        ".asc, .bin, .blf, .csv, .db, .mf4, .sniffed, .trc; rename it to the suffix of its "
        "format, or convert it to candump text"
    )


def _tables_from_stdin(data: bytes) -> str:
    script = (
        "from veronte4x import capture\n"
        "t = capture.read_tables('-')\n"
        "print(sorted((k, v.num_rows) for k, v in t.items()))\n"
        "print(t['errors'].column('detail').to_pylist() if 'errors' in t else [])\n"
    )
    done = subprocess.run(
        [sys.executable, "-c", script], input=data, capture_output=True, check=True
    )
    return done.stdout.decode()


def _summary(tables: dict[str, object]) -> str:
    got: dict[str, object] = tables
    errors = got.get("errors")
    details = [] if errors is None else errors.column("detail").to_pylist()  # type: ignore[attr-defined]
    counts = sorted((k, v.num_rows) for k, v in got.items())  # type: ignore[attr-defined]
    return f"{counts}\n{details}\n"


def test_gzip_on_standard_input_is_read_by_read_tables(tmp_path: Path) -> None:
    packed = gzip.compress(EXAMPLE.read_bytes())
    assert _tables_from_stdin(packed) == _summary(capture.read_tables(EXAMPLE))
    cut = tmp_path / "cut.log.gz"
    cut.write_bytes(packed[: len(packed) * 2 // 3])
    expected = capture.tables_from_records(capture.read(cut))
    assert _tables_from_stdin(cut.read_bytes()) == _summary(expected).replace(
        str(cut), "standard input"
    )
