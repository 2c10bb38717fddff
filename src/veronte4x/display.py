"""Rich display in Jupyter: compact HTML for messages, records, stats, transfers and nodes.

A class gets Jupyter's ``_repr_html_`` by deriving from `HtmlDisplay` (a mixin with no
slots, so frozen slotted dataclasses keep their layout); named tuples, which take no mixin,
call `to_html` from a method of their own. Plain ``repr`` is unchanged. Values are shown as
the command line's text shows them (`veronte4x.capture.readable.shown`): enums by name,
floats in their shortest form at the field's declared width, text as text, other bytes in
hex, times in ISO 8601 (UTC), and a column of units where the protocol gives them.
Everything is HTML-escaped.

This module imports nothing of the library at import time: the codecs import it.

Examples:
    >>> from veronte4x import codec
    >>> html = to_html(codec.Score(autopilot=1, score=0.5))
    >>> html.startswith('<table class="dataframe veronte4x">'), "<td>score</td><td>0.5</td>" in html
    (True, True)
"""

from __future__ import annotations

import dataclasses
from collections.abc import Iterable, Sequence
from html import escape
from typing import Any


class HtmlDisplay:
    """Mixin that gives Jupyter a compact HTML view of the object (``_repr_html_``)."""

    __slots__ = ()

    def _repr_html_(self) -> str:
        return to_html(self)


Cells = tuple[Any, ...]
"""The cells of one table row, left to right."""


def to_html(value: Any) -> str:
    """The HTML view of a message, `Record`, `Stats`, DroneCAN `Transfer`, node table or node
    entry (anything else: its ``repr``, escaped)."""
    from veronte4x.capture.records import Record
    from veronte4x.capture.stats import Stats
    from veronte4x.client.nodes import NodeEntry, NodeTable
    from veronte4x.dronecan.transfer import Transfer

    if isinstance(value, Record):
        return _record(value)
    if isinstance(value, Transfer):
        return _transfer(value)
    if isinstance(value, Stats):
        return _stats(value)
    if isinstance(value, NodeTable):
        return _nodes(value.all(), "nodes")
    if isinstance(value, NodeEntry):
        return _nodes([value], f"node {value.node_id}")
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        return message_html(value)
    return f"<pre>{escape(repr(value))}</pre>"


def message_html(message: Any, caption: str | None = None) -> str:
    """A message's fields as a table: name, readable value and unit."""
    rows = [(name, text, symbol or "") for name, text, symbol in _fields(message)]
    return table(caption or type(message).__name__, ("field", "value", "unit"), rows)


def _fields(message: Any, top: str | None = None, prefix: str = "") -> list[Cells]:
    from veronte4x.capture.readable import shown
    from veronte4x.units import unit

    owner = type(message)
    top = top or owner.__name__
    rows: list[Cells] = []
    for field in dataclasses.fields(message):
        value = getattr(message, field.name)
        name = prefix + field.name
        if dataclasses.is_dataclass(value) and not isinstance(value, type):
            rows += _fields(value, top, name + ".")
        elif type(value) is tuple:
            items = ", ".join(str(shown(owner, field.name, item)) for item in value)
            rows.append((name, f"({items})", unit(top, name)))
        else:
            rows.append((name, shown(owner, field.name, value), unit(top, name)))
    return rows


def _record(record: Any) -> str:
    from veronte4x.times import format_time

    head: list[Cells] = [
        ("time", format_time(record.timestamp)),
        ("channel", record.channel),
        ("CAN ID", f"0x{record.can_id:X}"),
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


def _transfer(transfer: Any) -> str:
    from veronte4x.times import format_time

    head: list[Cells] = [
        ("kind", transfer.kind.name.lower()),
        ("data type id", transfer.data_type_id),
        ("from node", transfer.source_node_id),
    ]
    if transfer.destination_node_id is not None:
        head.append(("to node", transfer.destination_node_id))
    head += [
        ("priority", transfer.priority),
        ("transfer id", transfer.transfer_id),
        ("time", format_time(transfer.timestamp)),
    ]
    name = type(transfer.message).__name__
    return side_by_side(
        [table(f"Transfer: {name}", ("", ""), head, header=False), message_html(transfer.message)]
    )


def _stats(stats: Any) -> str:
    from veronte4x.times import format_time

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


def _nodes(entries: Iterable[Any], caption: str) -> str:
    from veronte4x.capture.readable import shown
    from veronte4x.times import format_time

    columns = (
        "node",
        "health",
        "mode",
        "sub-mode",
        "vendor code",
        "uptime (s)",
        "first seen",
        "last seen",
        "restarts",
    )
    rows = [
        (
            entry.node_id,
            shown(type(entry), "health", entry.health),
            shown(type(entry), "mode", entry.mode),
            entry.sub_mode,
            entry.vendor_specific_status_code,
            entry.uptime_sec,
            format_time(entry.first_seen),
            format_time(entry.last_seen),
            entry.restarts,
        )
        for entry in entries
    ]
    return table(caption, columns, rows)


_CAPTION = 'style="text-align: left; font-weight: bold"'
"""Captions on the left, in bold (a notebook centres them)."""

_SIDE_BY_SIDE = '<div style="display: flex; flex-wrap: wrap; gap: 1.5em; align-items: flex-start">'
"""Several tables of one object next to each other, wrapping when the page is narrow."""


def side_by_side(tables: Iterable[str]) -> str:
    """Tables in one row (``class="dataframe"``: styled as pandas' in Jupyter and the docs)."""
    return _SIDE_BY_SIDE + "".join(tables) + "</div>"


def table(caption: str, columns: Sequence[str], rows: Iterable[Cells], header: bool = True) -> str:
    """An HTML table with a caption, column names (unless ``header`` is False) and rows;
    every cell is escaped."""
    out = [f'<table class="dataframe veronte4x"><caption {_CAPTION}>{escape(caption)}</caption>']
    if header:
        out.append("<thead><tr>")
        out += [f"<th>{escape(name)}</th>" for name in columns]
        out.append("</tr></thead>")
    out.append("<tbody>")
    for row in rows:
        out.append("<tr>")
        cells = iter(row)
        if not header:  # the first cell names the row
            out.append(f"<th>{escape(str(next(cells)))}</th>")
        out += [f"<td>{escape(str(cell))}</td>" for cell in cells]
        out.append("</tr>")
    out.append("</tbody></table>")
    return "".join(out)
