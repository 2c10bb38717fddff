"""Parameter sets of ESCs in a TOML file: written for people to review, read back to restore.

One ``[[node]]`` table per node with its node id, name, unique id and software version (so
that a file can be told apart from another vehicle's and applied to a replacement), and one
inline table per parameter: type, value, default and range, as GetSet reports them (DSDL
``uavcan.protocol.param.GetSet``). TOML rather than YAML: Python reads it with the standard
library (``tomllib``, 3.11 and later; ``tomli``, the ``toml`` extra, on 3.10), as it reads the
bus maps, and its few types (integers, floats, booleans, strings) are those of a parameter
value. The writer is this module's own: the core has no runtime dependency.

A GetSet answer with an empty value (or an empty name) names no parameter (the DSDL of
``uavcan.protocol.param.GetSet``): `dumps` leaves such an entry out, and `loads` skips an
entry of ``type = "empty"`` (as files written before did hold), so a saved file always loads
and nothing is ever applied from an empty value.

Nothing here touches a bus: `plan` compares a saved set with what a node reports now and
says what would change, or why it cannot be applied, before anything is sent.
"""

from __future__ import annotations

import math
import re
import sys
from dataclasses import dataclass
from typing import Any

from veronte4x.client.params import ParameterInfo, Plain, plain
from veronte4x.dronecan.messages import (
    BooleanValue,
    Empty,
    IntegerValue,
    RealValue,
    StringValue,
    Value,
)
from veronte4x.errors import SourceError
from veronte4x.extras import require

FORMAT = "veronte4x-esc-parameters/1"
"""The ``format`` key of a parameter file: its layout and version."""

SKIPPED = frozenset({"uavcan_node_id"})
"""Parameters never applied from a file: a node id applied to a replacement or to another
node would re-address it (set it with ``esc set`` when that is meant)."""

_TYPES: dict[type, str] = {
    IntegerValue: "integer",
    RealValue: "real",
    BooleanValue: "boolean",
    StringValue: "string",
}

_NO_PARAMETER_TYPE = "empty"
"""The ``type`` of an entry that names no parameter: skipped when read, never written."""


class ParameterFileError(SourceError):
    """A parameter file that cannot be read, or whose content is not a parameter set."""


@dataclass(frozen=True, slots=True)
class NodeParameters:
    """One node's saved parameters and who it was.

    Attributes:
        node_id: Its node id when saved.
        name: Its GetNodeInfo name.
        unique_id: Its 16-byte unique id, hex.
        software_version: ``major.minor`` of its firmware.
        image_crc: Its firmware image CRC (hex) when it reports one, else None.
        parameters: Its parameters in discovery order.
    """

    node_id: int
    name: str
    unique_id: str
    software_version: str
    image_crc: str | None
    parameters: tuple[ParameterInfo, ...]


@dataclass(frozen=True, slots=True)
class Change:
    """A parameter to set: its name, the node's value now and the file's."""

    name: str
    current: Plain
    wanted: Value


def _toml(value: Plain) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return repr(value)
    if value is None:
        return '""'
    escaped = value.replace("\\", "\\\\").replace('"', '\\"')
    escaped = "".join(c if c.isprintable() else _escape(c) for c in escaped)
    return f'"{escaped}"'


def _escape(char: str) -> str:
    code = ord(char)
    return f"\\u{code:04x}" if code <= 0xFFFF else f"\\U{code:08x}"


def _key(name: str) -> str:
    if name and all(c.isalnum() or c in "_-" for c in name) and name.isascii():
        return name
    return _toml(name)


def dumps(nodes: list[NodeParameters], comment: str = "") -> str:
    """The TOML text of ``nodes`` (``comment`` as its first line, after ``#``).

    A parameter that does not exist (`ParameterInfo.exists`: an empty value or name) is left
    out.
    """
    lines = [f"# {comment}"] if comment else []
    lines += [f"format = {_toml(FORMAT)}", ""]
    for node in nodes:
        lines += [
            "[[node]]",
            f"node_id = {node.node_id}",
            f"name = {_toml(node.name)}",
            f"unique_id = {_toml(node.unique_id)}",
            f"software_version = {_toml(node.software_version)}",
        ]
        if node.image_crc is not None:
            lines.append(f"image_crc = {_toml(node.image_crc)}")
        lines += ["", "[node.parameters]"]
        for p in node.parameters:
            if not p.exists:
                continue
            fields = [f"type = {_toml(_TYPES[type(p.value)])}", f"value = {_toml(plain(p.value))}"]
            for key, member in (("default", p.default), ("min", p.minimum), ("max", p.maximum)):
                if not isinstance(member, Empty):
                    fields.append(f"{key} = {_toml(plain(member))}")
            lines.append(f"{_key(p.name)} = {{ {', '.join(fields)} }}")
        lines.append("")
    return "\n".join(lines)


def _value(kind: str, value: Any, where: str) -> Value:
    checks: dict[str, tuple[type | tuple[type, ...], Any]] = {
        "integer": (int, IntegerValue),
        "real": ((int, float), RealValue),
        "boolean": (bool, lambda v: BooleanValue(int(v))),
        "string": (str, lambda v: StringValue(v.encode("utf-8"))),
    }
    if kind not in checks:
        raise ParameterFileError(f"{where}: type {kind!r} is not integer, real, boolean or string")
    python, make = checks[kind]
    if not isinstance(value, python) or (kind in ("integer", "real") and isinstance(value, bool)):
        raise ParameterFileError(f"{where}: {value!r} is not a value of type {kind}")
    result: Value = make(float(value) if kind == "real" else value)  # type: ignore[arg-type]
    return result


def loads(text: str) -> list[NodeParameters]:
    """The parameter sets in a file's text; an entry of ``type = "empty"`` is left out.

    Raises:
        ParameterFileError: Not TOML, not this format, or a value that is not of its type.
        MissingExtraError: Python 3.10 without tomli (the ``toml`` extra).
    """
    if sys.version_info >= (3, 11):
        import tomllib
    else:  # pragma: no cover - Python 3.10
        tomllib = require("tomli", "toml", "reading TOML on Python 3.10")
    try:
        document = tomllib.loads(text)
    except tomllib.TOMLDecodeError as error:
        raise ParameterFileError(f"not a TOML file: {error}") from None
    if document.get("format") != FORMAT:
        raise ParameterFileError(
            f"not a veronte4x parameter file (format = {FORMAT!r} expected); "
            "write one with: veronte4x esc params NODES --save FILE"
        )
    nodes = []
    for position, table in enumerate(document.get("node", []), 1):
        where = f"node table {position}"
        node_id = table.get("node_id")
        if isinstance(node_id, bool) or not isinstance(node_id, int) or not 1 <= node_id <= 127:
            raise ParameterFileError(f"{where}: node_id {node_id!r} is not a node id (1..127)")
        where = f"node {node_id}"
        parameters = []
        for name, entry in table.get("parameters", {}).items():
            if not isinstance(entry, dict) or "type" not in entry or "value" not in entry:
                raise ParameterFileError(f"{where}, {name}: a table with type and value expected")
            kind = entry["type"]
            if kind == _NO_PARAMETER_TYPE:
                continue
            value = _value(kind, entry["value"], f"{where}, {name}")
            bounds = {
                key: _value(kind, entry[key], f"{where}, {name}, {key}")
                if key in entry
                else Empty()
                for key in ("default", "min", "max")
            }
            parameters.append(
                ParameterInfo(name, value, bounds["default"], bounds["min"], bounds["max"])  # type: ignore[arg-type]
            )
        nodes.append(
            NodeParameters(
                node_id,
                str(table.get("name", "")),
                str(table.get("unique_id", "")),
                str(table.get("software_version", "")),
                table.get("image_crc"),
                tuple(parameters),
            )
        )
    if not nodes:
        raise ParameterFileError("the file holds no [[node]] table")
    _refuse_twice(nodes, _table_lines(text, len(nodes)))
    return nodes


_TABLE_HEADER = re.compile(r"\s*\[\[\s*node\s*\]\]\s*(?:#.*)?")


def _table_lines(text: str, count: int) -> list[int] | None:
    """The line (from 1) of each ``[[node]]`` header, or None when they do not match the
    ``count`` tables read (tables written as an inline array)."""
    lines = [n for n, line in enumerate(text.splitlines(), 1) if _TABLE_HEADER.fullmatch(line)]
    return lines if len(lines) == count else None


def _refuse_twice(nodes: list[NodeParameters], lines: list[int] | None) -> None:
    """Refuse a node id, or a unique id, given by two tables: one would be ignored.

    Raises:
        ParameterFileError: Naming both tables, by line where the headers show them.
    """
    first: dict[tuple[str, object], int] = {}
    for position, node in enumerate(nodes):
        for key in (("node_id", node.node_id), ("unique_id", node.unique_id)):
            if key == ("unique_id", ""):
                continue
            if key in first:
                earlier = first[key]
                where = (
                    f"lines {lines[earlier]} and {lines[position]}"
                    if lines is not None
                    else f"node tables {earlier + 1} and {position + 1}"
                )
                raise ParameterFileError(
                    f"{key[0]} {key[1]} is given twice ({where}): one would be ignored; "
                    "keep one table per node"
                )
            first[key] = position


def plan(node_id: int, saved: NodeParameters, current: list[ParameterInfo]) -> list[Change]:
    """What applying ``saved`` to a node whose parameters are ``current`` would set.

    Every saved parameter but `SKIPPED` must exist on the node, have its type and lie in
    the range the node reports now; equal values are left alone.

    Raises:
        ParameterFileError: A saved parameter the node lacks, of another type, or out of the
            node's range (nothing is to be sent then).
    """
    by_name = {p.name: p for p in current}
    changes = []
    for p in saved.parameters:
        if p.name in SKIPPED:
            continue
        now = by_name.get(p.name)
        if now is None:
            raise ParameterFileError(f"node {node_id} has no parameter {p.name!r}")
        problem = now.check(p.value)
        if problem is not None:
            raise ParameterFileError(f"node {node_id}: {problem}")
        if plain(now.value) != plain(p.value):
            changes.append(Change(p.name, plain(now.value), p.value))
    return changes
