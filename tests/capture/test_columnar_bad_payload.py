"""Column-wise, a complete transfer whose payload does not decode as its type is a
``bad payload`` error row, as the per-frame decoder reports it, and the reading goes on."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.capture.columnar_support import assert_same_tables, rows, transfer_frames, write
from veronte4x import capture, dronecan
from veronte4x.capture.columnar import engine
from veronte4x.dronecan.codec import BY_CLASS

NODE_STATUS = BY_CLASS[dronecan.NodeStatus]
NODE_INFO = BY_CLASS[dronecan.GetNodeInfoResponse]
GOOD_STATUS = dronecan.NodeStatus(uptime_sec=7)
INFO = dronecan.GetNodeInfoResponse(
    status=GOOD_STATUS,
    hardware_version=dronecan.HardwareVersion(unique_id=bytes(range(16))),
    name=b"com.example.esc",
)


def _lines(frames: list[tuple[int, bytes, bool]]) -> list[str]:
    stamp = 1_700_000_000.0
    out = []
    for number, (can_id, data, _) in enumerate(frames):
        out.append(f"({stamp + number / 1000:.6f}) can0 {can_id:08X}#{data.hex().upper()}")
    return out


def _capture(tmp_path: Path) -> tuple[Path, list[bytes]]:
    """A fixed-size type (NodeStatus) cut short in one frame, and a type of variable size
    (a GetNodeInfo response, several frames, its CRC right) cut inside its hardware
    version), each beside good transfers of the same type."""
    status = NODE_STATUS.encode(GOOD_STATUS, True)
    info = NODE_INFO.encode(INFO, True)
    bad = [status[:2], info[:20]]
    broken = transfer_frames(NODE_INFO, info, 21, 127, 5)
    broken[0] = (broken[0][0], bytes((broken[0][1][0] ^ 1,)) + broken[0][1][1:], True)
    frames = broken  # a CRC mismatch first: the error rows stay in the capture's order
    frames += transfer_frames(NODE_STATUS, status, 20, None, 0)
    frames += transfer_frames(NODE_STATUS, bad[0], 20, None, 1)
    frames += transfer_frames(NODE_STATUS, status, 21, None, 0)
    frames += transfer_frames(NODE_INFO, info, 20, 127, 0)
    frames += transfer_frames(NODE_INFO, bad[1], 20, 127, 1)
    frames += transfer_frames(NODE_INFO, info, 20, 127, 2)
    return write(tmp_path / "bad_payload.log", _lines(frames)), bad


def test_bad_payloads_are_error_rows_column_wise(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    path, bad = _capture(tmp_path)
    expected = capture.tables_from_records(capture.read(path))
    taken: list[int] = []
    original = engine.per_frame

    def per_frame(frames: object, which: object, decoder: object) -> object:
        taken.append(len(which))  # type: ignore[arg-type]
        return original(frames, which, decoder)  # type: ignore[arg-type]

    monkeypatch.setattr(engine, "per_frame", per_frame)
    got = capture.read_tables(path)
    assert taken == [0]  # no frame left to the per-frame decoder: the column-wise path ran
    assert_same_tables(got, expected)
    errors = rows(got["errors"])
    assert [(row["error"], row["sender"], row["data"]) for row in errors[1:]] == [
        ("bad payload", "node 20", bad[0]),
        ("bad payload", "node 20", bad[1]),
    ]
    assert (errors[0]["error"], errors[0]["sender"]) == ("crc mismatch", "node 21")
    for row, payload, codec in zip(errors[1:], bad, (NODE_STATUS, NODE_INFO), strict=True):
        with pytest.raises(dronecan.DecodeError) as refused:
            codec.decode(payload)
        assert row["detail"] == f"{dronecan.Problem.BAD_PAYLOAD.value} {refused.value}"
    assert [row["node_id"] for row in rows(got["NodeStatus"])] == [20, 21]
    assert [row["uptime_sec"] for row in rows(got["NodeStatus"])] == [7, 7]
    assert [row["name"] for row in rows(got["GetNodeInfoResponse"])] == ["com.example.esc"] * 2
