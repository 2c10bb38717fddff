"""bitstruct's C extension against the generated decoders, on the bit-level layouts.

Run: python benchmarks/bench_bitstruct.py [--seconds 0.2]

For each layout with fields that are not whole bytes (PWM set in both packings, a declared
layout with sub-byte and signed fields, the 6-byte Status), two decoders producing the same
message are timed side by side: the layout's generated decoder, and `bitstruct.c` unpacking
the fields followed by the same message construction (a builder class of identical slots,
as the generated code does), so only the field extraction differs. Both are checked to
give equal messages first. Rates are frames per second, best of five.
"""

from __future__ import annotations

import argparse
import platform
import timeit
from collections.abc import Callable

import bitstruct.c as bitstruct_c

from veronte4x import codec
from veronte4x.codec import layouts
from veronte4x.codegen import slot_builder

_BOOL = (False, True)


def _pwm(packing: codec.PwmPacking) -> tuple[Callable[[bytes], object], Callable[[bytes], object]]:
    generated = layouts.PWM_SET[packing].functions[0]
    build = slot_builder(codec.PwmSet)
    assert build is not None
    first = {wire: channel for channel, wire in layouts.PWM_COMMANDS.items()}
    if packing is codec.PwmPacking.MSB_FIRST:
        compiled = bitstruct_c.compile("u8u12u12u12u12")

        def with_bitstruct(data: bytes) -> object:
            command, *values = compiled.unpack(data)
            o = build()
            o.first_channel = first[command]
            o.values = tuple(values)
            o.__class__ = codec.PwmSet
            return o

    else:  # bytes 1-6 little-endian: reversed, the word reads MSB first, last channel first
        compiled = bitstruct_c.compile("u12u12u12u12")

        def with_bitstruct(data: bytes) -> object:
            v3, v2, v1, v0 = compiled.unpack(data[:0:-1])
            o = build()
            o.first_channel = first[data[0]]
            o.values = (v0, v1, v2, v3)
            o.__class__ = codec.PwmSet
            return o

    return lambda data: generated(data, False), with_bitstruct


_DECLARED = codec.Layout(
    5,
    "SubByte",
    [
        codec.unsigned("a", 4),
        codec.unsigned("b", 12),
        codec.signed("c", 10),
        codec.unsigned("d", 6),
        codec.signed("e", 16),
    ],
)


def _declared() -> tuple[Callable[[bytes], object], Callable[[bytes], object]]:
    generated = _DECLARED.frame.functions[0]
    cls = _DECLARED.message_class
    build = slot_builder(cls)
    assert build is not None
    # Little-endian fields from bit 0 up: on the reversed bytes, the last field comes first.
    compiled = bitstruct_c.compile("s16u6s10u12u4")

    def with_bitstruct(data: bytes) -> object:
        e, d, c, b, a = compiled.unpack(data[:0:-1])
        o = build()
        o.a, o.b, o.c, o.d, o.e = a, b, c, d, e
        o.__class__ = cls
        return o

    return lambda data: generated(data, False), with_bitstruct


def _status() -> tuple[Callable[[bytes], object], Callable[[bytes], object]]:
    generated = layouts.STATUS_4X.functions[0]
    build = slot_builder(codec.Status)
    assert build is not None
    names = [name for name, _ in layouts.STATUS_FLAGS]
    # Per byte, MSB first: byte 2 is arbitrating then selected; bytes 3-5 are flags 7..0.
    compiled = bitstruct_c.compile("u8u8b1u7" + "b1" * 24)

    def with_bitstruct(data: bytes) -> object:
        _, _, arbitrating, selected, *bits = compiled.unpack(data)
        o = build()
        o.selected = selected
        o.arbitrating = arbitrating
        o.alive = (bits[7], bits[6], bits[5], bits[4])
        o.ready = (bits[3], bits[2], bits[1], bits[0])
        flags = bits[15:7:-1] + bits[23:15:-1]
        for name, value in zip(names, flags, strict=True):
            setattr(o, name, value)
        o.__class__ = codec.Status
        return o

    return lambda data: generated(data, False), with_bitstruct


CASES: list[tuple[str, bytes, tuple[Callable[[bytes], object], Callable[[bytes], object]]]] = [
    ("PwmSet lsb_first", bytes.fromhex("0223614589c7ab"), _pwm(codec.PwmPacking.LSB_FIRST)),
    ("PwmSet msb_first", bytes.fromhex("0223614589c7ab"), _pwm(codec.PwmPacking.MSB_FIRST)),
    ("declared, sub-byte fields", bytes.fromhex("05a1b2c3d4e5f6"), _declared()),
    ("Status (6 B)", bytes.fromhex("00ff8177a5c3"), _status()),
]


def _rate(function: Callable[[], object], seconds: float) -> float:
    timer = timeit.Timer(function)
    number, _ = timer.autorange()
    number = max(1, int(number * seconds / 0.2))
    return number / min(timer.repeat(repeat=5, number=number))


def main() -> None:
    """Measure every case and print rates and the ratio generated / bitstruct."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=0.2, help="time per measurement")
    seconds = parser.parse_args().seconds
    print(f"Python {platform.python_version()} on {platform.machine()}")
    print(f"{'layout':28} {'generated/s':>12} {'bitstruct.c/s':>14} {'generated/bitstruct':>20}")
    for name, data, (generated, with_bitstruct) in CASES:
        assert generated(data) == with_bitstruct(data), name
        ours = _rate(lambda: generated(data), seconds)  # noqa: B023
        theirs = _rate(lambda: with_bitstruct(data), seconds)  # noqa: B023
        print(f"{name:28} {ours:12.0f} {theirs:14.0f} {ours / theirs:20.2f}")


if __name__ == "__main__":
    main()
