"""Message rates, period jitter, gaps and bus load, from frames and their times (sans-IO).

Fed one frame at a time (its time, CAN ID and data: from a capture or a live bus, the
caller decides), a `RateTracker` keeps per stream (a CAN ID; a Veronte CAN ID's message
type, by its bytes 0 and 1; or a DroneCAN session: data type, source and destination node)
the count, rate, period jitter and longest gap, and per channel the bus load. It never
reads a clock: `RateTracker.streams` takes the time "now".

Bus load counts every frame's bits over the span of every frame (data, remote, CAN FD and
error frames), with the usual worst-case bit-stuffing estimate of Davis, Burns, Bril and
Lukkien, "Controller Area Network (CAN) schedulability analysis: Refuted, revisited and
revised", Real-Time Systems 35 (2007), equation (2): ``floor((n - 1) / 4)`` stuff bits for
the ``n`` bits the stuffing rule covers.

- A classic frame: ``g + 8s + 13 + floor((g + 8s - 1) / 4)`` bits for ``s`` data bytes,
  with ``g`` = 34 for an 11-bit ID and 54 for a 29-bit one (the 13 are the CRC delimiter,
  ACK, end of frame and interframe space, which are not stuffed). A frame of 8 bytes with
  an 11-bit ID counts 135 bits; the same frame without stuffing 111 (`frame_bits`).
- A remote frame: a classic frame with no data field (``s`` = 0, whatever its DLC asks):
  55 bits with an 11-bit ID, 80 with a 29-bit one.
- A CAN FD frame (ISO 11898-1:2015, ISO CAN FD; `fd_frame_bits`), its data padded to the
  next length a DLC gives (12, 16, 20, 24, 32, 48, 64): the arbitration phase (start of
  frame to BRS: 17 bits with an 11-bit ID, 36 with a 29-bit one) and the 13 bits from the
  CRC delimiter to the interframe space go at the nominal bit rate; the data phase (ESI,
  DLC, data, the 4-bit stuff count, the CRC: 17 bits for up to 16 data bytes, 21 above, and
  its fixed stuff bits: one before the stuff count and one after every 4 bits, 6 with
  CRC-17 and 7 with CRC-21) at the data bit rate where BRS is set, at the nominal one where
  it is not. Dynamic stuffing covers start of frame to the end of the data (the CRC has
  the fixed stuff bits instead); its worst-case stuff bits go with the phase of their bits.
  8 bytes with an 11-bit ID: 34 bits in the arbitration phase and 113 in the data phase
  (CRC and fixed stuff bits as Vector's "CAN FD" e-learning and CiA's "Cyclic redundancy
  check (CRC) in CAN frames" describe them).
- An error frame: `ERROR_FRAME_BITS`.

The bit rate, unless given, is the lowest standard one at which the closest two frames fit
(a receiver stamps a frame once it is whole, so two frames are at least the second one's
unstuffed bits apart; the data phase of a CAN FD frame with BRS takes its time at the data
bit rate if given, none if not; error frames, stamped wherever a controller reports them,
are left out); `BusLoad.reason` says
why none was found.

A stream is flagged ``stopped`` when it has been silent for more than 3 of its periods (its
usual one, or its cycle if longer: the longest of its last 16 periods that another of
them matches within 10 %, which is the cycle of a stream that comes in bursts; a
DroneCAN node whose NodeStatus is silent that long is offline: the DroneCAN data type
``uavcan.protocol.NodeStatus`` sets OFFLINE_TIMEOUT_MS = 3000 for MAX_BROADCASTING_PERIOD_MS
= 1000), ``slow``
when its last 16 periods run at under half its usual rate, and counts its ``gaps`` (periods
longer than 3 usual ones).
"""

from __future__ import annotations

import itertools
import math
from collections import deque
from dataclasses import dataclass, field

from veronte4x.capture.busmap import AUTOPILOT_NAMES, BusMap, Role
from veronte4x.capture.dbc import command_names
from veronte4x.capture.readable import can_id_text
from veronte4x.dronecan.can_id import TransferKind, parse_can_id
from veronte4x.dronecan.definitions import DATA_TYPES

STANDARD_BITRATES = (125_000, 250_000, 500_000, 1_000_000)
"""The bit rates `detect_bitrate` chooses from."""

STOP_PERIODS = 3
"""A stream silent for more than this many periods has stopped; a longer period is a gap."""

SLOW_FACTOR = 2.0
"""A stream whose recent period is this many times its usual one is slow."""

RECENT = 16
"""Periods that make a stream's recent rate."""

ERROR_FRAME_BITS = 23
"""Bits an error frame counts: the error flag at its longest (6 dominant bits, up to 12
where other nodes' flags follow the first one's), the 8-bit error delimiter and the 3-bit
intermission (ISO 11898-1:2015). A log does not say where the error broke off a frame, so
the bits sent before it are not counted."""

FD_LENGTHS = (0, 1, 2, 3, 4, 5, 6, 7, 8, 12, 16, 20, 24, 32, 48, 64)
"""The data lengths a CAN FD DLC gives."""

_BINS_PER_OCTAVE = 64
_MIN_PERIOD = 1e-6
_NAMES = {(t.kind, t.data_type_id): t.full_name for t in DATA_TYPES}


def frame_bits(data_bytes: int, extended: bool, stuffing: bool = True) -> int:
    """Bits a classic CAN frame takes on the bus, interframe space included.

    Args:
        data_bytes: 0..8.
        extended: A 29-bit ID.
        stuffing: Count the worst-case stuff bits (Davis et al. 2007, equation (2)).
    """
    g = 54 if extended else 34
    bits = g + 8 * data_bytes + 13
    return bits + (g + 8 * data_bytes - 1) // 4 if stuffing else bits


def fd_frame_bits(data_bytes: int, extended: bool, stuffing: bool = True) -> tuple[int, int]:
    """Bits an ISO CAN FD frame takes on the bus, interframe space included: ``(nominal,
    data)``, the bits at the nominal bit rate and those of the data phase (see the module).

    Args:
        data_bytes: 0..64, padded to the next length a DLC gives.
        extended: A 29-bit ID.
        stuffing: Count the worst-case dynamic stuff bits (the fixed ones always count).
    """
    size = next(n for n in FD_LENGTHS if n >= min(data_bytes, 64))
    arbitration = 36 if extended else 17  # start of frame to BRS
    nominal = arbitration + 13  # and CRC delimiter, ACK slot and delimiter, EOF, intermission
    crc, fixed = (17, 6) if size <= 16 else (21, 7)
    data = 5 + 8 * size + 4 + crc + fixed  # ESI, DLC, data, stuff count, CRC
    if stuffing:
        first = (arbitration - 1) // 4
        nominal += first
        data += (arbitration + 5 + 8 * size - 1) // 4 - first
    return nominal, data


@dataclass
class Stream:
    """The timing of one stream, fed its times in order (see the module's rules).

    Attributes:
        label: What the stream is, as reports name it.
        channel: Interface name.
        count: Times fed.
        first: The first time (NaN before it).
        last: The latest time (NaN before it).
        longest: Longest period, in seconds.
        gaps: Periods longer than `STOP_PERIODS` usual ones.
    """

    label: str = ""
    channel: str = ""
    count: int = 0
    first: float = math.nan
    last: float = math.nan
    mean: float = 0.0  # of the periods (Welford)
    m2: float = 0.0
    longest: float = 0.0
    gaps: int = 0
    bins: dict[int, int] = field(default_factory=dict)  # log-binned periods, for the median
    sums: dict[int, float] = field(default_factory=dict)  # the periods of each bin, added
    recent: deque[float] = field(default_factory=lambda: deque(maxlen=RECENT))
    cached: float | None = None  # `usual`, refreshed every RECENT periods while counting

    def add(self, time: float) -> None:
        """Count one frame (or transfer, or record) at ``time`` seconds."""
        if self.count:
            period = time - self.last
            if self.count % RECENT == 1 or self.cached is None:
                self.cached = self.usual()
            usual = self.cached
            if usual is not None and period > STOP_PERIODS * usual:
                self.gaps += 1
            n = self.count  # periods so far + 1
            delta = period - self.mean
            self.mean += delta / n
            self.m2 += delta * (period - self.mean)
            self.longest = max(self.longest, period)
            key = _bin(period)
            self.bins[key] = self.bins.get(key, 0) + 1
            self.sums[key] = self.sums.get(key, 0.0) + period
            self.recent.append(period)
        else:
            self.first = time
        self.count += 1
        self.last = time

    def usual(self) -> float | None:
        """The median period (to 1/64 octave: the mean of the periods in the median's
        bin), or None before the first."""
        total = sum(self.bins.values())
        if not total:
            return None
        seen = 0
        for key in sorted(self.bins):
            seen += self.bins[key]
            if 2 * seen >= total:
                return self.sums[key] / self.bins[key]
        raise AssertionError("unreachable")  # pragma: no cover

    def rate(self) -> float:
        """Count per second over the stream's span (NaN below 2)."""
        periods, span = self.count - 1, self.last - self.first
        return periods / span if periods > 0 and span > 0 else math.nan

    def jitter(self) -> float:
        """Standard deviation of the periods, in seconds (NaN below 3 times)."""
        periods = self.count - 1
        return math.sqrt(self.m2 / (periods - 1)) if periods > 1 else math.nan

    def cycle(self) -> float:
        """The longest recent period that another recent one matches within 10 %: the
        cycle of a stream that comes in bursts, the period of a regular one; a single long
        gap is not a cycle (NaN before the first period)."""
        periods = sorted(self.recent, reverse=True)
        for longer, shorter in itertools.pairwise(periods):
            if shorter >= 0.9 * longer:
                return longer
        return periods[-1] if periods else math.nan

    def flags(self, now: float) -> tuple[str, ...]:
        """``stopped`` if silent at ``now`` for more than `STOP_PERIODS` periods (its usual
        one, or its `cycle` if longer); ``slow`` if its last `RECENT` periods run at under
        1/`SLOW_FACTOR` of its usual rate."""
        usual = self.usual()
        if usual is None or not self.recent:
            return ()
        recent = sorted(self.recent)[len(self.recent) // 2]
        flags = []
        # Stopped against the current cycle: a slow stream is not stopped yet, nor one that
        # comes in bursts (three ArbitrationVariables 0.1 ms apart every 20 ms: its median
        # period is the 0.1 ms, its cycle the 20 ms).
        if now - self.last > STOP_PERIODS * max(usual, self.cycle()):
            flags.append("stopped")
        if len(self.recent) == RECENT and recent > SLOW_FACTOR * usual:
            flags.append("slow")
        return tuple(flags)


def _bin(period: float) -> int:
    return math.floor(math.log2(max(period, _MIN_PERIOD)) * _BINS_PER_OCTAVE)


@dataclass(frozen=True, slots=True)
class StreamRate:
    """What `RateTracker.streams` reports of one stream.

    Attributes:
        channel: Interface name.
        label: The stream: ``arbiter 0x0FF``, ``0x123``, or a DroneCAN session
            (``uavcan.protocol.NodeStatus from node 20``).
        count: Frames, or DroneCAN transfers.
        rate: Count per second over the stream's span (NaN below 2).
        period: Usual (median) period in seconds, to 1/64 octave (NaN below 2).
        jitter: Standard deviation of the periods, in seconds (NaN below 3).
        longest_gap: Longest period, in seconds (0 below 2).
        silent: Seconds since the stream's last frame, at the time asked.
        gaps: Periods longer than 3 usual ones.
        flags: ``stopped`` (silent > 3 periods), ``slow`` (recent rate < half the usual).
    """

    channel: str
    label: str
    count: int
    rate: float
    period: float
    jitter: float
    longest_gap: float
    silent: float
    gaps: int
    flags: tuple[str, ...]


@dataclass(frozen=True, slots=True)
class BusLoad:
    """One channel's bus load.

    Attributes:
        channel: Interface name.
        frames: Frames counted, of every kind.
        bits: Their bits, worst-case stuffing included (see the module).
        seconds: From the first frame to the last.
        bitrate: Bit rate in bit/s (given, or detected: `detect_bitrate`), or None.
        detected: The bit rate was detected rather than given.
        percent: The time the bits take (``data_bits`` at ``data_bitrate``, the others at
            ``bitrate``) over ``seconds``, x 100; NaN without a bit rate or a span.
        data_bits: Of ``bits``, those of CAN FD data phases with BRS.
        data_bitrate: The CAN FD data bit rate in bit/s, if given.
        reason: Why ``percent`` is NaN, for a person (empty when it is not).
    """

    channel: str
    frames: int
    bits: int
    seconds: float
    bitrate: int | None
    detected: bool
    percent: float
    data_bits: int = 0
    data_bitrate: int | None = None
    reason: str = ""


class RateTracker:
    """Per-stream rates and per-channel bus load, fed frames and their times.

    Args:
        bus_map: Tells Veronte IDs (labelled by role) and DroneCAN frames (grouped by
            session, counted per transfer) from the rest.
        bitrate: The bus bit rate in bit/s; None detects it per channel.
        data_bitrate: The CAN FD data bit rate in bit/s, for the data phase of frames with
            BRS; None leaves the load of a channel with such frames unknown.
    """

    def __init__(
        self,
        bus_map: BusMap | None = None,
        bitrate: int | None = None,
        data_bitrate: int | None = None,
    ) -> None:
        self.bus_map = bus_map or BusMap()
        self.bitrate = bitrate
        self.data_bitrate = data_bitrate
        self._streams: dict[tuple[str, tuple[int, ...], bool], Stream] = {}
        self._bits: dict[str, int] = {}
        self._data_bits: dict[str, int] = {}
        self._frames: dict[str, int] = {}
        self._span: dict[str, tuple[float, float]] = {}
        # The highest bit rate two close frames imply, and those frames' distance.
        self._needed: dict[str, tuple[float, float]] = {}
        self._previous: dict[str, float] = {}
        self._commands = command_names(self.bus_map.layouts)

    def add(
        self,
        time: float,
        can_id: int,
        data: bytes,
        extended: bool = False,
        channel: str = "",
        *,
        remote: bool = False,
        fd: bool = False,
        brs: bool = False,
        error: bool = False,
    ) -> None:
        """Count one frame seen at ``time`` seconds: a data frame (0..8 bytes; 0..64 with
        ``fd``, CAN FD, its data phase at the data bit rate with ``brs``), a remote frame
        (no data field) or an error frame. Remote and error frames count in the bus load
        only, not in any stream."""
        phase_seconds = 0.0  # the least time a data phase at the data bit rate takes
        if error:
            bits, data_bits, unstuffed = ERROR_FRAME_BITS, 0, 0
        elif fd:
            nominal, phase = fd_frame_bits(len(data), extended)
            bare_nominal, bare_phase = fd_frame_bits(len(data), extended, stuffing=False)
            bits, data_bits = nominal + phase, phase if brs else 0
            unstuffed = bare_nominal if brs else bare_nominal + bare_phase
            if brs and self.data_bitrate:
                phase_seconds = bare_phase / self.data_bitrate
        else:
            size = 0 if remote else min(len(data), 8)
            bits, data_bits = frame_bits(size, extended), 0
            unstuffed = frame_bits(size, extended, stuffing=False)
        self._bits[channel] = self._bits.get(channel, 0) + bits
        if data_bits:
            self._data_bits[channel] = self._data_bits.get(channel, 0) + data_bits
        self._frames[channel] = self._frames.get(channel, 0) + 1
        first, _ = self._span.get(channel, (time, time))
        self._span[channel] = (min(first, time), time)
        if not error:
            self._close(channel, time, unstuffed, phase_seconds)
        if not (remote or error):
            self._stream(time, can_id, data, extended, channel)

    def _close(self, channel: str, time: float, unstuffed: int, phase_seconds: float) -> None:
        """Keep the bit rate the frame at ``time`` and the one before imply: its
        ``unstuffed`` bits at the nominal rate, after a data phase of ``phase_seconds``."""
        previous = self._previous.get(channel)
        if previous is not None and time > previous:
            # A receiver stamps a frame once it is whole: two frames cannot be closer than
            # the second one's bits without stuffing.
            left = time - previous - phase_seconds
            needed = unstuffed / left if left > 0 else math.inf
            if needed > self._needed.get(channel, (0.0, 0.0))[0]:
                self._needed[channel] = (needed, time - previous)
        self._previous[channel] = time

    def _stream(self, time: float, can_id: int, data: bytes, extended: bool, channel: str) -> None:
        """Count a data frame in its stream."""
        role, _ = self.bus_map.role(can_id, extended)
        key: tuple[int, ...] = (can_id,)
        if role is Role.DRONECAN:
            if not data or not data[-1] & 0x80:
                return  # not the first frame of a transfer: counted once, at its start
            key = (_session(can_id),)
        elif role in (Role.ARBITER, Role.AUTOPILOT) and data:
            # One CAN ID carries several Veronte message types, each at its own rate.
            key = (can_id, data[0], data[1] if not data[0] and len(data) > 1 else -1)
        stream = self._streams.get((channel, key, extended))
        if stream is None:
            stream = Stream(self._label(can_id, extended, role, key), channel)
            self._streams[(channel, key, extended)] = stream
        stream.add(time)

    def _label(self, can_id: int, extended: bool, role: Role, key: tuple[int, ...]) -> str:
        label = _label(self.bus_map, can_id, extended, role)
        if len(key) == 1:
            return label
        _, command, header = key
        if command:
            name = self._commands.get(command, f"command {command}")
        elif role is Role.ARBITER:
            name = "Status" if header == 0xFF else f"Score {header}"
        else:
            name = "Ready" if header == 0xFF else f"ArbitrationVariable {header}"
        return f"{label} {name}"

    def streams(self, now: float | None = None) -> list[StreamRate]:
        """Every stream's figures, by channel and label; ``now`` defaults to the last frame."""
        out = []
        end = max((last for _, last in self._span.values()), default=math.nan)
        now = end if now is None else now
        for stream in self._streams.values():
            usual = stream.usual()
            out.append(
                StreamRate(
                    stream.channel,
                    stream.label,
                    stream.count,
                    stream.rate(),
                    usual if usual is not None else math.nan,
                    stream.jitter(),
                    stream.longest,
                    now - stream.last,
                    stream.gaps,
                    stream.flags(now),
                )
            )
        return sorted(out, key=lambda s: (s.channel, s.label))

    def load(self) -> list[BusLoad]:
        """Each channel's bus load over its frames' span."""
        out = []
        for channel, bits in sorted(self._bits.items()):
            first, last = self._span[channel]
            seconds = last - first
            data_bits = self._data_bits.get(channel, 0)
            bitrate, detected = self.bitrate, self.bitrate is None
            if detected:
                needed = self._needed.get(channel)
                bitrate = None if needed is None else detect_bitrate(needed[0])
            percent, reason = math.nan, ""
            if bitrate is None:
                reason = self._undetected(channel)
            elif data_bits and self.data_bitrate is None:
                reason = "CAN FD frames with BRS: data bit rate unknown; give --data-bitrate"
            elif seconds <= 0:
                reason = "no time between the first frame and the last"
            else:
                busy = (bits - data_bits) / bitrate
                if self.data_bitrate is not None:
                    busy += data_bits / self.data_bitrate
                percent = 100 * busy / seconds
            out.append(
                BusLoad(
                    channel,
                    self._frames[channel],
                    bits,
                    seconds,
                    bitrate,
                    detected,
                    percent,
                    data_bits,
                    self.data_bitrate,
                    reason,
                )
            )
        return out

    def _undetected(self, channel: str) -> str:
        """Why no bit rate was detected on the channel, and what to do."""
        if channel not in self._needed:
            return "no two frames at different times to detect it from; give --bitrate"
        _, apart = self._needed[channel]
        return (
            f"frames {_microseconds(apart)} apart: faster than any standard bit rate; "
            "give --bitrate"
        )


def detect_bitrate(needed: float) -> int | None:
    """The smallest standard bit rate at or above ``needed`` bit/s (what the closest frames
    imply), or None if even 1 Mbit/s is too slow (timestamps not precise enough)."""
    return next((rate for rate in STANDARD_BITRATES if rate >= needed), None)


def _microseconds(seconds: float) -> str:
    return f"{seconds * 1e6:.3g} µs"


def _session(can_id: int) -> int:
    """A DroneCAN session key: the CAN ID without its priority."""
    return can_id & 0xFFFFFF


def _label(bus_map: BusMap, can_id: int, extended: bool, role: Role) -> str:
    ident = can_id_text(can_id, extended)
    if role is Role.ARBITER:
        return f"arbiter {ident}"
    if role is Role.AUTOPILOT:
        _, index = bus_map.role(can_id, extended)
        return f"{AUTOPILOT_NAMES[index or 0]} {ident}"
    if role is not Role.DRONECAN:
        return ident
    parsed = parse_can_id(can_id)
    name = _NAMES.get((parsed.kind, parsed.data_type_id), f"DroneCAN type {parsed.data_type_id}")
    if parsed.kind is TransferKind.MESSAGE:
        return f"{name} from node {parsed.source_node_id}"
    kind = "request" if parsed.kind is TransferKind.REQUEST else "response"
    return f"{name} {kind} {parsed.source_node_id}->{parsed.destination_node_id}"
