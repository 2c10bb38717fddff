"""The columnar engine on captures of many DroneCAN sessions (issue 19, "no cliff"): the
column-wise path takes every regular session whatever their number, and the tables stay
those of the per-frame decoder, sessions concurrent or not, faults included; both for a
file and for the same bytes on standard input (`read_tables` of ``-``), in batches."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest

import veronte4x.dronecan
from tests.capture.columnar_support import assert_same_tables, many_sessions, read_piped, write
from veronte4x import capture
from veronte4x.capture.columnar import dronecan, engine
from veronte4x.capture.columnar.stream import StreamDecoder

pytest.importorskip("pyarrow")


def _decoded(path: Path, monkeypatch: pytest.MonkeyPatch) -> tuple[dict[str, Any], int]:
    """read_tables of ``path``, and how many frames went to the per-frame decoder."""
    sent = []
    original = engine.per_frame

    def counting(frames: Any, rows: np.ndarray, decoder: Any) -> Any:
        sent.append(len(rows))
        return original(frames, rows, decoder)

    monkeypatch.setattr(engine, "per_frame", counting)
    return capture.read_tables(path), sum(sent)


# The 100,000-session cases run in the soak run only: 10,000 already pass the session table
# tenfold, and a sampled mutation run of the session code (docs/mutation.md) killed every
# mutant without them.
@pytest.mark.parametrize(
    "count", [10, 1_000, 1_025, 10_000, pytest.param(100_000, marks=pytest.mark.soak)]
)
def test_one_session_after_another_stays_column_wise(
    count: int, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    path = write(tmp_path / "capture.log", many_sessions(count, concurrent=False))
    got, per_frame = _decoded(path, monkeypatch)
    assert per_frame == 0
    expected = capture.tables_from_records(capture.read(path))
    assert_same_tables(got, expected)
    assert_same_tables(read_piped(path), expected)


@pytest.mark.parametrize(
    ("count", "concurrent", "faults"),
    [
        (10, True, 0.2),
        (1_000, True, 0.0),
        (1_000, True, 0.05),
        (2_000, True, 0.0),  # the table is too small: the reassembler drops sessions
        (2_000, True, 0.05),
        (2_000, False, 0.05),
        (10_000, False, 0.02),
        (10_000, True, 0.01),
        pytest.param(100_000, False, 0.001, marks=pytest.mark.soak),
    ],
)
def test_many_sessions_agree(count: int, concurrent: bool, faults: float, tmp_path: Path) -> None:
    path = write(tmp_path / "capture.log", many_sessions(count, concurrent, faults, seed=count))
    expected = capture.tables_from_records(capture.read(path))
    assert_same_tables(capture.read_tables(path), expected)
    assert_same_tables(read_piped(path), expected)


@pytest.mark.parametrize("seed", range(6))
def test_a_session_left_open_before_a_thousand_others_agrees(
    seed: int, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A transfer cut short, then more sessions than the table holds: the reassembler drops
    the session and reports it; the column path must see that and decode it frame by frame."""
    lines = many_sessions(3, concurrent=False, transfers=1, seed=seed)
    request = veronte4x.dronecan.GetSetRequest(index=seed, name=b"a long parameter name")
    frames = veronte4x.dronecan.encode(
        request, source_node_id=126, transfer_id=seed, destination_node_id=127
    )
    cut = [f"(1700000000.{k:06d}) can0 {f.can_id:08X}#{f.data.hex()}" for k, f in enumerate(frames)]
    others = many_sessions(dronecan.MAX_SESSIONS + seed, concurrent=False, transfers=1, seed=seed)
    path = write(tmp_path / "capture.log", lines + cut[: 1 + seed % 2] + others)
    expected = capture.tables_from_records(capture.read(path))
    passes: list[frozenset[str]] = []

    def counting(*args: Any) -> Any:
        decoder = StreamDecoder(*args)
        passes.append(decoder.per_frame_channels)
        return decoder

    monkeypatch.setattr("veronte4x.capture.columnar.StreamDecoder", counting)
    assert_same_tables(capture.read_tables(path), expected)
    assert passes == [frozenset(), {"can0"}]  # decoded again, can0 frame by frame
    passes.clear()
    assert_same_tables(read_piped(path), expected)  # the same, read once from a pipe
    assert passes == [frozenset(), {"can0"}]
