"""Sources of every kind read in the test's own process: one channel of a two-channel log
(bad lines kept for counting), a format registered again under its name, candump text on
standard input (plain and gzip), a named pipe without a suffix, a missing file, and gzip
files without a suffix longer than the bytes sniffed or cut short."""

from __future__ import annotations

import gzip
import io
import os
import sys
import threading
from collections.abc import Iterator
from pathlib import Path

import can
import pytest

from tests.capture.test_reader_registry import toy  # noqa: F401 - a fixture
from veronte4x import capture
from veronte4x.capture.frames import BadLine, Frame
from veronte4x.capture.readers import registry
from veronte4x.capture.source import resolve
from veronte4x.codec import Ready

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "capture.log"


def _two_channels(path: Path) -> Path:
    with can.Logger(str(path)) as logger:
        for i, data in enumerate([b"\0\xff\1", b"\0\xff\0", b"\0\xff\1"]):
            logger(
                can.Message(
                    timestamp=1.0 + i / 10,
                    arbitration_id=9,
                    is_extended_id=False,
                    data=data,
                    channel=i % 2,
                )
            )
    return path


def test_one_channel_of_a_log_that_has_two(tmp_path: Path) -> None:
    """A format without a records path of its own (python-can's) is filtered frame by
    frame: a channel keeps its frames only."""
    asc = _two_channels(tmp_path / "two.asc")
    assert [(f.channel, f.data) for f in capture.open_frames(asc)] == [  # type: ignore[union-attr]
        ("0", b"\0\xff\1"),
        ("1", b"\0\xff\0"),
        ("0", b"\0\xff\1"),
    ]
    assert [(f.channel, f.data) for f in capture.open_frames(asc, "1")] == [  # type: ignore[union-attr]
        ("1", b"\0\xff\0")
    ]
    records = list(capture.read(asc, channel="0"))
    assert [(r.channel, r.sender, r.message) for r in records] == [
        ("0", "AP2", Ready(True)),
        ("0", "AP2", Ready(True)),
    ]
    assert list(capture.open_frames(asc, "can9")) == []


def test_a_channel_filter_keeps_the_bad_lines(toy: Path) -> None:  # noqa: F811
    """Bad lines carry no channel: they are kept whatever the filter, so that a file's bad
    lines are counted once whichever channel is read."""
    everything = list(capture.open_frames(toy))
    assert [f for f in everything if isinstance(f, BadLine)] == [
        BadLine(
            6, "not a frame", "not id,data,time: not enough values to unpack (expected 3, got 1)"
        )
    ]
    assert list(capture.open_frames(toy, "can0")) == everything
    assert list(capture.open_frames(toy, "can1")) == [
        f for f in everything if isinstance(f, BadLine)
    ]
    [bad] = capture.read(toy, channel="can1")
    assert (bad.error, bad.detail) == (
        "bad line",
        "line 6: not id,data,time: not enough values to unpack (expected 3, got 1): 'not a frame'",
    )


def test_a_format_registered_again_replaces_the_old_one(toy: Path) -> None:  # noqa: F811
    """Registering a reader under a name already taken replaces it (a user's fix of a
    format), its own suffixes being no conflict; the order formats are tried in stays."""
    order = list(registry.READERS)
    before = list(capture.open_frames(toy))

    def reversed_frames(source: capture.source.Source) -> Iterator[Frame | BadLine]:
        frames: list[Frame | BadLine] = list(registry.load("toy_reader:frames")(source))
        return reversed(frames)

    replacement = registry.Reader("toy", (".toy", ".toy2"), reversed_frames)
    assert registry.register(replacement) is replacement
    assert list(registry.READERS) == order
    assert registry.claimants("flight.toy2") == [replacement]
    assert list(capture.open_frames(toy)) == before[::-1]


def _stdin(monkeypatch: pytest.MonkeyPatch, data: bytes) -> io.BufferedReader[io.BytesIO]:
    """Standard input holding ``data``, as a pipe gives it (a buffered binary stream)."""
    binary = io.BufferedReader(io.BytesIO(data))
    monkeypatch.setattr(sys, "stdin", io.TextIOWrapper(binary))
    return binary


@pytest.mark.parametrize("packed", [False, True])
def test_standard_input_plain_or_gzip(monkeypatch: pytest.MonkeyPatch, packed: bool) -> None:
    """``-`` is candump text on standard input, gzip recognised by its first bytes without
    consuming them; both the record path (chunks of bytes) and the frame path (lines of
    text) read it, and neither closes standard input."""
    text = EXAMPLE.read_bytes()
    data = gzip.compress(text) if packed else text
    binary = _stdin(monkeypatch, data)
    source = resolve("-")
    assert (source.format, source.gzipped, source.is_stdin) == ("candump", packed, True)
    assert list(capture.read("-")) == list(capture.read(EXAMPLE))
    assert not binary.closed
    binary = _stdin(monkeypatch, data)
    assert list(capture.open_frames("-")) == list(capture.open_frames(EXAMPLE))
    assert not binary.closed


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="named pipes are POSIX")
def test_a_pipe_without_a_suffix_is_read_as_candump(tmp_path: Path) -> None:
    """A pipe (``<(candump -L can0)``) cannot be read twice, so its content is not sniffed:
    it is read by the format that streams."""
    pipe = tmp_path / "live"
    os.mkfifo(pipe)
    source = resolve(pipe)
    assert (source.format, source.gzipped) == ("candump", False)
    writer = threading.Thread(target=lambda: pipe.write_bytes(EXAMPLE.read_bytes()))
    writer.start()
    try:
        records = list(capture.read(pipe))
    finally:
        writer.join()
    assert records == list(capture.read(EXAMPLE))


def test_a_missing_file_without_a_suffix_fails_when_opened(tmp_path: Path) -> None:
    missing = tmp_path / "flight"
    assert resolve(missing).format == "candump"
    with pytest.raises(FileNotFoundError) as raised:
        list(capture.read(missing))
    assert raised.value.filename == str(missing)


def test_gzip_without_a_suffix_is_sniffed_from_its_first_bytes(tmp_path: Path) -> None:
    """The content of a gzip file is sniffed from its first 4096 gunzipped bytes however
    long it is, and from as many as a file cut short holds."""
    lines = EXAMPLE.read_text().splitlines(keepends=True) * 40
    text = "".join(lines).encode()
    assert len(text) > 8 * registry.SNIFF_BYTES
    long = tmp_path / "long.bin"
    long.write_bytes(gzip.compress(text))
    assert (resolve(long).format, resolve(long).gzipped) == ("candump", True)
    assert len(list(capture.read(long))) == len(lines)
    cut = tmp_path / "cut.bin"
    cut.write_bytes(gzip.compress(text)[:300])
    assert (resolve(cut).format, resolve(cut).gzipped) == ("candump", True)
    records = list(capture.read(cut))
    assert records[-1].error == "truncated"
    assert all(r.error != "truncated" for r in records[:-1])
