"""Benchmark: veronte4x.dronecan against the ``dronecan`` package, side by side.

Encode (message object to frames) and decode (frames through reassembly to a message
object) transfers per second for NodeStatus, esc.Status (3 frames) and RawCommand with 4
and 8 ESCs. Both libraries get the same messages and frames, in the same run.

Run: ``.venv/bin/python benchmarks/bench_dronecan.py [--seconds 0.5]``
"""

from __future__ import annotations

import argparse
import os
import platform
import sys
import timeit
from collections.abc import Callable
from typing import Any

import dronecan as dc
from dronecan import transport
from veronte4x import dronecan as v4

CASES: dict[str, tuple[Any, Callable[[], Any]]] = {
    "NodeStatus": (
        v4.NodeStatus(123456, v4.Health.OK, v4.Mode.OPERATIONAL, 0, 0),
        lambda: dc.uavcan.protocol.NodeStatus(
            uptime_sec=123456, health=0, mode=0, sub_mode=0, vendor_specific_status_code=0
        ),
    ),
    "esc.Status (3 frames)": (
        v4.EscStatus(3, 24.5, 12.25, 310.0, 4321, 55, 2),
        lambda: dc.uavcan.equipment.esc.Status(
            error_count=3,
            voltage=24.5,
            current=12.25,
            temperature=310.0,
            rpm=4321,
            power_rating_pct=55,
            esc_index=2,
        ),
    ),
    "RawCommand x4": (
        v4.RawCommand((1000, 2000, -3000, 8191)),
        lambda: dc.uavcan.equipment.esc.RawCommand(cmd=[1000, 2000, -3000, 8191]),
    ),
    "RawCommand x8": (
        v4.RawCommand((1000, 2000, -3000, 8191, 0, -8192, 17, 4095)),
        lambda: dc.uavcan.equipment.esc.RawCommand(
            cmd=[1000, 2000, -3000, 8191, 0, -8192, 17, 4095]
        ),
    ),
}


def _rate(function: Callable[[], Any], seconds: float) -> float:
    """Transfers per second: best of 3 runs of about ``seconds`` each."""
    number = 1
    while timeit.timeit(function, number=number) < seconds / 10:
        number *= 2
    best = min(timeit.repeat(function, number=number, repeat=3))
    return number / best


def _cycle(transfers: list[Any]) -> Callable[[], Any]:
    """A function returning the next item of ``transfers`` each call, round and round."""
    position = [0]

    def step() -> Any:
        position[0] = (position[0] + 1) % len(transfers)
        return transfers[position[0]]

    return step


def _ours(message: Any) -> tuple[Callable[[], Any], Callable[[], Any]]:
    """Encode one message object; decode transfers with transfer ids 0..31 in turn."""

    def encode() -> Any:
        return v4.encode(message, source_node_id=42, transfer_id=7, priority=16)

    transfers = [
        [(f.can_id, f.data) for f in v4.encode(message, source_node_id=42, transfer_id=tid)]
        for tid in range(32)
    ]
    following = _cycle(transfers)
    feed = v4.Reassembler().feed
    clock = [0.0]

    def decode() -> Any:
        clock[0] += 0.001
        result = None
        for can_id, data in following():
            result = feed(can_id, data, clock[0])
        return result.message

    assert decode() == message
    return encode, decode


def _reference(make: Callable[[], Any]) -> tuple[Callable[[], Any], Callable[[], Any], list]:
    """The same with the dronecan package: its Transfer.to_frames, TransferManager, from_frames."""
    message = make()

    def encode() -> Any:
        t = transport.Transfer(
            transfer_id=7, source_node_id=42, payload=message, transfer_priority=16
        )
        return t.to_frames()

    frames = encode()
    following = _cycle(
        [
            transport.Transfer(
                transfer_id=tid, source_node_id=42, payload=message, transfer_priority=16
            ).to_frames()
            for tid in range(32)
        ]
    )
    manager = transport.TransferManager()

    def decode() -> Any:
        result = None
        for frame in following():
            result = manager.receive_frame(frame)
        t = transport.Transfer()
        t.from_frames(result)
        return t.payload

    return encode, decode, frames


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=0.5, help="time per measurement")
    args = parser.parse_args()
    print(f"python {platform.python_version()}, nproc {os.cpu_count()}, {platform.machine()}")
    print(f"{'case':24} {'op':6} {'veronte4x/s':>12} {'dronecan/s':>11} {'ratio':>7}")
    worst = float("inf")
    for name, (ours, make) in CASES.items():
        our_encode, our_decode = _ours(ours)
        ref_encode, ref_decode, ref_frames = _reference(make)
        our_frames = our_encode()
        assert [(f.can_id, f.data) for f in our_frames] == [
            (f.message_id, bytes(f.bytes)) for f in ref_frames
        ], name
        for op, mine, theirs in (
            ("encode", our_encode, ref_encode),
            ("decode", our_decode, ref_decode),
        ):
            a, b = _rate(mine, args.seconds), _rate(theirs, args.seconds)
            worst = min(worst, a / b)
            print(f"{name:24} {op:6} {a:12,.0f} {b:11,.0f} {a / b:6.1f}x")
    print(f"lowest ratio: {worst:.1f}x")
    sys.exit(0)


if __name__ == "__main__":
    main()
