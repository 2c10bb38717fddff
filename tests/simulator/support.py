"""Helpers for the simulator tests: feed requests to an ESC, decode what it sends."""

from __future__ import annotations

from typing import Any

from veronte4x import dronecan
from veronte4x.dronecan.float16 import float16_bits, float16_value
from veronte4x.simulator import SimulatedEsc

CLIENT = 1
ESC = 20

_TRANSFER_IDS: dict[tuple[int, type, int | None], int] = {}


def feed(
    esc: SimulatedEsc,
    message: Any,
    timestamp: float,
    *,
    transfer_id: int | None = None,
    priority: int = 16,
    destination: int | None = ESC,
    source: int = CLIENT,
) -> None:
    """Encode ``message`` from ``source`` and give its frames to ``esc``.

    Transfer ids count per ESC, type and destination unless given, as a real sender's do
    (the reassembler drops a repeated transfer id within its 2 s timeout).
    """
    if isinstance(message, dronecan.RawCommand):
        destination = None
    if transfer_id is None:
        key = (id(esc), type(message), destination)
        transfer_id = _TRANSFER_IDS.get(key, 0)
        _TRANSFER_IDS[key] = (transfer_id + 1) % 32
    for frame in dronecan.encode(
        message,
        source_node_id=source,
        destination_node_id=destination,
        transfer_id=transfer_id,
        priority=priority,
    ):
        esc.receive(frame.can_id, frame.data, timestamp)


def decode(frames: list[dronecan.TransferFrame], timestamp: float = 0.0) -> list[dronecan.Transfer]:
    """Reassemble the frames of one poll into transfers (all must complete)."""
    reassembler = dronecan.Reassembler()
    transfers = [reassembler.feed(f.can_id, f.data, timestamp) for f in frames]
    assert sum(reassembler.counts.values()) == 0
    return [t for t in transfers if t is not None]


def names(frames: list[dronecan.TransferFrame]) -> list[str]:
    """Class names of the transfers in ``frames``."""
    return [type(t.message).__name__ for t in decode(frames)]


def ask(esc: SimulatedEsc, message: Any, timestamp: float, **kwargs: Any) -> dronecan.Transfer:
    """Send one request and return the only response the next poll carries."""
    feed(esc, message, timestamp, **kwargs)
    frames = esc.poll(timestamp)
    responses = [t for t in decode(frames) if t.kind is dronecan.TransferKind.RESPONSE]
    assert len(responses) == 1
    return responses[0]


def f16(value: float) -> float:
    """``value`` as a float16 field carries it."""
    return float16_value(float16_bits(value))


class StepClock:
    """A clock that moves ``step`` seconds further at every reading."""

    def __init__(self, step: float = 0.001, start: float = 0.0) -> None:
        self.step = step
        self.now = start

    def __call__(self) -> float:
        self.now += self.step
        return self.now
