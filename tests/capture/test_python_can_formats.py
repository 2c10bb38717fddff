"""Every log format python-can writes reads back through veronte4x and decodes."""

from pathlib import Path

import can
import pytest

from veronte4x import capture, codec, dronecan
from veronte4x.capture import open_frames
from veronte4x.capture.frames import Frame

STATUS = dronecan.NodeStatus(
    uptime_sec=7, health=dronecan.Health.OK, mode=dronecan.Mode.OPERATIONAL, sub_mode=0,
    vendor_specific_status_code=0,
)  # fmt: skip
NODE_FRAME = dronecan.encode(STATUS, source_node_id=20, transfer_id=1)[0]
MESSAGES = [
    can.Message(timestamp=10.0, arbitration_id=9, is_extended_id=False, data=b"\x00\xff\x01"),
    can.Message(
        timestamp=10.5, arbitration_id=0xFF, is_extended_id=False,
        data=codec.encode(codec.Score(autopilot=1, score=0.25)),
    ),
    can.Message(
        timestamp=11.0, arbitration_id=NODE_FRAME.can_id, is_extended_id=True,
        data=NODE_FRAME.data,
    ),
]  # fmt: skip


@pytest.mark.parametrize("suffix", [".asc", ".blf", ".csv", ".trc", ".log.gz", ".log"])
def test_format(tmp_path: Path, suffix: str) -> None:
    path = tmp_path / f"capture{suffix}"
    with can.Logger(str(path)) as logger:
        for message in MESSAGES:
            logger(message)
    frames = [f for f in open_frames(str(path)) if isinstance(f, Frame)]
    assert [(f.can_id, f.data, f.extended) for f in frames] == [
        (m.arbitration_id, bytes(m.data), m.is_extended_id) for m in MESSAGES
    ]
    records = list(capture.read(str(path)))
    assert [r.message for r in records] == [
        codec.Ready(ready=True),
        codec.Score(autopilot=1, score=0.25),
        STATUS,
    ]
    assert [r.sender for r in records] == ["AP2", "arbiter", "node 20"]
