"""A cancellation of an `AsyncBusClient` operation is never lost, also when it comes just as a
frame does: ``asyncio.wait_for`` dropped such a cancellation before Python 3.12 (CPython
gh-86296), and the operation went on (an endless one, ``serve_allocations``, never ended).
On a bus busy with telemetry, each of many cancellations at varied moments ends its task."""

from __future__ import annotations

import asyncio
import random
import sys
import threading

import can
import pytest

from veronte4x.client.aio import AsyncBusClient
from veronte4x.simulator import SimulatedEsc
from veronte4x.simulator.can_node import EscBus

BOUND = 10.0
"""Seconds a cancelled task has to end: a guard, not a timing (it ends at its next await)."""


@pytest.mark.skipif(sys.version_info < (3, 11), reason="Python 3.10 has no asyncio.timeout")
def test_every_cancellation_ends_the_operation_on_a_busy_bus() -> None:
    delays = random.Random(0)

    async def cancel_once(bus: can.BusABC) -> bool:
        async with AsyncBusClient(bus) as client:
            task = asyncio.ensure_future(client.discover(3600.0))
            await asyncio.sleep(delays.uniform(0.0, 0.1))
            task.cancel()
            done, _ = await asyncio.wait([task], timeout=BOUND)
            return bool(done) and task.cancelled()

    with (
        can.Bus(interface="virtual", channel="test-aio-cancel-race") as esc_bus,
        can.Bus(interface="virtual", channel="test-aio-cancel-race") as client_bus,
    ):
        escs = EscBus(esc_bus, [SimulatedEsc(n, telem_frequency=500) for n in range(21, 25)])
        stop = threading.Event()
        thread = threading.Thread(target=escs.run, args=(stop,))
        thread.start()
        try:
            ended = [asyncio.run(cancel_once(client_bus)) for _ in range(20)]
        finally:
            stop.set()
            thread.join()
    assert ended == [True] * 20
