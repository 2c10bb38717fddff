"""What `veronte4x monitor` shows: the latest of every message type per sender (sans-IO).

`MonitorState` takes decoded records and keeps, per stream (sender, message type and
channel: a node's NodeStatus on ``can0`` and on ``can1`` are two rows), the latest message,
the count, the rate over the stream's last complete intervals (`stream_rate`) and the
errors; and the arbiter's state from its Status and Score frames (Veronte Autopilot 4x
Software Manual, the arbiter's CAN messages). A record is only kept and counted: the
latest fields are shown for people (as `veronte4x.capture.readable.shown` gives them: enums
by name, units) when the table is asked for (`MonitorState.rows`), a few times a second
live, so that a full bus costs the reader no text. Each row also keeps its timing as
`veronte4x.capture.rates` counts a stream: usual period, jitter, longest gap, and the flags
``stopped`` (silent for more than 3 periods: a DroneCAN node whose NodeStatus is stopped is
offline) and ``slow``; the table shows them with ``rates=True`` (``monitor --rates``). Time
is the records' own timestamps, so a capture and a live bus give the same table; "now", for
the silence of a stream, is the latest timestamp unless the caller gives it. `render_text`
writes the table as plain text; the terminal view is drawn by the CLI.
"""

from __future__ import annotations

import math
from collections import deque
from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING, Any

from veronte4x.capture.busmap import AUTOPILOT_NAMES
from veronte4x.capture.rates import STOP_PERIODS, Stream
from veronte4x.capture.readable import can_id_text, format_message, hex_bytes, shown
from veronte4x.capture.records import Record
from veronte4x.codec import Score, Status
from veronte4x.words import counted

if TYPE_CHECKING:
    from veronte4x.capture.readers.live import BusLoss

RATE_WINDOW = 2.0
"""Seconds over which a row's rate is counted (`stream_rate`)."""


def stream_rate(times: Sequence[float], now: float, window: float = RATE_WINDOW) -> float:
    """A stream's records per second over its complete intervals, never diluted by time
    before the stream's first record or after its last.

    The intervals are those between the stream's records in the ``window`` seconds up to
    ``now``: their count over the time they span. With fewer than two records in the window
    (a stream slower than it, such as the arbiter's Scores every 3 s), the stream's last
    interval, while the stream has been silent for at most `STOP_PERIODS` of it; else 0.

    Args:
        times: The stream's timestamps, in order (at least its last two, and those of the
            window).
        now: The end of the window: the latest timestamp, or a live bus's time now.
        window: Seconds.

    Examples:
        >>> stream_rate([0.0, 0.2, 0.4], now=0.4)  # 5 Hz, 0.4 s into the capture
        5.0
        >>> stream_rate([0.0, 3.0], now=4.0), stream_rate([0.0, 3.0], now=13.0)
        (0.3333333333333333, 0.0)
    """
    recent = [t for t in times if now - window < t <= now]
    if len(recent) >= 2 and recent[-1] > recent[0]:
        return (len(recent) - 1) / (recent[-1] - recent[0])
    if len(times) >= 2:
        last = times[-1] - times[-2]
        if last > 0 and now - times[-1] <= STOP_PERIODS * last:
            return 1 / last
    return 0.0


def fields_text(message: Any) -> str:
    """A message's fields as people read them, with units: ``voltage=25.2 V, rpm=1200 rpm``.

    The same text as `veronte4x.capture.readable.format_message`, without the class name.
    """
    text = format_message(message)
    return text[len(type(message).__name__) + 1 : -1]


def rate_text(rate: float) -> str:
    """A rate in records per second, to one decimal."""
    return str(round(rate, 1))


@dataclass(frozen=True, slots=True)
class Row:
    """One line of the monitor.

    Attributes:
        sender: Who sent it (``AP1``, ``arbiter``, ``node 21``, ...).
        kind: The message class name.
        channel: The interface it came on.
        can_id: The CAN ID it came on last.
        count: Records of this type from this sender.
        errors: Bad frames on this sender's CAN ID since this type was first decoded there.
        rate: Records per second over the stream's last complete intervals
            (`stream_rate`).
        fields: The latest message's fields, as people read them (`fields_text`).
        last_seen: Timestamp of the latest one.
        period: Usual (median) period in seconds, to 1/64 octave (NaN below 2 records).
        jitter: Standard deviation of the periods, in seconds (NaN below 3 records).
        longest_gap: Longest period, in seconds.
        flags: ``stopped`` (silent for more than 3 periods), ``slow`` (its recent rate
            under half its usual one); see `veronte4x.capture.rates`.
        extended: Whether ``can_id`` is a 29-bit ID (`veronte4x.capture.Record.extended`),
            shown with 8 hex digits as candump shows it.
    """

    sender: str
    kind: str
    channel: str
    can_id: int
    count: int
    errors: int
    rate: float
    fields: str
    last_seen: float | None
    period: float = math.nan
    jitter: float = math.nan
    longest_gap: float = 0.0
    flags: tuple[str, ...] = ()
    extended: bool = False


@dataclass
class _Entry:
    can_id: int
    extended: bool
    count: int = 0
    errors: int = 0
    latest: object = None  # the latest message, or undecoded traffic's bytes; None: none yet
    last_seen: float | None = None
    times: deque[float] = field(default_factory=deque)
    timing: Stream = field(default_factory=Stream)


@dataclass(frozen=True, slots=True)
class ArbiterView:
    """The arbiter's latest Status and Scores.

    Attributes:
        status: The latest Status, or None.
        scores: The latest score of each autopilot (0 = AP1 .. 3 = external).
    """

    status: Status | None
    scores: tuple[tuple[int, float], ...]

    def describe(self) -> str:
        """One line: selected autopilot, arbitration, mode, alive and ready flags, scores."""
        parts = []
        status = self.status
        if status is None:
            parts.append("arbiter: no Status yet")
        else:
            mode = {None: "", True: ", normal mode", False: ", MAINTENANCE mode"}
            parts.append(
                f"arbiter: selected {AUTOPILOT_NAMES[status.selected]}, "
                f"arbitration {'on' if status.arbitrating else 'OFF'}" + mode[status.normal_mode]
            )
            for name, flags in (("alive", status.alive), ("ready", status.ready)):
                named = " ".join(AUTOPILOT_NAMES[i] if ok else "-" for i, ok in enumerate(flags))
                parts.append(f"{name} {named}")
        if self.scores:
            parts.append(
                "scores "
                + " ".join(
                    f"{AUTOPILOT_NAMES[a]} {shown(Score, 'score', s)}" for a, s in self.scores
                )
            )
        return "; ".join(parts)


class MonitorState:
    """The monitor's table, updated record by record.

    Args:
        rate_window: Seconds over which rates are counted.
        rates: Show each row's timing (period, jitter, longest gap, flags) in the table.
        loss: What the bus layer of a live bus dropped, for the summary (kept up to date
            by its reader, `veronte4x.capture.readers.live.read_bus`).

    Examples:
        >>> from veronte4x import capture
        >>> state = MonitorState()
        >>> for record in capture.read("examples/capture.log"):
        ...     state.add(record)
        >>> [(r.sender, r.kind, r.count) for r in state.rows("score")]
        [('arbiter', 'Score', 3)]
    """

    def __init__(
        self,
        rate_window: float = RATE_WINDOW,
        rates: bool = False,
        loss: BusLoss | None = None,
    ) -> None:
        self.rate_window = rate_window
        self.rates = rates
        self.loss = loss
        self.records = 0
        self.errors = 0
        self.first_timestamp: float | None = None
        self.last_timestamp: float | None = None
        self._rows: dict[tuple[str, str, str], _Entry] = {}
        self._by_id: dict[tuple[str, str, int], tuple[str, str, str]] = {}
        self._status: Status | None = None
        self._scores: dict[int, float] = {}

    def add(self, record: Record) -> None:
        """Take one record."""
        self.records += 1
        stamp = record.timestamp
        if stamp is not None:
            if self.first_timestamp is None:
                self.first_timestamp = stamp
            if self.last_timestamp is None or stamp > self.last_timestamp:
                self.last_timestamp = stamp
        sender, channel = record.sender, record.channel
        if record.error is not None:
            self.errors += 1
            key = self._by_id.get(
                (sender, channel, record.can_id), (sender, f"error: {record.error}", channel)
            )
            entry = self._entry(key, record)
            entry.errors += 1
            return
        message = record.message
        if message is None:  # foreign traffic: a row per what it is, its bytes as decode shows
            key = (sender, record.detail or "undecoded", channel)
        else:
            key = (sender, type(message).__name__, channel)
        entry = self._entry(key, record)
        self._by_id[(sender, channel, record.can_id)] = key
        if entry.can_id != record.can_id:
            entry.can_id = record.can_id
            entry.extended = record.extended
        entry.count += 1
        entry.latest = record.data if message is None else message  # shown by `rows`
        entry.last_seen = stamp
        if stamp is not None:
            if not entry.timing.count or stamp >= entry.timing.last:
                entry.timing.add(stamp)
            if not entry.times or stamp >= entry.times[-1]:
                entry.times.append(stamp)
            while len(entry.times) > 2 and entry.times[0] <= stamp - self.rate_window:
                entry.times.popleft()
        if isinstance(message, Status):
            self._status = message
        elif isinstance(message, Score):
            self._scores[message.autopilot] = message.score

    def _entry(self, key: tuple[str, str, str], record: Record) -> _Entry:
        """The row of ``key``, made for ``record`` if it is the first."""
        entry = self._rows.get(key)
        if entry is None:
            entry = self._rows[key] = _Entry(record.can_id, record.extended)
        return entry

    @property
    def arbiter(self) -> ArbiterView:
        """The arbiter's latest Status and Scores."""
        return ArbiterView(self._status, tuple(sorted(self._scores.items())))

    def rows(self, text_filter: str = "", now: float | None = None) -> list[Row]:
        """The rows by sender and type; only those whose sender or type contains the filter
        (any case). ``now`` (default: the latest timestamp) is when a stream's silence ends,
        for its ``stopped`` flag."""
        wanted = text_filter.lower()
        if now is None:
            now = self.last_timestamp
        rows = []
        for (sender, kind, channel), e in sorted(self._rows.items()):
            if wanted and wanted not in sender.lower() and wanted not in kind.lower():
                continue
            rate = 0.0 if now is None else stream_rate(e.times, now, self.rate_window)
            usual = e.timing.usual()
            rows.append(
                Row(
                    sender,
                    kind,
                    channel,
                    e.can_id,
                    e.count,
                    e.errors,
                    rate,
                    _fields(e.latest),
                    e.last_seen,
                    math.nan if usual is None else usual,
                    e.timing.jitter(),
                    e.timing.longest,
                    () if now is None else e.timing.flags(now),
                    e.extended,
                )
            )
        return rows

    def summary(self) -> str:
        """One line: records, errors, time span, and the frames the bus layer lost where
        it counts them."""
        span = ""
        if self.first_timestamp is not None and self.last_timestamp is not None:
            span = f", {round(self.last_timestamp - self.first_timestamp, 3)} s"
        lost = None if self.loss is None else self.loss.text()
        text = f"{counted(self.records, 'record')}, {self.errors} bad{span}"
        return text + (f", {lost}" if lost else "")


def _fields(latest: object) -> str:
    """A row's fields: the latest message's (`fields_text`), undecoded bytes in hex."""
    if latest is None:
        return ""
    return hex_bytes(latest) if type(latest) is bytes else fields_text(latest)


def seconds_text(value: float) -> str:
    """A duration to 3 significant digits, in µs, ms or s (``-`` for NaN): ``100 ms``."""
    if math.isnan(value):
        return "-"
    if value < 1e-3:
        return f"{value * 1e6:.3g} µs"
    return f"{value * 1000:.3g} ms" if value < 1 else f"{value:.3g} s"


def flags_text(flags: tuple[str, ...]) -> str:
    """A row's flags as the table shows them: ``STOPPED``, ``slow``."""
    return " ".join(flag.upper() if flag == "stopped" else flag for flag in flags)


TIMING_HEADS = ("period", "jitter", "gap", "state")
"""The timing columns of the table with ``rates``."""


def timing_texts(row: Row) -> tuple[str, str, str, str]:
    """A row's timing columns (`TIMING_HEADS`) as text; no gap without two timed records."""
    gap = "-" if math.isnan(row.period) else seconds_text(row.longest_gap)
    return seconds_text(row.period), seconds_text(row.jitter), gap, flags_text(row.flags)


def render_text(state: MonitorState, text_filter: str = "", now: float | None = None) -> str:
    """The monitor as plain text: the arbiter line, a summary, then one line per row (with
    its timing columns if the state shows rates); where the rows come on several channels,
    each sender is followed by its row's channel (``node 20 can1``)."""
    rows = state.rows(text_filter, now)
    lines = [state.arbiter.describe(), state.summary()]
    if len({r.channel for r in rows}) > 1:  # a stream per channel: say which
        rows = [replace(r, sender=f"{r.sender} {r.channel}") for r in rows]
    sender_width = max([len("sender"), *(len(r.sender) for r in rows)])
    kind_width = max([len("type"), *(len(r.kind) for r in rows)])
    timing: list[tuple[str, ...]] = [timing_texts(r) if state.rates else () for r in rows]
    heads = TIMING_HEADS if state.rates else ()
    widths = [max([len(head), *(len(t[i]) for t in timing)]) for i, head in enumerate(heads)]
    lines.append(
        f"{'sender':<{sender_width}}  {'type':<{kind_width}}  {'id':>8}  {'count':>7}  "
        f"{'rate/s':>7}  {_cells(heads, widths)}{'errors':>6}  fields"
    )
    for r, texts in zip(rows, timing, strict=True):
        columns = _cells(texts, widths)
        can_id = can_id_text(r.can_id, r.extended)
        line = (
            f"{r.sender:<{sender_width}}  {r.kind:<{kind_width}}  {can_id:>8}  "
            f"{r.count:>7}  {rate_text(r.rate):>7}  {columns}{r.errors:>6}  {r.fields}"
        )
        lines.append(line.rstrip())
    return "\n".join(lines) + "\n"


def _cells(texts: tuple[str, ...], widths: list[int]) -> str:
    return "".join(f"{text:>{width}}  " for text, width in zip(texts, widths, strict=True))
