"""A firmware update's events late, repeated or out of order: the first outcome stands, a
repeated answer does not restart a timer, a node's NodeStatus before it reads is no
failure; and the refusal texts a user reads, word for word. Sans-IO, times as arguments."""

from __future__ import annotations

import pytest

from veronte4x import dronecan
from veronte4x.client import FirmwareUpdate, NodeEntry, NodeTable, Phase, UpdateProgress
from veronte4x.client.files import FileRead

OK = dronecan.BeginFirmwareUpdateResponse(0)
NO_ANSWER = "node 21 did not answer uavcan.protocol.file.BeginFirmwareUpdate (sent 3 times)"


def _status(node: int, mode: dronecan.Mode, at: float) -> NodeEntry:
    status = dronecan.NodeStatus(7, dronecan.Health.OK, mode, 0, 0)
    return NodeTable().observe_status(node, status, at)


def test_a_late_acceptance_does_not_revive_an_update_given_up() -> None:
    update = FirmwareUpdate(21, b"fw", 600, now=0.0)
    update.no_answer(NO_ANSWER)
    update.accepted(OK, 1.5)  # the answer to the last attempt, too late
    assert update.progress == UpdateProgress(21, Phase.FAILED, 0, 600, NO_ANSWER, True)
    assert update.next_deadline() is None
    update.served(21, FileRead(b"fw", 0, 256, 600), 2.0)  # and the node reads anyway
    assert update.poll(100.0) == UpdateProgress(21, Phase.FAILED, 0, 600, NO_ANSWER, True)


def test_a_repeated_acceptance_while_reading_keeps_the_read_timer() -> None:
    update = FirmwareUpdate(21, b"fw", 600, now=0.0, start_timeout=10, read_timeout=1)
    update.accepted(OK, 0.1)
    update.served(21, FileRead(b"fw", 0, 256, 600), 0.2)
    update.accepted(OK, 0.9)  # a duplicate answer: not back to waiting for 10 s
    assert update.progress == UpdateProgress(21, Phase.READING, 256, 600)
    assert update.next_deadline() == 1.2
    assert update.poll(1.2) == UpdateProgress(
        21,
        Phase.FAILED,
        256,
        600,
        "node 21 stopped reading the image at byte 256 of 600 (nothing for 1 s)",
        True,
    )


@pytest.mark.parametrize("accepted", [False, True])
def test_the_node_running_before_it_reads_is_no_failure(accepted: bool) -> None:
    """A node still reports OPERATIONAL between its answer and its first read (before it
    restarts into its bootloader): the update waits on."""
    update = FirmwareUpdate(21, b"fw", 600, now=0.0, start_timeout=2)
    if accepted:
        update.accepted(OK, 0.1)
    update.status(_status(21, dronecan.Mode.OPERATIONAL, 0.5), 0.5)
    phase = Phase.WAITING if accepted else Phase.STARTING
    assert update.progress == UpdateProgress(21, phase, 0, 600)
    assert update.next_deadline() == (2.1 if accepted else None)


def test_a_late_no_answer_keeps_the_first_outcome() -> None:
    done = FirmwareUpdate(21, b"fw", 200, now=0.0)
    done.accepted(OK, 0.1)
    done.served(21, FileRead(b"fw", 0, 200, 200), 0.2)
    done.status(_status(21, dronecan.Mode.OPERATIONAL, 0.3), 0.3)
    done.no_answer(NO_ANSWER)
    assert done.progress == UpdateProgress(21, Phase.DONE, 200, 200)
    refused = FirmwareUpdate(21, b"fw", 200, now=0.0)
    refused.accepted(dronecan.BeginFirmwareUpdateResponse(2), 0.1)
    refused.no_answer(NO_ANSWER)
    assert refused.progress == UpdateProgress(
        21, Phase.FAILED, 0, 200, "node 21 refused the update: IN_PROGRESS", False
    )


@pytest.mark.parametrize(
    ("error", "detail", "text"),
    [
        (
            dronecan.FirmwareUpdateError.INVALID_MODE,
            b"",
            "node 21 refused the update: INVALID_MODE; this module cannot be updated over DroneCAN",
        ),
        (
            dronecan.FirmwareUpdateError.INVALID_MODE,
            b"no bootloader",
            "node 21 refused the update: INVALID_MODE (no bootloader); "
            "this module cannot be updated over DroneCAN",
        ),
        (255, b"flash locked", "node 21 refused the update: UNKNOWN (flash locked)"),
        (42, b"", "node 21 refused the update: error 42"),
        (250, b"\xffbad\xfe", "node 21 refused the update: error 250 (\ufffdbad\ufffd)"),
    ],
)
def test_a_refusal_in_plain_words(error: int, detail: bytes, text: str) -> None:
    update = FirmwareUpdate(21, b"fw", 600, now=0.0)
    update.accepted(dronecan.BeginFirmwareUpdateResponse(error, detail), 0.1)
    assert update.progress == UpdateProgress(21, Phase.FAILED, 0, 600, text, False)
    assert update.next_deadline() is None
