"""python-can in and out, through python-can's virtual bus."""

import can
import pytest

from veronte4x import codec
from veronte4x.canbus import to_can_messages
from veronte4x.capture.busmap import BusMap
from veronte4x.capture.can_messages import DecodingListener, decode_can_message, to_can_message
from veronte4x.capture.decoder import CaptureDecoder
from veronte4x.capture.records import Record


def test_to_can_message_picks_the_ids_of_the_bus_map() -> None:
    status = codec.Status(0, True, (True,) * 4, (True,) * 4)
    msg = to_can_message(status)
    assert (msg.arbitration_id, bytes(msg.data), msg.is_extended_id) == (
        255,
        bytes.fromhex("00ff80ff"),
        False,
    )
    ready = to_can_message(codec.Ready(ready=True), autopilot=2)
    assert ready.arbitration_id == 10
    custom = BusMap(arbiter_id=0x100, autopilot_ids=(1, 2, 3, 4), extended=True)
    assert to_can_message(codec.Score(1, 0.5), bus_map=custom).is_extended_id
    with pytest.raises(ValueError, match=r"Ready needs autopilot=0\.\.3 or can_id"):
        to_can_message(codec.Ready(ready=True))
    with pytest.raises(ValueError, match="PwmSet needs a can_id"):
        to_can_message(codec.PwmSet(0, (0, 0, 0, 0)))
    with pytest.raises(codec.EncodeError):
        to_can_message(codec.Score(9, 0.5))


def test_decode_can_message() -> None:
    msg = can.Message(timestamp=2.5, arbitration_id=9, is_extended_id=False, data=b"\x00\xff\x01")
    [record] = decode_can_message(msg)
    assert record.message == codec.Ready(ready=True)
    assert record.sender == "AP2"
    assert record.timestamp == 2.5


def test_listener_decodes_live_traffic_on_the_virtual_bus() -> None:
    records: list[Record] = []
    with (
        can.Bus(interface="virtual", channel="veronte4x-test") as sender,
        can.Bus(interface="virtual", channel="veronte4x-test") as receiver,
    ):
        listener = DecodingListener(records.append)
        sender.send(to_can_message(codec.ArbitrationVariable(3, 1.5), autopilot=0))
        sender.send(to_can_message(codec.Score(2, 0.25)))
        for _ in range(2):
            received = receiver.recv(timeout=1.0)
            assert received is not None
            listener.on_message_received(received)
    assert [r.message for r in records] == [
        codec.ArbitrationVariable(3, 1.5),
        codec.Score(2, 0.25),
    ]
    assert [r.sender for r in records] == ["AP1", "arbiter"]


def test_dronecan_messages_go_out_as_their_transfer_frames() -> None:
    from veronte4x import dronecan

    status = dronecan.EscStatus(
        error_count=0, voltage=24.0, current=1.5, temperature=300.0, rpm=900,
        power_rating_pct=10, esc_index=1,
    )  # fmt: skip
    messages = to_can_messages(status, source_node_id=21, transfer_id=4, channel="can0")
    frames = dronecan.encode(status, source_node_id=21, transfer_id=4)
    assert [(m.arbitration_id, bytes(m.data), m.is_extended_id) for m in messages] == [
        (f.can_id, f.data, True) for f in frames
    ]
    assert len(messages) == 3
    decoder = CaptureDecoder()
    records = [r for m in messages for r in decode_can_message(m, decoder)]
    assert [r.message for r in records] == [status]
    assert records[0].sender == "node 21"
