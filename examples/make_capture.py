"""Write a realistic candump log of one Veronte 4x vehicle with four Vertiq ESCs.

Usage: python examples/make_capture.py [OUTPUT] [--minutes 2] [--fail-at 60] [--seed 4]

What is on the bus (one CAN bus, ``can0``), at the rates of Embention's templates:
- AP1, AP2, AP3 (IDs 8, 9, 10) send their Ready and three arbitration variables (roll and
  pitch, relative; GNSS accuracy, absolute) every 20 ms, and a PWM set (channels 0-3) every
  20 ms.
- The arbiter (ID 255) is `veronte4x.arbiter.Arbiter` configured by ``arbiter.toml``, fed
  with those frames: its Status every 0.25 s and Scores every 3 s are what the capture
  records as the arbiter's frames.
- A flight controller (DroneCAN node 10) sends RawCommand for four ESCs every 20 ms, and
  asks each ESC for its node info once at start.
- Four simulated Vertiq ESCs (`veronte4x.simulator.SimulatedEsc`, nodes 20-23, ESC indices
  0-3) publish NodeStatus at 1 Hz and esc.Status and Temperature at 10 Hz, and answer.
  They differ as real ones do (`ESC_MODELS`, and each its own throttle): one draws more
  current, one sits in a warmer place, one warms up through the flight.
- Every frame is stamped when it ends on a 1 Mbit/s bus that carries one frame at a time,
  the lowest CAN ID first (`veronte4x.capture.bus_time`).
- At ``--fail-at`` seconds the autopilot selected then stops sending: the arbiter declares
  it dead after 0.1 s and switches; ``veronte4x replay`` explains it.

The sensor values are random but seeded, so the same arguments give the same file.
"""

from __future__ import annotations

import argparse
import math
import random
from collections.abc import Hashable, Iterator
from dataclasses import replace
from pathlib import Path

from veronte4x import arbiter, codec, dronecan
from veronte4x.arbiter.config_file import load_config
from veronte4x.capture.bus_time import PendingFrame, transmit
from veronte4x.dronecan.vertiq import raw_command
from veronte4x.simulator import DEFAULT_MODEL, SimulatedEsc

START = 1_763_737_200.0  # capture clock at t = 0 (2025-11-21 15:00 UTC)
TICK = 0.020  # the autopilots' arbitration period
BITRATE = 1_000_000  # bit/s
AUTOPILOT_IDS = (8, 9, 10)
FC_NODE = 10
ESC_NODES = (20, 21, 22, 23)
ESC_MODELS = (
    DEFAULT_MODEL,
    replace(DEFAULT_MODEL, max_current=33.0),  # a heavier propeller: more current
    replace(DEFAULT_MODEL, ambient_temperature=303.15),  # mounted near the battery
    replace(DEFAULT_MODEL, coil_heating=0.2, mcu_heating=4.0),  # one that warms up
)
"""Each ESC's motor (`veronte4x.simulator.MotorModel`): four that differ as real ones do."""
CONFIG = load_config(str(Path(__file__).with_name("arbiter.toml")))


class Bus:
    """Collects the frames the nodes send and writes them in candump -L form, each stamped
    when it ends on a 1 Mbit/s bus (`veronte4x.capture.bus_time`: one frame at a time, the
    lowest CAN ID first)."""

    def __init__(self) -> None:
        self.frames: list[PendingFrame] = []
        self.texts: list[str] = []

    def send(
        self, time: float, can_id: int, data: bytes, sender: Hashable, extended: bool = False
    ) -> None:
        ident = f"{can_id:08X}" if extended else f"{can_id:03X}"
        self.frames.append(PendingFrame(time, can_id, extended, len(data), sender))
        self.texts.append(f"can0 {ident}#{data.hex().upper()}")

    def lines(self, start: float = START) -> list[str]:
        """The candump -L lines in time order, the capture clock at ``start`` at t = 0."""
        queued = sorted(range(len(self.frames)), key=lambda i: self.frames[i].ready)
        ends = transmit([self.frames[i] for i in queued], BITRATE)
        order = sorted(range(len(ends)), key=ends.__getitem__)
        return [f"({start + ends[i]:.6f}) {self.texts[queued[i]]}" for i in order]

    def write(self, path: Path, start: float = START) -> int:
        """Write the lines (`lines`); return how many."""
        lines = self.lines(start)
        path.write_text("".join(line + "\n" for line in lines))
        return len(lines)


def attitude(time: float) -> tuple[float, float]:
    """The true roll and pitch of a gently manoeuvring aircraft, rad."""
    return 0.15 * math.sin(time / 7.0), 0.05 + 0.04 * math.sin(time / 11.0)


def throttle(time: float) -> float:
    """Collective throttle: spool-up, then cruise with slow variation."""
    return min(1.0, time / 5.0) * (0.55 + 0.1 * math.sin(time / 13.0))


def esc_throttle(time: float, index: int) -> float:
    """One ESC's throttle: the collective plus the attitude controller's corrections (the
    front pair works harder in the climb, each motor has its own small oscillation)."""
    trim = (0.04, 0.03, -0.02, -0.03)[index]
    return min(1.0, throttle(time) * (1.0 + trim + 0.02 * math.sin(0.9 * time + index)))


def generate(minutes: float, fail_at: float, seed: int) -> Bus:
    """Simulate the vehicle and return the bus traffic."""
    rng = random.Random(seed)
    bus = Bus()
    model = arbiter.Arbiter(CONFIG)
    escs = [
        SimulatedEsc(node, index, start_time=0.0, model=model_)
        for index, (node, model_) in enumerate(zip(ESC_NODES, ESC_MODELS, strict=True))
    ]
    bias = (0.012, 0.001, -0.006)  # each autopilot's steady attitude error, rad
    noise = 0.0015  # sensor noise, rad
    gnss = (1.7, 1.9, 1.5)  # each autopilot's GNSS accuracy, m
    failed: int | None = None
    fc_tid = 0
    end = minutes * 60.0
    ticks = int(end / TICK)

    def deliver(
        time: float,
        sender: Hashable,
        frames: Iterator[dronecan.TransferFrame] | list[dronecan.TransferFrame],
    ) -> None:
        for frame in frames:
            bus.send(time, frame.can_id, frame.data, sender, extended=True)
            for esc in escs:
                esc.receive(frame.can_id, frame.data, time)

    for node in ESC_NODES:  # the flight controller asks every ESC who it is
        request = dronecan.GetNodeInfoRequest()
        deliver(
            0.001 * node,
            "flight controller",
            dronecan.encode(
                request, source_node_id=FC_NODE, transfer_id=0, destination_node_id=node
            ),
        )
    for tick in range(ticks):
        now = tick * TICK
        if failed is None and now >= fail_at:
            failed = model.state.selected
        roll, pitch = attitude(now)
        for ap, can_id in enumerate(AUTOPILOT_IDS):
            if ap == failed:
                continue
            at = now + 0.0005 * ap
            values = (
                roll + bias[ap] + rng.gauss(0.0, noise),
                pitch + bias[ap] + rng.gauss(0.0, noise),
                gnss[ap] + rng.uniform(-0.05, 0.05),
            )
            messages: list[codec.Message] = [codec.Ready(ready=True)]
            messages += [codec.ArbitrationVariable(n, v) for n, v in enumerate(values)]
            pwm = tuple(round(2048 + 1500 * math.sin(now / 3 + ch)) for ch in range(4))
            messages.append(codec.PwmSet(0, pwm))  # type: ignore[arg-type]
            for message in messages:
                data = codec.encode(message)
                bus.send(at, can_id, data, f"AP{ap + 1}")
                if not isinstance(message, codec.PwmSet):
                    model.receive(can_id, data, at)
        for can_id, data in model.poll(now + 0.002):
            bus.send(now + 0.002, can_id, data, "arbiter")
        command = raw_command([esc_throttle(now, index) for index in range(len(escs))])
        deliver(
            now + 0.003,
            "flight controller",
            dronecan.encode(command, source_node_id=FC_NODE, transfer_id=fc_tid),
        )
        fc_tid = (fc_tid + 1) % 32
        for index, esc in enumerate(escs):
            at = now + 0.005 + 0.001 * index
            deliver(at, f"ESC {index}", esc.poll(at))
    return bus


def main() -> None:
    """Parse the arguments, simulate, write the file."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("output", nargs="?", default=str(Path(__file__).with_name("flight.log")))
    parser.add_argument("--minutes", type=float, default=2.0, help="length of the flight")
    parser.add_argument("--fail-at", type=float, default=60.0, help="seconds to the failure")
    parser.add_argument("--seed", type=int, default=4, help="random seed of the sensor noise")
    args = parser.parse_args()
    if not Path(args.output).resolve().parent.is_dir():  # before the work, not after it
        parser.error(f"{Path(args.output).parent}: no such directory for the output")
    count = generate(args.minutes, args.fail_at, args.seed).write(Path(args.output))
    print(f"wrote {count} frames to {args.output}")


if __name__ == "__main__":
    main()
