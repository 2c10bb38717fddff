"""Where a firmware update stands, from what the node does (sans-IO).

The sequence (DSDL ``uavcan.protocol.file.BeginFirmwareUpdate``; Vertiq "Standard DroneCAN
Support", section 2.4): the ground station asks the node to begin, naming itself as the
file server and a path; the node answers, then pulls the image with ``file.Read`` requests
of 256 bytes until a short read marks the end, then restarts into the new firmware. This
module follows that from the events an adapter gives it and says when it is done, or why
it failed, with the times as arguments.
"""

from __future__ import annotations

import enum
import functools
import math
from dataclasses import dataclass

from veronte4x.client.errors import InvalidRequestError
from veronte4x.client.files import FileRead
from veronte4x.client.nodes import NodeEntry
from veronte4x.dronecan.image_crc import crc64we
from veronte4x.dronecan.messages import BeginFirmwareUpdateResponse, FirmwareUpdateError, Mode
from veronte4x.errors import real
from veronte4x.words import counted

START_TIMEOUT = 10.0
"""Seconds a node may take from accepting the update to its first read (erasing flash)."""

READ_TIMEOUT = 5.0
"""Seconds without a read, while reading, after which the update counts as stalled."""

RESTART_TIMEOUT = 30.0
"""Seconds after the last read within which the node must report that it runs again."""


MAX_IMAGE_SIZE = 2 * 1024 * 1024
"""Bytes an image may have unless told otherwise: 2 MiB, twice the flash of the largest
ESC microcontrollers in use (an assumption, not a DroneCAN or Vertiq figure), so that a
wrong file (a log, a disk image) is refused before a node erases its flash."""


@dataclass(frozen=True, slots=True)
class FirmwareOptions:
    """The limits of a firmware update, passed as one value from a client's keywords to
    the operation that runs the update.

    Attributes:
        start_timeout: Seconds from accepting to the first read (`START_TIMEOUT`).
        read_timeout: Seconds without a read that count as a stall (`READ_TIMEOUT`).
        restart_timeout: Seconds after the last read for the node to run again
            (`RESTART_TIMEOUT`).
        max_image_size: Bytes above which an image is refused (`MAX_IMAGE_SIZE`).

    Raises:
        InvalidRequestError: A timeout that is not a finite number of seconds above 0.
    """

    start_timeout: float = START_TIMEOUT
    read_timeout: float = READ_TIMEOUT
    restart_timeout: float = RESTART_TIMEOUT
    max_image_size: int = MAX_IMAGE_SIZE

    def __post_init__(self) -> None:
        _check_timeouts(self.start_timeout, self.read_timeout, self.restart_timeout)


def _check_timeouts(start_timeout: object, read_timeout: object, restart_timeout: object) -> None:
    """Refuse an update timeout that is not a finite number of seconds above 0 (a NaN or an
    infinite one would never give a stalled update up).

    Raises:
        InvalidRequestError: Which timeout, and its value.
    """
    for name, value in (
        ("start_timeout", start_timeout),
        ("read_timeout", read_timeout),
        ("restart_timeout", restart_timeout),
    ):
        seconds = real(value)
        if seconds is None or not 0 < seconds < math.inf:
            raise InvalidRequestError(
                f"the firmware update's {name} is {value!r}, not a finite number of seconds "
                "above 0; nothing was sent"
            )


DEFAULT_OPTIONS = FirmwareOptions()
"""The limits of an update unless told otherwise."""


def check_image(image: bytes, max_size: int = MAX_IMAGE_SIZE) -> None:
    """Refuse an image that cannot be a firmware: empty, or larger than ``max_size`` bytes.

    Raises:
        InvalidRequestError: The image is empty or too large.
    """
    if not image:
        raise InvalidRequestError("the firmware image is empty (0 bytes); nothing was sent")
    if len(image) > max_size:
        raise InvalidRequestError(
            f"the firmware image has {counted(len(image), 'byte')}, more than the limit of "
            f"{max_size}; nothing was sent (raise the limit if the image is right)"
        )


def image_crc(image: bytes) -> int:
    """CRC-64-WE of a firmware image, as a node reports it (``SoftwareVersion.image_crc``).

    Computed once for the latest image and remembered: a fleet update compares one image
    with every node's CRC before and after, and the CRC in pure Python takes about a
    second per megabyte, as much CPU as serving the image to a node.
    """
    return _remembered_crc(bytes(image))


@functools.lru_cache(maxsize=1)
def _remembered_crc(image: bytes) -> int:
    return crc64we(image)


class Phase(enum.Enum):
    """The phases of an update."""

    STARTING = "starting"
    """BeginFirmwareUpdate sent, no answer yet."""
    WAITING = "waiting"
    """Accepted; the node has not read yet."""
    READING = "reading"
    """The node is pulling the image."""
    RESTARTING = "restarting"
    """The whole image was read; waiting for the node to run again."""
    DONE = "done"
    """The node runs again after reading the whole image."""
    FAILED = "failed"
    """See `UpdateProgress.error`."""


@dataclass(frozen=True, slots=True)
class UpdateProgress:
    """A snapshot of an update.

    Attributes:
        node_id: The node being updated.
        phase: Where it stands.
        sent: Bytes of the image sent so far (the end of the furthest read).
        size: Bytes in the image.
        error: Why it failed, one line, when `phase` is FAILED.
        timed_out: It failed because the node fell silent (not because it refused).
    """

    node_id: int
    phase: Phase
    sent: int
    size: int
    error: str | None = None
    timed_out: bool = False

    @property
    def finished(self) -> bool:
        """Done or failed."""
        return self.phase in (Phase.DONE, Phase.FAILED)


class FirmwareUpdate:
    """One firmware update of one node, driven by events and the time.

    Args:
        node_id: The node.
        path: The path the node was told to read.
        size: Bytes in the image.
        now: When BeginFirmwareUpdate was sent.
        start_timeout: See `START_TIMEOUT`.
        read_timeout: See `READ_TIMEOUT`.
        restart_timeout: See `RESTART_TIMEOUT`.

    Raises:
        InvalidRequestError: A timeout that is not a finite number of seconds above 0.

    Examples:
        >>> from veronte4x import dronecan
        >>> update = FirmwareUpdate(21, b"fw.bin", 300, now=0.0)
        >>> update.accepted(dronecan.BeginFirmwareUpdateResponse(0), 0.1)
        >>> update.served(21, FileRead(b"fw.bin", 0, 256, 300), 0.2)
        >>> progress = update.poll(0.3)
        >>> progress.phase, progress.sent, progress.size
        (<Phase.READING: 'reading'>, 256, 300)
        >>> update.poll(6.0).error
        'node 21 stopped reading the image at byte 256 of 300 (nothing for 5 s)'
    """

    def __init__(
        self,
        node_id: int,
        path: bytes,
        size: int,
        now: float,
        *,
        start_timeout: float = START_TIMEOUT,
        read_timeout: float = READ_TIMEOUT,
        restart_timeout: float = RESTART_TIMEOUT,
    ) -> None:
        _check_timeouts(start_timeout, read_timeout, restart_timeout)
        self.node_id = node_id
        self.path = path
        self.size = size
        self.start_timeout = start_timeout
        self.read_timeout = read_timeout
        self.restart_timeout = restart_timeout
        self._phase = Phase.STARTING
        self._sent = 0
        self._since = now
        self._error: str | None = None
        self._timed_out = False

    @property
    def progress(self) -> UpdateProgress:
        """Where the update stands."""
        return UpdateProgress(
            self.node_id, self._phase, self._sent, self.size, self._error, self._timed_out
        )

    def _fail(self, error: str, timed_out: bool = False) -> None:
        if not self.progress.finished:
            self._phase = Phase.FAILED
            self._error = error
            self._timed_out = timed_out

    def accepted(self, response: BeginFirmwareUpdateResponse, now: float) -> None:
        """The node answered BeginFirmwareUpdate."""
        if self._phase is not Phase.STARTING:
            return
        if response.error != FirmwareUpdateError.OK:
            known = {int(e): e.name for e in FirmwareUpdateError}
            name = known.get(int(response.error), f"error {int(response.error)}")
            detail = response.optional_error_message.decode("utf-8", "replace")
            self._fail(
                f"node {self.node_id} refused the update: {name}"
                + (f" ({detail})" if detail else "")
                + (
                    "; this module cannot be updated over DroneCAN"
                    if response.error == FirmwareUpdateError.INVALID_MODE
                    else ""
                )
            )
            return
        self._phase = Phase.WAITING
        self._since = now

    def no_answer(self, error: str) -> None:
        """BeginFirmwareUpdate got no answer (``error`` says so)."""
        self._fail(error, timed_out=True)

    def served(self, node_id: int, read: FileRead, now: float) -> None:
        """The file server answered a read of ``node_id``."""
        if node_id != self.node_id or read.path != self.path or self.progress.finished:
            return
        if self._phase in (Phase.STARTING, Phase.WAITING):
            self._phase = Phase.READING
        self._since = now
        self._sent = max(self._sent, read.offset + read.length)
        if read.end_of_file and self._sent >= self.size:
            self._phase = Phase.RESTARTING

    def status(self, entry: NodeEntry, now: float) -> None:
        """A NodeStatus of any node (the updated node's counts)."""
        if entry.node_id != self.node_id or entry.mode == Mode.SOFTWARE_UPDATE:
            return
        if self._phase is Phase.RESTARTING:
            self._phase = Phase.DONE
        elif self._phase is Phase.READING:
            self._fail(
                f"node {self.node_id} left the update at byte {self._sent} of {self.size} "
                f"and runs its old firmware"
            )

    def next_deadline(self) -> float | None:
        """When `poll` next may time the update out, or None when nothing times out."""
        timeout = {
            Phase.WAITING: self.start_timeout,
            Phase.READING: self.read_timeout,
            Phase.RESTARTING: self.restart_timeout,
        }.get(self._phase)
        return None if timeout is None else self._since + timeout

    def poll(self, now: float) -> UpdateProgress:
        """Check the timeouts at ``now``; return where the update stands."""
        waited = now - self._since
        if self._phase is Phase.WAITING and waited >= self.start_timeout:
            self._fail(
                f"node {self.node_id} accepted the update but did not read the image "
                f"within {self.start_timeout:g} s",
                timed_out=True,
            )
        elif self._phase is Phase.READING and waited >= self.read_timeout:
            self._fail(
                f"node {self.node_id} stopped reading the image at byte {self._sent} of "
                f"{self.size} (nothing for {self.read_timeout:g} s)",
                timed_out=True,
            )
        elif self._phase is Phase.RESTARTING and waited >= self.restart_timeout:
            self._fail(
                f"node {self.node_id} read the whole image but did not report running "
                f"within {self.restart_timeout:g} s",
                timed_out=True,
            )
        return self.progress
