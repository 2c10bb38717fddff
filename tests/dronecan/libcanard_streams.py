"""The frame streams of the libcanard acceptance vectors (data/libcanard_acceptance.json).

Each stream is a list of frames ``(microseconds, interface, can_id, data)``. The vectors
hold the frames themselves and, for each frame, what libcanard's ``canardHandleRxFrame``
returned and the transfer it delivered; so the test needs only the JSON, and this module
is the recipe for its frames. ``python tests/dronecan/libcanard_streams.py input`` prints
the streams as input for a harness around libcanard (built outside the project; the JSON's
``note`` says how), ``... vectors OUTPUT`` turns the harness's output into the JSON.

libcanard keeps one receiver state per descriptor and refuses a service frame not
addressed to its own node, so every stream is run once per destination node id in it,
each run on a fresh instance with that local node id, and each frame takes the result of
the run addressed to it (broadcasts: node 100). The states of different descriptors never
meet, so this is what one instance receiving every node's services would do.
"""

from __future__ import annotations

import json
import random
import sys
from pathlib import Path
from typing import Any

from fault_streams import stream as fault_stream

from veronte4x import dronecan
from veronte4x.dronecan.codec import BY_CLASS, BY_ID

Frame = tuple[int, int, int, bytes]
OK, OPERATIONAL = dronecan.Health.OK, dronecan.Mode.OPERATIONAL
LOCAL_NODE = 100
VECTORS = Path(__file__).parent / "data" / "libcanard_acceptance.json"
LIBCANARD_KIND = {0: 2, 1: 1, 2: 0}  # TransferKind to CanardTransferType


def _status(uptime: int) -> Any:
    return dronecan.NodeStatus(uptime, OK, OPERATIONAL, 0, 0)


def _esc(index: int) -> Any:
    return dronecan.EscStatus(index, 12.5, -3.0, 300.0, 7, 50, 1)  # three frames


def _raw(count: int) -> Any:
    return dronecan.RawCommand(tuple(range(-count // 2, count - count // 2)))  # 0 to 3: one frame


def _frames(message: Any, tid: int, node: int = 10) -> list[tuple[int, bytes]]:
    return [
        (f.can_id, f.data) for f in dronecan.encode(message, source_node_id=node, transfer_id=tid)
    ]


def _timed(
    transfers: list[list[tuple[int, bytes]]], step: int, start: int = 1_000_000
) -> list[Frame]:
    """Frames one after the other, ``step`` microseconds apart, on interface 0."""
    frames = [frame for transfer in transfers for frame in transfer]
    return [(start + step * n, 0, can_id, data) for n, (can_id, data) in enumerate(frames)]


def _toggled(frame: tuple[int, bytes]) -> tuple[int, bytes]:
    can_id, data = frame
    return can_id, data[:-1] + bytes([data[-1] ^ 0x20])


def _hand_made() -> dict[str, list[Frame]]:
    esc = [_frames(_esc(i), tid) for i, tid in enumerate([5, 6, 7])]
    raw7 = _frames(_raw(7), 9)  # two frames
    long = _frames(_raw(16), 3)  # five frames
    return {
        # A node whose transfer id never advances (the StaticPressure capture of issue 35).
        "stuck single frames": _timed(
            [_frames(dronecan.StaticPressure(101_325.0 + i, 1.0), 0) for i in range(17)], 20_000
        ),
        "stuck multi-frame": _timed([_frames(_esc(i), 4) for i in range(5)], 20_000),
        "stuck multi-frame past the timeout": _timed(
            [_frames(_esc(i), 4) for i in range(4)], 700_000
        ),
        "stuck single and multi-frame": _timed(
            [_frames(_raw(n), 2) for n in (2, 7, 3, 7, 7, 1)], 10_000
        ),
        "the same single frame again": _timed(
            [_frames(_status(1), 2)] * 3 + [_frames(_status(2), 3)], 10_000
        ),
        "in order": _timed([_frames(_esc(i), i % 32) for i in range(40)], 1_000),
        "wrapped": _timed([_frames(_status(i), (30 + i) % 32) for i in range(6)], 10_000),
        "wrapped multi-frame": _timed([_frames(_esc(i), (29 + i) % 32) for i in range(6)], 10_000),
        "skipped by one": _timed(
            [_frames(_esc(0), 3), _frames(_esc(1), 5), _frames(_esc(2), 6)], 10_000
        ),
        "skipped by two": _timed(
            [_frames(_esc(0), 3), _frames(_esc(1), 6), _frames(_esc(2), 7)], 10_000
        ),
        "backwards by one": _timed(
            [_frames(_esc(0), 8), _frames(_esc(1), 7), _frames(_esc(2), 8)], 10_000
        ),
        "backwards by one single frames": _timed(
            [_frames(_status(0), 8), _frames(_status(1), 7), _frames(_status(2), 8)], 10_000
        ),
        "the same transfer again": _timed([esc[0], esc[0], esc[1]], 10_000),
        "a frame twice": _timed([esc[0][:2] + esc[0][1:], esc[1]], 10_000),
        "first frame twice": _timed([esc[0][:1] + esc[0], esc[1]], 10_000),
        "dropped middle frame": _timed([esc[0][:1] + esc[0][2:], esc[1], esc[2]], 10_000),
        "dropped first frame": _timed([esc[0][1:], esc[1], esc[2]], 10_000),
        "dropped last frame": _timed([esc[0][:2], esc[1], esc[2]], 10_000),
        "toggle flipped": _timed([[esc[0][0], _toggled(esc[0][1]), esc[0][2]], esc[1]], 10_000),
        "toggle set on a first frame": _timed([[_toggled(esc[0][0]), *esc[0][1:]], esc[1]], 10_000),
        "toggle set on a single frame": _timed(
            [[_toggled(_frames(_status(0), 1)[0])], _frames(_status(1), 2)], 10_000
        ),
        "frame out of order then resent": _timed(
            [[long[0], long[2], long[1], long[2], long[3], long[4]]], 10_000
        ),
        "interrupted after one frame, same id": _timed([esc[0][:1], _frames(_esc(2), 5)], 10_000),
        "interrupted after two frames, same id": _timed([esc[0][:2], _frames(_esc(2), 5)], 10_000),
        "interrupted by the next id": _timed([esc[0][:2], esc[1], esc[2]], 10_000),
        "interrupted by a single frame": _timed(
            [raw7[:1], _frames(_raw(2), 9), _frames(_raw(7), 10)], 10_000
        ),
        "timeout within a transfer": [
            (1_000_000, 0, *esc[0][0]),
            (1_010_000, 0, *esc[0][1]),
            (3_500_000, 0, *esc[0][2]),
            *[(3_600_000 + 10_000 * i, 0, *f) for i, f in enumerate(esc[1])],
        ],
        "exactly the timeout": [
            *[(1_000_000 + 10_000 * i, 0, *f) for i, f in enumerate(esc[0])],
            *[(3_000_000 + 10_000 * i, 0, *f) for i, f in enumerate(_frames(_esc(1), 5))],
            *[(3_000_001 + 10_000 * i, 0, *f) for i, f in enumerate(_frames(_esc(2), 5))],
        ],
        "interleaved sessions": [
            (1_000_000 + 1_000 * i, 0, *f)
            for i, f in enumerate(
                x
                for pair in zip(_frames(_esc(0), 1, 10), _frames(_esc(1), 1, 11), strict=True)
                for x in pair
            )
        ],
        "interleaved transfers of one session": _timed(
            [[x for pair in zip(esc[0], esc[1], strict=True) for x in pair]], 1_000
        ),
        # Interfaces: veronte4x takes each channel as a bus of its own (see the test).
        "interface switch": [
            *[
                (1_000_000 + 10_000 * i, 0, *f)
                for i, f in enumerate(_frames(_status(0), 0) + _frames(_status(1), 1))
            ],
            *[(1_100_000 + 10_000 * i, 1, *f) for i, f in enumerate(_frames(_status(2), 2))],
            *[(2_500_000 + 10_000 * i, 1, *f) for i, f in enumerate(_frames(_status(3), 3))],
        ],
        "redundant interfaces": [
            (1_000_000 + 20_000 * n + 1_000 * iface, iface, can_id, data)
            for n, (can_id, data) in enumerate(f for i in range(4) for f in _frames(_esc(i), i))
            for iface in (0, 1)
        ],
    }


def _faulted(seed: int, rate: float, sessions: int) -> list[Frame]:
    """A stream of `fault_streams` (services among its sessions), ``rate`` of it damaged."""
    _, wire, times = fault_stream(seed, 160, rate, sessions)
    return [
        (round(t * 1e6) + 1_000_000, 0, f.can_id, f.data) for f, t in zip(wire, times, strict=True)
    ]


def streams() -> dict[str, list[Frame]]:
    """Every stream, by name."""
    found = _hand_made()
    for seed in range(8):
        found[f"faulted {seed}"] = _faulted(seed, 0.2, 4)
    for seed in range(8, 20):
        found[f"faulted {seed}, one session"] = _faulted(seed, 0.3, 1)
    rng = random.Random(35)
    for seed in range(4):  # one session, transfer ids and toggles at random
        frames: list[Frame] = []
        at = 1_000_000
        for n in range(60):
            message = _esc(n % 3) if rng.random() < 0.5 else _status(n)
            for can_id, data in _frames(message, rng.choice([n % 32, 0, 1, (n - 1) % 32])):
                if rng.random() < 0.1:
                    continue
                if rng.random() < 0.1:
                    data = data[:-1] + bytes([data[-1] ^ 0x20])
                at += rng.choice([1_000, 1_000, 400_000, 1_100_000])
                frames.append((at, 0, can_id, data))
        found[f"random tids {seed}"] = frames
    return found


def _destination(can_id: int) -> int:
    return (can_id >> 8) & 0x7F if can_id & 0x80 else LOCAL_NODE


def _runs(stream: list[Frame]) -> list[tuple[int, int | None]]:
    """The harness runs of a stream: (local node id, interface or None for all of them)."""
    nodes = sorted({LOCAL_NODE} | {_destination(c) for _, _, c, _ in stream})
    interfaces = sorted({i for _, i, _, _ in stream})
    alone = [None] if len(interfaces) == 1 else [None, *interfaces]
    return [(node, interface) for node in nodes for interface in alone]


def _fed(stream: list[Frame], interface: int | None) -> list[int]:
    return [n for n, (_, i, _, _) in enumerate(stream) if interface is None or i == interface]


def harness_input(named: dict[str, list[Frame]]) -> str:
    """The harness's input: the accepted types, then each stream once per run."""
    types = [c.data_type for c in {*BY_ID.values(), *BY_CLASS.values()}]
    lines = sorted(
        f"sig {t.data_type_id} {LIBCANARD_KIND[t.kind]} {t.signature:x}"
        for t in types
        if t.full_name.startswith("uavcan.")
    )
    for stream in named.values():
        for node, interface in _runs(stream):
            lines.append(f"new {node}")
            for n in _fed(stream, interface):
                t, i, c, d = stream[n]
                lines.append(f"frame {t} {i} {c:x} {d.hex()}")
    return "\n".join(lines) + "\n"


def vectors(named: dict[str, list[Frame]], output: str, commit: str, note: str) -> dict[str, Any]:
    """The JSON document from the harness's ``output`` for ``harness_input(named)``.

    ``libcanard`` is each frame's result with every interface fed to one instance;
    ``interfaces_apart``, for a stream on several interfaces, with each interface fed to
    an instance of its own."""
    lines = output.splitlines()
    head = int(lines.pop(0).split()[1])
    found: dict[str, Any] = {}
    for name, stream in named.items():
        results: dict[tuple[int, int | None], dict[int, list[Any]]] = {}
        for run in _runs(stream):
            results[run] = {}
            for n in _fed(stream, run[1]):
                fields = lines.pop(0).split()
                code = int(fields[1])
                results[run][n] = (
                    [code, int(fields[3]), fields[5] if len(fields) > 5 else ""]
                    if len(fields) > 2
                    else [code]
                )
        found[name] = {
            "frames": [[t, i, c, d.hex()] for t, i, c, d in stream],
            "libcanard": [
                results[_destination(c), None][n] for n, (_, _, c, _) in enumerate(stream)
            ],
        }
        if any(run[1] is not None for run in results):
            found[name]["interfaces_apart"] = [
                results[_destination(c), i][n] for n, (_, i, c, _) in enumerate(stream)
            ]
    assert not lines
    return {"note": note, "libcanard_commit": commit, "payload_head_size": head, "streams": found}


if __name__ == "__main__":
    if sys.argv[1] == "input":
        sys.stdout.write(harness_input(streams()))
    else:
        document = vectors(streams(), Path(sys.argv[2]).read_text(), sys.argv[3], sys.argv[4])
        VECTORS.write_text(
            json.dumps(document, separators=(",", ":")).replace("],[", "],\n[") + "\n"
        )
