"""Decode and encode speed of veronte4x.codec, side by side with cantools and a struct floor.

Run: python benchmarks/bench_codec.py [--seconds 0.3]

For each message type, cantools gets an equivalent DBC message built in memory (same
signals, little endian) and runs `decode_message` / `encode_message` on the same frames.
The floor is `struct.unpack_from` plus building the same frozen dataclass, the least any
Python decoder returning typed messages can do. Rates are frames per second, best of five
turns, the libraries timed in turns so that they see the same machine load.
"""

from __future__ import annotations

import argparse
import platform
import struct
import timeit
from collections.abc import Callable
from dataclasses import dataclass

import cantools.database as cdb
from cantools.database.can import Database, Message, Signal
from cantools.database.conversion import BaseConversion

from veronte4x import codec
from veronte4x.codec.layouts import STATUS_FLAGS

ARB, AP = codec.Sender.ARBITER, codec.Sender.AUTOPILOT


@dataclass
class Case:
    name: str
    data: bytes
    sender: codec.Sender
    signals: list[tuple[str, int, int, bool]]  # name, start bit, length, is_float
    floor: Callable[[bytes], object]


def _bits(prefix: str, start: int, count: int) -> list[tuple[str, int, int, bool]]:
    return [(f"{prefix}{i}", start + i, 1, False) for i in range(count)]


_STATUS_STRUCT = struct.Struct("<BBBBBB")
_FLOAT_STRUCT = struct.Struct("<BBf")
_BOOL = (False, True)


def _floor_status(data: bytes) -> object:
    _, _, b2, b3, b4, b5 = _STATUS_STRUCT.unpack_from(data)
    return codec.Status(
        b2 & 0x7F,
        _BOOL[b2 >> 7],
        (_BOOL[b3 & 1], _BOOL[b3 >> 1 & 1], _BOOL[b3 >> 2 & 1], _BOOL[b3 >> 3 & 1]),
        (_BOOL[b3 >> 4 & 1], _BOOL[b3 >> 5 & 1], _BOOL[b3 >> 6 & 1], _BOOL[b3 >> 7]),
        *[_BOOL[b4 >> i & 1] for i in range(8)],
        *[_BOOL[b5 >> i & 1] for i in range(8)],
    )


def _floor_score(data: bytes) -> object:
    _, autopilot, score = _FLOAT_STRUCT.unpack_from(data)
    return codec.Score(autopilot, score)


def _floor_variable(data: bytes) -> object:
    _, number, value = _FLOAT_STRUCT.unpack_from(data)
    return codec.ArbitrationVariable(number, value)


def _floor_ready(data: bytes) -> object:
    return codec.Ready(data[2] == 1)


def _floor_pwm(data: bytes) -> object:
    word = int.from_bytes(data[1:7], "little")
    return codec.PwmSet(0, (word & 0xFFF, word >> 12 & 0xFFF, word >> 24 & 0xFFF, word >> 36))


def _floor_opaque(data: bytes) -> object:
    return codec.JetiTemperature(data[1:])


HEAD = [("cmd", 0, 8, False)]
CASES = [
    Case(
        "Status (6 B)",
        bytes.fromhex("00ff8177ffff"),
        ARB,
        [*HEAD, ("header", 8, 8, False), ("selected", 16, 7, False), ("arbitrating", 23, 1, False),
         *_bits("alive", 24, 4), *_bits("ready", 28, 4),
         *[(name, 32 + i, 1, False) for i, (name, _) in enumerate(STATUS_FLAGS)]],
        _floor_status,
    ),
    Case(
        "Score",
        bytes.fromhex("00010000803f"),
        ARB,
        [*HEAD, ("autopilot", 8, 8, False), ("score", 16, 32, True)],
        _floor_score,
    ),
    Case(
        "Ready",
        bytes.fromhex("00ff01"),
        AP,
        [*HEAD, ("header", 8, 8, False), ("ready", 16, 1, False), ("reserved", 17, 7, False)],
        _floor_ready,
    ),
    Case(
        "ArbitrationVariable",
        bytes.fromhex("0000cdcccc3d"),
        AP,
        [*HEAD, ("number", 8, 8, False), ("value", 16, 32, True)],
        _floor_variable,
    ),
    Case(
        "PwmSet",
        bytes.fromhex("0223614589c7ab"),
        AP,
        [*HEAD, *[(f"value{i}", 8 + 12 * i, 12, False) for i in range(4)]],
        _floor_pwm,
    ),
    Case(
        "JetiTemperature (opaque, 7 B payload)",
        bytes.fromhex("09000102030405ff"),
        AP,
        [*HEAD, ("payload", 8, 56, False)],
        _floor_opaque,
    ),
]  # fmt: skip


def _database() -> Database:
    messages = []
    for frame_id, case in enumerate(CASES):
        signals = [
            Signal(
                name,
                start,
                length,
                byte_order="little_endian",
                conversion=BaseConversion.factory(scale=1, offset=0, is_float=is_float),
            )
            for name, start, length, is_float in case.signals
        ]
        messages.append(Message(frame_id, case.name.split()[0], len(case.data), signals))
    return cdb.can.Database(messages)


def _rates(functions: list[Callable[[], object]], seconds: float) -> list[float]:
    """Calls per second of each function, timed in turns (best of five turns each), so
    that all of them see the same load on a shared machine."""
    timers = [timeit.Timer(function) for function in functions]
    numbers = [max(1, int(timer.autorange()[0] * seconds / 0.2)) for timer in timers]
    best = [float("inf")] * len(timers)
    for _ in range(5):
        for i, (timer, number) in enumerate(zip(timers, numbers, strict=True)):
            best[i] = min(best[i], timer.timeit(number) / number)
    return [1 / b for b in best]


def main() -> None:
    """Measure every case and print a table of rates and ratios."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=0.3, help="time per measurement")
    seconds = parser.parse_args().seconds
    db = _database()
    print(f"Python {platform.python_version()} on {platform.machine()}, {platform.processor()}")
    print(
        f"{'message':38} {'decode/s':>10} {'cantools':>10} {'floor':>10} {'x cantools':>10}"
        f" {'encode/s':>10} {'cantools':>10} {'x cantools':>10}"
    )
    for frame_id, case in enumerate(CASES):
        data, sender = case.data, case.sender
        message = codec.decode(data, sender=sender)
        values = db.decode_message(frame_id, data, decode_choices=False)
        assert db.encode_message(frame_id, values) == data
        assert codec.encode(message) == data
        ours, theirs, floor = _rates(
            [
                lambda: codec.decode(data, sender=sender),  # noqa: B023
                lambda: db.decode_message(frame_id, data),  # noqa: B023
                lambda: case.floor(data),  # noqa: B023
            ],
            seconds,
        )
        ours_enc, theirs_enc = _rates(
            [
                lambda: codec.encode(message),  # noqa: B023
                lambda: db.encode_message(frame_id, values),  # noqa: B023
            ],
            seconds,
        )
        print(
            f"{case.name:38} {ours:10.0f} {theirs:10.0f} {floor:10.0f} {ours / theirs:10.2f}"
            f" {ours_enc:10.0f} {theirs_enc:10.0f} {ours_enc / theirs_enc:10.2f}"
        )


if __name__ == "__main__":
    main()
