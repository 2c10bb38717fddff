"""``async for record in capture.stream(bus)``: live decoding on python-can's virtual bus.

The frames are a real capture's (examples/capture.log: the arbiter and the autopilots), the
traffic of two simulated ESCs (multi-frame esc.Status), and frames no decoder knows or that
are damaged; a third bus node records what was sent, to compare the stream's records with
`capture.read` of a log of the same messages.
"""

from __future__ import annotations

import asyncio
import itertools
import math
import threading
from pathlib import Path

import can
import pytest

from veronte4x import capture
from veronte4x.capture import CaptureDecoder, Record
from veronte4x.capture.frames import Frame
from veronte4x.capture.readers.candump import parse_candump
from veronte4x.capture.readers.live import BusFailedError
from veronte4x.capture.readers.pythoncan import frame_from_message
from veronte4x.simulator import SimulatedEsc

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "capture.log"
END = can.Message(arbitration_id=0x7FE, data=b"end", is_extended_id=False)
"""The last message sent: the test's consumer stops at it."""

_CHANNELS = itertools.count()


def _messages() -> list[can.Message]:
    """Every shape of frame: Veronte, DroneCAN single and multi-frame, foreign, damaged."""
    lines = EXAMPLE.read_text().splitlines()
    veronte = [f for f in parse_candump(lines) if isinstance(f, Frame)]
    messages = [
        can.Message(arbitration_id=f.can_id, data=f.data, is_extended_id=f.extended)
        for f in veronte
    ]
    escs = [SimulatedEsc(21, 0, telem_frequency=50), SimulatedEsc(22, 1, telem_frequency=50)]
    for step in range(5):
        for esc in escs:
            messages += [
                can.Message(arbitration_id=f.can_id, data=f.data, is_extended_id=True)
                for f in esc.poll(step * 0.02)
            ]
    multi = next(m for m in messages if m.is_extended_id and len(m.data) == 8)
    messages += [
        can.Message(arbitration_id=multi.arbitration_id, data=multi.data, is_extended_id=True),
        can.Message(arbitration_id=0x123, data=b"\x01\x02", is_extended_id=False),  # foreign
        can.Message(arbitration_id=0x10015515, data=b"", is_extended_id=True),  # no tail byte
        can.Message(arbitration_id=0x008, is_remote_frame=True, is_extended_id=False),
    ]
    return messages


async def _collect(bus: can.BusABC, **options: object) -> list[Record]:
    records = []
    async for record in capture.stream(bus, **options):  # type: ignore[arg-type]
        if record.can_id == END.arbitration_id:
            break
        records.append(record)
    return records


def _notifier_threads() -> list[threading.Thread]:
    return [t for t in threading.enumerate() if "notifier" in t.name.lower()]


def test_the_records_are_those_read_gives_for_the_same_frames(tmp_path: Path) -> None:
    channel = f"test-live-stream-{next(_CHANNELS)}"
    sent = _messages()
    before = len(_notifier_threads())
    with (
        can.Bus(interface="virtual", channel=channel) as live,
        can.Bus(interface="virtual", channel=channel) as sender,
        can.Bus(interface="virtual", channel=channel) as spy,
    ):

        async def main() -> list[Record]:
            consumer = asyncio.create_task(_collect(live))
            for index, message in enumerate(sent):
                sender.send(message)
                if index % 7 == 0:  # some frames come one by one, others in bursts
                    await asyncio.sleep(0.001)
            sender.send(END)
            return await consumer

        records = asyncio.run(main())
        heard = []
        message = spy.recv(0.0)
        while message is not None:
            heard.append(message)
            message = spy.recv(0.0)
        assert live.recv(0.0) is None  # the stream's notifier read everything...
        sender.send(END)
        assert live.recv(1.0) is not None  # ...and let go of the bus when the loop broke
    assert len(_notifier_threads()) == before
    heard = heard[:-1]  # END
    assert len(heard) == len(sent)
    expected = list(CaptureDecoder().decode(frame_from_message(m) for m in heard))
    assert records == expected  # read's path for a python-can log, exactly
    kinds = {type(r.message).__name__ for r in records}
    assert {"Ready", "Score", "NodeStatus", "Status", "Temperature"} <= kinds
    assert any(r.error for r in records)  # the damaged and foreign frames are counted
    # And capture.read of a log of the same messages (candump keeps microseconds).
    log = tmp_path / "live.log"
    with can.Logger(str(log)) as logger:
        for message in heard:
            logger(message)
    from_file = list(capture.read(log))
    assert [r._replace(timestamp=None) for r in from_file] == [
        r._replace(timestamp=None) for r in records
    ]
    assert all(
        math.isclose(a.timestamp or 0, b.timestamp or 0, abs_tol=1e-6)
        for a, b in zip(from_file, records, strict=True)
    )


def test_a_duration_ends_it_and_a_channel_filters_it() -> None:
    channel = f"test-live-stream-{next(_CHANNELS)}"
    with (
        can.Bus(interface="virtual", channel=channel) as live,
        can.Bus(interface="virtual", channel=channel) as sender,
    ):
        sender.send(can.Message(arbitration_id=0x0FF, data=b"\x01", is_extended_id=False))

        async def main(keep: str) -> list[Record]:
            return [r async for r in capture.stream(live, channel=keep, duration=0.3)]

        assert [r.channel for r in asyncio.run(main(channel))] == [channel]
        sender.send(can.Message(arbitration_id=0x0FF, data=b"\x01", is_extended_id=False))
        assert asyncio.run(main("can9")) == []


def test_a_cancelled_consumer_closes_the_stream() -> None:
    channel = f"test-live-stream-{next(_CHANNELS)}"
    before = len(_notifier_threads())
    with (
        can.Bus(interface="virtual", channel=channel) as live,
        can.Bus(interface="virtual", channel=channel) as sender,
    ):
        got: list[Record] = []

        async def consume() -> None:
            async for record in capture.stream(live):
                got.append(record)

        async def main() -> None:
            task = asyncio.create_task(consume())
            sender.send(can.Message(arbitration_id=0x0FF, data=b"\x01", is_extended_id=False))
            while not got:
                await asyncio.sleep(0.01)
            task.cancel()
            with pytest.raises(asyncio.CancelledError):
                await task

        asyncio.run(main())
        sender.send(END)
        assert live.recv(1.0) is not None  # nothing reads the bus any more
    assert len(got) == 1
    assert len(_notifier_threads()) == before


# python-can's notifier, bound to a loop, hands the error to the loop and raises it in its
# own thread too: the thread's traceback is python-can's, the stream's error is ours.
@pytest.mark.filterwarnings("ignore::pytest.PytestUnhandledThreadExceptionWarning")
def test_a_failing_bus_ends_it_with_the_library_error_after_what_came_before() -> None:
    channel = f"test-live-stream-{next(_CHANNELS)}"
    with can.Bus(interface="virtual", channel=channel) as sender:
        live = can.Bus(interface="virtual", channel=channel)
        got: list[Record] = []

        async def main() -> None:
            sender.send(can.Message(arbitration_id=0x0FF, data=b"\x01", is_extended_id=False))
            with pytest.raises(BusFailedError, match=r"^the CAN bus failed: "):
                async for record in capture.stream(live):
                    got.append(record)
                    live.shutdown()  # the next receive fails

        asyncio.run(main())
    assert len(got) == 1
