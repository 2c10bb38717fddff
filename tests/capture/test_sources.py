"""How a source is opened: paths of any kind, content sniffing, directories, truncation."""

from __future__ import annotations

import gzip
from pathlib import Path

import can
import pytest

from veronte4x import capture
from veronte4x.arbiter.config_file import load_config
from veronte4x.capture.busmap import BusMap
from veronte4x.capture.source import resolve
from veronte4x.errors import MissingExtraError, SourceError
from veronte4x.extras import require

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
EXAMPLE = EXAMPLES / "capture.log"


def test_every_function_that_takes_a_file_takes_a_path(tmp_path: Path) -> None:
    assert len(list(capture.read(EXAMPLE))) == 39
    assert len(list(capture.open_frames(EXAMPLE))) == 39
    assert load_config(EXAMPLES / "arbiter.toml").holding_time == 2.0
    bus_map = tmp_path / "bus.toml"
    bus_map.write_text("[veronte]\narbiter_id = 254\n")
    assert BusMap.from_toml(bus_map).arbiter_id == 254
    asc = tmp_path / "capture.asc"
    with can.Logger(str(asc)) as logger:
        logger(can.Message(timestamp=1.0, arbitration_id=9, is_extended_id=False, data=b"\0\xff\1"))
    [record] = capture.read(asc)
    assert record.sender == "AP2"


def test_resolve_by_suffix_then_by_content(tmp_path: Path) -> None:
    assert resolve(EXAMPLE).format == "candump"
    assert resolve(tmp_path / "x.blf").format == "python-can"
    plain = tmp_path / "capture"
    plain.write_bytes(EXAMPLE.read_bytes())
    assert resolve(plain).format == "candump"
    packed = tmp_path / "capture.dat"
    packed.write_bytes(gzip.compress(EXAMPLE.read_bytes()))
    assert (resolve(packed).format, resolve(packed).gzipped) == ("candump", True)
    assert len(list(capture.read(packed))) == 39
    with pytest.raises(SourceError, match="is a directory: give a capture file"):
        capture.read(tmp_path)
    other = tmp_path / "notes.md"
    other.write_text("# not a capture\n")
    with pytest.raises(
        SourceError,
        match="its content is not candump or gvret or dataflash or pydronecan, and its suffix",
    ):
        capture.read(other)
    garbled = tmp_path / "garbled"
    garbled.write_text("garbage first\n" + EXAMPLE.read_text())
    assert resolve(garbled).format == "candump"  # one bad line first is still candump
    empty = tmp_path / "empty"
    empty.write_bytes(b"")
    with pytest.raises(SourceError, match="empty is empty: give a capture file"):
        resolve(empty)


def test_a_truncated_gzip_ends_with_a_truncated_record(tmp_path: Path) -> None:
    text = "".join(f"({i}.0) can0 009#00FF01\n" for i in range(3000)).encode()
    whole = gzip.compress(text)
    path = tmp_path / "cut.log.gz"
    path.write_bytes(whole[: len(whole) // 2])
    records = list(capture.read(path))
    assert all(r.error is None for r in records[:-1])
    last = records[-1]
    assert last.error == "truncated"
    assert last.detail == (
        f"{path}: the gzip data ends early, at line {len(records)}: the file is truncated"
    )
    frames = list(capture.open_frames(path))
    assert frames[-1].reason == last.detail  # type: ignore[union-attr]


def test_a_missing_extra_names_it() -> None:
    with pytest.raises(MissingExtraError) as caught:
        require("no_such_module_veronte4x", "can", "reading x.blf")
    assert str(caught.value) == (
        "reading x.blf needs the 'no_such_module_veronte4x' package: pip install 'veronte4x[can]'"
    )
    assert isinstance(caught.value, ImportError)
