"""Sans-IO reassembly of DroneCAN transfers from a stream of frames.

One receiver state ("session") per transfer descriptor: source node, destination node,
data type and kind, i.e. the CAN ID without its priority bits (spec 4.1 "Reception",
"State variables"). Two sets of rules decide which frames a session takes:

- by default libcanard's, exactly as its ``canardHandleRxFrame`` on one interface
  (`Reassembler._receive`): a single frame is always delivered, a multi-frame transfer
  repeating the transfer id delivered last within the timeout is refused, a frame with an
  unexpected toggle bit or transfer id is ignored and the transfer goes on;
- with ``strict=True`` veronte4x's own: every transfer whose frames all arrive, once, in
  order and uncorrupted, with no other frame of its session in between and within the
  transfer-ID timeout, is delivered, unless it repeats the transfer id delivered last in
  its session within the timeout (2 s after the first frame of that transfer, by the
  frames' own timestamps); a multi-frame transfer repeating the id of a single frame is
  taken all the same, since its CRC vouches for it and nothing vouches for the single
  frame (docs/dronecan/reassembly.md, "What cannot be recovered"). So a stray frame never
  makes the next intact transfer look like a repeat.

Time comes only from the ``timestamp`` argument; nothing reads a clock
(docs/dronecan/reassembly.md, "Transfer acceptance").

Bus data never raises: what happened to a frame is a value. `Reassembler.push` returns
the transfer the frame completes, or the `Problems` it caused (with the transfer it
completed all the same, if any), or None; `Reassembler.feed` returns just the transfer.
Each problem is also counted in `counts` and recorded as a `ProblemReport` in the bounded
`problems`. Under the strict rules a transfer that started or was seen but never came out
is counted exactly once, under the first problem that broke it, and the rest of its frames
are dropped silently; under libcanard's each refused frame is reported, and a transfer a
restart drops as `Problem.INTERRUPTED` or `Problem.TIMEOUT`.
Arguments of the wrong type are caller mistakes, not bus data: they raise `TypeError`
(see `Reassembler.push`).

The sessions are kept in the order their latest transfer began, so expiring idle sessions
and evicting the oldest one cost O(1) amortised, whatever the size of the table.
"""

from __future__ import annotations

import enum
import math
import weakref
from binascii import crc_hqx  # the transfer CRC, see veronte4x.dronecan.crc
from collections import OrderedDict, deque
from collections.abc import Mapping
from typing import Any, NamedTuple, cast

from veronte4x.dronecan.can_id import TransferKind
from veronte4x.dronecan.codec import BY_ID, TypeCodec
from veronte4x.dronecan.compiled import DECODE_FALLBACK
from veronte4x.dronecan.tail import (
    END_OF_TRANSFER,
    FRAME_FLAGS,
    SINGLE_FRAME,
    START_OF_TRANSFER,
    TOGGLE,
    TRANSFER_ID_MASK,
)
from veronte4x.dronecan.transfer import Transfer, received
from veronte4x.dronecan.typeset import TypeSet, types_or_default
from veronte4x.errors import BytesLike, DecodeError, argument_type_error

TRANSFER_ID_TIMEOUT = 2.0
"""Transfer-ID timeout in seconds (spec 4.1 "State variables")."""


class Problem(enum.Enum):
    """What went wrong with a frame or a transfer; the value says it in words.

    The members in `TRANSFER_PROBLEMS` mean a transfer was lost, and each lost
    transfer is counted once, under the first problem that hit it. The others mean a frame
    was ignored and nothing was lost (under the default rules, libcanard's, a frame refused
    is reported whether or not its transfer was lost already).
    """

    MALFORMED_FRAME = (
        "Not a DroneCAN frame: no tail byte, more than 8 bytes, a CAN ID beyond 29 bits, a "
        "service with node id 0, a multi-frame anonymous frame, or a frame other than the "
        "last of a transfer with fewer than 8 bytes (which also loses that transfer)."
    )
    UNKNOWN_TYPE = "A frame of none of the supported types (counted per frame)."
    MISSED_START = "A frame of a transfer whose first frame was not seen."
    TOGGLE_ERROR = (
        "A toggle bit out of sequence that is not a repeat: a frame was lost or reordered; "
        "the strict rules drop the transfer, libcanard's ignore the frame."
    )
    DUPLICATE_FRAME = "A repeat of the frame accepted just before; ignored."
    UNEXPECTED_TRANSFER_ID = (
        "A frame with another transfer id than its session expects, within the transfer-ID "
        "timeout: a first frame repeating the one delivered last (under the strict rules, "
        "with other content: a replayed transfer), or a stray frame; ignored."
    )
    CRC_MISMATCH = "The transfer CRC does not match the payload."
    TIMEOUT = "A transfer still incomplete after the transfer-ID timeout."
    INTERRUPTED = "A transfer still incomplete when the next one of its session started."
    PAYLOAD_TOO_LONG = "More bytes than the largest payload of the type."
    BAD_PAYLOAD = "A complete transfer whose payload does not decode as its type."
    EVICTED = "An incomplete transfer dropped because the session table was full."


TRANSFER_PROBLEMS: frozenset[Problem] = frozenset(
    {
        Problem.MISSED_START,
        Problem.TOGGLE_ERROR,
        Problem.CRC_MISMATCH,
        Problem.TIMEOUT,
        Problem.INTERRUPTED,
        Problem.PAYLOAD_TOO_LONG,
        Problem.BAD_PAYLOAD,
        Problem.EVICTED,
    }
)
"""Problems that lose a transfer under the strict rules (MALFORMED_FRAME also does when it
hits one in progress); under libcanard's, TOGGLE_ERROR and MISSED_START only ignore a frame."""


class ProblemReport(NamedTuple):
    """One recorded problem: what, on which frame, when, and a detail in words."""

    problem: Problem
    can_id: int
    data: bytes
    timestamp: float
    detail: str


class Problems(NamedTuple):
    """What went wrong when one frame came: its problem reports, in the order they
    happened, and the transfer the frame completed all the same (None if it completed none).

    One frame causes at most two reports: it makes room in a full session table, losing
    another session's transfer, or it ends its own session's transfer in progress
    (`Problem.TIMEOUT`, `Problem.INTERRUPTED`); then it is itself a problem, or it
    completes a single-frame transfer (which comes after the reports).
    """

    reports: tuple[ProblemReport, ...]
    transfer: Transfer | None


Outcome = Transfer | Problems | None
"""What `Reassembler.push` returns for a frame: the transfer it completes, the problems it
caused, or None (a frame taken, nothing to tell)."""


def _join(report: ProblemReport | None, outcome: Outcome) -> Outcome:
    """``outcome`` preceded by ``report`` (None: no report)."""
    if report is None:
        return outcome
    if outcome is None:
        return Problems((report,), None)
    if isinstance(outcome, Problems):
        return Problems((report, *outcome.reports), outcome.transfer)
    return Problems((report,), outcome)


_NEVER = -math.inf
_HEAD = 5
"""Payload bytes libcanard keeps in a receiver state before it takes buffer blocks
(``CANARD_MULTIFRAME_RX_PAYLOAD_HEAD_SIZE`` with its default 32-byte blocks): a first frame
restarts a transfer in progress only once more are stored."""
_SWITCH_DELAY = 1.0
"""libcanard's ``IFACE_SWITCH_DELAY_USEC`` in seconds: a first frame this long after the
latest accepted one restarts its session unless its transfer id is behind the expected one."""
_LOST = 32
"""Added to a transfer id in `_Session.closed` when that transfer was lost (not delivered)."""


class _Session:
    """Receiver state of one transfer descriptor (spec 4.1 "State variables").

    Also holds what every transfer of the descriptor shares: its codec, kind and type id.
    """

    __slots__ = (
        "buffer",
        "carried",
        "closed",
        "closed_at",
        "codec",
        "counted",
        "crc",
        "crc_seed",
        "data_type_id",
        "decode_frame",
        "decode_payload",
        "kind",
        "last",
        "limit",
        "orphan",
        "start",
        "tid",
        "toggle",
    )

    def __init__(self, shared: tuple[Any, ...], can_id: int) -> None:
        self.codec: Any = None
        self.reset(shared, can_id)

    def reset(self, shared: tuple[Any, ...], can_id: int) -> None:
        """Make this the fresh state of the session of ``can_id`` (of the type ``shared``)."""
        if self.codec is not shared[0]:
            (
                self.codec,
                self.kind,
                self.data_type_id,
                self.decode_frame,
                self.decode_payload,
                self.crc_seed,
                self.limit,
            ) = shared
        # The transfer id the fast path of `feed` takes: the one in progress, or the one
        # after the transfer delivered last; -1 sends every frame through the full update.
        self.tid = -1
        self.toggle = 0  # expected toggle bit (0 or TOGGLE)
        self.start = _NEVER  # timestamp of the first frame of the latest transfer
        self.buffer: bytearray | None = None  # payload so far (CRC first), None when idle
        self.last = b""  # the frame accepted last
        # The transfer that ended last: its id if it was delivered (then it began at
        # `start`), its id + _LOST if it was lost or counted as MISSED_START (then its frames
        # are silent until `closed_at` + timeout), -1 if none.
        self.closed = -1
        self.closed_at = _NEVER
        self.counted = False  # the transfer in progress was already counted as lost
        self.orphan = False  # libcanard's rules: the payload stored has no first frame
        # libcanard's CRC registers, which only a first frame resets: the CRC computed up to
        # the latest frame stored (None: not known) and the one its first frame carried.
        self.crc: int | None = 0
        self.carried = 0


def _shared(codec: TypeCodec) -> tuple[Any, ...]:
    """What every session of a type holds, in the order `_Session` takes it."""
    return (
        codec,
        codec.data_type.kind,
        codec.data_type.data_type_id,
        codec.fast.decode_frame,
        codec.fast.decode,
        codec.crc_seed,
        codec.max_payload + 3,  # CRC and tail byte included
    )


class _SessionTypes:
    """What the sessions of each type of a type set share (`_shared`), filled in per type
    on first use so that a type's decoders are compiled only when its first frame comes."""

    def __init__(self, by_id: Mapping[tuple[TransferKind, int], TypeCodec]) -> None:
        self.by_id = by_id
        self.messages: dict[int, tuple[Any, ...]] = {}
        """By message type id."""
        self.services: dict[int, tuple[Any, ...]] = {}
        """By service key: type id << 1 | request bit."""

    def message(self, dtid: int) -> tuple[Any, ...] | None:
        """`_shared` of a message type, now in `messages`; None if the set has no such type."""
        codec = self.by_id.get((TransferKind.MESSAGE, dtid))
        if codec is None:
            return None
        shared = self.messages[dtid] = _shared(codec)
        return shared

    def service(self, key: int) -> tuple[Any, ...] | None:
        """`_shared` of a request or response type, now in `services`; None if unknown."""
        kind = TransferKind.REQUEST if key & 1 else TransferKind.RESPONSE
        codec = self.by_id.get((kind, key >> 1))
        if codec is None:
            return None
        shared = self.services[key] = _shared(codec)
        return shared


_STANDARD_TYPES = _SessionTypes(BY_ID)
_SESSION_TYPES: weakref.WeakKeyDictionary[TypeSet, _SessionTypes] = weakref.WeakKeyDictionary()
_BYTES_LIKE = (bytes, bytearray, memoryview)
_START_AND_TOGGLE = START_OF_TRANSFER | TOGGLE
"""The tail bits a transfer's next frame has as expected: no start, the session's toggle."""
_FRAME_ERRORS = DECODE_FALLBACK  # what a generated single-frame decoder raises


def _argument_error(
    function: str, can_id: object, data: object, timestamp: object
) -> TypeError | None:
    """The `TypeError` for arguments of the wrong type, naming ``function``; None if right."""
    if not isinstance(can_id, int) or isinstance(can_id, bool):
        return argument_type_error(function, "can_id", "an int", can_id)
    if not isinstance(data, _BYTES_LIKE):
        return argument_type_error(function, "data", "bytes-like", data)
    if not isinstance(timestamp, (int, float)) or isinstance(timestamp, bool):
        return argument_type_error(function, "timestamp", "a float", timestamp)
    return None


def _check_arguments(can_id: object, data: object, timestamp: object) -> bytes:
    """Refuse arguments of the wrong type (`TypeError`); return the data as bytes."""
    error = _argument_error("Reassembler.push", can_id, data, timestamp)
    if error is not None:
        raise error
    return bytes(cast(BytesLike, data))


class Reassembler:
    """Turn a stream of frames into checked, decoded transfers.

    Args:
        transfer_id_timeout: Seconds after the first frame of a transfer after which its
            session restarts (spec: 2 s).
        max_sessions: Most receiver states kept; beyond, timed-out sessions are dropped,
            then the one whose latest transfer began first. Memory is bounded by this times
            the largest payload (378 B).
        max_reports: How many recent `ProblemReport` entries `problems` keeps.
        types: The DroneCAN types to decode (`TypeSet`); None for the default set
            (the standard one, plus what `veronte4x.dronecan.load_dsdl` added).
        strict: False (the default): accept and refuse frames as libcanard's
            ``canardHandleRxFrame`` does, so a node whose transfer id never advances is
            heard at every single frame. True: veronte4x's own stricter rules, which refuse
            a single frame repeating the transfer id delivered last within the timeout,
            drop a transfer at its first toggle error and count each lost transfer once
            (docs/dronecan/reassembly.md, "Transfer acceptance").

    Attributes:
        counts: Number of each `Problem` so far.
        problems: The most recent problem reports, oldest first.
        reported: Number of problem reports so far.
        strict: Whether it follows veronte4x's strict rules rather than libcanard's.
        transfers: Number of transfers delivered.
        types: The `TypeSet` it decodes with.
    """

    def __init__(
        self,
        transfer_id_timeout: float = TRANSFER_ID_TIMEOUT,
        max_sessions: int = 1024,
        max_reports: int = 256,
        types: TypeSet | None = None,
        strict: bool = False,
    ) -> None:
        types = types_or_default(types, "Reassembler")
        found = _STANDARD_TYPES if types is TypeSet.standard() else _SESSION_TYPES.get(types)
        if found is None:
            found = _SESSION_TYPES[types] = _SessionTypes(types.by_id)
        self._session_types = found
        self._messages, self._services = found.messages, found.services
        self.types = types
        if not isinstance(transfer_id_timeout, (int, float)) or isinstance(
            transfer_id_timeout, bool
        ):
            raise argument_type_error(
                "Reassembler", "transfer_id_timeout", "a float", transfer_id_timeout
            )
        for name, value in (("max_sessions", max_sessions), ("max_reports", max_reports)):
            if not isinstance(value, int) or isinstance(value, bool):
                raise argument_type_error("Reassembler", name, "an int", value)
            if value < 1:
                raise ValueError(f"Reassembler: {name} must be at least 1, not {value}")
        if not isinstance(strict, bool):
            raise argument_type_error("Reassembler", "strict", "a bool", strict)
        self.strict = strict
        self.timeout = transfer_id_timeout
        self.max_sessions = max_sessions
        self.counts: dict[Problem, int] = dict.fromkeys(Problem, 0)
        self.problems: deque[ProblemReport] = deque(maxlen=max_reports)
        self.reported = 0
        self.transfers = 0
        self._sessions: dict[int, _Session] = {}  # for lookups: a plain dict is fastest
        # The same sessions, oldest first: in the order their latest transfer began (or
        # their latest lost frame came). Only the front is ever examined for expiry.
        self._age: OrderedDict[int, _Session] = OrderedDict()
        self._touch = self._age.move_to_end
        self._get = self._sessions.get

    @property
    def session_count(self) -> int:
        """Number of receiver states held now."""
        return len(self._sessions)

    def _report(
        self, problem: Problem, can_id: int, data: Any, timestamp: float, detail: str
    ) -> ProblemReport:
        """Count and record a problem; return its report."""
        self.counts[problem] += 1
        self.reported += 1
        report = ProblemReport(problem, can_id, bytes(data), timestamp, detail)
        self.problems.append(report)
        return report

    def _problem(
        self, problem: Problem, can_id: int, data: Any, timestamp: float, detail: str
    ) -> Problems:
        """`_report` a problem that is all a frame caused."""
        return Problems((self._report(problem, can_id, data, timestamp, detail),), None)

    def push(self, can_id: int, data: BytesLike, timestamp: float) -> Outcome:
        """Take one frame; return what happened: the transfer it completes, the problems
        it caused, or None.

        Bad bus data never raises: each problem is returned in `Problems`, and also
        counted in `counts` and recorded in `problems`.

        Args:
            can_id: The 29-bit extended CAN ID.
            data: The frame's data bytes, tail byte last (bytes, bytearray or memoryview).
            timestamp: Reception time in seconds, from any monotonic source.

        Returns:
            The `Transfer` the frame completes; or `Problems`, the reports of what went
            wrong (in order) and the transfer completed all the same, if any; or None when
            the frame was taken and there is nothing to tell (a frame of a transfer in
            progress).

        Raises:
            TypeError: An argument of the wrong type (a caller mistake, not bus data):
                ``can_id`` not an int, ``data`` not bytes-like, ``timestamp`` not a number.
        """
        # Fast paths: the next frame of a known session, in order, nothing unusual. Any
        # other case goes to _feed, which redoes the full state update (nothing changed yet).
        # Frame lengths: decode_frame checks a single frame's exact length itself.
        try:
            key = can_id & 0xFFFFFF
            session = self._get(key)
            if session is None:
                return self._open(can_id, data, timestamp)
            tail = data[-1]
            tid = tail & TRANSFER_ID_MASK
            if (
                data.__class__ is not bytes
                or can_id >> 29
                or tid != session.tid
                or timestamp - session.start > self.timeout
            ):
                return self._feed(can_id, data, timestamp)
        except (TypeError, IndexError):  # wrong type, no tail byte
            return self._feed(can_id, data, timestamp)
        buffer = session.buffer
        if buffer is None:
            # a single frame
            if tail & FRAME_FLAGS == SINGLE_FRAME and session.decode_frame is not None:
                try:
                    message = session.decode_frame(data)
                except _FRAME_ERRORS:  # wrong length: the checked path reports it
                    return self._feed(can_id, data, timestamp)
                session.tid = (tid + 1) & TRANSFER_ID_MASK
                session.closed = tid
                session.start = timestamp
                session.last = data
                self._touch(key)
                self.transfers += 1
                return received(message, can_id, tid, timestamp, session.kind, session.data_type_id)
            if tail & FRAME_FLAGS == START_OF_TRANSFER and len(data) == 8:  # first frame of several
                session.buffer = bytearray(data[:-1])
                session.toggle = TOGGLE
                session.start = timestamp
                session.last = data
                self._touch(key)
                return None
        elif (
            tail & _START_AND_TOGGLE == session.toggle
            and (len(data) == 8 or (tail & END_OF_TRANSFER and len(data) <= 8))
            and len(buffer) + len(data) <= session.limit
        ):
            buffer += data[:-1]
            session.last = data
            if not tail & END_OF_TRANSFER:
                session.toggle ^= TOGGLE
                return None
            return self._complete(session, can_id, data, tid)
        return self._feed(can_id, data, timestamp)

    def feed(self, can_id: int, data: BytesLike, timestamp: float) -> Transfer | None:
        """Take one frame; return the transfer it completes, else None.

        `push` with the problems left out of the result: bad bus data never raises, and
        each problem is counted in `counts` and recorded in `problems`.

        Args:
            can_id: The 29-bit extended CAN ID.
            data: The frame's data bytes, tail byte last (bytes, bytearray or memoryview).
            timestamp: Reception time in seconds, from any monotonic source.

        Raises:
            TypeError: An argument of the wrong type (a caller mistake, not bus data):
                ``can_id`` not an int, ``data`` not bytes-like, ``timestamp`` not a number.
        """
        try:
            outcome = self.push(can_id, data, timestamp)
        except TypeError as error:
            raise _argument_error("Reassembler.feed", can_id, data, timestamp) or error from None
        if type(outcome) is Problems:
            return outcome.transfer
        return outcome  # type: ignore[return-value]

    def _feed(self, can_id: int, data: Any, timestamp: float) -> Outcome:
        """The full state update of spec 4.1 with every check."""
        if data.__class__ is not bytes or can_id.__class__ is not int:
            data = _check_arguments(can_id, data, timestamp)
        elif timestamp.__class__ is not float:
            _check_arguments(can_id, data, timestamp)
        size = len(data)
        if not 0 < size <= 8 or not 0 <= can_id <= 0x1FFFFFFF:
            return self._problem(
                Problem.MALFORMED_FRAME,
                can_id,
                data[:64],
                timestamp,
                f"{size} data bytes, CAN ID {can_id:#x}",
            )
        tail = data[-1]
        if can_id & 0x80:
            key = (can_id >> 15) & 0x1FF
            shared = self._services.get(key) or self._session_types.service(key)
            if not can_id & 0x7F or not can_id & 0x7F00:
                return self._problem(Problem.MALFORMED_FRAME, can_id, data, timestamp, "node id 0")
        elif can_id & 0x7F:
            dtid = (can_id >> 8) & 0xFFFF
            shared = self._messages.get(dtid) or self._session_types.message(dtid)
        elif tail & SINGLE_FRAME != SINGLE_FRAME:
            return self._problem(
                Problem.MALFORMED_FRAME, can_id, data, timestamp, "multi-frame anonymous"
            )
        else:  # anonymous: the type id's low 2 bits beside a discriminator (spec 4.1)
            dtid = (can_id >> 8) & 3
            shared = self._messages.get(dtid) or self._session_types.message(dtid)
        if shared is None:
            return self._problem(Problem.UNKNOWN_TYPE, can_id, data, timestamp, "unknown data type")
        session = self._sessions.get(can_id & 0xFFFFFF)
        evicted = None
        if session is None:
            # libcanard makes states at first frames
            if not tail & START_OF_TRANSFER and not self.strict:
                detail = f"transfer id {tail & TRANSFER_ID_MASK}"
                return self._problem(Problem.MISSED_START, can_id, data, timestamp, detail)
            session, evicted = self._new_session(shared, can_id, timestamp)
        if not self.strict:
            return _join(evicted, self._receive(session, can_id, data, tail, timestamp))
        if tail & START_OF_TRANSFER:
            return _join(evicted, self._start(session, can_id, data, tail, timestamp))
        return _join(evicted, self._continue(session, can_id, data, tail, timestamp))

    def _open(self, can_id: int, data: Any, timestamp: float) -> Outcome:
        """The first frame of a session not in the table: a lean path for a valid single
        frame of a type with a generated decoder; anything else goes through `_feed`."""
        if (
            data.__class__ is not bytes
            or can_id.__class__ is not int
            or not 0 < len(data) <= 8
            or not 0 < can_id <= 0x1FFFFFFF
        ):
            return self._feed(can_id, data, timestamp)
        tail = data[-1]
        if can_id & 0x80:
            key = (can_id >> 15) & 0x1FF
            shared = self._services.get(key) or self._session_types.service(key)
            if not can_id & 0x7F00 or not can_id & 0x7F:
                return self._feed(can_id, data, timestamp)
        elif can_id & 0x7F:
            dtid = (can_id >> 8) & 0xFFFF
            shared = self._messages.get(dtid) or self._session_types.message(dtid)
        else:
            return self._feed(can_id, data, timestamp)
        if shared is None or tail & FRAME_FLAGS != SINGLE_FRAME or shared[3] is None:
            return self._feed(can_id, data, timestamp)
        try:
            message = shared[3](data)
        except _FRAME_ERRORS:  # wrong length: the checked path reports it
            return self._feed(can_id, data, timestamp)
        session, evicted = self._new_session(shared, can_id, timestamp)
        tid = tail & TRANSFER_ID_MASK
        session.tid = (tid + 1) & TRANSFER_ID_MASK
        session.closed = tid
        session.start = timestamp
        session.last = data
        self.transfers += 1
        transfer = received(message, can_id, tid, timestamp, shared[1], shared[2])
        return transfer if evicted is None else Problems((evicted,), transfer)

    def _new_session(
        self, shared: tuple[Any, ...], can_id: int, timestamp: float
    ) -> tuple[_Session, ProblemReport | None]:
        """Add a session, first making room if the table is full; return it, and the
        report of the transfer lost in making room (None if none was).

        The front of the age order is the session whose latest transfer began first; if
        any session is idle past the timeout, that one is. It is dropped (its incomplete
        transfer counted as TIMEOUT if it timed out, else as EVICTED).
        """
        sessions = self._sessions
        evicted = None
        if len(sessions) < self.max_sessions:
            session = _Session(shared, can_id)
        else:
            key, session = self._age.popitem(last=False)
            del sessions[key]
            if session.buffer is not None and not session.counted:
                if timestamp - max(session.start, session.closed_at) > self.timeout:
                    problem, detail = Problem.TIMEOUT, f"transfer id {session.tid}"
                else:
                    problem, detail = Problem.EVICTED, "session table full"
                evicted = self._report(problem, key, b"", timestamp, detail)
            session.reset(shared, can_id)  # the dropped state, reused
        key = can_id & 0xFFFFFF
        sessions[key] = self._age[key] = session
        return session, evicted

    def _lost(self, session: _Session, can_id: int, tid: int, timestamp: float) -> None:
        """Remember transfer ``tid`` as lost: under the strict rules its other frames are now
        silent; under libcanard's the session expects the next transfer id."""
        session.buffer = None
        session.toggle = 0
        session.counted = session.orphan = False
        session.closed = tid + _LOST
        session.closed_at = timestamp
        session.tid = (tid + 1) & TRANSFER_ID_MASK if not self.strict else -1
        self._touch(can_id & 0xFFFFFF)

    def _abandon(
        self,
        session: _Session,
        problem: Problem,
        can_id: int,
        data: Any,
        timestamp: float,
        silent_from: float | None = None,
    ) -> ProblemReport | None:
        """Drop the transfer in progress, counting it unless it was counted already;
        return its report (None if it was counted before).

        Its remaining frames are silent for a timeout from ``silent_from`` (default: now).
        """
        report = None
        if not session.counted:
            report = self._report(problem, can_id, data, timestamp, f"transfer id {session.tid}")
        at = timestamp if silent_from is None else silent_from
        self._lost(session, can_id, session.tid, at)
        return report

    def _recent(self, session: _Session, tid: int, timestamp: float) -> bool:
        """Whether transfer ``tid`` ended (delivered or lost) within the timeout."""
        if session.closed == tid:
            return timestamp - session.start <= self.timeout
        if session.closed == tid + _LOST:
            return timestamp - session.closed_at <= self.timeout
        return False

    def _receive(
        self, session: _Session, can_id: int, data: bytes, tail: int, ts: float
    ) -> Outcome:
        """libcanard's state update (``canardHandleRxFrame``, for one interface), with its
        refusals as problems.

        The state is libcanard's: the expected transfer id (`_Session.tid`), the expected
        toggle, the time of the latest accepted first frame (`_Session.start`) and the
        payload stored. ``orphan`` marks a payload no first frame began: libcanard appends
        frames matching the expected toggle and transfer id to its state even then, and
        the last of them fails the CRC. ``counted`` marks a payload not to deliver (an
        orphan, or one past the type's largest, reported once as `PAYLOAD_TOO_LONG` and
        no longer stored: libcanard stores it and its decoder refuses it).
        """
        tid = tail & TRANSFER_ID_MASK
        first = tail & START_OF_TRANSFER
        key = can_id & 0xFFFFFF
        since = ts - session.start
        buffer = session.buffer
        stored = 0 if buffer is None else len(buffer) - (0 if session.orphan else 2)
        ended = None
        if (
            since > self.timeout
            or (first and ((session.tid - tid) & TRANSFER_ID_MASK > 1 or stored > _HEAD))
            or (first and since > _SWITCH_DELAY and (tid - session.tid) & TRANSFER_ID_MASK < 16)
        ):
            if buffer is not None and not session.counted:
                problem = Problem.TIMEOUT if since > self.timeout else Problem.INTERRUPTED
                ended = self._report(problem, can_id, data, ts, f"transfer id {session.tid}")
            buffer = session.buffer = None
            session.counted = session.orphan = False
            session.toggle = 0
            session.tid = tid
            session.closed_at = ts
            self._touch(key)
            if not first:
                session.tid = (tid + 1) & TRANSFER_ID_MASK
                missed = self._report(Problem.MISSED_START, can_id, data, ts, f"transfer id {tid}")
                return _join(ended, Problems((missed,), None))
        if first and tail & END_OF_TRANSFER:  # a single frame: delivered whatever its toggle
            if buffer is not None and not session.counted:
                ended = self._report(
                    Problem.INTERRUPTED, can_id, data, ts, f"transfer id {session.tid}"
                )
            session.buffer = None
            session.counted = session.orphan = False
            session.start = ts
            session.last = data
            self._touch(key)
            transfer_id, session.tid = session.tid, tid  # `_deliver` moves on from ``tid``
            outcome = self._deliver(session, can_id, data[:-1], tid, ts, False)
            # libcanard: the expected id, plus one
            session.tid = (transfer_id + 1) & TRANSFER_ID_MASK
            return _join(ended, outcome)
        if tail & TOGGLE != session.toggle:
            problem = Problem.DUPLICATE_FRAME if data == session.last else Problem.TOGGLE_ERROR
            detail = f"toggle {tail >> 5 & 1}, expected {session.toggle >> 5}"
            return _join(ended, self._problem(problem, can_id, data, ts, detail))
        if tid != session.tid:
            detail = f"transfer id {tid}, expected {session.tid}"
            return _join(
                ended, self._problem(Problem.UNEXPECTED_TRANSFER_ID, can_id, data, ts, detail)
            )
        if first:
            if len(data) <= 3:
                return _join(
                    ended,
                    self._problem(Problem.MALFORMED_FRAME, can_id, data, ts, "short first frame"),
                )
            if buffer is not None and not session.counted:
                ended = self._report(Problem.INTERRUPTED, can_id, data, ts, f"transfer id {tid}")
            session.buffer = bytearray(data[:-1])
            session.counted = session.orphan = False
            session.start = ts
            session.last = data
            session.toggle ^= TOGGLE  # 0 unless it restarts a transfer at an odd frame
            self._touch(key)
            return _join(ended, None)
        if buffer is None:
            buffer = session.buffer = bytearray()
            session.counted = session.orphan = True
        if len(buffer) + len(data) <= session.limit:
            buffer += data[:-1]
        else:  # libcanard stores it all: its CRC is no longer known
            session.crc = None
            if not session.counted:
                session.counted = True
                report = self._report(
                    Problem.PAYLOAD_TOO_LONG, can_id, data, ts, f"transfer id {tid}"
                )
                ended = ended or report  # a restart leaves no payload: never both
        session.last = data
        if not tail & END_OF_TRANSFER:
            session.toggle ^= TOGGLE
            return _join(ended, None)
        return _join(ended, self._complete(session, can_id, data, tid))

    def _start(self, session: _Session, can_id: int, data: bytes, tail: int, ts: float) -> Outcome:
        """A first frame: close what is in progress, then begin a transfer unless the
        frame repeats the transfer delivered last."""
        if session.buffer is not None and ts - session.start > self.timeout:
            # Dated from its own first frame: a new transfer with its id is not counted.
            ended = self._abandon(session, Problem.TIMEOUT, can_id, data, ts, session.start)
            return _join(ended, self._begin(session, can_id, data, tail, ts))
        return self._begin(session, can_id, data, tail, ts)

    def _begin(self, session: _Session, can_id: int, data: bytes, tail: int, ts: float) -> Outcome:
        """A first frame, no transfer of its session in progress past the timeout."""
        tid = tail & TRANSFER_ID_MASK
        again = session.closed == tid and ts - session.start <= self.timeout
        if again:
            if data == session.last:
                return self._problem(Problem.DUPLICATE_FRAME, can_id, data, ts, "frame again")
            if (
                tail & END_OF_TRANSFER
                or session.buffer is not None
                or session.last[-1] & SINGLE_FRAME != SINGLE_FRAME
            ):
                return self._problem(
                    Problem.UNEXPECTED_TRANSFER_ID, can_id, data, ts, f"transfer id {tid} again"
                )
            # A multi-frame transfer with the id of the single frame delivered last: no
            # sender reuses an id within the timeout, so one of the two is not what was
            # sent. A single frame has no CRC (a flipped bit in its tail byte gives it
            # another transfer id unnoticed) while this transfer's CRC and the transfer id
            # of each of its frames vouch for it: it is taken, and delivered if it
            # completes (docs/dronecan/reassembly.md, "What cannot be recovered").
        # The late first frame of a transfer already counted lost begins it "counted": if
        # it fails, it is not counted again; if it completes (the frame counted was not
        # its own), it is delivered.
        counted = not again and self._recent(session, tid, ts)
        if session.buffer is None:
            return self._take_first(session, can_id, data, tail, ts, counted)
        if data == session.last:  # the same first frame: its buffer is unchanged
            session.start = ts  # a transfer is dated by the last copy of its first frame
            self._touch(can_id & 0xFFFFFF)
            return self._problem(Problem.DUPLICATE_FRAME, can_id, data, ts, "first frame again")
        ended = self._abandon(session, Problem.INTERRUPTED, can_id, data, ts)
        return _join(ended, self._take_first(session, can_id, data, tail, ts, counted))

    def _take_first(
        self, session: _Session, can_id: int, data: bytes, tail: int, ts: float, counted: bool
    ) -> Outcome:
        """A first frame, its session idle: deliver it, begin a transfer or drop it."""
        tid = tail & TRANSFER_ID_MASK
        if tail & TOGGLE:
            self._lost(session, can_id, tid, ts)
            if counted:
                return None
            return self._problem(
                Problem.TOGGLE_ERROR, can_id, data, ts, "toggle set on first frame"
            )
        if not tail & END_OF_TRANSFER and len(data) != 8:
            self._lost(session, can_id, tid, ts)
            if counted:
                return None
            return self._problem(Problem.MALFORMED_FRAME, can_id, data, ts, "short first frame")
        session.start = ts
        session.last = data
        self._touch(can_id & 0xFFFFFF)
        if tail & END_OF_TRANSFER:  # single-frame transfer
            return self._deliver(session, can_id, data[:-1], tid, ts, counted)
        session.tid = tid
        session.counted = counted
        session.buffer = bytearray(data[:-1])
        session.toggle = TOGGLE
        return None

    def _continue(
        self, session: _Session, can_id: int, data: bytes, tail: int, ts: float
    ) -> Outcome:
        """A frame other than the first: the next of the transfer in progress, or a stray."""
        tid = tail & TRANSFER_ID_MASK
        buffer = session.buffer
        if buffer is not None and tid == session.tid:
            if ts - session.start > self.timeout:
                return _join(self._abandon(session, Problem.TIMEOUT, can_id, data, ts), None)
            if tail & TOGGLE != session.toggle:
                if data == session.last:
                    return self._problem(Problem.DUPLICATE_FRAME, can_id, data, ts, "frame again")
                return _join(self._abandon(session, Problem.TOGGLE_ERROR, can_id, data, ts), None)
            if not tail & END_OF_TRANSFER and len(data) != 8:
                return _join(
                    self._abandon(session, Problem.MALFORMED_FRAME, can_id, data, ts), None
                )
            if len(buffer) + len(data) > session.limit:
                return _join(
                    self._abandon(session, Problem.PAYLOAD_TOO_LONG, can_id, data, ts), None
                )
            buffer += data[:-1]
            session.last = data
            if not tail & END_OF_TRANSFER:
                session.toggle ^= TOGGLE
                return None
            return self._complete(session, can_id, data, tid)
        if data == session.last:
            return self._problem(Problem.DUPLICATE_FRAME, can_id, data, ts, "frame again")
        if self._recent(session, tid, ts):
            return None
        # A frame of a transfer whose first frame was not seen. Only this transfer id is
        # remembered; it does not change which transfer ids are accepted next.
        session.closed = tid + _LOST
        session.closed_at = ts
        if buffer is None:
            session.tid = -1
        self._touch(can_id & 0xFFFFFF)
        return self._problem(Problem.MISSED_START, can_id, data, ts, f"transfer id {tid}")

    def _complete(self, session: _Session, can_id: int, data: Any, tid: int) -> Outcome:
        """The last frame of a multi-frame transfer arrived: check the CRC and decode."""
        buffer = session.buffer
        assert buffer is not None
        if session.counted and not self.strict:  # libcanard's rules: see `_receive`
            return self._complete_orphan(session, can_id, data, tid)
        payload = bytes(buffer[2:])
        crc = crc_hqx(payload, session.crc_seed)
        session.crc, session.carried = crc, buffer[0] | buffer[1] << 8
        if crc != buffer[0] | buffer[1] << 8:
            report = None
            if not session.counted:
                report = self._report(
                    Problem.CRC_MISMATCH,
                    can_id,
                    data,
                    session.start,
                    f"CRC {buffer[0] | buffer[1] << 8:#06x}, computed {crc:#06x}",
                )
            self._lost(session, can_id, tid, session.start)
            return _join(report, None)
        session.buffer = None
        session.toggle = 0
        try:
            message = session.decode_payload(payload)
        except (*DECODE_FALLBACK, DecodeError):  # bad length or content: the checked path decides
            return self._deliver(session, can_id, payload, tid, session.start, session.counted)
        session.closed = tid
        session.tid = (tid + 1) & TRANSFER_ID_MASK
        session.counted = session.orphan = False
        self.transfers += 1
        return received(message, can_id, tid, session.start, session.kind, session.data_type_id)

    def _complete_orphan(self, session: _Session, can_id: int, data: Any, tid: int) -> Outcome:
        """libcanard's rules: the last frame of a payload not to deliver. One past its type's
        largest was reported already. One no first frame began is checked as libcanard
        does, against the CRC registers its state kept from before: it fails, unless they
        happen to match (an empty last frame right after a transfer that passed its CRC)."""
        payload = bytes(session.buffer or b"")
        base = session.crc
        session.crc = None if base is None or not session.orphan else crc_hqx(payload, base)
        if not session.orphan:
            self._lost(session, can_id, tid, session.start)
            return None
        if session.crc == session.carried:
            return self._deliver(session, can_id, payload, tid, session.start, False)
        report = self._report(Problem.CRC_MISMATCH, can_id, data, session.start, "no first frame")
        self._lost(session, can_id, tid, session.start)
        return Problems((report,), None)

    def _deliver(
        self, session: _Session, can_id: int, payload: Any, tid: int, ts: float, counted: bool
    ) -> Outcome:
        """Decode a complete payload through the checked path and deliver it."""
        try:
            message = session.codec.decode(payload)
        except DecodeError as error:
            report = None
            if not counted:
                report = self._report(Problem.BAD_PAYLOAD, can_id, payload, ts, str(error))
            self._lost(session, can_id, tid, ts)
            return _join(report, None)
        session.buffer = None
        session.toggle = 0
        session.counted = session.orphan = False
        session.closed = tid
        session.tid = (tid + 1) & TRANSFER_ID_MASK
        self.transfers += 1
        return received(message, can_id, tid, ts, session.kind, session.data_type_id)

    def expire(self, timestamp: float) -> int:
        """Drop sessions idle past the transfer-ID timeout at ``timestamp``.

        Incomplete transfers among them are counted as `TIMEOUT`. Call it now and then on
        a quiet bus to report transfers whose end never came. Sessions are examined
        oldest first and the examination stops at the first one still active, so it
        costs O(1) per session dropped; with timestamps that go backwards, a session may
        be dropped later than its own timestamps would allow.

        Returns:
            The number of sessions dropped.

        Raises:
            TypeError: ``timestamp`` is not a number.
        """
        return self._expire("Reassembler.expire", timestamp, [])

    def expire_reports(self, timestamp: float) -> list[ProblemReport]:
        """`expire`, returning the reports of the transfers lost (`TIMEOUT`), in order.

        Raises:
            TypeError: ``timestamp`` is not a number.
        """
        reports: list[ProblemReport] = []
        self._expire("Reassembler.expire_reports", timestamp, reports)
        return reports

    def _expire(self, function: str, timestamp: float, reports: list[ProblemReport]) -> int:
        """`expire`: the number of sessions dropped; the reports appended to ``reports``."""
        if not isinstance(timestamp, (int, float)) or isinstance(timestamp, bool):
            raise argument_type_error(function, "timestamp", "a float", timestamp)
        age, timeout, dropped = self._age, self.timeout, 0
        while age:
            key = next(iter(age))
            session = age[key]
            if timestamp - max(session.start, session.closed_at) <= timeout:
                break
            del age[key], self._sessions[key]
            dropped += 1
            if session.buffer is not None and not session.counted:
                reports.append(
                    self._report(Problem.TIMEOUT, key, b"", timestamp, f"transfer id {session.tid}")
                )
        return dropped
