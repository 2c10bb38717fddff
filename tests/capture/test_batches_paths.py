"""Batches of candump text on standard input (a real pipe), against the per-frame reader
of the same input; and `ahead` over batches that come from a plain iterator.

Gzip on standard input that ends early: its compressed bytes are kept, so that the lines
the block reader lost are read again from them line by line.
"""

from __future__ import annotations

import gzip
import os
import sys
import threading
from collections.abc import Iterator
from typing import Any

import numpy as np
import pytest

from veronte4x import capture
from veronte4x.capture.columnar.batches import Batch, ahead, read_batches
from veronte4x.capture.columnar.frames import FrameColumns, concat, from_frames
from veronte4x.capture.frames import Frame, Truncation

TEXT = b"".join(b"(%d.000000) can0 0FF#00FF%04X\n" % (i, i) for i in range(3000))
"""More than the 64 KiB a pipe holds, and more than the bytes `resolve` peeks at."""


def _pipe_stdin(monkeypatch: pytest.MonkeyPatch, data: bytes) -> threading.Thread:
    """Standard input as a pipe that a thread fills with ``data`` and closes."""
    read, write = os.pipe()

    def fill() -> None:
        with open(write, "wb") as stream:
            stream.write(data)

    writer = threading.Thread(target=fill)
    writer.start()
    monkeypatch.setattr(sys, "stdin", open(read, encoding="utf-8"))  # noqa: SIM115
    return writer


def _per_frame(monkeypatch: pytest.MonkeyPatch, data: bytes) -> list[object]:
    writer = _pipe_stdin(monkeypatch, data)
    items: list[object] = list(capture.open_frames("-"))
    writer.join()
    sys.stdin.close()
    return items


def _batched(monkeypatch: pytest.MonkeyPatch, data: bytes) -> tuple[list[object], list[Batch]]:
    writer = _pipe_stdin(monkeypatch, data)
    batches = list(read_batches("-", batch_bytes=4096))
    writer.join()
    sys.stdin.close()
    joined = concat([batch.frames for batch in batches])
    frames: list[object] = list(joined.frames_of(np.arange(len(joined.can_id))))
    return frames + [bad for _, bad in joined.bad_lines], batches


@pytest.mark.parametrize("compress", [False, True], ids=["plain", "gzip"])
def test_standard_input_in_batches_is_the_per_frame_readers(
    monkeypatch: pytest.MonkeyPatch, compress: bool
) -> None:
    """Every line, the first ones (which `resolve` peeks at) included; a pipe does not
    tell how far it is read."""
    data = gzip.compress(TEXT, mtime=0) if compress else TEXT
    got, batches = _batched(monkeypatch, data)
    assert got == _per_frame(monkeypatch, data)
    assert len(got) == 3000 and got[0] == Frame(0.0, "can0", 0xFF, b"\x00\xff\x00\x00")
    assert len(batches) > 1
    assert {batch.position for batch in batches} == {None}


def test_truncated_gzip_on_standard_input_in_batches(monkeypatch: pytest.MonkeyPatch) -> None:
    data = gzip.compress(TEXT, mtime=0)
    cut = data[: len(data) * 2 // 3]
    expected = _per_frame(monkeypatch, cut)
    assert isinstance(expected[-1], Truncation)
    got, _ = _batched(monkeypatch, cut)
    assert got == expected


def _batch(number: int) -> Batch:
    frame = Frame(float(number), "can0", number, bytes([number]))
    return Batch(from_frames([(number, frame)]), number * 10)


def test_ahead_over_a_plain_iterator_prepares_each_batch_on_its_thread() -> None:
    """Batches from an iterator without ``close`` (not a generator): each comes in order,
    with what ``prepare`` made of its frames on the reading thread."""
    here = threading.get_ident()
    threads: list[int] = []

    def prepare(frames: FrameColumns) -> Any:
        threads.append(threading.get_ident())
        return int(frames.can_id[0]) * 2

    source: Iterator[Batch] = iter([_batch(1), _batch(2), _batch(3)])
    assert not hasattr(source, "close")
    got = list(ahead(source, prepare))
    assert [(b.frames.can_id.tolist(), b.position, b.prepared) for b in got] == [
        ([1], 10, 2),
        ([2], 20, 4),
        ([3], 30, 6),
    ]
    assert len(threads) == 3 and here not in threads
    assert [b.prepared for b in ahead(iter([_batch(4)]))] == [None]  # no prepare: None
