"""Column-wise reading of candump text on standard input: plain, gzip, and the text the
column parser leaves to the per-frame reader (lone carriage returns)."""

from __future__ import annotations

import gzip
import io
import sys

import numpy as np
import pytest

from veronte4x.capture.columnar.sources import read_frames
from veronte4x.capture.frames import Frame

TEXT = b"(1.000000) can0 0FF#00FF8177FFFF\n(2.000000) can0 1004D42A#C0\n"
FRAMES = [
    Frame(1.0, "can0", 0xFF, bytes.fromhex("00ff8177ffff")),
    Frame(2.0, "can0", 0x1004D42A, b"\xc0", extended=True),
]


def _frames(data: bytes, monkeypatch: pytest.MonkeyPatch) -> tuple[list[Frame], list[object]]:
    stdin = io.TextIOWrapper(io.BufferedReader(io.BytesIO(data)))  # peekable, as a pipe is
    monkeypatch.setattr(sys, "stdin", stdin)
    columns = read_frames("-")
    return list(columns.frames_of(np.arange(len(columns.can_id)))), list(columns.bad_lines)


@pytest.mark.parametrize(
    "data",
    [
        TEXT,
        gzip.compress(TEXT, mtime=0),
        TEXT.replace(b"\n", b"\r", 1),
        gzip.compress(TEXT[:-1] + b"\r", mtime=0),
    ],
    ids=["plain", "gzip", "lone-cr", "gzip-cr-at-end"],
)
def test_standard_input_plain_gzip_and_lone_carriage_returns(
    data: bytes, monkeypatch: pytest.MonkeyPatch
) -> None:
    assert _frames(data, monkeypatch) == (FRAMES, [])
