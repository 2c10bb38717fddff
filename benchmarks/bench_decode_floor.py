"""What a Veronte decode costs at least: the call and building the message, against cantools.

Run: python benchmarks/bench_decode_floor.py [--seconds 0.3]

For each frame of `bench_codec.py`, four calls timed in turns (best of five turns each), in
nanoseconds per frame: cantools' `decode_message`, `codec.decode`, a function of the same
signature that returns a ready message (the call alone), and one that builds the message as
the generated decoder does (a class with the same slots, one store per field, ``__class__``
assignment) from values it already holds (the call and the build). The last column is the
ratio to cantools that a decoder with nothing else to do (no dispatch, no unpack, no check)
would reach.
"""

from __future__ import annotations

import argparse
import dataclasses
from collections.abc import Callable
from typing import Any

from bench_codec import CASES, _database, _rates

from veronte4x import codec
from veronte4x.codec.messages import Message
from veronte4x.codegen import slot_builder


def _returning(message: Message) -> Callable[..., Message]:
    def decode(data: bytes, *, sender: codec.Sender, allow_excess: bool = False) -> Message:
        return message

    return decode


def _building(message: Message) -> Callable[..., Message]:
    """A function that builds a message equal to ``message`` the way the generated one does."""
    cls = type(message)
    names = [field.name for field in dataclasses.fields(cls)]
    lines = ["def decode(data, *, sender, allow_excess=False):", "    o = _builder()"]
    lines += [f"    o.{name} = _{name}" for name in names]
    lines += ["    o.__class__ = _cls", "    return o"]
    namespace: dict[str, Any] = {"_builder": slot_builder(cls), "_cls": cls}
    namespace.update({f"_{name}": getattr(message, name) for name in names})
    exec("\n".join(lines) + "\n", namespace)
    decode: Callable[..., Message] = namespace["decode"]
    return decode


def main() -> None:
    """Measure every case and print nanoseconds per frame and the ratios."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=0.3, help="time per measurement")
    seconds = parser.parse_args().seconds
    db = _database()
    print(
        f"{'message':38} {'cantools':>9} {'decode':>7} {'call':>5} {'call+build':>10}"
        f" {'x cantools':>10} {'ceiling':>7}"
    )
    for frame_id, case in enumerate(CASES):
        data, sender = case.data, case.sender
        message = codec.decode(data, sender=sender)
        returning, building = _returning(message), _building(message)
        assert building(data, sender=sender) == message
        rates = _rates(
            [
                lambda: db.decode_message(frame_id, data),  # noqa: B023
                lambda: codec.decode(data, sender=sender),  # noqa: B023
                lambda: returning(data, sender=sender),  # noqa: B023
                lambda: building(data, sender=sender),  # noqa: B023
            ],
            seconds,
        )
        theirs, ours, call, build = (1e9 / rate for rate in rates)
        print(
            f"{case.name:38} {theirs:9.0f} {ours:7.0f} {call:5.0f} {build:10.0f}"
            f" {theirs / ours:10.1f} {theirs / build:7.1f}"
        )


if __name__ == "__main__":
    main()
