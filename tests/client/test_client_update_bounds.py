"""Bounds the other client tests left open: node ids 1 and 127 taken, the update's deadline
per phase, an end-of-file read short of the image size."""

from __future__ import annotations

import pytest

from veronte4x import dronecan
from veronte4x.client import FirmwareUpdate, Phase
from veronte4x.client.files import FileRead
from veronte4x.client.protocol import ClientProtocol


@pytest.mark.parametrize("node_id", [1, 127])
def test_node_ids_1_and_127_are_taken(node_id: int) -> None:
    assert ClientProtocol(node_id=node_id).node_id == node_id


def test_the_deadline_follows_the_phase_and_a_short_end_of_file_keeps_reading() -> None:
    update = FirmwareUpdate(
        21, b"fw", 600, now=0.0, start_timeout=2, read_timeout=1, restart_timeout=5
    )
    assert update.next_deadline() is None  # STARTING: the request's own timeout counts
    update.accepted(dronecan.BeginFirmwareUpdateResponse(0), 0.5)
    assert update.next_deadline() == 2.5
    update.served(21, FileRead(b"fw", 0, 256, 600), 1.0)
    assert update.next_deadline() == 2.0
    update.served(21, FileRead(b"fw", 256, 100, 600), 1.5)  # a short read, short of 600
    assert update.progress.phase is Phase.READING
    update.served(21, FileRead(b"fw", 356, 244, 600), 1.6)
    assert update.progress.phase is Phase.RESTARTING
    assert update.next_deadline() == 6.6
