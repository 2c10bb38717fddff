"""Veronte 4x and DroneCAN records from live python-can traffic, and Veronte messages as
``can.Message``.

Needs the ``can`` extra (``pip install "veronte4x[can]"``). Opening a bus and DroneCAN frames
as ``can.Message`` are `veronte4x.canbus`; decoding itself stays sans-IO in
`veronte4x.capture.decoder`.
"""

from __future__ import annotations

from collections.abc import Callable

from veronte4x.errors import MissingExtraError

try:
    import can
except ModuleNotFoundError as missing:  # pragma: no cover - the can extra is installed in CI
    if missing.name != "can":
        raise
    raise MissingExtraError("can", "can", "veronte4x.capture.can_messages") from None

from veronte4x import codec
from veronte4x.capture.busmap import BusMap
from veronte4x.capture.decoder import CaptureDecoder
from veronte4x.capture.readers.pythoncan import frame_from_message
from veronte4x.capture.records import Record

__all__ = ["DecodingListener", "decode_can_message", "to_can_message"]


def decode_can_message(message: can.Message, decoder: CaptureDecoder | None = None) -> list[Record]:
    """Decode one ``can.Message`` into its records (none while a DroneCAN transfer is open).

    Pass the same `CaptureDecoder` for every message of a bus: it keeps the DroneCAN
    reassembly state between frames.
    """
    return list((decoder or CaptureDecoder()).decode((frame_from_message(message),)))


def to_can_message(
    message: codec.Message,
    can_id: int | None = None,
    *,
    autopilot: int | None = None,
    bus_map: BusMap | None = None,
    timestamp: float = 0.0,
    channel: str | None = None,
) -> can.Message:
    """Encode a Veronte message into a ``can.Message``.

    Args:
        message: The message.
        can_id: The CAN ID. By default Status and Score go on the bus map's arbiter ID and
            Ready and ArbitrationVariable on the ID of `autopilot`; other messages need it.
        autopilot: 0 = AP1 .. 3 = external, for Ready and ArbitrationVariable.
        bus_map: IDs and codec choices; Embention's template defaults if None.
        timestamp: The message's timestamp.
        channel: The message's channel.

    Raises:
        EncodeError: A field is out of range.
        ValueError: No CAN ID given and none follows from the message.
    """
    bus_map = bus_map or BusMap()
    if can_id is None:
        if isinstance(message, (codec.Status, codec.Score)):
            can_id = bus_map.arbiter_id
        elif isinstance(message, (codec.Ready, codec.ArbitrationVariable)):
            if autopilot is None or not 0 <= autopilot <= 3:
                raise ValueError(f"{type(message).__name__} needs autopilot=0..3 or can_id")
            can_id = bus_map.autopilot_ids[autopilot]
        else:
            raise ValueError(f"{type(message).__name__} needs a can_id")
    return can.Message(
        timestamp=timestamp,
        arbitration_id=can_id,
        is_extended_id=bus_map.extended,
        data=bus_map.codec().encode(message),
        channel=channel,
    )


class DecodingListener(can.Listener):
    """A ``can.Listener`` that decodes live traffic and hands each record to a callback.

    Attach it to a bus with ``can.Notifier(bus, [DecodingListener(records.append)])``. Each
    received message goes through `on_message_received`:

    Examples:
        >>> from veronte4x import dronecan
        >>> from veronte4x.canbus import to_can_messages
        >>> records = []
        >>> listener = DecodingListener(records.append)
        >>> status = dronecan.NodeStatus(5, dronecan.Health.OK, dronecan.Mode.OPERATIONAL, 0, 0)
        >>> for message in to_can_messages(status, source_node_id=10, transfer_id=0):
        ...     listener.on_message_received(message)
        >>> records[0].node_id, records[0].message.uptime_sec
        (10, 5)

    Args:
        callback: Called with every record, in order.
        bus_map: IDs and codec choices; Embention's template defaults if None.
    """

    def __init__(self, callback: Callable[[Record], object], bus_map: BusMap | None = None) -> None:
        self.callback = callback
        self.decoder = CaptureDecoder(bus_map)

    def on_message_received(self, msg: can.Message) -> None:
        """Decode one received message and pass its records on."""
        for record in self.decoder.decode((frame_from_message(msg),)):
            self.callback(record)
