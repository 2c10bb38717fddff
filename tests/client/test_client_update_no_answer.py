"""A firmware update of a node that never answers BeginFirmwareUpdate ends with the
NoResponseError's words (the CLI prints them), marked as a timeout, the image no longer
served."""

from __future__ import annotations

from typing import Any

import pytest

from veronte4x import dronecan
from veronte4x.client import FirmwareUpdateFailedError, Phase
from veronte4x.client import operations as ops
from veronte4x.client.protocol import ClientProtocol

TEXT = (
    "node 99 did not answer uavcan.protocol.file.BeginFirmwareUpdate (sent 2 times, 0.5 s "
    "each); check the node id, the bus and the bit rate"
)


def test_an_update_without_an_answer_fails_with_the_no_response_text() -> None:
    protocol = ClientProtocol()
    runner = ops.Runner(protocol, timeout=0.5, retries=1)
    seen: list[Any] = []
    task = runner.start(
        ops.update_firmware(protocol, 99, b"image", "fw.bin", progress=seen.append), 0.0
    )
    now, sent = 0.0, 0
    while not task.done:
        now += 0.1
        sent += len(protocol.take_frames())
        runner.feed(protocol.poll(now), now)
        runner.poll(now)
        assert now < 5
    assert sent == 2  # the request and its one retry, nothing after
    with pytest.raises(FirmwareUpdateFailedError) as failed:
        task.result()
    assert str(failed.value) == TEXT
    assert failed.value.timed_out
    [progress] = seen
    assert (progress.phase, progress.error, progress.timed_out) == (Phase.FAILED, TEXT, True)
    read = dronecan.FileReadRequest(0, dronecan.Path(b"fw.bin"))
    assert protocol.files.read(read)[1].size is None  # no longer served
