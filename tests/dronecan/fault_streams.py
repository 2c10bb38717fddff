"""Long frame streams with faults, and what an exact reassembler must make of them.

`stream` puts thousands of transfers of a few sessions (distinct descriptors: single and
multi-frame messages, service requests) on a simulated bus, interleaved, and damages a
fraction of the frames: dropped, sent twice, swapped with the next, a bit flipped anywhere,
truncated, a bit of the CAN ID flipped, a bit of the tail byte flipped. Every frame keeps
where it came from, so `check` can judge the reassembler's output against what was sent.
"""

from __future__ import annotations

import random
from dataclasses import dataclass
from typing import Any

from veronte4x import dronecan

TIMEOUT = dronecan.TRANSFER_ID_TIMEOUT
FAULTS = ("drop", "twice", "swap", "bit", "truncate", "can_id", "tail")
_OK, _OPERATIONAL = dronecan.Health.OK, dronecan.Mode.OPERATIONAL


@dataclass(frozen=True)
class Sent:
    """One transfer put on the bus."""

    key: int  # the session: CAN ID without priority
    tid: int
    message: Any
    frames: tuple[tuple[int, bytes], ...]


@dataclass(frozen=True)
class OnWire:
    """One frame of the stream and where it came from."""

    can_id: int
    data: bytes
    transfer: int  # index into the sent transfers
    index: int  # frame index within its transfer
    damaged: bool  # its bytes or CAN ID differ from what was sent


def _message(rng: random.Random, request: bool) -> Any:
    if request:
        if rng.random() < 0.5:
            return dronecan.GetNodeInfoRequest()
        return dronecan.GetSetRequest(name=rng.randbytes(rng.randrange(21)))
    kind = rng.randrange(3)
    if kind == 0:
        return dronecan.NodeStatus(rng.randrange(4), _OK, _OPERATIONAL, 0, rng.randrange(4))
    if kind == 1:
        return dronecan.EscStatus(rng.randrange(4), 12.5, -3.0, 300.0, 7, 50, rng.randrange(3))
    return dronecan.RawCommand(tuple(rng.randrange(-2, 3) for _ in range(rng.randrange(17))))


def _damage(
    rng: random.Random, frames: list[tuple[int, bytes]], number: int, rate: float
) -> list[OnWire]:
    out: list[OnWire] = []
    i = 0
    while i < len(frames):
        can_id, data = frames[i]
        fault = rng.choice(FAULTS) if rng.random() < rate else None
        if fault == "twice":
            out += [OnWire(can_id, data, number, i, False)] * 2
        elif fault == "swap" and i + 1 < len(frames):
            after = frames[i + 1]
            out += [OnWire(*after, number, i + 1, False), OnWire(can_id, data, number, i, False)]
            i += 1
        elif fault == "bit":
            flipped = bytearray(data)
            bit = rng.randrange(8 * len(data))
            flipped[bit // 8] ^= 1 << (bit % 8)
            out.append(OnWire(can_id, bytes(flipped), number, i, True))
        elif fault == "truncate" and len(data) > 1:
            out.append(OnWire(can_id, data[: rng.randrange(1, len(data))], number, i, True))
        elif fault == "can_id":
            out.append(OnWire(can_id ^ 1 << rng.randrange(29), data, number, i, True))
        elif fault == "tail":
            tail = data[-1] ^ 1 << rng.randrange(8)
            out.append(OnWire(can_id, data[:-1] + bytes([tail]), number, i, True))
        elif fault != "drop":
            out.append(OnWire(can_id, data, number, i, False))
        i += 1
    return out


def stream(
    seed: int, transfers: int, rate: float, sessions: int = 4
) -> tuple[list[Sent], list[OnWire], list[float]]:
    """``transfers`` transfers of ``sessions`` sessions, a ``rate`` of their frames damaged.

    Time advances 1 ms per frame, now and then 0.7 s or 2.5 s (past the transfer-ID timeout).
    """
    rng = random.Random(seed)
    sent: list[Sent] = []
    streams: list[list[OnWire]] = []
    for source in rng.sample(range(1, 8), sessions):
        destination, first_tid, request = rng.randrange(1, 7), rng.randrange(32), rng.random() < 0.3
        own: list[OnWire] = []
        for n in range(transfers // sessions):
            message, tid = _message(rng, request), (first_tid + n) % 32
            frames = [
                (f.can_id, f.data)
                for f in dronecan.encode(
                    message,
                    source_node_id=source,
                    transfer_id=tid,
                    destination_node_id=destination if request else None,
                )
            ]
            own += _damage(rng, frames, len(sent), rate)
            sent.append(Sent(frames[0][0] & 0xFFFFFF, tid, message, tuple(frames)))
        streams.append(own)
    wire: list[OnWire] = []
    cursors = [0] * len(streams)
    while live := [s for s, own in enumerate(streams) if cursors[s] < len(own)]:
        pick = rng.choice(live)
        wire.append(streams[pick][cursors[pick]])
        cursors[pick] += 1
    times, now = [], 0.0
    for _ in wire:
        now += rng.choice([0.001] * 30 + [0.0, 0.7, 2.5])
        times.append(now)
    return sent, wire, times


def intact(sent: list[Sent], wire: list[OnWire], times: list[float]) -> dict[int, list[int]]:
    """Transfers whose frames all arrived, once, in order, undamaged, with no other frame of
    their session in between, within the timeout: transfer index to its stream positions."""
    positions: dict[int, list[int]] = {}
    for position, frame in enumerate(wire):
        positions.setdefault(frame.transfer, []).append(position)
    found = {}
    for number, transfer in enumerate(sent):
        where = positions.get(number, [])
        frames = [wire[p] for p in where]
        if (
            [f.index for f in frames] != list(range(len(transfer.frames)))
            or any(f.damaged for f in frames)
            or times[where[-1]] - times[where[0]] > TIMEOUT
        ):
            continue
        between = wire[where[0] : where[-1] + 1]
        if any(f.can_id & 0xFFFFFF == transfer.key and f.transfer != number for f in between):
            continue
        found[number] = where
    return found


@dataclass
class Verdict:
    """What a reassembler made of a stream, judged against what was sent."""

    lost: list[int]  # intact transfers not delivered, beyond what no receiver can recover
    unrecoverable: list[int]  # intact transfers lost for want of any way to tell
    corrupted: int  # deliveries of a damaged single frame (no CRC can catch them)


def check(sent: list[Sent], wire: list[OnWire], times: list[float], results: list[Any]) -> Verdict:
    """Judge ``results`` (one `feed` result per frame of ``wire``).

    Raises ``AssertionError`` for a delivered transfer that is neither one that was sent
    nor a damaged single frame, or an intact transfer delivered with other content.
    Unrecoverable: an intact single-frame transfer refused because the transfer delivered
    just before it in its session was a single frame with the same transfer id and within
    the timeout (a damaged frame whose tail byte now names that transfer id, or a replay:
    nothing in the frames tells them apart; see docs/dronecan/reassembly.md).
    """
    corrupted = 0
    for position, got in enumerate(results):
        if got is None:
            continue
        frame = wire[position]
        if got.message != sent[frame.transfer].message:
            assert frame.damaged and frame.data[-1] & 0xC0 == 0xC0, (position, got, frame)
            corrupted += 1
    lost, unrecoverable = [], []
    for number, where in intact(sent, wire, times).items():
        got = results[where[-1]]
        if got is not None:
            assert got.message == sent[number].message and got.transfer_id == sent[number].tid
            continue
        key, start = sent[number].key, where[0]
        before = [
            (wire[p], results[p])
            for p in range(start)
            if results[p] is not None and wire[p].can_id & 0xFFFFFF == key
        ]
        if before and len(sent[number].frames) == 1:
            frame, previous = before[-1]
            if (
                previous.transfer_id == sent[number].tid
                and frame.data[-1] & 0xC0 == 0xC0
                and times[start] - previous.timestamp <= TIMEOUT
            ):
                unrecoverable.append(number)
                continue
        lost.append(number)
    return Verdict(lost, unrecoverable, corrupted)
