"""When frames end on one classic CAN bus, given when each is ready to send (sans-IO).

A simulation's frames are ready at the times its nodes produce them; on a real bus a frame
waits until the bus is free, then the pending frame with the lowest arbitration field
goes first (ISO 11898-1:2015, bitwise arbitration: a dominant 0 wins, so the lower
identifier wins, and a base frame beats an extended frame of the same 11 base bits, its
IDE bit being dominant), and a node sends its own frames in the order it queued them. A
receiver stamps a frame when it is whole, so a frame's time in a log is the end of its
last bit. Frame lengths are `veronte4x.capture.rates.frame_bits` with the worst-case
stuff bits.
"""

from __future__ import annotations

import heapq
from collections import deque
from collections.abc import Hashable, Sequence
from dataclasses import dataclass

from veronte4x.capture.rates import frame_bits

__all__ = ["PendingFrame", "transmit"]


@dataclass(frozen=True, slots=True)
class PendingFrame:
    """A frame a node wants to send.

    Attributes:
        ready: When the node queues it, s.
        can_id: Its CAN ID (11 or 29 bits).
        extended: A 29-bit ID.
        data_bytes: Its data length, 0..8.
        sender: The queue it waits in (a node): frames of one sender go in order.
    """

    ready: float
    can_id: int
    extended: bool
    data_bytes: int
    sender: Hashable


def _arbitration(frame: PendingFrame) -> tuple[int, int, int]:
    """The order of arbitration: lower wins."""
    if frame.extended:
        return frame.can_id >> 18, 1, frame.can_id & 0x3FFFF
    return frame.can_id, 0, 0


def transmit(frames: Sequence[PendingFrame], bitrate: int = 1_000_000) -> list[float]:
    """The time each of ``frames`` ends on the bus, in the order given.

    Args:
        frames: Every frame of the bus; a sender's frames in the order it queues them (a
            frame is queued no earlier than the sender's frame before it).
        bitrate: The bus's bit rate, bit/s.

    Returns:
        The end time of each frame, s: non-decreasing in the order the bus carries them.
    """
    queued: list[float] = []
    latest: dict[Hashable, float] = {}
    for frame in frames:
        latest[frame.sender] = max(frame.ready, latest.get(frame.sender, frame.ready))
        queued.append(latest[frame.sender])
    arrivals = sorted(range(len(frames)), key=queued.__getitem__)
    queues: dict[Hashable, deque[int]] = {}
    heads: list[tuple[tuple[int, int, int], int]] = []  # (arbitration, index) of each queue's head
    ends = [0.0] * len(frames)
    now, taken = 0.0, 0

    def queue(index: int) -> None:
        waiting = queues.setdefault(frames[index].sender, deque())
        waiting.append(index)
        if len(waiting) == 1:
            heapq.heappush(heads, (_arbitration(frames[index]), index))

    while taken < len(arrivals) or heads:
        if not heads:
            now = max(now, queued[arrivals[taken]])
        while taken < len(arrivals) and queued[arrivals[taken]] <= now:
            queue(arrivals[taken])
            taken += 1
        _, index = heapq.heappop(heads)
        frame = frames[index]
        now += frame_bits(frame.data_bytes, frame.extended) / bitrate
        ends[index] = now
        waiting = queues[frame.sender]
        waiting.popleft()
        if waiting:
            following = waiting[0]
            heapq.heappush(heads, (_arbitration(frames[following]), following))
    return ends
