"""What every DroneCAN node of the package does alike, below the ground client and the
simulated ESC that both use it (sans-IO): transfer ids per stream, and service requests
matched with their responses, timed out and retried.

`veronte4x.client` (the ground station) and `veronte4x.simulator` (a Vertiq ESC pulling a
firmware image) both send requests; neither imports the other.
"""

from __future__ import annotations

from veronte4x.node.requests import (
    DEFAULT_RETRIES,
    DEFAULT_TIMEOUT,
    Answered,
    Pending,
    Requester,
    TimedOut,
    answers,
)
from veronte4x.node.transfer_ids import TRANSFER_ID_MODULO, TransferIds

__all__ = [
    "DEFAULT_RETRIES",
    "DEFAULT_TIMEOUT",
    "TRANSFER_ID_MODULO",
    "Answered",
    "Pending",
    "Requester",
    "TimedOut",
    "TransferIds",
    "answers",
]
