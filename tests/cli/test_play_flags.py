"""``veronte4x play`` keeps every flag: CAN FD with its BRS and ESI, a remote frame's DLC,
error frames and the channel map, checked across processes on a udp_multicast bus (CAN FD
on: python-can's ``fd=True``) by a receiver in the test process."""

from __future__ import annotations

from pathlib import Path

import can

from tests.client.cli_support import GROUP, bus_args, free_port, veronte4x

LINES = [
    "(1.000000) can0 123#11223344",  # classic, 11-bit
    "(1.001000) can0 12345678#AABB",  # classic, 29-bit
    "(1.002000) can0 321#R5",  # remote frame asking for 5 bytes
    "(1.003000) can0 1ABCDEF0#R",  # remote frame, 29-bit, DLC 0
    "(1.004000) can0 124##1" + "11" * 12,  # CAN FD with BRS
    "(1.005000) can0 125##2" + "22" * 8,  # CAN FD with ESI, no BRS
    "(1.006000) can0 12345679##3" + "33" * 64,  # CAN FD, BRS and ESI, 29-bit
    "(1.007000) can0 126##0",  # CAN FD, no data, no flags
    "(1.008000) can0 20000004#0004000000000000",  # error frame (controller problem)
    "(1.009000) can1 127#01",  # another channel
]

Seen = tuple[int, bool, bool, bool, bool, bool, bool, int, bytes, object]
"""What is compared of a message: ID, extended, remote, error, FD, BRS, ESI, DLC, data,
channel."""

EXPECTED: list[Seen] = [
    (0x123, False, False, False, False, False, False, 4, bytes.fromhex("11223344"), None),
    (0x12345678, True, False, False, False, False, False, 2, b"\xaa\xbb", None),
    (0x321, False, True, False, False, False, False, 5, b"", None),
    (0x1ABCDEF0, True, True, False, False, False, False, 0, b"", None),
    (0x124, False, False, False, True, True, False, 12, b"\x11" * 12, None),
    (0x125, False, False, False, True, False, True, 8, b"\x22" * 8, None),
    (0x12345679, True, False, False, True, True, True, 64, b"\x33" * 64, None),
    (0x126, False, False, False, True, False, False, 0, b"", None),
    (0x4, True, False, True, False, False, False, 8, bytes.fromhex("0004000000000000"), None),
    (0x127, False, False, False, False, False, False, 1, b"\x01", None),
]


def seen(message: can.Message) -> Seen:
    return (
        message.arbitration_id,
        message.is_extended_id,
        message.is_remote_frame,
        message.is_error_frame,
        message.is_fd,
        message.bitrate_switch,
        message.error_state_indicator,
        message.dlc,
        bytes(message.data),
        message.channel,
    )


def receive(bus: can.BusABC, count: int) -> list[Seen]:
    """Up to ``count`` messages, each waited for generously (a hang guard, not a verdict)."""
    got: list[Seen] = []
    while len(got) < count and (message := bus.recv(30.0)) is not None:
        got.append(seen(message))
    return got


def test_every_flag_and_dlc_reaches_the_bus(tmp_path: Path) -> None:
    capture = tmp_path / "flags.log"
    capture.write_text("\n".join(LINES) + "\n", encoding="utf-8")
    port = free_port()
    with can.Bus(interface="udp_multicast", channel=GROUP, port=port, fd=True) as listener:
        result = veronte4x("play", str(capture), *bus_args(port))
        assert result.returncode == 0, result.stderr
        assert result.stderr.startswith("veronte4x: sent 10 frames in ")
        assert receive(listener, len(EXPECTED)) == EXPECTED


def test_a_channel_map_renames_the_channel_and_keeps_the_flags(tmp_path: Path) -> None:
    capture = tmp_path / "flags.log"
    capture.write_text("\n".join(LINES) + "\n", encoding="utf-8")
    port = free_port()
    with can.Bus(interface="udp_multicast", channel=GROUP, port=port, fd=True) as listener:
        result = veronte4x(
            "play",
            str(capture),
            "--interface",
            "udp_multicast",
            "--bus-option",
            f"port={port}",
            "--channel-map",
            f"can0={GROUP}",
        )
        assert result.returncode == 0, result.stderr
        assert result.stderr.startswith("veronte4x: sent 9 frames in ")
        # can0's frames, each on the mapped channel; can1 is not mapped, so not sent.
        assert receive(listener, 9) == [(*e[:-1], GROUP) for e in EXPECTED[:-1]]


def test_an_asc_capture_plays_with_its_flags(tmp_path: Path) -> None:
    """The same frames read from an ASC file python-can wrote (python-can numbers its
    channels from 0) reach the bus as python-can's ASCReader reads them."""
    messages = [
        can.Message(arbitration_id=0x321, is_extended_id=False, is_remote_frame=True, dlc=5),
        can.Message(
            arbitration_id=0x12345679,
            data=b"\x33" * 64,
            is_fd=True,
            bitrate_switch=True,
            error_state_indicator=True,
        ),
        can.Message(is_error_frame=True, channel=1),
    ]
    path = tmp_path / "flags.asc"
    with can.ASCWriter(str(path)) as writer:
        for stamp, message in enumerate(messages):
            message.timestamp = 1.0 + stamp / 1000
            writer.on_message_received(message)
    with can.ASCReader(str(path)) as reader:
        expected = [(*seen(m)[:-1], None) for m in reader]
    port = free_port()
    with can.Bus(interface="udp_multicast", channel=GROUP, port=port, fd=True) as listener:
        result = veronte4x("play", str(path), *bus_args(port))
        assert result.returncode == 0, result.stderr
        assert receive(listener, len(expected)) == expected
    assert [e[2:8] for e in expected] == [
        (True, False, False, False, False, 5),
        (False, False, True, True, True, 64),
        (False, True, False, False, False, 0),
    ]
