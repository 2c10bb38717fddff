"""Sans-IO reassembly of DroneCAN transfers from a stream of frames.

One receiver state ("session") per transfer descriptor: source node, destination node,
data type and kind, i.e. the CAN ID without its priority bits. The state update follows
the non-redundant pseudocode of spec 4.1 "Reception": a start frame restarts the session
when it is uninitialised, when the transfer-ID timeout (2 s after the first frame of the
last transfer, by the frames' own timestamps) has passed, or when its transfer id is
neither the expected one nor the previous one; frames with the wrong toggle or transfer id
are ignored. Time comes only from the ``timestamp`` argument; nothing reads a clock.

Problems never raise. Each is counted in `counts` and recorded as a
`ProblemReport` in the bounded `problems`. A transfer that
started or was seen but never came out is counted exactly once, under the first problem
that broke it; the rest of its frames are dropped silently.
"""

from __future__ import annotations

import enum
from binascii import crc_hqx  # the transfer CRC, see veronte4x.dronecan.crc
from collections import deque
from typing import Any, NamedTuple

from veronte4x.dronecan.can_id import TransferKind
from veronte4x.dronecan.codec import BY_ID, Codec
from veronte4x.dronecan.transfer import Transfer
from veronte4x.errors import DecodeError

TRANSFER_ID_TIMEOUT = 2.0
"""Transfer-ID timeout in seconds (spec 4.1 "State variables")."""


class Problem(enum.Enum):
    """What went wrong with a frame or a transfer; the value says it in words.

    The members in `TRANSFER_PROBLEMS` mean a transfer was lost, and each lost
    transfer is counted once, under the first problem that hit it. The others mean a frame
    was ignored and nothing was lost.
    """

    MALFORMED_FRAME = (
        "Not a DroneCAN frame: no tail byte, more than 8 bytes, a CAN ID beyond 29 bits, a "
        "service with node id 0, a multi-frame anonymous frame, or a frame other than the "
        "last of a transfer with fewer than 8 bytes (which also loses that transfer)."
    )
    UNKNOWN_TYPE = "A frame of none of the eight types (counted per frame)."
    MISSED_START = "A frame of a transfer whose first frame was not seen."
    TOGGLE_ERROR = (
        "A toggle bit out of sequence that is not a repeat: a frame was lost or reordered; "
        "the transfer is dropped."
    )
    DUPLICATE_FRAME = "A repeat of the frame accepted just before; ignored."
    UNEXPECTED_TRANSFER_ID = (
        "A first frame with a transfer id already handled (a replayed transfer, or the late "
        "first frame of a transfer counted as MISSED_START); ignored."
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
"""Problems that lose a transfer (MALFORMED_FRAME also does when it hits one in progress)."""


class ProblemReport(NamedTuple):
    """One recorded problem: what, on which frame, when, and a detail in words."""

    problem: Problem
    can_id: int
    data: bytes
    timestamp: float
    detail: str


class _Session:
    """Receiver state of one transfer descriptor (spec 4.1 "State variables").

    Also holds what every transfer of the descriptor shares: its codec, kind, type id and
    destination.
    """

    __slots__ = (
        "buffer",
        "closed",
        "codec",
        "crc_seed",
        "data_type_id",
        "decode_frame",
        "decode_payload",
        "destination",
        "kind",
        "last",
        "limit",
        "start",
        "tid",
        "toggle",
    )

    def __init__(self, codec: Codec, can_id: int) -> None:
        self.codec = codec
        self.kind = codec.data_type.kind
        self.data_type_id = codec.data_type.data_type_id
        self.destination = (can_id >> 8) & 0x7F if can_id & 0x80 else None
        self.decode_frame = codec.fast.decode_frame if codec.fast else None
        self.decode_payload = codec.fast.decode if codec.fast else codec.decode
        self.crc_seed = codec.crc_seed
        self.limit = codec.max_payload + 3  # CRC and tail byte included
        self.tid = 0  # transfer id expected next, or in progress
        self.toggle = 0  # expected toggle bit (0 or 0x20)
        self.start = -float("inf")  # timestamp of the first frame of the latest transfer
        self.buffer: bytearray | None = None  # payload so far (CRC first), None when idle
        self.last = b""  # the frame accepted last
        self.closed = -1  # transfer id of the transfer that ended last, or -1


_new_tuple = tuple.__new__
_MESSAGES = {dtid: c for (kind, dtid), c in BY_ID.items() if kind is TransferKind.MESSAGE}
_SERVICES = {
    dtid << 1 | (kind is TransferKind.REQUEST): c
    for (kind, dtid), c in BY_ID.items()
    if kind is not TransferKind.MESSAGE
}


class Reassembler:
    """Turn a stream of frames into checked, decoded transfers.

    Args:
        transfer_id_timeout: Seconds after the first frame of a transfer after which its
            session restarts (spec: 2 s).
        max_sessions: Most receiver states kept; beyond, timed-out sessions are dropped,
            then the oldest. Memory is bounded by this times the largest payload (378 B).
        max_reports: How many recent `ProblemReport` entries `problems` keeps.

    Attributes:
        counts: Number of each `Problem` so far.
        problems: The most recent problem reports, oldest first.
        reported: Number of problem reports so far; the reports of one `feed` are the
            last ``reported - before`` entries of `problems` (up to its length).
        transfers: Number of transfers delivered.
    """

    def __init__(
        self,
        transfer_id_timeout: float = TRANSFER_ID_TIMEOUT,
        max_sessions: int = 1024,
        max_reports: int = 256,
    ) -> None:
        self.timeout = transfer_id_timeout
        self.max_sessions = max_sessions
        self.counts: dict[Problem, int] = dict.fromkeys(Problem, 0)
        self.problems: deque[ProblemReport] = deque(maxlen=max_reports)
        self.reported = 0
        self.transfers = 0
        self._sessions: dict[int, _Session] = {}

    @property
    def session_count(self) -> int:
        """Number of receiver states held now."""
        return len(self._sessions)

    def _report(
        self, problem: Problem, can_id: int, data: Any, timestamp: float, detail: str
    ) -> None:
        self.counts[problem] += 1
        self.reported += 1
        self.problems.append(ProblemReport(problem, can_id, bytes(data), timestamp, detail))

    def feed(self, can_id: int, data: bytes, timestamp: float) -> Transfer | None:
        """Take one frame; return the transfer it completes, else None.

        Args:
            can_id: The 29-bit extended CAN ID.
            data: The frame's data bytes, tail byte last.
            timestamp: Reception time in seconds, from any monotonic source.
        """
        # Fast paths: the next frame of a known session, in order, nothing unusual. Any
        # other case goes to _feed, which redoes the full state update (nothing changed yet).
        # Frame lengths: decode_frame checks a single frame's exact length itself.
        try:
            session = self._sessions[can_id & 0xFFFFFF]
            tail = data[-1]
            tid = tail & 0x1F
        except (KeyError, TypeError, IndexError):  # new session, not an int, no tail byte
            return self._feed(can_id, data, timestamp)
        if can_id >> 29 or tid != session.tid or timestamp - session.start > self.timeout:
            return self._feed(can_id, data, timestamp)
        buffer = session.buffer
        if buffer is None:
            if tail & 0xE0 == 0xC0 and session.decode_frame is not None:  # single frame
                try:
                    message = session.decode_frame(data)
                except Exception:
                    return self._feed(can_id, data, timestamp)
                session.tid = (tid + 1) & 0x1F
                session.closed = tid
                session.start = timestamp
                session.last = data
                self.transfers += 1
                return _new_tuple(
                    Transfer,
                    (
                        message,
                        can_id & 0x7F,
                        session.destination,
                        can_id >> 24,
                        tid,
                        timestamp,
                        session.kind,
                        session.data_type_id,
                    ),
                )
            if tail & 0xE0 == 0x80 and len(data) == 8:  # first frame of several
                session.buffer = bytearray(data[:-1])
                session.toggle = 0x20
                session.start = timestamp
                session.last = data
                return None
        elif (
            tail & 0xA0 == session.toggle
            and (len(data) == 8 or (tail & 0x40 and len(data) <= 8))
            and len(buffer) + len(data) <= session.limit
        ):
            buffer += data[:-1]
            session.last = data
            if not tail & 0x40:
                session.toggle ^= 0x20
                return None
            return self._complete(session, can_id, data, tid)
        return self._feed(can_id, data, timestamp)

    def _feed(self, can_id: int, data: bytes, timestamp: float) -> Transfer | None:
        """The full state update of spec 4.1 with every check."""
        try:
            size = len(data)
            if not 0 < size <= 8 or not 0 <= can_id <= 0x1FFFFFFF:
                self._report(
                    Problem.MALFORMED_FRAME,
                    can_id,
                    data[:64],
                    timestamp,
                    f"{size} data bytes, CAN ID {can_id!r}",
                )
                return None
            tail = data[-1]
        except TypeError:
            self._report(Problem.MALFORMED_FRAME, -1, b"", timestamp, "not a frame")
            return None
        if can_id & 0x80:
            codec = _SERVICES.get((can_id >> 15) & 0x1FF)
            if not can_id & 0x7F or not can_id & 0x7F00:
                self._report(Problem.MALFORMED_FRAME, can_id, data, timestamp, "node id 0")
                return None
        elif can_id & 0x7F:
            codec = _MESSAGES.get((can_id >> 8) & 0xFFFF)
        else:
            if tail & 0xC0 != 0xC0:
                self._report(
                    Problem.MALFORMED_FRAME, can_id, data, timestamp, "multi-frame anonymous"
                )
            else:
                self._report(Problem.UNKNOWN_TYPE, can_id, data, timestamp, "anonymous message")
            return None
        if codec is None:
            self._report(Problem.UNKNOWN_TYPE, can_id, data, timestamp, "unknown data type")
            return None
        session = self._sessions.get(can_id & 0xFFFFFF)
        if session is None:
            session = self._new_session(codec, can_id, timestamp)
        tid = tail & 0x1F
        timed_out = timestamp - session.start > self.timeout
        if timed_out or (tail & 0x80 and (session.tid - tid) & 0x1F > 1):
            late_start = not timed_out and tid == session.closed
            if session.buffer is not None:
                problem = Problem.TIMEOUT if timed_out else Problem.INTERRUPTED
                self._abandon(session, problem, can_id, data, timestamp)
            if late_start:  # the first frame of a transfer already counted as MISSED_START
                session.closed = tid
                session.tid = (tid + 1) & 0x1F
                self._report(
                    Problem.UNEXPECTED_TRANSFER_ID, can_id, data, timestamp, "late first frame"
                )
                return None
            session.tid = tid
            session.toggle = 0
        if tail & 0x80:
            return self._start(session, codec, can_id, data, tail, timestamp)
        return self._continue(session, codec, can_id, data, tail, timestamp)

    def _new_session(self, codec: Codec, can_id: int, timestamp: float) -> _Session:
        if len(self._sessions) >= self.max_sessions:
            self.expire(timestamp)
            if len(self._sessions) >= self.max_sessions:
                oldest = min(self._sessions, key=lambda k: self._sessions[k].start)
                dropped = self._sessions.pop(oldest)
                if dropped.buffer is not None:
                    self._report(Problem.EVICTED, oldest, b"", timestamp, "session table full")
        session = self._sessions[can_id & 0xFFFFFF] = _Session(codec, can_id)
        return session

    def _abandon(
        self, session: _Session, problem: Problem, can_id: int, data: Any, timestamp: float
    ) -> None:
        self._report(problem, can_id, data, timestamp, f"transfer id {session.tid}")
        session.buffer = None
        session.closed = session.tid

    def _start(
        self, session: _Session, codec: Codec, can_id: int, data: Any, tail: int, ts: float
    ) -> Transfer | None:
        tid = tail & 0x1F
        if tid != session.tid:  # the previous transfer id: a repeat
            problem = (
                Problem.DUPLICATE_FRAME
                if data == session.last
                else (Problem.UNEXPECTED_TRANSFER_ID)
            )
            self._report(problem, can_id, data, ts, f"transfer id {tid} again")
            return None
        if session.buffer is not None:
            if data == session.last:
                self._report(Problem.DUPLICATE_FRAME, can_id, data, ts, "first frame again")
                return None
            self._abandon(session, Problem.INTERRUPTED, can_id, data, ts)
        if tail & 0x20:
            session.closed = tid
            self._report(Problem.TOGGLE_ERROR, can_id, data, ts, "toggle set on first frame")
            return None
        session.start = ts
        session.last = data
        if tail & 0x40:  # single-frame transfer
            session.tid = (tid + 1) & 0x1F
            session.closed = tid
            return self._deliver(codec, can_id, data[:-1], tid, ts)
        if len(data) != 8:
            session.closed = tid
            self._report(Problem.MALFORMED_FRAME, can_id, data, ts, "short first frame")
            return None
        session.buffer = bytearray(data[:-1])
        session.toggle = 0x20
        return None

    def _continue(
        self, session: _Session, codec: Codec, can_id: int, data: Any, tail: int, ts: float
    ) -> Transfer | None:
        tid = tail & 0x1F
        buffer = session.buffer
        if buffer is None or tid != session.tid:
            if data == session.last:
                self._report(Problem.DUPLICATE_FRAME, can_id, data, ts, "frame again")
            elif tid != session.closed:
                session.closed = tid
                if buffer is None:
                    # Spec: skip to the next transfer id. The timeout counts from this
                    # frame, so the late first frame of this transfer is not taken as new.
                    session.tid = (tid + 1) & 0x1F
                    session.start = ts
                self._report(Problem.MISSED_START, can_id, data, ts, f"transfer id {tid}")
            return None
        if tail & 0x20 != session.toggle:
            if data == session.last:
                self._report(Problem.DUPLICATE_FRAME, can_id, data, ts, "frame again")
            else:
                self._abandon(session, Problem.TOGGLE_ERROR, can_id, data, ts)
            return None
        if not tail & 0x40 and len(data) != 8:
            self._abandon(session, Problem.MALFORMED_FRAME, can_id, data, ts)
            return None
        buffer += data[:-1]
        if len(buffer) > codec.max_payload + 2:
            self._abandon(session, Problem.PAYLOAD_TOO_LONG, can_id, data, ts)
            return None
        session.last = data
        if not tail & 0x40:
            session.toggle ^= 0x20
            return None
        return self._complete(session, can_id, data, tid)

    def _complete(self, session: _Session, can_id: int, data: Any, tid: int) -> Transfer | None:
        """The last frame of a multi-frame transfer arrived: check the CRC and decode."""
        buffer = session.buffer
        assert buffer is not None
        session.buffer = None
        session.closed = tid
        session.tid = (tid + 1) & 0x1F
        payload = bytes(buffer[2:])
        crc = crc_hqx(payload, session.crc_seed)
        if crc != buffer[0] | buffer[1] << 8:
            self._report(
                Problem.CRC_MISMATCH,
                can_id,
                data,
                session.start,
                f"CRC {buffer[0] | buffer[1] << 8:#06x}, computed {crc:#06x}",
            )
            return None
        try:
            message = session.decode_payload(payload)
        except Exception:  # odd length or bad content: the checked path decides
            return self._deliver(session.codec, can_id, payload, tid, session.start)
        self.transfers += 1
        return _new_tuple(
            Transfer,
            (
                message,
                can_id & 0x7F,
                session.destination,
                can_id >> 24,
                tid,
                session.start,
                session.kind,
                session.data_type_id,
            ),
        )

    def _deliver(
        self, codec: Codec, can_id: int, payload: Any, tid: int, ts: float
    ) -> Transfer | None:
        try:
            message = codec.decode(payload)
        except DecodeError as error:
            self._report(Problem.BAD_PAYLOAD, can_id, payload, ts, str(error))
            return None
        self.transfers += 1
        data_type = codec.data_type
        if can_id & 0x80:
            destination: int | None = (can_id >> 8) & 0x7F
        else:
            destination = None
        return _new_tuple(
            Transfer,
            (
                message,
                can_id & 0x7F,
                destination,
                can_id >> 24,
                tid,
                ts,
                data_type.kind,
                data_type.data_type_id,
            ),
        )

    def resume(self, can_id: int, transfer_id: int, start: float, last: bytes) -> None:
        """Set a session's state as it is just after a transfer came out whole.

        For a stream whose earlier frames were reassembled elsewhere (the columnar engine
        hands a session over this way): the session of ``can_id`` then expects the next
        transfer id, times out from ``start`` and takes a repeat of ``last`` as a duplicate.

        Args:
            can_id: A CAN ID of the session (its priority bits are ignored).
            transfer_id: The transfer id of the transfer that came out last.
            start: The timestamp of that transfer's first frame.
            last: The data of its last frame.
        """
        if can_id & 0x80:
            codec = _SERVICES.get((can_id >> 15) & 0x1FF)
        else:
            codec = _MESSAGES.get((can_id >> 8) & 0xFFFF)
        if codec is None:
            raise ValueError(f"no DroneCAN type for CAN ID {can_id:#x}")
        session = self._sessions.get(can_id & 0xFFFFFF)
        if session is None:
            session = self._new_session(codec, can_id, start)
        session.buffer = None
        session.tid = (transfer_id + 1) & 0x1F
        session.closed = transfer_id
        session.start = start
        session.last = last
        session.toggle = 0

    def expire(self, timestamp: float) -> int:
        """Drop sessions idle past the transfer-ID timeout at ``timestamp``.

        Incomplete transfers among them are counted as `TIMEOUT`. Call it
        now and then on a quiet bus to report transfers whose end never came.

        Returns:
            The number of sessions dropped.
        """
        stale = [k for k, s in self._sessions.items() if timestamp - s.start > self.timeout]
        for key in stale:
            session = self._sessions.pop(key)
            if session.buffer is not None:
                self._report(Problem.TIMEOUT, key, b"", timestamp, f"transfer id {session.tid}")
        return len(stale)
