"""A parser of DSDL (UAVCAN v0, as DroneCAN uses it) and the data type signature.

The language is that of the DroneCAN specification, section "Data structure description
language (DSDL)": one definition per ``.uavcan`` file, named ``[ID.]Name.uavcan`` in the
directory of its namespace; lines of fields (``[cast] type[array] name``), constants
(``[cast] type NAME = value``), void padding (``voidN``), the ``@union`` directive and,
for a service, ``---`` between request and response. Comments start with ``#``.

The data type signature follows the specification's section "Data type signature": the
CRC-64-WE of the normalized definition (full name, then each field as ``[cast] type name``,
constants and comments left out, ``---`` between the halves of a service), or the value of
``OVERRIDE_SIGNATURE``, extended with the signature of each nested type in field order.

What may reach the generated classes is held to a strict grammar, that of the
``dronecan`` package's parser: namespace (directory) names ``[a-z][a-z0-9_]*``, type names
``[A-Z][A-Za-z0-9_]*``, field and constant names ``[a-zA-Z][a-zA-Z0-9_]*``, full names of
at most 80 characters, constants of finite values in range for their type. Comments are
free text (the generated code quotes them).

Errors name the file and the line (`DsdlError`), in one line of printable characters.
"""

from __future__ import annotations

import math
import os
import re
import sys
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from pathlib import Path

from veronte4x.dronecan.crc import crc64we
from veronte4x.errors import DsdlError

CAST_MODES = ("saturated", "truncated")


@dataclass(frozen=True)
class PrimitiveType:
    """``uintN``, ``intN``, ``floatN`` (16, 32, 64), ``bool`` or ``voidN``, and its cast mode."""

    kind: str
    bits: int
    cast: str = "saturated"

    @property
    def name(self) -> str:
        """The DSDL spelling without the cast mode: ``uint8``, ``bool``, ``void3``."""
        return "bool" if self.kind == "bool" else f"{self.kind}{self.bits}"

    @property
    def normalized(self) -> str:
        """As in the normalized definition: ``saturated uint8``, ``void3``."""
        return self.name if self.kind == "void" else f"{self.cast} {self.name}"


@dataclass(frozen=True)
class ArrayType:
    """``T[N]`` (static) or ``T[<=N]`` / ``T[<N+1]`` (dynamic) of a primitive or nested type."""

    item: PrimitiveType | str
    max_size: int
    dynamic: bool

    @property
    def normalized(self) -> str:
        """As in the normalized definition: ``saturated uint8[<=80]``."""
        item = self.item.normalized if isinstance(self.item, PrimitiveType) else self.item
        return f"{item}[{'<=' if self.dynamic else ''}{self.max_size}]"


FieldType = PrimitiveType | ArrayType | str
"""A field's type: a primitive, an array, or the full name of a nested type."""


@dataclass(frozen=True)
class Attribute:
    """A field (``name`` empty for void padding) with its line and trailing comment."""

    name: str
    type: FieldType
    line: int
    comment: str = ""

    @property
    def normalized(self) -> str:
        """As in the normalized definition: ``saturated uint8 name``, ``void3``."""
        t = self.type
        text = t if isinstance(t, str) else t.normalized
        return f"{text} {self.name}" if self.name else text


@dataclass(frozen=True)
class Constant:
    """A constant: name, primitive type, value (int, float or bool), line and comment."""

    name: str
    type: PrimitiveType
    value: int | float | bool
    line: int
    comment: str = ""


@dataclass
class Section:
    """The body of a message or nested type, or one half of a service."""

    fields: list[Attribute] = field(default_factory=list)
    constants: list[Constant] = field(default_factory=list)
    union: bool = False
    doc: str = ""


@dataclass
class Definition:
    """One parsed ``.uavcan`` file.

    Attributes:
        full_name: E.g. ``uavcan.protocol.NodeStatus``.
        default_id: The default data type id of the file name, or None for a nested type.
        service: Whether the file has a request and a response (``---``).
        sections: One section, or two for a service (request, response).
        path: The file.
        doc: The comment block at the top of the file.
        override_signature: The value of ``OVERRIDE_SIGNATURE``, or None: it stands for
            the CRC of `normalized` in the signature.
    """

    full_name: str
    default_id: int | None
    service: bool
    sections: list[Section]
    path: str
    doc: str = ""
    override_signature: int | None = None

    @property
    def short_name(self) -> str:
        """The last component of the full name."""
        return self.full_name.rsplit(".", 1)[-1]

    @property
    def namespace(self) -> str:
        """The full name without the short name."""
        return self.full_name.rsplit(".", 1)[0]

    def normalized(self) -> str:
        """The normalized definition the DSDL signature is computed from."""
        lines = [self.full_name]
        for i, section in enumerate(self.sections):
            if i:
                lines.append("---")
            if section.union:
                lines.append("@union")
            lines += [a.normalized for a in section.fields]
        return "\n".join(lines)


_NAME = re.compile(r"[a-zA-Z][a-zA-Z0-9_]*\Z")
_NAMESPACE = re.compile(r"[a-z][a-z0-9_]*\Z")
_FILE = re.compile(r"(?:([0-9]+)\.)?([A-Z][A-Za-z0-9_]*)\.uavcan\Z")
_PRIMITIVE = re.compile(r"(uint|int|float|void)([0-9]+)\Z|bool\Z")
_ARRAY = re.compile(r"(.+?)\[(<=|<)?([0-9]+)\]\Z")
_COMPOUND = re.compile(r"[A-Za-z][A-Za-z0-9_]*(\.[A-Za-z][A-Za-z0-9_]*)*\Z")
_CONSTANT = re.compile(r"(\S+) +(\S+?) *= *(.+)\Z")
_DIRECTIVE = re.compile(r"[A-Z][A-Z0-9]*_[A-Z0-9_]*\Z")
"""The first word of a directive: an upper-case word with ``_`` in it, such as
``OVERRIDE_SIGNATURE``, on a line of no ``=`` where no field name follows it."""
_OVERRIDE = "OVERRIDE_SIGNATURE"
_HEX = re.compile(r"0[xX][0-9a-fA-F]{1,16}\Z|[0-9a-fA-F]{1,16}\Z")
_DIRECTIVES = f"veronte4x reads @union and {_OVERRIDE} 0x<16 hex digits>"
_MAX_FULL_NAME = 80
"""Longest full name (the specification's limit, which the ``dronecan`` package enforces)."""
_FLOAT_MAX = {16: 65504.0, 32: 3.4028234663852886e38, 64: sys.float_info.max}
"""Largest finite value of each float type: a constant's value must lie within it."""
_MAX_ID = {False: 65535, True: 255}
"""Largest default data type id of a message and of a service (CAN ID fields of v0)."""


def _primitive(text: str, cast: str | None, path: str, line: int) -> PrimitiveType | None:
    found = _PRIMITIVE.match(text)
    if found is None:
        return None
    if text == "bool":
        return PrimitiveType("bool", 1, cast or "saturated")
    kind, bits = found.group(1), int(found.group(2))
    low = {"uint": 1, "int": 2, "void": 1, "float": 16}[kind]
    if not low <= bits <= 64 or (kind == "float" and bits not in (16, 32, 64)):
        raise DsdlError(path, line, f"{text}: no such type (bit length out of range)")
    if kind == "void" and cast is not None:
        raise DsdlError(path, line, f"{text}: void fields take no cast mode")
    return PrimitiveType(kind, bits, cast or "saturated")


def _type(text: str, cast: str | None, namespace: str, path: str, line: int) -> FieldType:
    array = _ARRAY.match(text)
    if array is not None:
        item = _type(array.group(1), cast, namespace, path, line)
        if isinstance(item, ArrayType):
            raise DsdlError(path, line, f"{text}: arrays of arrays are not allowed")
        if isinstance(item, PrimitiveType) and item.kind == "void":
            raise DsdlError(path, line, f"{text}: arrays of void are not allowed")
        size = int(array.group(3)) - (array.group(2) == "<")
        if size < 1:
            raise DsdlError(path, line, f"{text}: an array holds at least one item")
        return ArrayType(item, size, array.group(2) is not None)
    primitive = _primitive(text, cast, path, line)
    if primitive is not None:
        return primitive
    if cast is not None:
        raise DsdlError(path, line, f"{cast} {text}: a cast mode applies to primitive types only")
    if _COMPOUND.match(text) is None:
        raise DsdlError(path, line, f"{text!r} is not a type name")
    return text if "." in text else f"{namespace}.{text}"


_ESCAPES = {"n": "\n", "r": "\r", "t": "\t", "\\": "\\", "'": "'", '"': '"', "0": "\0"}


def _value(text: str, t: PrimitiveType, path: str, line: int) -> int | float | bool:
    """A constant's value: an int, float, ``true``/``false`` or a character literal."""
    value: int | float | bool
    if len(text) >= 3 and text[0] == text[-1] == "'":
        body = text[1:-1]
        if len(body) == 2 and body[0] == "\\" and body[1] in _ESCAPES:
            body = _ESCAPES[body[1]]
        if len(body) != 1:
            raise DsdlError(path, line, f"{text}: a character literal holds one character")
        value = ord(body)
    elif text.lower() in ("true", "false"):
        value = text.lower() == "true"
    else:
        value = _number(text, path, line)
    if t.kind == "float":
        limit = _FLOAT_MAX[t.bits]
        if not -limit <= value <= limit:
            raise DsdlError(path, line, f"{text}: out of range for {t.name}")
        return float(value)
    if t.kind == "bool":
        if value not in (0, 1):
            raise DsdlError(path, line, f"{text}: not a bool")
        return bool(value)
    if isinstance(value, (float, bool)):
        raise DsdlError(path, line, f"{text}: not an integer for {t.name}")
    low = -(1 << (t.bits - 1)) if t.kind == "int" else 0
    high = (1 << (t.bits - 1)) - 1 if t.kind == "int" else (1 << t.bits) - 1
    if not low <= value <= high:
        raise DsdlError(path, line, f"{text}: out of range for {t.name}")
    return value


def _number(text: str, path: str, line: int) -> int | float:
    """An integer (decimal, ``0x``, ``0o``, ``0b``) or a finite float written in ASCII."""
    if text.isascii():
        try:
            return int(text, 0)
        except ValueError:
            pass
        try:
            value = float(text)
        except ValueError:
            pass
        else:
            if math.isfinite(value):
                return value
            raise DsdlError(path, line, f"{text}: not a finite number")
    raise DsdlError(path, line, f"{text}: not a constant value")


def _split_comment(raw: str) -> tuple[str, str]:
    """The code and the comment of a line (``#`` inside a character literal is code)."""
    if "'" not in raw:
        code, _, comment = raw.partition("#")
        return code.strip(), comment.strip()
    quoted = False
    for i, char in enumerate(raw):
        if char == "'" and (i == 0 or raw[i - 1] != "\\"):
            quoted = not quoted
        elif char == "#" and not quoted:
            return raw[:i].strip(), raw[i + 1 :].strip()
    return raw.strip(), ""


def parse_text(text: str, full_name: str, default_id: int | None, path: str) -> Definition:
    """Parse the text of one definition; nested type names are resolved, not checked."""
    namespace = full_name.rsplit(".", 1)[0]
    sections = [Section()]
    header: list[str] = []
    started = False
    names: set[str] = set()
    override: int | None = None
    for number, raw in enumerate(text.splitlines(), 1):
        code, comment = _split_comment(raw)
        section = sections[-1]
        if not code:
            if not started and raw.lstrip().startswith("#"):
                header.append(comment)
            elif not comment:
                started = started or bool(header)
            continue
        started = True
        note = comment
        if code == "---":
            if len(sections) == 2:
                raise DsdlError(path, number, "a second '---'")
            sections.append(Section())
            names = set()
            continue
        if code.startswith("@"):
            if code != "@union":
                raise DsdlError(path, number, f"unsupported directive {code} ({_DIRECTIVES})")
            if section.fields or section.union:
                raise DsdlError(path, number, "@union must come before the fields")
            section.union = True
            continue
        tokens = code.split()
        if tokens[0] == _OVERRIDE:
            override = _override(tokens, path, number)
            continue
        directive = _DIRECTIVE.match(tokens[0]) and "=" not in code
        if directive and len(tokens) >= 2 and _NAME.match(tokens[1]) is None:
            raise DsdlError(path, number, f"unsupported directive {tokens[0]} ({_DIRECTIVES})")
        cast = tokens[0] if tokens[0] in CAST_MODES else None
        if cast is not None:
            tokens = tokens[1:]
        constant = _CONSTANT.match(" ".join(tokens))
        if constant is not None:
            t = _type(constant.group(1), cast, namespace, path, number)
            if not isinstance(t, PrimitiveType) or t.kind == "void":
                raise DsdlError(
                    path, number, f"constant {constant.group(2)}: not of a primitive type"
                )
            name = _check_name(constant.group(2), names, path, number)
            value = _value(constant.group(3).strip(), t, path, number)
            section.constants.append(Constant(name, t, value, number, note))
            continue
        if "=" in code.replace("<=", ""):
            raise DsdlError(path, number, f"cannot read constant {code!r}")
        if len(tokens) == 1:
            t = _type(tokens[0], cast, namespace, path, number)
            if not (isinstance(t, PrimitiveType) and t.kind == "void"):
                raise DsdlError(path, number, f"field {code!r} has no name")
            if section.union:
                raise DsdlError(path, number, "a union has no void fields")
            section.fields.append(Attribute("", t, number, note))
            continue
        if len(tokens) != 2:
            raise DsdlError(path, number, f"cannot read {code!r}")
        t = _type(tokens[0], cast, namespace, path, number)
        if isinstance(t, PrimitiveType) and t.kind == "void":
            raise DsdlError(path, number, "void fields have no name")
        section.fields.append(
            Attribute(_check_name(tokens[1], names, path, number), t, number, note)
        )
    for section in sections:
        if section.union and len(section.fields) < 2:
            raise DsdlError(path, None, "a union needs at least two fields")
    service = len(sections) == 2
    if default_id is not None and default_id > _MAX_ID[service]:
        kind = "service" if service else "message"
        raise DsdlError(path, None, f"{kind} id {default_id} above {_MAX_ID[service]}")
    doc = "\n".join(header).strip()
    sections[0].doc = doc
    return Definition(full_name, default_id, service, sections, path, doc, override)


def _override(tokens: list[str], path: str, line: int) -> int:
    """The signature of an ``OVERRIDE_SIGNATURE`` line: one hexadecimal number of 64 bits
    at most, ``0x`` in front or not, as the ``dronecan`` package reads it (``int(x, 16)``;
    a second such line replaces the first there too)."""
    if len(tokens) != 2 or _HEX.match(tokens[1]) is None:
        raise DsdlError(
            path, line, f"{_OVERRIDE} takes one hexadecimal signature of 64 bits: {_DIRECTIVES}"
        )
    return int(tokens[1], 16)


def _check_name(name: str, seen: set[str], path: str, line: int) -> str:
    if _NAME.match(name) is None:
        raise DsdlError(path, line, f"{name!r} is not a valid name")
    if name in seen:
        raise DsdlError(path, line, f"{name} defined twice")
    seen.add(name)
    return name


def parse_file(path: Path, full_name_prefix: str) -> Definition:
    """Parse ``path`` (``[ID.]Name.uavcan``) whose namespace is ``full_name_prefix``."""
    found = _FILE.match(path.name)
    if found is None:
        raise DsdlError(path, None, "not a DSDL file name ([ID.]Name.uavcan)")
    full_name = f"{full_name_prefix}.{found.group(2)}"
    if len(full_name) > _MAX_FULL_NAME:
        raise DsdlError(
            path, None, f"full name {full_name} longer than {_MAX_FULL_NAME} characters"
        )
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as error:
        raise DsdlError(path, None, f"cannot read: {error}") from None
    default_id = int(found.group(1)) if found.group(1) else None
    return parse_text(text, full_name, default_id, str(path))


def definition_files(roots: Iterable[str | os.PathLike[str]]) -> list[tuple[str, Path, int]]:
    """The full name, file and root (its index in ``roots``) of every definition under each
    root namespace directory: the roots in order, the files of each sorted. Only the
    directories are listed; no file is read.

    Raises:
        DsdlError: A root that is not a directory, a directory name that is no namespace
            name, or a file name that is not ``[ID.]Name.uavcan``.
    """
    found = []
    for index, root in enumerate(roots):
        base = Path(root)
        if not base.is_dir():
            raise DsdlError(base, None, "not a directory of DSDL definitions")
        _check_namespace(base.name, base)
        for path in sorted(base.rglob("*.uavcan")):
            parts = path.relative_to(base).parent.parts
            for part in parts:
                _check_namespace(part, path)
            name = _FILE.match(path.name)
            if name is None:
                raise DsdlError(path, None, "not a DSDL file name ([ID.]Name.uavcan)")
            found.append((".".join((base.name, *parts, name.group(2))), path, index))
    return found


def parse_namespaces(
    roots: Iterable[str | os.PathLike[str]], *, override: bool = False
) -> dict[str, Definition]:
    """Parse every definition under each root namespace directory (e.g. ``.../uavcan``).

    Two roots of one name (a user's ``com`` beside the shipped one) add up. With
    ``override``, a definition in a later root replaces the one of the same full name in
    an earlier root (`veronte4x.dronecan.vendor_roots.overrides` lists them); without it,
    that is an error, as two definitions of one name in one root always are.

    Raises:
        DsdlError: A malformed file, or a type defined twice (naming both files).
    """
    found: dict[str, Definition] = {}
    root_of: dict[str, int] = {}
    for full_name, path, root in definition_files(roots):
        definition = parse_file(path, full_name.rsplit(".", 1)[0])
        other = found.get(full_name)
        if other is not None and not (override and root_of[full_name] < root):
            raise DsdlError(path, None, f"{full_name} also in {other.path}")
        found[full_name] = definition
        root_of[full_name] = root
    return found


def _check_namespace(name: str, path: Path) -> None:
    if _NAMESPACE.match(name) is None:
        raise DsdlError(
            path,
            None,
            f"directory name '{name}' is not a namespace name "
            "(a lowercase ASCII letter, then lowercase letters, digits or _)",
        )


MAX_DEPTH = 100
"""Most levels of nested types below a definition (the standard set has 4)."""


def check_references(definitions: dict[str, Definition]) -> None:
    """Raise `DsdlError` for a nested type defined nowhere, one that nests itself, or
    nesting deeper than `MAX_DEPTH`; in time linear in the definitions (each visited once)."""
    for d in definitions.values():
        for section in d.sections:
            for a in section.fields:
                target = nested_name(a.type)
                if target is None:
                    continue
                if target not in definitions:
                    raise DsdlError(d.path, a.line, f"unknown type {target}")
                if definitions[target].service:
                    raise DsdlError(d.path, a.line, f"{target} is a service, not a nested type")
    depths: dict[str, int] = {}
    for name in definitions:
        _depth(name, definitions, depths, ())


def _depth(
    name: str, definitions: dict[str, Definition], depths: dict[str, int], trail: tuple[str, ...]
) -> int:
    """Levels of nested types below ``name`` (0 for none), stored in ``depths``."""
    found = depths.get(name)
    if found is not None:
        return found
    d = definitions[name]
    if name in trail:
        raise DsdlError(d.path, None, f"{name} contains itself")
    if len(trail) > MAX_DEPTH:
        top = definitions[trail[0]]
        raise DsdlError(
            top.path, None, f"{top.full_name} nests types more than {MAX_DEPTH} levels deep"
        )
    depth = 0
    for section in d.sections:
        for a in section.fields:
            target = nested_name(a.type)
            if target is not None:
                depth = max(depth, 1 + _depth(target, definitions, depths, (*trail, name)))
    depths[name] = depth
    return depth


def nested_name(t: FieldType) -> str | None:
    """The full name of the nested type of a field (or of its items), else None."""
    if isinstance(t, str):
        return t
    if isinstance(t, ArrayType) and isinstance(t.item, str):
        return t.item
    return None


# -- signatures -------------------------------------------------------------------------


def signature(
    name: str, definitions: Mapping[str, Definition], known: dict[str, int] | None = None
) -> int:
    """The data type signature of ``name``: the CRC of its normalized definition (or its
    ``OVERRIDE_SIGNATURE``), extended by each nested type's signature (then the running
    value itself) in field order.

    Args:
        name: A full name of ``definitions`` (checked by `check_references`).
        definitions: Every definition, by full name.
        known: Signatures computed before, by full name; each one computed here is added
            (pass one dictionary to many calls: every type is then computed once).
    """
    known = {} if known is None else known
    found = known.get(name)
    if found is not None:
        return found
    d = definitions[name]
    value = d.override_signature
    if value is None:
        value = crc64we(d.normalized().encode())
    for section in d.sections:
        for a in section.fields:
            target = nested_name(a.type)
            if target is not None:
                nested = signature(target, definitions, known)
                value = crc64we(nested.to_bytes(8, "little") + value.to_bytes(8, "little"), value)
    known[name] = value
    return value
