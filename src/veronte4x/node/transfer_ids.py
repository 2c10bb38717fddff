"""Transfer ids, counted per (destination, transfer kind, data type) as the spec asks."""

from __future__ import annotations

from veronte4x.dronecan.can_id import TransferKind
from veronte4x.dronecan.tail import TRANSFER_ID_MASK

TRANSFER_ID_MODULO = TRANSFER_ID_MASK + 1
"""Transfer ids are 5 bits: they count 0..31 and wrap."""


class TransferIds:
    """The next transfer id of each outgoing transfer stream.

    A stream is a data type of one kind sent to one destination (None for a broadcast
    message); DroneCAN increments the id per stream, so that a receiver can tell a new
    transfer from a repeated one.

    Args:
        first: The id of each stream's first transfer. A short-lived tool (one command line
            run) should start at a random value: a receiver takes a transfer with the id it
            just received from the same stream, within its 2 s transfer-id timeout, for a
            repeat, so a run that starts at 0 again right after another would lose its
            first request.

    Examples:
        >>> ids = TransferIds()
        >>> [ids.next(TransferKind.REQUEST, 11, 21) for _ in range(3)], ids.next(
        ...     TransferKind.REQUEST, 11, 22
        ... )
        ([0, 1, 2], 0)
    """

    __slots__ = ("_first", "_next")

    def __init__(self, first: int = 0) -> None:
        self._first = first % TRANSFER_ID_MODULO
        self._next: dict[tuple[TransferKind, int, int | None], int] = {}

    def next(self, kind: TransferKind, data_type_id: int, destination: int | None) -> int:
        """The id for the next transfer of this stream; the stream's counter moves on."""
        key = (kind, data_type_id, destination)
        transfer_id = self._next.get(key, self._first)
        self._next[key] = (transfer_id + 1) % TRANSFER_ID_MODULO
        return transfer_id
