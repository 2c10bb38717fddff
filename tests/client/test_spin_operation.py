"""`spin` as an operation of both clients (issue 37, item 3): the same tests through the
blocking `BusClient.spin` and the asyncio `AsyncBusClient.spin`, against simulated ESCs on
python-can's virtual bus, with a spy on the bus that sees every RawCommand the client sends.
Arguments are refused before anything is sent, a shared index before any command, a limit
or a silent node stops every motor, and an interrupt or a cancellation sends zero throttle
three times and nothing after."""

from __future__ import annotations

import asyncio
import itertools
import re
import subprocess
import sys
import threading
import time
from collections.abc import Iterator
from typing import Any

import can
import pytest

from veronte4x import dronecan
from veronte4x.client import (
    InvalidRequestError,
    Spin,
    SpinArgumentError,
    SpinResult,
    SpinStoppedError,
)
from veronte4x.client.aio import AsyncBusClient
from veronte4x.client.bus import BusClient
from veronte4x.client.commander import STOP_REPEATS
from veronte4x.client.indices import EscIndexError
from veronte4x.client.spin import spin_plan
from veronte4x.dronecan import vertiq
from veronte4x.simulator import SimulatedEsc
from veronte4x.simulator.can_node import EscBus

from ..simulator.support import StepClock

CLIENT = 127
RAW_COMMAND = 1030
GUARD = 60.0
"""Seconds after which a wait for an event counts as a hang (a guard, not a verdict)."""
_CHANNELS = itertools.count()

CLIENTS = ["blocking", "asyncio"]


class Rig:
    """Simulated ESCs served from a thread, a client's bus and a spy's bus, on one channel."""

    def __init__(self, escs: list[SimulatedEsc]) -> None:
        channel = f"test-spin-operation-{next(_CHANNELS)}"
        self.escs = escs
        self.esc_bus = can.Bus(interface="virtual", channel=channel)
        self.bus = can.Bus(interface="virtual", channel=channel)
        self.spy = can.Bus(interface="virtual", channel=channel)
        self.served = EscBus(self.esc_bus, escs)
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self.served.run, args=(self._stop,), daemon=True)
        self._thread.start()
        self.sent: list[can.Message] = []

    def client_frames(self) -> list[can.Message]:
        """Every frame the client has sent so far (read from the spy)."""
        while (message := self.spy.recv(0.0)) is not None:
            if message.arbitration_id & 0x7F == CLIENT:
                self.sent.append(message)
        return self.sent

    def commands(self) -> list[tuple[int, ...]]:
        """The RawCommand the client has sent so far, as their ``cmd``."""
        found = []
        for message in self.client_frames():
            can_id = message.arbitration_id
            if not can_id & 0x80 and (can_id >> 8) & 0xFFFF == RAW_COMMAND:
                transfer = dronecan.decode_frames([(can_id, bytes(message.data))])
                found.append(transfer.message.cmd)
        return found

    def close(self) -> None:
        self._stop.set()
        self._thread.join()
        for bus in (self.esc_bus, self.bus, self.spy):
            bus.shutdown()


@pytest.fixture
def rig(request: pytest.FixtureRequest) -> Iterator[Rig]:
    made = Rig(request.param)
    yield made
    made.close()


def _apart() -> list[SimulatedEsc]:
    return [SimulatedEsc(21, 0), SimulatedEsc(22, 1)]


def _shared() -> list[SimulatedEsc]:
    return [SimulatedEsc(21, 0), SimulatedEsc(22, 0)]


def spin(kind: str, rig: Rig, *args: Any, **options: Any) -> SpinResult:
    """``spin`` through the blocking or the asyncio client on the rig's bus."""
    if kind == "blocking":
        return BusClient(rig.bus, timeout=2.0).spin(*args, **options)

    async def main() -> SpinResult:
        async with AsyncBusClient(rig.bus, timeout=2.0) as client:
            return await client.spin(*args, **options)

    return asyncio.run(main())


def _stopped(rig: Rig, indices: int) -> None:
    """The client's last commands are zero throttle, three times; every motor stops."""
    commands = rig.commands()
    assert commands[-STOP_REPEATS:] == [(0,) * indices] * STOP_REPEATS
    end = time.monotonic() + GUARD
    while any(esc.motor.driven for esc in rig.escs):
        assert time.monotonic() < end, "a motor still turns"
        time.sleep(0.01)


@pytest.mark.parametrize("kind", CLIENTS)
@pytest.mark.parametrize("rig", [_apart()], indirect=True)
@pytest.mark.parametrize(
    ("arguments", "text"),
    [
        ({"throttle": 1.5}, "throttle 1.5 is outside -1..1"),
        ({"throttle": "0.5"}, "throttle '0.5' is not a number"),
        ({"duration": float("inf")}, "duration inf must be a finite number of seconds above 0"),
        ({"duration": 0}, "duration 0 must be a finite number of seconds above 0"),
        ({"silence": 0.0}, "silence 0 must be above 0"),
        ({"rate": float("nan")}, "rate nan must be above 0"),
        ({"watchdog": -1}, "watchdog -1 must be above 0"),
        ({"max_current": float("inf")}, "max_current inf must be finite"),
        ({"max_temperature": True}, "max_temperature True is not a number"),
        ({"nodes": []}, "a spin needs the nodes named: none was given"),
        ({"nodes": [128]}, "128 is no node id (1..127); nothing was sent"),
    ],
)
def test_arguments_are_refused_before_anything_is_sent(
    kind: str, rig: Rig, arguments: dict[str, Any], text: str
) -> None:
    given = {"nodes": [21], "throttle": 0.2, "duration": 1.0, **arguments}
    with pytest.raises(InvalidRequestError) as error:
        spin(kind, rig, given.pop("nodes"), given.pop("throttle"), given.pop("duration"), **given)
    assert str(error.value) == text
    assert isinstance(error.value, SpinArgumentError) == ("nodes" not in arguments)
    assert rig.client_frames() == []


@pytest.mark.parametrize("kind", CLIENTS)
@pytest.mark.parametrize("rig", [_shared()], indirect=True)
def test_a_shared_index_is_refused_before_any_command(kind: str, rig: Rig) -> None:
    starts: list[Spin] = []
    with pytest.raises(EscIndexError) as error:
        spin(kind, rig, [21], 0.3, 5.0, on_start=starts.append)
    assert str(error.value) == (
        "node 22 has esc_index 0 too: RawCommand would turn it with node 21; name it as well "
        "to spin both, or give it an esc_index of its own; nothing was sent"
    )
    assert starts == [] and rig.commands() == []
    assert rig.client_frames()  # the survey read the indices
    assert not any(esc.motor.driven for esc in rig.escs)


@pytest.mark.parametrize("kind", CLIENTS)
@pytest.mark.parametrize("rig", [_apart()], indirect=True)
def test_a_spin_that_runs_its_course(kind: str, rig: Rig) -> None:
    starts: list[Spin] = []
    result = spin(kind, rig, [22, 21, 22], 0.3, 0.5, on_start=starts.append)
    assert [s.setpoint for s in starts] == [{1: 0.3, 0: 0.3}]
    assert (result.throttle, result.duration) == (0.3, 0.5)
    assert [(n.node_id, n.esc_index) for n in result.nodes] == [(22, 1), (21, 0)]
    assert all(n.telemetry > 0 and n.peak_rpm is not None for n in result.nodes)
    assert vertiq.raw_command([0.3, 0.3]).cmd in rig.commands()
    _stopped(rig, 2)


@pytest.mark.parametrize("kind", CLIENTS)
@pytest.mark.parametrize("rig", [_apart()], indirect=True)
def test_over_current_stops_every_motor(kind: str, rig: Rig) -> None:
    # silence=30: a loaded machine may starve the simulators' thread for a while
    with pytest.raises(SpinStoppedError) as error:
        spin(kind, rig, [21, 22], 0.4, 60.0, max_current=1.0, silence=30.0)
    assert error.value.over_limit
    assert re.fullmatch(
        r"node 2[12] reported \d+\.\d A, above the limit of 1 A", error.value.reason
    )
    assert str(error.value) == f"{error.value.reason}; every motor stopped: zero throttle sent"
    assert [n.esc_index for n in error.value.result.nodes] == [0, 1]
    _stopped(rig, 2)


@pytest.mark.parametrize("kind", CLIENTS)
@pytest.mark.parametrize("rig", [_apart()], indirect=True)
def test_a_node_that_falls_silent_stops_every_motor(kind: str, rig: Rig) -> None:
    def silence_22(spin: Spin) -> None:
        rig.served.escs = [esc for esc in rig.served.escs if esc.node_id != 22]

    with pytest.raises(SpinStoppedError) as error:
        spin(kind, rig, [22, 21], 0.3, 60.0, silence=1.0, on_start=silence_22)
    assert not error.value.over_limit
    assert error.value.reason == "node 22 fell silent: no esc.Status or NodeStatus for 1 s"
    commands = rig.commands()
    assert commands[-STOP_REPEATS:] == [(0, 0)] * STOP_REPEATS
    end = time.monotonic() + GUARD
    while rig.escs[0].motor.driven:  # node 21, still served, stops
        assert time.monotonic() < end, "node 21 still turns"
        time.sleep(0.01)


def _turning(rig: Rig) -> bool:
    return any(any(cmd) for cmd in rig.commands())


@pytest.mark.parametrize("rig", [_apart()], indirect=True)
def test_an_interrupted_blocking_spin_sends_zeros_and_nothing_after(rig: Rig) -> None:
    """Ctrl-C in a wait of the spin (the client's ``while_waiting``): zero throttle three
    times, the KeyboardInterrupt goes on, the sending thread is gone."""

    def waiting() -> None:
        if _turning(rig):
            raise KeyboardInterrupt

    client = BusClient(rig.bus, timeout=2.0, while_waiting=waiting)
    with pytest.raises(KeyboardInterrupt):
        client.spin([21, 22], 0.3, 60.0)
    assert not any(t.name == "veronte4x-raw-command" for t in threading.enumerate())
    sent = len(rig.client_frames())
    _stopped(rig, 2)  # the motors stopped meanwhile: the client sent nothing after its zeros
    assert len(rig.client_frames()) == sent


@pytest.mark.parametrize("rig", [_apart()], indirect=True)
def test_a_cancelled_asyncio_spin_sends_zeros_and_nothing_after(rig: Rig) -> None:
    async def main() -> None:
        async with AsyncBusClient(rig.bus, timeout=2.0) as client:
            task = asyncio.create_task(client.spin([21, 22], 0.3, 60.0))
            end = time.monotonic() + GUARD
            while not _turning(rig):
                assert time.monotonic() < end, "the spin never sent a throttle"
                await asyncio.sleep(0.01)
            task.cancel()
            with pytest.raises(asyncio.CancelledError):
                await task
            assert asyncio.all_tasks() == {asyncio.current_task()}  # no stream task left
            _stopped(rig, 2)
            sent = len(rig.client_frames())
            await asyncio.sleep(0.2)  # the loop runs: a stream left behind would send
            assert len(rig.client_frames()) == sent

    asyncio.run(main())


def test_a_blocking_spin_on_a_step_clock() -> None:
    """The simulated ESCs run in the client's waits and both read one step clock: the spin
    lasts its duration of that clock, and the zeros come last."""
    channel = f"test-spin-operation-{next(_CHANNELS)}"
    with (
        can.Bus(interface="virtual", channel=channel) as esc_bus,
        can.Bus(interface="virtual", channel=channel) as bus,
    ):
        clock = StepClock(0.001)
        esc = SimulatedEsc(21, 2)
        escs = EscBus(esc_bus, [esc], clock)
        client = BusClient(bus, clock=clock, timeout=0.5, while_waiting=escs.step)
        ends: list[float] = []
        result = client.spin([21], -0.2, 1.0, on_start=lambda s: ends.append(s.end))
        (node,) = result.nodes
        assert (node.node_id, node.esc_index) == (21, 2)
        assert node.telemetry > 0 and node.peak_rpm is not None and node.peak_rpm < 0
        assert clock.now >= ends[0]  # it ran its duration of the step clock
        for _ in range(50):
            escs.step()  # the ESC takes the zeros still on the bus
        assert not esc.motor.driven


def test_the_plan_keeps_the_first_of_each_node_and_allows_all_unknown() -> None:
    plan = spin_plan([23, 21, 23], 0, 2, rate=50, watchdog=0.5, allow_unknown="all")
    assert (plan.nodes, plan.allow_unknown, plan.throttle) == ((23, 21), "all", 0.0)
    assert spin_plan([21], 1, 2, rate=50, watchdog=0.5, allow_unknown=[30]).allow_unknown == (30,)


@pytest.mark.parametrize(
    ("option", "value", "text"),
    [
        ("--throttle", "2", "--throttle 2 is outside -1..1"),
        ("--duration", "inf", "--duration inf must be a finite number of seconds above 0"),
        ("--rate", "0", "--rate 0 must be above 0"),
        ("--max-current", "inf", "--max-current inf must be finite"),
        ("--max-temperature", "nan", "--max-temperature nan must be finite"),
    ],
)
def test_the_command_line_names_its_option(option: str, value: str, text: str) -> None:
    """The library's refusal, in the command line's words: exit code 2, one line."""
    arguments = {"--throttle": "0.1", "--duration": "1", option: value}
    result = subprocess.run(
        [sys.executable, "-m", "veronte4x", "esc", "spin", "21", "--yes",
         *itertools.chain.from_iterable(arguments.items()),
         "--interface", "virtual", "--channel", f"test-spin-cli-{next(_CHANNELS)}"],
        capture_output=True, text=True, timeout=GUARD, check=False,
    )  # fmt: skip
    assert (result.returncode, result.stdout, result.stderr) == (2, "", f"veronte4x: {text}\n")
