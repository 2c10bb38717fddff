"""Every standard and shipped vendor DroneCAN type decodes column-wise: over captures of
all of them at once (valid values of each, arrays empty, full and between, every union
branch, text of any bytes), no transfer is decoded alone and no frame goes to the per-frame
decoder, and the tables equal the per-frame path's."""

from __future__ import annotations

from collections import Counter
from pathlib import Path
from tempfile import TemporaryDirectory
from typing import Any
from unittest import mock

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.capture.columnar_support import (
    assert_same_tables,
    schema_values,
    transfer_frames,
    write,
)
from veronte4x import capture, dronecan
from veronte4x.capture.columnar import engine
from veronte4x.capture.columnar.dronecan import type_index_of
from veronte4x.dronecan.can_id import TransferKind

CODECS = type_index_of().codecs
"""The default set's types: the standard ones and the shipped vendor ones."""


def _name(found: Any) -> str:
    return str(found.data_type.full_name)


GROUP = 12
"""Types per capture (hypothesis draws a few of each into one example)."""

TOO_BIG = [HealthCheck.too_slow, HealthCheck.data_too_large, HealthCheck.large_base_example]


@pytest.mark.parametrize("group", range(0, len(CODECS), GROUP))
@settings(max_examples=6, suppress_health_check=TOO_BIG)
@given(data=st.data())
def test_every_type_decodes_without_a_call_per_transfer(group: int, data: st.DataObject) -> None:
    lines, stamp = [], 1.0
    for found in CODECS[group : group + GROUP]:
        service = found.data_type.kind is not TransferKind.MESSAGE
        for tid in range(data.draw(st.integers(1, 3), label=_name(found))):
            value = data.draw(schema_values(found.data_type.schema))
            message: Any = dronecan.from_builtin(found.data_type.schema.cls, value)
            payload = found.encode(message, True)
            for can_id, frame, _ in transfer_frames(
                found, payload, 10, 20 if service else None, tid
            ):
                stamp += 0.0001
                lines.append(f"({stamp:.6f}) can0 {can_id:08X}#{frame.hex().upper()}")
    alone: Counter[str] = Counter()
    per_frame: list[int] = []
    one_transfer, whole = engine._one_transfer, engine.per_frame

    def counted_transfer(frames: Any, found: Any, transfer: int, codec: Any, stamp: Any) -> Any:
        alone[_name(codec)] += 1
        return one_transfer(frames, found, transfer, codec, stamp)

    def counted_frames(frames: Any, rows: Any, decoder: Any) -> Any:
        per_frame.append(len(rows))
        return whole(frames, rows, decoder)

    with TemporaryDirectory() as folder:
        path = write(Path(folder) / "every.log", lines)
        with (
            mock.patch.object(engine, "_one_transfer", counted_transfer),
            mock.patch.object(engine, "per_frame", counted_frames),
        ):
            got = capture.read_tables(path)
        expected = capture.tables_from_records(capture.read(path))
    assert dict(alone) == {}  # the fall-back types: none
    assert not any(per_frame)
    assert_same_tables(got, expected)
