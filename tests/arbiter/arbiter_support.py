"""Helpers for the arbiter tests: frame bytes built by hand and a rig of autopilots."""

from __future__ import annotations

import struct

from veronte4x.arbiter import Arbiter, ArbiterConfig, SystemChecks, VariableConfig

# Golden frames (seed 000 sections 3.1.3 and 3.1.4; notes/veronte-protocol.md).
READY = bytes.fromhex("00ff01")
NOT_READY = bytes.fromhex("00ff00")

SEED_VARIABLES = (
    VariableConfig(weight=1.0, absolute=False),
    VariableConfig(weight=1.0, absolute=False),
    VariableConfig(weight=0.01, absolute=True),
)
SEED_VALUES = {0: [0.12, 0.30, 1.7], 1: [0.10, 0.28, 1.9], 2: [0.07, 0.27, 1.5]}


def variable(number: int, value: float) -> bytes:
    """An arbitration variable frame: 00, number, float32 little-endian."""
    return bytes([0, number]) + struct.pack("<f", value)


def f32(value: float) -> float:
    """``value`` rounded to float32, as it travels on the wire."""
    result: float = struct.unpack("<f", struct.pack("<f", value))[0]
    return result


class Rig:
    """Autopilots that send Ready and every variable each ``period`` s, and an arbiter.

    Attributes:
        arb: The model under test.
        values: Each autopilot's current variable values (change them between steps).
        silent: Per autopilot, the messages it no longer sends: "ready" or a number.
        capture: Every frame of the bus: (time, CAN ID, data), the arbiter's included.
    """

    def __init__(
        self,
        config: ArbiterConfig,
        values: dict[int, list[float]] | None = None,
        *,
        period: float = 0.05,
        checks: SystemChecks | None = None,
    ) -> None:
        self.config = config
        self.arb = Arbiter(config, checks=checks)
        base = values if values is not None else SEED_VALUES
        self.values = {ap: list(base.get(ap, base[0])) for ap in range(4)}
        self.period = period
        self.silent: dict[int, set[int | str]] = {ap: set() for ap in range(4)}
        self.not_ready: set[int] = set()
        self.capture: list[tuple[float, int, bytes]] = []
        self.tick = 0

    @property
    def time(self) -> float:
        """The time of the next step."""
        return round(self.tick * self.period, 9)

    def mute(self, autopilot: int, *messages: int | str) -> None:
        """Stop ``autopilot`` sending ``messages`` ("ready" or numbers); none means all."""
        chosen = messages or ("ready", *range(len(self.config.variables)))
        self.silent[autopilot].update(chosen)

    def send(self, autopilot: int, data: bytes, time: float) -> None:
        """One frame from ``autopilot`` to the arbiter, captured."""
        can_id = self.config.autopilot_ids[autopilot]
        self.capture.append((time, can_id, data))
        self.arb.receive(can_id, data, time)

    def step(self) -> list[tuple[int, bytes]]:
        """Every autopilot sends its messages, then the arbiter is polled."""
        time = self.time
        for autopilot in range(4):
            silent = self.silent[autopilot]
            if "ready" not in silent:
                ready = NOT_READY if autopilot in self.not_ready else READY
                self.send(autopilot, ready, time)
            for number, value in enumerate(self.values[autopilot][: len(self.config.variables)]):
                if number not in silent:
                    self.send(autopilot, variable(number, value), time)
        frames = self.arb.poll(time)
        self.capture += [(time, can_id, data) for can_id, data in frames]
        self.tick += 1
        return frames

    def run_until(self, end: float) -> list[tuple[float, int, bytes]]:
        """Step up to and including ``end``; the arbiter's frames with their times."""
        sent = []
        while self.time <= end + 1e-9:
            time = self.time
            sent += [(time, can_id, data) for can_id, data in self.step()]
        return sent


# What the real arbiter sent in `failure_capture`, written by hand from seed 000 section
# 3.1.1: byte 2 = selected | arbitrating << 7, byte 3 = alive bits 0-3 | ready bits 4-7.
STATUS_AP2_ALL_ALIVE = bytes.fromhex("00ff8177ffff")
STATUS_AP3_AP2_DEAD = bytes.fromhex("00ff8275ffff")


def failure_capture(
    fail_at: float = 1.55, end: float = 3.0, status_after: bytes = STATUS_AP3_AP2_DEAD
) -> list[tuple[float, int, bytes]]:
    """Three autopilots sending the seed example every 0.05 s on IDs 8, 9, 10; AP2 falls
    silent from ``fail_at``; the arbiter's Status every 0.25 s on ID 255."""
    capture = []
    for tick in range(round(end / 0.05) + 1):
        time = round(tick * 0.05, 9)
        for autopilot, can_id in enumerate((8, 9, 10)):
            if autopilot == 1 and time >= fail_at:
                continue
            capture.append((time, can_id, READY))
            for number, value in enumerate(SEED_VALUES[autopilot]):
                capture.append((time, can_id, variable(number, value)))
        if tick % 5 == 0:
            status = STATUS_AP2_ALL_ALIVE if time < fail_at + 0.1 else status_after
            capture.append((time, 255, status))
    return capture
