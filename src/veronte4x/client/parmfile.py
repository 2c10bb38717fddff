"""The DroneCAN GUI tool's parameter files (``.parm``): one ``NAME VALUE`` line per parameter.

The GUI tool's node window saves a node's parameters with "Save To File" and applies them with
"Load From File" (``dronecan/gui_tool``, ``dronecan_gui_tool/widgets/node_properties.py`` at
commit 4eda5d8, class ``ConfigParams``: the writer ``_do_save_to_file``, lines 806-821, with
``param_as_string``, lines 784-804; the reader ``_do_load_from_file``, lines 855-883, with
``save_param``, lines 834-853). What those lines define:

- one line per parameter of one node, in the node's order: the name, one space, the value,
  a newline; nothing else (no node id, no type, no default, no range, no comment);
- integers and reals as Python's ``str`` writes them (``3``, ``0.5``), booleans as ``True``
  or ``False`` (since commit a694622, March 2024), strings as they are; a parameter whose
  text is empty (an empty string) is left out;
- the reader splits each line at whitespace, takes the value's type from the node's current
  value, and sets only parameters whose text differs.

Mission Planner writes ArduPilot parameter files with the same ``.parm`` suffix as
``NAME,VALUE`` lines, and reads lines split at spaces, commas or tabs, skipping lines that
start with ``#`` (``ArduPilot/MissionPlanner``, ``ExtLibs/Utilities/ParamFile.cs``). This
module reads both: the separator is the first space, tab or comma after the name (a string
value keeps a comma after that space, as the GUI tool reads it; a number may follow one), and blank
lines and ``#`` lines are skipped. Where the GUI tool guesses, this reader refuses: a line
without a value, a name given twice, an integer written ``1.0``, a boolean that is not one
of the words below, a name the node lacks (the GUI tool skips it silently).

The file holds no node id, so it is applied to one node named on the command line, and the
types come from that node (`typed`). Nothing here touches a bus.
"""

from __future__ import annotations

import math
import re
import struct
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import PurePath

from veronte4x.client.paramfile import NodeParameters, ParameterFileError
from veronte4x.client.params import ParameterInfo
from veronte4x.dronecan.messages import (
    BooleanValue,
    Empty,
    IntegerValue,
    RealValue,
    StringValue,
    Value,
)

SUFFIXES = frozenset({".parm", ".param", ".params"})
"""File name suffixes taken for this format without looking at the content."""

ENCODED = frozenset({"STARTUP_TUNE"})
"""Parameters the GUI tool writes in a form of its own rather than the node's value: AM32's
startup melody as RTTTL text (``dronecan_gui_tool/am32_rtttl.py``, ``is_am32_melody_param``);
refused rather than set as that text."""

_BOOLEANS = {
    "true": 1, "t": 1, "yes": 1, "y": 1, "1": 1,
    "false": 0, "f": 0, "no": 0, "n": 0, "0": 0,
}  # fmt: skip
"""Boolean words, case-insensitive: those the GUI tool reads as true, and their opposites
(it reads anything else as false; this reader refuses anything else)."""

_LINE = re.compile(r"([^\s,]+)(?:,|[ \t])(.*)")
_INTEGER = re.compile(r"[+-]?[0-9]+")
_REAL = re.compile(r"[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?")
_TOML_START = re.compile(r"\s*(?:\[|format\s*=)")


@dataclass(frozen=True, slots=True)
class ParmLine:
    """One parameter line of a ``.parm`` file.

    Attributes:
        line: Its line number, from 1.
        name: The parameter's name.
        text: The value as written: everything after the separator that follows the name.
    """

    line: int
    name: str
    text: str


def is_parm(path: str, text: str) -> bool:
    """Whether a parameter file is in this format rather than veronte4x's TOML one.

    By the suffix (`SUFFIXES`, or ``.toml``), else by the content: veronte4x's files begin
    with a TOML table or their ``format = ...`` key, a ``.parm`` file with a name.
    """
    suffix = PurePath(path).suffix.lower()
    if suffix in SUFFIXES or suffix == ".toml":
        return suffix != ".toml"
    for line in text.split("\n"):
        if line.strip() and not line.lstrip().startswith("#"):
            return _TOML_START.match(line) is None
    return False


def loads(text: str) -> tuple[ParmLine, ...]:
    """The parameter lines of a ``.parm`` file's text.

    Raises:
        ParameterFileError: A line that is not a name and a value, a name given twice, or
            no parameter at all.
    """
    lines: list[ParmLine] = []
    seen: dict[str, int] = {}
    for number, line in enumerate(text.split("\n"), 1):
        line = line.removesuffix("\r")
        if not line.strip() or line.lstrip().startswith("#"):
            continue
        match = _LINE.fullmatch(line.lstrip())
        if match is None or not match[2]:
            raise ParameterFileError(
                f"line {number}: {line.strip()!r} is not a parameter line (NAME VALUE)"
            )
        name = match[1]
        if name in seen:
            raise ParameterFileError(
                f"line {number}: {name} is given twice (also on line {seen[name]})"
            )
        seen[name] = number
        lines.append(ParmLine(number, name, match[2]))
    if not lines:
        raise ParameterFileError("the .parm file holds no parameter line (NAME VALUE)")
    return tuple(lines)


def typed(
    lines: Sequence[ParmLine], node_id: int, current: Sequence[ParameterInfo]
) -> NodeParameters:
    """The parameter set of ``lines`` for a node whose parameters are ``current``: each value
    of the type the node reports for that name now (the file says no type).

    Reals are rounded to float32, the width of ``real_value`` on the bus (DSDL
    ``uavcan.protocol.param.Value``), so that ``0.1`` equals what the node reads back. The
    result says who the node is only by ``node_id``: a ``.parm`` file names no node.

    Raises:
        ParameterFileError: A name the node lacks, a parameter without a value on the node,
            or a value that is not of the node's type.
    """
    by_name = {p.name: p for p in current}
    parameters = []
    for line in lines:
        now = by_name.get(line.name)
        if now is None:
            raise ParameterFileError(
                f"line {line.line}: node {node_id} has no parameter {line.name!r}"
            )
        if line.name in ENCODED and isinstance(now.value, StringValue):
            raise ParameterFileError(
                f"line {line.line}: {line.name} is saved by the GUI tool as an RTTTL melody, "
                "not as the node's value; set it with the GUI tool"
            )
        value = _value(now.value, line)
        parameters.append(ParameterInfo(line.name, value, Empty(), Empty(), Empty()))
    return NodeParameters(node_id, "", "", "", None, tuple(parameters))


def _value(kind: Value, line: ParmLine) -> Value:
    where = f"line {line.line}: {line.name}"
    if isinstance(kind, StringValue):
        try:
            return StringValue(line.text.encode("utf-8"))
        except UnicodeEncodeError:  # a lone surrogate, from text decoded with surrogates
            raise ParameterFileError(f"{where}: the value is not UTF-8 text") from None
    word = line.text.strip(" \t")
    if word.startswith(","):  # Mission Planner's NAME , VALUE: the comma after a space
        word = word[1:].lstrip(" \t")
    if isinstance(kind, IntegerValue):
        if _INTEGER.fullmatch(word) is None:
            raise ParameterFileError(f"{where} takes an integer, not {word!r}")
        if not -(2**63) <= int(word) < 2**63:
            raise ParameterFileError(f"{where}: {word} is beyond the range of an int64")
        return IntegerValue(int(word))
    if isinstance(kind, RealValue):
        if _REAL.fullmatch(word) is None:
            raise ParameterFileError(f"{where} takes a finite number, not {word!r}")
        number = float(word)
        try:
            (single,) = struct.unpack("<f", struct.pack("<f", number))
        except OverflowError:
            single = math.inf
        if not math.isfinite(single):
            raise ParameterFileError(f"{where}: {word} is beyond the range of a float32")
        return RealValue(single)
    if isinstance(kind, BooleanValue):
        if word.lower() not in _BOOLEANS:
            raise ParameterFileError(f"{where} takes True or False, not {word!r}")
        return BooleanValue(_BOOLEANS[word.lower()])
    raise ParameterFileError(f"{where} has no value on the node (an empty parameter)")
