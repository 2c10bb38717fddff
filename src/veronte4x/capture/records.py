"""The decoded record: one per frame, per DroneCAN transfer, per undecoded frame, or per
problem."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, NamedTuple

from veronte4x.capture.busmap import AUTOPILOT_NAMES, Role
from veronte4x.capture.readable import can_id_text
from veronte4x.codegen import compile_source
from veronte4x.display import Cells, message_html, side_by_side, table
from veronte4x.times import format_time


class Record(NamedTuple):
    """One decoded frame or transfer, an undecoded one, or the error that stopped it.

    Three cases: decoded (`message` set), undecoded foreign traffic (`message` and `error`
    None: a CAN ID outside the bus map, a DroneCAN data type with no codec; normal on a
    shared bus, not an error) and errors (`error` set).

    A named tuple rather than a dataclass: a capture makes one per frame, and a tuple is
    the cheapest immutable record Python builds.

    Attributes:
        timestamp: The frame's timestamp (for a transfer, its last frame's), or None.
        channel: Interface name.
        can_id: CAN ID of the frame (for a transfer, of its frames).
        role: Arbiter, autopilot, DroneCAN or unknown, from the bus map.
        autopilot: 0 = AP1, 1 = AP2, 2 = AP3, 3 = external, for an autopilot's frame.
        node_id: DroneCAN source node id.
        message: The decoded message, or None when undecoded or `error` is set.
        error: What stopped decoding, in a few words (``decode error``, ``unknown command``,
            ``bad line``, ``error frame``, ``remote frame``, or a DroneCAN reassembly problem
            such as ``crc mismatch``), or None.
        detail: The error's full text; for undecoded traffic, what it was
            (``11-bit CAN ID 0x123``, ``DroneCAN data type 1234``); or "".
        data: The raw bytes of the frame (for a DroneCAN transfer, of its last frame, tail
            byte included; the payload is in `message`).
        destination_node_id: DroneCAN destination node id of a service transfer.
        extended: Whether the frame came on a 29-bit (extended) CAN ID, its IDE bit (for a
            transfer, its frames', always; for a bad line, False), so that an extended
            frame with a small ID prints with 8 digits, as candump prints it.
    """

    timestamp: float | None
    channel: str
    can_id: int
    role: Role
    autopilot: int | None
    node_id: int | None
    message: Any
    error: str | None
    detail: str
    data: bytes
    destination_node_id: int | None = None
    extended: bool = False

    @property
    def sender(self) -> str:
        """Who sent it: ``arbiter``, ``AP1`` .. ``external``, ``node N`` or ``unknown``."""
        if self.role is Role.AUTOPILOT and self.autopilot is not None:
            return AUTOPILOT_NAMES[self.autopilot]
        if self.role is Role.DRONECAN and self.node_id is not None:
            return f"node {self.node_id}"
        return self.role.value

    @property
    def kind(self) -> str:
        """The message class name, ``unknown`` for undecoded traffic, or ``error: <error>``."""
        if self.error is not None:
            return f"error: {self.error}"
        if self.message is None:
            return "unknown"
        return type(self.message).__name__

    def _repr_html_(self) -> str:
        """Jupyter's view: the record and its message as tables (`record_html`)."""
        return record_html(self)


def record_html(record: Record) -> str:
    """A record as HTML: where and when it came from, then its message's fields."""
    head: list[Cells] = [
        ("time", format_time(record.timestamp)),
        ("channel", record.channel),
        ("CAN ID", can_id_text(record.can_id, record.extended)),
        ("sender", record.sender),
    ]
    if record.destination_node_id is not None:
        head.append(("to node", record.destination_node_id))
    if record.error is not None:
        head += [("error", record.error), ("detail", record.detail)]
    elif record.message is None:
        head.append(("undecoded", record.detail))
    head.append(("data", record.data.hex(" ")))
    parts = [table(f"Record: {record.kind}", ("", ""), head, header=False)]
    if record.message is not None:
        parts.append(message_html(record.message))
    return side_by_side(parts)


DEFAULTS: dict[str, Any] = {
    "autopilot": None,
    "node_id": None,
    "message": None,
    "error": None,
    "detail": "",
    "data": b"",
    "destination_node_id": None,
    "extended": False,
}
"""The value of each `Record` field a factory is not given (the fields without one,
``timestamp``, ``channel``, ``can_id`` and ``role``, must be given)."""


def factory(name: str, given: tuple[str, ...], **fixed: Any) -> Callable[..., Record]:
    """A function that builds a `Record` from the fields ``given`` (its parameters, in that
    order), the fields ``fixed`` at their values and every other at its `DEFAULTS` value.

    Every `Record` of the package is built by one of the factories below: a field added to
    `Record` (with its default in `DEFAULTS`) is then added to every record. A factory is
    generated code (see `veronte4x.codegen`): one ``tuple.__new__`` call, as fast as a hand
    written tuple and faster than the named tuple's own ``__new__``.

    Raises:
        ValueError: A field of `Record` is neither given, fixed nor defaulted, or a name is
            no field.
    """
    fields = Record._fields
    unknown = [f for f in (*given, *fixed) if f not in fields]
    if unknown:
        raise ValueError(f"not fields of Record: {', '.join(unknown)}")
    namespace: dict[str, Any] = {"_new": tuple.__new__, "_Record": Record}
    values = []
    for field in fields:
        if field in given:
            values.append(field)
        elif field in fixed or field in DEFAULTS:
            namespace[f"_{field}"] = fixed[field] if field in fixed else DEFAULTS[field]
            values.append(f"_{field}")
        else:
            raise ValueError(f"the Record field {field} has no default: give it")
    source = f"def {name}({', '.join(given)}):\n    return _new(_Record, ({', '.join(values)}))\n"
    made: Callable[..., Record] = compile_source(source, namespace, f"Record factory {name}")[name]
    return made


veronte_record = factory(
    "veronte_record",
    ("timestamp", "channel", "can_id", "role", "autopilot", "message", "data", "extended"),
)
"""A decoded Veronte frame: ``(timestamp, channel, can_id, role, autopilot, message, data,
extended)``."""

transfer_record = factory(
    "transfer_record",
    ("timestamp", "channel", "can_id", "node_id", "message", "data", "destination_node_id"),
    role=Role.DRONECAN,
    extended=True,
)
"""A decoded DroneCAN transfer: ``(timestamp, channel, can_id, node_id, message, data,
destination_node_id)``."""

error_record = factory(
    "error_record",
    ("timestamp", "channel", "can_id", "role", "autopilot", "node_id", "error", "detail", "data",
     "extended"),
)  # fmt: skip
"""An error, or undecoded traffic (``error`` None): ``(timestamp, channel, can_id, role,
autopilot, node_id, error, detail, data, extended)``."""

dbc_record = factory(
    "dbc_record", ("timestamp", "channel", "can_id", "message", "data", "extended"),
    role=Role.UNKNOWN,
)  # fmt: skip
"""A frame outside the bus map that a DBC decoded: ``(timestamp, channel, can_id, message,
data, extended)``; its role stays ``unknown``."""
