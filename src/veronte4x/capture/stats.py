"""Counts over a stream of records: per message type, per sender, undecoded traffic, errors."""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field

from veronte4x.capture.records import Record
from veronte4x.display import Cells, side_by_side, table
from veronte4x.times import format_time


@dataclass
class Stats:
    """Running counts of decoded records.

    Attributes:
        records: Records seen.
        by_type: Decoded records per message class name.
        by_sender: Records per sender (``arbiter``, ``AP1``, ``node 42``, ...).
        unknown: Undecoded foreign traffic per what it was (``11-bit CAN ID 0x123``,
            ``DroneCAN data type 1234``): normal on a shared bus, not errors.
        errors: Error records per kind (``decode error``, ``bad line``, ...).
        first_timestamp: Earliest timestamp seen, or None.
        last_timestamp: Latest timestamp seen, or None.
    """

    records: int = 0
    by_type: Counter[str] = field(default_factory=Counter)
    by_sender: Counter[str] = field(default_factory=Counter)
    unknown: Counter[str] = field(default_factory=Counter)
    errors: Counter[str] = field(default_factory=Counter)
    first_timestamp: float | None = None
    last_timestamp: float | None = None

    def add(self, record: Record) -> None:
        """Count one record."""
        self.records += 1
        if record.error is not None:
            self.errors[record.error] += 1
        elif record.message is None:
            self.unknown[record.detail] += 1
        else:
            self.by_type[type(record.message).__name__] += 1
        self.by_sender[record.sender] += 1
        stamp = record.timestamp
        if stamp is not None:
            if self.first_timestamp is None or stamp < self.first_timestamp:
                self.first_timestamp = stamp
            if self.last_timestamp is None or stamp > self.last_timestamp:
                self.last_timestamp = stamp

    def report(self) -> str:
        """The counts as a plain-text report."""
        lines = [
            f"records: {self.records}, undecoded: {sum(self.unknown.values())}, "
            f"errors: {sum(self.errors.values())}"
        ]
        if self.first_timestamp is not None and self.last_timestamp is not None:
            span = self.last_timestamp - self.first_timestamp
            first, last = format_time(self.first_timestamp), format_time(self.last_timestamp)
            lines.append(f"time: {first} to {last} ({round(span, 6)} s)")
        for title, counter in (
            ("by message type", self.by_type),
            ("by sender", self.by_sender),
            ("undecoded traffic", self.unknown),
            ("errors by kind", self.errors),
        ):
            lines.append(f"{title}:")
            lines += [f"  {name:<28} {count:>10}" for name, count in sorted(counter.items())]
            if not counter:
                lines.append("  (none)")
        return "\n".join(lines)

    def _repr_html_(self) -> str:
        """Jupyter's view: the counts as tables (`stats_html`)."""
        return stats_html(self)


def stats_html(stats: Stats) -> str:
    """Counts as HTML: the totals and the time span, then one table per non-empty count."""
    undecoded, errors = sum(stats.unknown.values()), sum(stats.errors.values())
    head: list[Cells] = [("records", stats.records), ("undecoded", undecoded), ("errors", errors)]
    if stats.first_timestamp is not None and stats.last_timestamp is not None:
        span = round(stats.last_timestamp - stats.first_timestamp, 6)
        head += [
            ("from", format_time(stats.first_timestamp)),
            ("to", format_time(stats.last_timestamp)),
            ("span", f"{span} s"),
        ]
    parts = [table("Stats", ("", ""), head, header=False)]
    for title, counter in (
        ("by message type", stats.by_type),
        ("by sender", stats.by_sender),
        ("undecoded traffic", stats.unknown),
        ("errors by kind", stats.errors),
    ):
        if counter:
            parts.append(table(title, ("", "count"), sorted(counter.items())))
    return side_by_side(parts)
