"""Rich display in Jupyter: the HTML table builders every view shares, and messages' view.

A class gets Jupyter's ``_repr_html_`` by deriving from `HtmlDisplay` (a mixin with no
slots, so frozen slotted dataclasses keep their layout): a message's fields as a table
(`message_html`). A class with more to show overrides ``_repr_html_`` with a view of its
own package, built from `table` and `side_by_side`: `veronte4x.capture.records.record_html`,
`veronte4x.capture.stats.stats_html`, `veronte4x.dronecan.view.transfer_html`,
`veronte4x.client.nodes.nodes_html`. Plain ``repr`` is unchanged. Values are shown as the
command line's text shows them (`veronte4x.values.shown`): enums by name, floats in their
shortest form at the field's declared width, text as text, other bytes in hex, and a column
of units where the protocol gives them; an index with a name, the name beside it (a Status's
``selected`` as ``1 (AP2)``, `veronte4x.values.name_of`). Everything is HTML-escaped.

This module imports no package of the library (the codecs import it): only the modules
below every protocol, `veronte4x.values` and `veronte4x.units`.

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

from veronte4x.units import unit
from veronte4x.values import name_of, shown


class HtmlDisplay:
    """Mixin that gives Jupyter a compact HTML view of the object (``_repr_html_``): by
    default its fields as a table (`message_html`)."""

    __slots__ = ()

    def _repr_html_(self) -> str:
        return message_html(self)


Cells = tuple[Any, ...]
"""The cells of one table row, left to right."""


def to_html(value: Any) -> str:
    """The HTML view of anything: its own (``_repr_html_``), a dataclass's fields as a table,
    or else its ``repr``, escaped."""
    view = None if isinstance(value, type) else getattr(value, "_repr_html_", None)
    if view is not None:
        html: str = view()
        return html
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        return message_html(value)
    return f"<pre>{escape(repr(value))}</pre>"


def message_html(message: Any, caption: str | None = None) -> str:
    """A message's fields as a table: name, readable value and unit."""
    rows = [(name, text, symbol or "") for name, text, symbol in _fields(message)]
    return table(caption or type(message).__name__, ("field", "value", "unit"), rows)


def _fields(message: Any, top: str | None = None, prefix: str = "") -> list[Cells]:
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
            text = shown(owner, field.name, value)
            named = name_of(owner, field.name, value)
            rows.append((name, text if named is None else f"{text} ({named})", unit(top, name)))
    return rows


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
