"""The same scenarios through the blocking `BusClient` and the asyncio `AsyncBusClient`,
against simulated ESCs served from a thread on python-can's virtual bus (real clock)."""

from __future__ import annotations

import asyncio
import inspect
import itertools
import threading
from collections.abc import Callable, Iterator
from typing import Any

import can
import pytest

from veronte4x import dronecan
from veronte4x.client import (
    FirmwareUpdateFailedError,
    InvalidRequestError,
    NoResponseError,
    ParameterError,
    Phase,
    UpdateProgress,
)
from veronte4x.client import operations as ops
from veronte4x.client.aio import AsyncBusClient
from veronte4x.client.bus import BusClient
from veronte4x.client.firmware import FirmwareOptions
from veronte4x.dronecan.image_crc import crc64we
from veronte4x.simulator import SimulatedEsc
from veronte4x.simulator.can_node import EscBus

_CHANNELS = itertools.count()
NODES = (21, 22, 23, 24)


class Blocking:
    """Calls a client's methods and returns their results, whether they block or are awaited."""

    def __init__(self, client: Any, loop: asyncio.AbstractEventLoop | None) -> None:
        self.client = client
        self.loop = loop

    def __getattr__(self, name: str) -> Callable[..., Any]:
        method = getattr(self.client, name)
        if self.loop is None or not inspect.iscoroutinefunction(method):
            return method  # type: ignore[no-any-return]
        loop = self.loop
        return lambda *args, **kwargs: loop.run_until_complete(method(*args, **kwargs))


def _escs(*escs: SimulatedEsc) -> list[SimulatedEsc]:
    return list(escs) or [SimulatedEsc(n, i) for i, n in enumerate(NODES)]


@pytest.fixture(params=["blocking", "asyncio"])
def kind(request: pytest.FixtureRequest) -> str:
    return str(request.param)


@pytest.fixture
def bench(kind: str) -> Iterator[Callable[..., Blocking]]:
    """``bench(*escs)``: the ESCs served in a thread, and a client of ``kind`` for them."""
    channel = f"test-scenarios-{next(_CHANNELS)}"
    stops: list[Callable[[], None]] = []

    def make(*escs: SimulatedEsc, timeout: float = 0.3) -> Blocking:
        esc_bus = can.Bus(interface="virtual", channel=channel)
        client_bus = can.Bus(interface="virtual", channel=channel)
        stop = threading.Event()
        thread = threading.Thread(target=EscBus(esc_bus, _escs(*escs)).run, args=(stop,))
        thread.start()
        if kind == "blocking":
            client = Blocking(BusClient(client_bus, timeout=timeout, retries=1), None)
        else:
            loop = asyncio.new_event_loop()
            aio = AsyncBusClient(client_bus, timeout=timeout, retries=1)

            async def start() -> None:
                aio.start()

            loop.run_until_complete(start())
            client = Blocking(aio, loop)

            def close() -> None:
                aio.stop()
                loop.close()

            stops.append(close)

        def stop_all() -> None:
            stop.set()
            thread.join()
            esc_bus.shutdown()
            client_bus.shutdown()

        stops.append(stop_all)
        return client

    yield make
    for stop in stops:
        stop()


def test_discovery_and_node_info(bench: Callable[..., Blocking]) -> None:
    client = bench()
    assert [e.node_id for e in client.discover(1.1)] == list(NODES)
    assert client.node_info(22).hardware_version.unique_id == b"veronte4x.sim\x00\x00\x16"


def test_parameters_set_saved_and_refused(bench: Callable[..., Blocking]) -> None:
    client = bench()
    assert [p.name for p in client.list_params(21)] == [
        "uavcan_node_id",
        "bit_rate",
        "esc_index",
        "zero_behavior",
        "telem_frequency",
    ]
    assert client.set_param(21, "zero_behavior", "1").value == dronecan.IntegerValue(1)
    client.save_params(21)
    assert client.get_param(21, "zero_behavior").value == dronecan.IntegerValue(1)
    with pytest.raises(InvalidRequestError, match=r"^an empty parameter name is refused"):
        client.set_param(21, "", 5)
    with pytest.raises(ParameterError, match=r"^node 21: 20 is out of range for esc_index"):
        client.set_param(21, "esc_index", 20)
    with pytest.raises(ParameterError, match=r"^node 21 has no parameter 'esc_idx'$"):
        client.get_param(21, "esc_idx")
    with pytest.raises(NoResponseError, match=r"^node 99 did not answer"):
        client.node_info(99)


def test_every_node_read_at_once(bench: Callable[..., Blocking]) -> None:
    client = bench()
    tasks = client.run_all([ops.list_params(n) for n in (*NODES, 99)])
    assert [[p.value for p in t.result()][2] for t in tasks[:4]] == [
        dronecan.IntegerValue(i) for i in range(4)
    ]
    assert isinstance(tasks[4].error, NoResponseError)


def test_firmware_update(bench: Callable[..., Blocking]) -> None:
    client = bench()
    image = bytes((i * 7) & 0xFF for i in range(3000))
    seen: list[UpdateProgress] = []
    info = client.update_firmware(22, image, "esc.bin", progress=seen.append)
    assert info.software_version.image_crc == crc64we(image)
    assert seen[-1].phase is Phase.DONE


def test_firmware_update_of_a_node_that_hangs(bench: Callable[..., Blocking]) -> None:
    client = bench(SimulatedEsc(21, update_stall_offset=1024))
    with pytest.raises(FirmwareUpdateFailedError) as error:
        client.update_firmware(21, bytes(4096), read_timeout=0.5)
    assert str(error.value) == (
        "node 21 stopped reading the image at byte 1024 of 4096 (nothing for 0.5 s)"
    )


def test_firmware_update_progress_bar_when_interactive(
    bench: Callable[..., Blocking],
    capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    pytest.importorskip("tqdm")
    client = bench()
    image = bytes((i * 7) & 0xFF for i in range(3000))
    client.update_firmware(21, image, progress=True)
    assert "node 21 firmware" in capsys.readouterr().err
    client.update_firmware(22, image, progress=False)
    client.update_firmware(23, image)  # standard error is no terminal here, and no notebook
    assert capsys.readouterr().err == ""
    monkeypatch.setattr("veronte4x.progress._interactive", lambda: True)
    info = client.update_firmware(24, image)  # as in a terminal or a notebook
    assert "node 24 firmware" in capsys.readouterr().err
    assert info.software_version.image_crc == crc64we(image)


def test_one_node_that_stops_mid_update_leaves_the_others_updated(
    bench: Callable[..., Blocking],
) -> None:
    client = bench(
        SimulatedEsc(21, 0, update_stall_offset=2048),
        SimulatedEsc(22, 1),
        SimulatedEsc(23, 2),
    )
    image = bytes((i * 11) & 0xFF for i in range(6000))
    tasks = client.run_all(
        [
            ops.update_firmware(
                client.client.protocol, n, image, options=FirmwareOptions(read_timeout=0.5)
            )
            for n in (21, 22, 23)
        ]
    )
    assert isinstance(tasks[0].error, FirmwareUpdateFailedError)
    assert str(tasks[0].error) == (
        "node 21 stopped reading the image at byte 2048 of 6000 (nothing for 0.5 s)"
    )
    assert [t.result().software_version.image_crc for t in tasks[1:]] == [crc64we(image)] * 2
