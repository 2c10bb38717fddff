"""Python source of the message classes of a set of DSDL definitions.

`standard` is this module's output for the standard ``uavcan`` namespace, and `vendor`
for the vendor namespaces shipped beside it, checked into the package with the rest of
what is generated ahead of time (``python -m veronte4x.dronecan.generate`` rewrites them,
see `veronte4x.dronecan.shipped_source`; a test compares). For a namespace the user loads,
`veronte4x.dronecan.load_dsdl` makes the same source at run time. These rules are the one
home of the names, for both.

Naming rules (documented in the DroneCAN types page):

- A message or nested type is named by its short name (``BatteryInfo``, ``Fix2``); the
  halves of a service add ``Request`` and ``Response`` (``GetTransportStatsRequest``).
- When two types of the set share a short name (the five ``Status`` messages), or the
  name is already taken (``Mode``), each gets the CamelCase of its namespace's last
  component in front (``ActuatorStatus``, ``CameraGimbalStatus``, ``HardpointCommand``),
  and more components while a clash remains.
- The types that veronte4x named before keep their names (`HAND_NAMES`).
- A vendor type (`plan` with ``named``: the classes of the set it is added to keep their
  names) climbs its `_ladder`: its short name, then one more namespace component in front
  per step (the root last), then its full name with ``_`` for ``.`` (``esc.Status`` is
  ``esc_Status``: ``EscStatus`` is the standard one). It stops at the first name that no
  class or enum of the set has, that is no short name of a type in the set, no keyword,
  builtin or name of the generated module; the keys of one clash climb together, so the
  order of the roots does not matter; two keys still of one name at the top are a
  `DsdlError` naming both files.
- Constants sharing the prefix ``P_`` where ``p`` is an unsigned integer field of the
  same type become an ``enum.IntEnum`` named ``CamelCase(P)``
  (``ActuatorCommand.command_type``: ``CommandType``); where two types would give the same
  name, or the name is taken, the class name goes in front (``FixStatus``,
  ``Fix2Status``, ``ArmingStatusStatus``). The field decodes to it (an int where the value
  has no member; annotated with the enum alone where every value has one). Constants
  ``P_FLAG_*`` for a field ``p_flags`` become an ``enum.IntFlag`` and the field stays an
  int. Members drop the prefix unless a name would then start with a digit. Every
  constant also stays a class attribute of its DSDL name; a signed field's constants are
  only that (the field stays an int), and so are constants of a prefix that repeat a value
  (``Fix2.sub_mode``: ``SUB_MODE_DGPS_OTHER`` and ``SUB_MODE_RTK_FLOAT`` are both 0), so
  no enum gives a value two names.
- Attributes are the DSDL names; a Python keyword takes ``_`` after it, more while that is
  another name of the class (`attribute_names`).
- An enumeration type, whose one field ``p`` is an unsigned integer and whose constants
  (two or more, distinct) all have ``p``'s type without such a prefix
  (``debug.LogLevel``, ``DataTypeKind``, ``tunnel.Protocol``), gets an ``enum.IntEnum``
  of them named as above with ``p`` for the prefix (``LogLevelValue``,
  ``DataTypeKindValue``, ``ProtocolProtocol``), members named as the constants; ``p``
  decodes to it.
- A union (only ``param.Value`` and ``param.NumericValue`` in the standard set) holds one
  member class: the nested type's own class, or a class with one field ``value`` named
  ``<Union><Member>`` in CamelCase.
"""

from __future__ import annotations

import ast
import builtins
import keyword
import re
from collections import Counter
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field

from veronte4x.dronecan.parser import (
    ArrayType,
    Attribute,
    Constant,
    Definition,
    FieldType,
    PrimitiveType,
    Section,
    nested_name,
)
from veronte4x.errors import DsdlError

HAND_NAMES: dict[str, str] = {
    "uavcan.protocol.NodeStatus": "NodeStatus",
    "uavcan.equipment.esc.Status": "EscStatus",
    "uavcan.equipment.device.Temperature": "Temperature",
    "uavcan.equipment.esc.RawCommand": "RawCommand",
    "uavcan.protocol.SoftwareVersion": "SoftwareVersion",
    "uavcan.protocol.HardwareVersion": "HardwareVersion",
    "uavcan.protocol.GetNodeInfo.Request": "GetNodeInfoRequest",
    "uavcan.protocol.GetNodeInfo.Response": "GetNodeInfoResponse",
    "uavcan.protocol.param.Empty": "Empty",
    "uavcan.protocol.param.Value": "Value",
    "uavcan.protocol.param.NumericValue": "NumericValue",
    "uavcan.protocol.param.GetSet.Request": "GetSetRequest",
    "uavcan.protocol.param.GetSet.Response": "GetSetResponse",
    "uavcan.protocol.RestartNode.Request": "RestartNodeRequest",
    "uavcan.protocol.RestartNode.Response": "RestartNodeResponse",
    "uavcan.protocol.file.Path": "Path",
    "uavcan.protocol.file.BeginFirmwareUpdate.Request": "BeginFirmwareUpdateRequest",
    "uavcan.protocol.file.BeginFirmwareUpdate.Response": "BeginFirmwareUpdateResponse",
    "uavcan.protocol.param.ExecuteOpcode.Request": "ExecuteOpcodeRequest",
    "uavcan.protocol.param.ExecuteOpcode.Response": "ExecuteOpcodeResponse",
    "uavcan.protocol.file.Error": "FileErrorCode",
    "uavcan.protocol.file.EntryType": "EntryType",
    "uavcan.protocol.file.GetInfo.Request": "FileGetInfoRequest",
    "uavcan.protocol.file.GetInfo.Response": "FileGetInfoResponse",
    "uavcan.protocol.file.Read.Request": "FileReadRequest",
    "uavcan.protocol.file.Read.Response": "FileReadResponse",
}
"""The classes veronte4x had before the DSDL compiler (their names, fields and enums are
public API, re-exported by `veronte4x.dronecan.messages`): key (full name, ``.Request`` or
``.Response`` for a service half) to class name."""

HAND_ENUMS: dict[tuple[str, str], str] = {
    ("uavcan.protocol.NodeStatus", "health"): "Health",
    ("uavcan.protocol.NodeStatus", "mode"): "Mode",
    ("uavcan.protocol.file.BeginFirmwareUpdate.Response", "error"): "FirmwareUpdateError",
    ("uavcan.protocol.param.ExecuteOpcode.Request", "opcode"): "Opcode",
    ("uavcan.equipment.device.Temperature", "error_flags"): "TemperatureErrorFlag",
    ("uavcan.protocol.SoftwareVersion", "optional_field_flags"): "SoftwareVersionFlag",
    ("uavcan.protocol.file.EntryType", "flags"): "EntryTypeFlag",
}
"""The enums (and flags) of the classes of `HAND_NAMES`, by their names of before; the
other constants of those classes stay class attributes only."""

HAND_CONSTANT_ENUMS: dict[str, str] = {"uavcan.protocol.file.Error": "FileError"}
"""Types whose constants, without a common prefix, form an enum of their own that no
field decodes to (``file.Error``'s ``value`` stays an int that compares equal to them)."""

HAND_CONSTANTS: dict[str, tuple[tuple[str, int, str], ...]] = {
    "uavcan.protocol.file.Read.Response": (
        ("MAX_DATA", 256, "Most bytes of ``data`` in one response (its DSDL array size)."),
    ),
}
"""Class attributes that veronte4x added to the DSDL constants before (public API)."""

HAND_UNION_MEMBERS: dict[str, tuple[str, ...]] = {
    "uavcan.protocol.param.Value": (
        "Empty",
        "IntegerValue",
        "RealValue",
        "BooleanValue",
        "StringValue",
    ),
    "uavcan.protocol.param.NumericValue": ("Empty", "IntegerValue", "RealValue"),
}
"""The member classes of the unions veronte4x had before, in member order (``Value`` and
``NumericValue`` share ``IntegerValue`` and ``RealValue``)."""

_RESERVED = {
    "Health",
    "Mode",
    "FirmwareUpdateError",
    "FileError",
    "Opcode",
    "EntryTypeFlag",
    "TemperatureErrorFlag",
    "SoftwareVersionFlag",
    "IntegerValue",
    "RealValue",
    "BooleanValue",
    "StringValue",
    "Message",
    "HandNamedMessage",
    "Frame",
    "TransferFrame",
    "Transfer",
    "CanId",
}
"""Names of the public API other than the message classes."""

_MODULE_NAMES = {
    "annotations",
    "enum",
    "frozen_dataclass",
    "_setattr",
    "Any",
    "ClassVar",
    "TypeAlias",
    "HtmlDisplay",
    "CLASSES",
    "ENUMS",
    "UNION_MEMBERS",
}
"""Names the generated module imports or defines besides its classes."""


@dataclass
class Plan:
    """What the generated source holds for each key (see `keys`)."""

    sections: dict[str, tuple[Definition, Section]] = field(default_factory=dict)
    names: dict[str, str] = field(default_factory=dict)
    enums: dict[tuple[str, str], tuple[str, str, list[Constant], str]] = field(default_factory=dict)
    """(key, field) -> (enum name, ``IntEnum`` or ``IntFlag``, constants, their prefix)."""
    members: dict[str, tuple[str, ...]] = field(default_factory=dict)
    """Union key -> member class names."""
    constant_enums: dict[str, tuple[str, list[Constant]]] = field(default_factory=dict)
    """Key -> (enum name, constants) of `HAND_CONSTANT_ENUMS`."""


def keys(d: Definition) -> list[str]:
    """The keys of a definition: its full name, or ``<full name>.Request`` and ``.Response``."""
    return [f"{d.full_name}.Request", f"{d.full_name}.Response"] if d.service else [d.full_name]


def _camel(text: str) -> str:
    return "".join(part[:1].upper() + part[1:] for part in re.split(r"[_\W]+", text) if part)


def _prefix(namespace: str, depth: int) -> str:
    parts = namespace.split(".")
    return "".join(_camel(p) for p in parts[len(parts) - depth :]) if depth else ""


def usable(name: str) -> bool:
    """Whether a generated name can be a module-level class: an identifier, no keyword
    (``None``, ``True``), no ``__`` in front (mangled inside class bodies)."""
    return name.isidentifier() and not keyword.iskeyword(name) and not name.startswith("__")


def _ladder(d: Definition, half: str) -> list[str]:
    """The names a key may take, in order: its short name, then with ever more components
    of its namespace in front (the root last), then its full name with ``_`` for ``.``."""
    base = d.short_name + half
    depth = d.namespace.count(".") + 1
    return [
        *(_prefix(d.namespace, n) + base for n in range(depth + 1)),
        d.full_name.replace(".", "_") + half,
    ]


def _class_names(
    definitions: dict[str, Definition], taken: set[str], named: dict[str, str]
) -> dict[str, str]:
    """Class name of every key, by the rules of the module docstring.

    Every key not in ``named`` climbs its `_ladder` while its name is taken, or is the short
    name of a type in ``named``, or is the name of another key; all keys of a clash climb
    together, so the result does not depend on the order of the definitions. Two keys left
    with one name at the top of their ladders are a `DsdlError` naming both files; a key
    whose whole ladder is taken by names of another set gives ``_2``, ``_3``, ...
    """
    suffixes = ("Request", "Response")
    ladders: dict[str, list[str]] = {}
    claimed = set(taken) | set(named.values())
    for d in definitions.values():
        for i, key in enumerate(keys(d)):
            half = suffixes[i] if d.service else ""
            if key in named:
                claimed.add(d.short_name + half)
            else:
                ladders[key] = _ladder(d, half)
    level = dict.fromkeys(ladders, 0)
    while True:
        names = {key: ladder[level[key]] for key, ladder in ladders.items()}
        counts = Counter(names.values())
        clashes = [
            key
            for key, name in names.items()
            if name in claimed or counts[name] > 1 or not usable(name)
        ]
        climbing = [key for key in clashes if level[key] + 1 < len(ladders[key])]
        if not climbing:
            break
        for key in climbing:
            level[key] += 1
    result = dict(named)
    result.update((key, name) for key, name in names.items() if key not in clashes)
    sharing = sorted(key for key in clashes if counts[names[key]] > 1)
    for key in sharing:
        other = next(k for k in sharing if names[k] == names[key] and k != key)
        first, second = (
            definitions[k.removesuffix(".Request").removesuffix(".Response")] for k in (key, other)
        )
        raise DsdlError(
            second.path,
            None,
            f"{key} and {other} would both be class {names[key]}; rename one "
            f"({first.path}, {second.path})",
        )
    used = claimed | set(result.values())
    for key in sorted(clashes):
        top = next(n for n in reversed(ladders[key]) if usable(n))
        result[key] = _numbered(top, used)
        used.add(result[key])
    return result


def _numbered(name: str, used: set[str]) -> str:
    """``name_2``, ``name_3``, ...: the first that is not in ``used``."""
    number = 2
    while f"{name}_{number}" in used:
        number += 1
    return f"{name}_{number}"


def _enum_candidates(
    key: str, section: Section
) -> list[tuple[tuple[str, str], str, list[Constant], str]]:
    """(key, field), kind, constants and prefix of each field with enum constants."""
    found = []
    for a in section.fields:
        t = a.type
        if not a.name or not isinstance(t, PrimitiveType) or t.kind != "uint":
            continue
        for prefix, flag in ((a.name.upper() + "_", False), (a.name.upper()[:-1] + "_", True)):
            if flag and not a.name.endswith("s"):
                continue
            members = [c for c in section.constants if c.name.startswith(prefix) and c.type == t]
            if len(members) >= 2:
                if len({c.value for c in members}) == len(members):  # else a value has 2 names
                    found.append(((key, a.name), "IntFlag" if flag else "IntEnum", members, prefix))
                break
    named = [a for a in section.fields if a.name]
    constants = section.constants
    if not found and len(named) == 1 and len(constants) >= 2:  # an enumeration type
        a = named[0]
        if (
            isinstance(a.type, PrimitiveType)
            and a.type.kind == "uint"
            and all(c.type == a.type for c in constants)
            and len({c.value for c in constants}) == len(constants)
        ):
            found.append(((key, a.name), "IntEnum", list(constants), ""))
    return found


def plan(
    definitions: dict[str, Definition],
    known: Iterable[str] = (),
    named: Mapping[str, str] | None = None,
) -> Plan:
    """Names of the classes, enums and union members of ``definitions``.

    Args:
        definitions: Every definition the classes may refer to.
        known: Names taken already (the classes and enums of another set of types).
        named: The class name of each key named already (the set the definitions are
            added to): those keys keep it, and get no enums or union members here.
    """
    result = Plan()
    fixed = {**HAND_NAMES, **(named or {})}
    taken = set(_RESERVED) | _MODULE_NAMES | set(dir(builtins)) | set(known)
    result.names = _class_names(definitions, taken, fixed)
    taken |= set(result.names.values())
    candidates = []
    mine = []
    for d in definitions.values():
        for key, section in zip(keys(d), d.sections, strict=True):
            result.sections[key] = (d, section)
            if key in HAND_CONSTANT_ENUMS:
                result.constant_enums[key] = (HAND_CONSTANT_ENUMS[key], section.constants)
            if key in HAND_NAMES:
                for where, kind, constants, prefix in _enum_candidates(key, section):
                    if where in HAND_ENUMS:
                        result.enums[where] = (HAND_ENUMS[where], kind, constants, prefix)
                continue
            if section.union and d.default_id is not None:
                raise DsdlError(d.path, None, "a union as a top-level type is not supported")
            found = _enum_candidates(key, section)
            candidates += found
            if key in fixed:
                continue
            mine += found
            if section.union:
                result.members[key] = _member_names(key, d, section, definitions, result, taken)
    counts: dict[str, int] = {}
    for where, *_, prefix in candidates:
        stem = _camel(prefix.lower() or where[1])
        counts[stem] = counts.get(stem, 0) + 1
    for where, kind, constants, prefix in mine:
        name = _camel(prefix.lower() or where[1])
        if counts[name] > 1 or name in taken:
            name = result.names[where[0]] + name
        if name in taken or not usable(name):
            name = _numbered(name, taken)
        taken.add(name)
        result.enums[where] = (name, kind, constants, prefix)
    for key, hand in HAND_UNION_MEMBERS.items():
        if key in result.names:
            result.members[key] = hand
    return result


def _member_names(
    key: str,
    d: Definition,
    section: Section,
    definitions: dict[str, Definition],
    result: Plan,
    taken: set[str],
) -> tuple[str, ...]:
    members = []
    for a in section.fields:
        target = a.type if isinstance(a.type, str) else None
        inner = definitions.get(target) if target is not None else None
        if inner is not None and inner.sections[0].union:
            raise DsdlError(d.path, a.line, "a union in a union is not supported")
        if target is not None:
            name = result.names[target]
            if name in members:
                raise DsdlError(d.path, a.line, f"two members of the union hold a {name}")
        else:
            name = result.names[key] + _camel(a.name)
            if name in taken or not usable(name):
                name = _numbered(name, taken)
            taken.add(name)
        members.append(name)
    return tuple(members)


# -- source ------------------------------------------------------------------------------


def _doc(text: str, indent: str) -> list[str]:
    """The lines of a docstring of ``text`` (a comment, a name: data): triple-quoted where
    every character is printable (backslashes doubled, ``\"""`` as ``'''``), else the quoted
    literal of `repr`; never source."""
    text = text.strip()
    if not all(char == "\n" or char.isprintable() for char in text):
        return [f"{indent}{text!r}"]
    text = text.replace("\\", "\\\\").replace('"""', "'''")
    if text.endswith('"'):
        text += " "
    lines = text.splitlines() or [""]
    if len(lines) == 1:
        return [f'{indent}"""{lines[0]}"""']
    return [
        f'{indent}"""{lines[0]}',
        *[(indent + line).rstrip() for line in lines[1:]],
        f'{indent}"""',
    ]


def _dsdl_file(d: Definition) -> str:
    parts = d.namespace.split(".")[1:]
    name = f"{d.default_id}.{d.short_name}" if d.default_id is not None else d.short_name
    return "/".join([*parts, f"{name}.uavcan"])


def _title(d: Definition, key: str) -> str:
    if d.default_id is None:
        return f"``{d.full_name}`` (nested; ``{_dsdl_file(d)}``)."
    if d.service:
        half = "request" if key.endswith(".Request") else "response"
        return f"``{d.full_name}`` {half}, service {d.default_id} (``{_dsdl_file(d)}``)."
    return f"``{d.full_name}``, message {d.default_id} (``{_dsdl_file(d)}``)."


def _python_type(t: FieldType, p: Plan, enum: str | None) -> tuple[str, str]:
    """Annotation and default of a field."""
    if isinstance(t, str):
        name = p.names[t]
        if t in p.members:
            return name, f"{p.members[t][0]}()"
        return name, f"{name}()"
    if isinstance(t, ArrayType):
        item = t.item
        if isinstance(item, PrimitiveType) and item.kind == "uint" and item.bits == 8:
            return "bytes", 'b""' if t.dynamic else f"bytes({t.max_size})"
        inner = _python_type(item, p, None)[0]
        if t.dynamic:
            return f"tuple[{inner}, ...]", "()"
        value = _python_type(item, p, None)[1]
        return f"tuple[{inner}, ...]", f"({value},) * {t.max_size}"
    if t.kind == "float":
        return "float", "0.0"
    if t.kind == "bool":
        return "bool", "False"
    if enum is not None:
        return f"{enum} | int", "0"
    return "int", "0"


def _covers(t: FieldType, constants: list[Constant]) -> bool:
    """Whether the constants name every value of an unsigned field (it always decodes to
    the enum: ``NodeStatus.health``). Counted, not listed: a ``uint23`` has 8 M values."""
    if not isinstance(t, PrimitiveType) or t.kind != "uint":
        return False
    values = {c.value for c in constants}
    return len(values) == 1 << t.bits and all(
        isinstance(v, int) and 0 <= v < 1 << t.bits for v in values
    )


def _literal(value: int | float | bool) -> str:
    return repr(value)


TEXT_WORDS = frozenset(
    {
        "name",
        "path",
        "text",
        "string",
        "message",
        "key",
        "description",
        "reason",
        "label",
        "source",
        "ascii",
        "utf",
    }
)
"""The words that make a ``uint8[<=N]`` field text (see `is_text`)."""


def is_text(attribute: Attribute) -> bool:
    """Whether a field holds text: a dynamic ``uint8`` array whose name or DSDL comment
    has one of the `TEXT_WORDS` (``name``, ``parameter_name``, ``reason_text``,
    ``string_value``, ``optional_error_message``, ``source``, or a comment such as "Full
    data type name" or "in ASCII characters"). Other byte arrays are data (``data``,
    ``buffer``, ``unique_id``). Only the field's own line counts, not the comment block
    above it, which often describes the whole type."""
    t = attribute.type
    if not (
        isinstance(t, ArrayType)
        and t.dynamic
        and isinstance(t.item, PrimitiveType)
        and t.item.kind == "uint"
        and t.item.bits == 8
    ):
        return False
    words = re.findall(r"[a-z]+", f"{attribute.name} {attribute.comment}".lower())
    return not TEXT_WORDS.isdisjoint(words)


def is_float16(attribute: Attribute) -> bool:
    """Whether a field holds half-precision floats: ``float16``, or an array of them."""
    return _float_bits(attribute) == 16


def is_float32(attribute: Attribute) -> bool:
    """Whether a field holds single-precision floats: ``float32``, or an array of them."""
    return _float_bits(attribute) == 32


def _float_bits(attribute: Attribute) -> int | None:
    t = attribute.type
    item = t.item if isinstance(t, ArrayType) else t
    return item.bits if isinstance(item, PrimitiveType) and item.kind == "float" else None


FACTS: tuple[tuple[str, Callable[[Attribute], bool]], ...] = (
    ("_TEXT_FIELDS_", is_text),
    ("_FLOAT16_FIELDS_", is_float16),
    ("_FLOAT32_FIELDS_", is_float32),
)
"""The class attributes a generated class has where some of its fields pass the test
(read by `veronte4x.values`): each a ``frozenset`` of attribute names, absent when empty
(a union member's is ``{"value"}``). The trailing ``_`` keeps them apart from any DSDL
name."""


def _fact_lines(tested: Iterable[tuple[str, Attribute]]) -> list[str]:
    """The `FACTS` of a class body, from its (attribute, field) pairs."""
    pairs = list(tested)
    lines = []
    for fact, test in FACTS:
        names = sorted({attribute for attribute, a in pairs if test(a)})
        if names:
            listed = ", ".join(f'"{n}"' for n in names)
            lines.append(f"    {fact}: ClassVar[frozenset[str]] = frozenset({{{listed}}})")
    return lines


def _class_source(key: str, p: Plan) -> list[str]:
    d, section = p.sections[key]
    name = p.names[key]
    lines = ["", "", "@frozen_dataclass", f"class {name}(HtmlDisplay):"]
    doc = _title(d, key)
    if section.doc:
        doc += "\n\n" + section.doc
    lines += _doc(doc, "    ")
    attributes = attribute_names(key, section)
    facts = _fact_lines((attributes[a.name], a) for a in section.fields if a.name)
    if section.constants or key in HAND_CONSTANTS or facts:
        lines.append("")
    lines += facts
    body: dict[str, str] = {}  # each name of the class body, to its DSDL name

    def claim(attribute: str, dsdl: str, line: int | None) -> str:
        other = body.setdefault(attribute, dsdl)
        if other != dsdl:
            raise DsdlError(d.path, line, f"{other} and {dsdl} would both be attribute {attribute}")
        return attribute

    for c in section.constants:
        kind = "float" if c.type.kind == "float" else "bool" if c.type.kind == "bool" else "int"
        constant = claim(attributes[c.name], c.name, c.line)
        lines.append(f"    {constant}: ClassVar[{kind}] = {_literal(c.value)}")
        if c.comment:
            lines += _doc(c.comment, "    ")
    for constant, value, comment in HAND_CONSTANTS.get(key, ()):
        lines.append(f"    {claim(constant, constant, None)}: ClassVar[int] = {value}")
        lines += _doc(comment, "    ")
    hidden: dict[str, str] = {}
    written: list[tuple[str, str, str]] = []
    comments: list[str | None] = []
    for a in (a for a in section.fields if a.name):
        enum = p.enums.get((key, a.name))
        enum_name = enum[0] if enum is not None and enum[1] == "IntEnum" else None
        annotation, default = _python_type(a.type, p, enum_name)
        if enum is not None and enum_name is not None and _covers(a.type, enum[2]):
            annotation, default = enum_name, f"{enum_name}(0)"  # every value has a member
        if _names(default) & body.keys():  # an attribute above hides a class the default calls
            hidden[a.name] = default
            default = f"_defaults[{a.name!r}]"
        written.append((claim(attributes[a.name], a.name, a.line), annotation, default))
        comments.append(a.comment)
    if hidden:  # made before the class, where the names are the module's
        lines[2:2] = ["_defaults = {", *(f"    {f!r}: {v}," for f, v in hidden.items()), "}"]
    return lines + _slots_and_init(written, comments)


def _slots_and_init(
    written: list[tuple[str, str, str]], comments: list[str | None] | None = None
) -> list[str]:
    """The ``__slots__``, field annotations and ``__init__`` of a class body, from each
    field's (attribute, annotation, default): what `veronte4x.dronecan.written` needs to
    make the class a dataclass without compiling anything at import."""
    slots = "".join(f'"{attribute}", ' for attribute, _, _ in written).rstrip()
    lines = ["", f"    __slots__ = ({slots})", ""]
    for (attribute, annotation, _), comment in zip(
        written, comments or [None] * len(written), strict=True
    ):
        lines.append(f"    {attribute}: {annotation}")
        if comment:
            lines += _doc(comment, "    ")
    this = "_self" if any(attribute == "self" for attribute, _, _ in written) else "self"
    lines += ["", "    def __init__(", f"        {this},"]
    lines += [f"        {a}: {annotation} = {default}," for a, annotation, default in written]
    lines.append("    ) -> None:")
    lines += [f'        _setattr({this}, "{a}", {a})' for a, _, _ in written] or ["        pass"]
    return lines


def _names(expression: str) -> set[str]:
    """The names a generated expression (a field's default) refers to."""
    tree = ast.parse(expression, mode="eval")
    return {node.id for node in ast.walk(tree) if isinstance(node, ast.Name)}


def attribute_names(key: str, section: Section) -> dict[str, str]:
    """The Python attribute of each constant and named field of the section of ``key`` (of
    each member of a union), by DSDL name.

    A name that is no Python keyword is kept as it is; a keyword takes ``_`` after it, and
    more while that is a name of the class already (another field or constant, or one of
    `HAND_CONSTANTS`). So ``class`` and ``class_`` in one type are ``class__`` and
    ``class_``: every value keeps an attribute of its own.
    """
    names = [c.name for c in section.constants] + [a.name for a in section.fields if a.name]
    taken = {n for n in names if not keyword.iskeyword(n)}
    taken |= {constant for constant, _, _ in HAND_CONSTANTS.get(key, ())}
    result: dict[str, str] = {}
    for name in names:
        attribute = name
        while keyword.iskeyword(attribute) or (attribute != name and attribute in taken):
            attribute += "_"
        taken.add(attribute)
        result[name] = attribute
    return result


_MEMBER = re.compile(r"[A-Za-z][A-Za-z0-9_]*\Z")
"""An enum member name: no ``_`` in front (``_sunder_`` names are the enum module's)."""


def _member(name: str) -> bool:
    return bool(_MEMBER.match(name)) and not keyword.iskeyword(name) and name != "mro"


def _enum_members(d: Definition, constants: list[Constant], prefix_len: int) -> list[str]:
    """The members of an enum of ``constants``: their names without the prefix, else whole
    (``_`` after a Python keyword or ``mro``); `DsdlError` if two would be one."""
    stripped = [c.name[prefix_len:] for c in constants]
    if all(_member(s) for s in stripped):
        return stripped
    members = [c.name if _member(c.name) else f"{c.name}_" for c in constants]
    seen: dict[str, Constant] = {}
    for member, c in zip(members, constants, strict=True):
        other = seen.setdefault(member, c)
        if other is not c:
            raise DsdlError(
                d.path, c.line, f"constants {other.name} and {c.name} would both be {member}"
            )
    return members


def _enum_source(
    name: str, kind: str, constants: list[Constant], prefix_len: int, d: Definition
) -> list[str]:
    which = f"``{constants[0].name[:prefix_len]}*``" if prefix_len else f"of ``{d.full_name}``"
    lines = ["", "", f"class {name}(enum.{kind}):", *_doc(f"DSDL constants {which}.", "    "), ""]
    for member, c in zip(_enum_members(d, constants, prefix_len), constants, strict=True):
        lines.append(f"    {member} = {_literal(c.value)}")
        if c.comment:
            lines += _doc(c.comment, "    ")
    return lines


def _order(p: Plan, generated: list[str]) -> list[str]:
    """The generated keys, every nested type before its users (defaults are instances)."""
    done: set[str] = set()
    ordered: list[str] = []

    def visit(key: str) -> None:
        if key in done:
            return
        done.add(key)
        _, section = p.sections[key]
        for a in section.fields:
            target = nested_name(a.type)
            if target is not None and target in generated_set:
                visit(target)
        ordered.append(key)

    generated_set = set(generated)
    for key in generated:
        visit(key)
    return ordered


def module_source(p: Plan, generate: Iterable[str], docstring: str, imports: dict[str, str]) -> str:
    """The source of a module of classes for the keys ``generate``.

    Args:
        p: The plan of every key the classes refer to.
        generate: The keys whose classes the module defines.
        docstring: The module docstring.
        imports: Other class names the module needs, to the module they come from.
    """
    generated = _order(p, list(generate))
    head = [
        *_doc(docstring, ""),
        "",
        "from __future__ import annotations",
        "",
        "import enum",
        "from typing import Any, ClassVar, TypeAlias",
        "",
        "from veronte4x.display import HtmlDisplay",
        "from veronte4x.dronecan.written import frozen_dataclass",
    ]
    by_module: dict[str, list[str]] = {}
    for name, module in sorted(imports.items()):
        by_module.setdefault(module, []).append(name)
    for module, names in sorted(by_module.items()):
        head.append(f"from {module} import (")
        head += [f"    {n}," for n in sorted(names)]
        head.append(")")
    head += [
        "",
        "_setattr = object.__setattr__",
        '"""How each ``__init__`` sets a frozen field."""',
    ]
    body: list[str] = []
    for (key, _), (name, kind, constants, prefix) in p.enums.items():
        if key in generated:
            body += _enum_source(name, kind, constants, len(prefix), p.sections[key][0])
    for key, (name, constants) in p.constant_enums.items():
        if key in generated:
            body += _enum_source(name, "IntEnum", constants, 0, p.sections[key][0])
    done: set[str] = set()
    for key in generated:
        if key in p.members:
            body += _union_source(key, p, done)
        else:
            body += _class_source(key, p)
    exported = sorted(
        {e[0] for k, e in p.enums.items() if k[0] in generated}
        | {e[0] for k, e in p.constant_enums.items() if k in generated}
        | {p.names[k] for k in generated}
        | {m for k in generated for m in p.members.get(k, ()) if m not in imports}
    )
    tables = ["", "", "__all__ = ["]
    tables += [f"    {name!r}," for name in exported]
    tables += ["]", "", "CLASSES: dict[str, Any] = {"]
    tables += [f"    {key!r}: {p.names[key]}," for key in generated]
    tables += ["}", '"""The class of each key (full name, with ``.Request``/``.Response``)."""']
    tables += ["", "ENUMS: dict[tuple[str, str], type] = {"]
    tables += [
        f"    ({key!r}, {f!r}): {name},"
        for (key, f), (name, kind, _, _) in p.enums.items()
        if key in generated and kind == "IntEnum"
    ]
    tables += ["}", '"""The enum a field decodes to, by (key, field name)."""']
    tables += ["", "UNION_MEMBERS: dict[str, tuple[type, ...]] = {"]
    tables += [
        f"    {key!r}: ({', '.join(p.members[key])},)," for key in generated if key in p.members
    ]
    tables += ["}", '"""The member classes of each union, in member order."""', ""]
    return "\n".join(head + body + tables)


def _union_source(key: str, p: Plan, done: set[str]) -> list[str]:
    """The member classes of a union (each once: unions may share them), and its alias."""
    d, section = p.sections[key]
    name = p.names[key]
    lines: list[str] = []
    for a, member in zip(section.fields, p.members[key], strict=True):
        if isinstance(a.type, str) or member in done:
            continue
        done.add(member)
        annotation, default = _python_type(a.type, p, None)
        lines += ["", "", "@frozen_dataclass", f"class {member}(HtmlDisplay):"]
        lines += _doc(f"Member ``{a.name}`` of the union ``{d.full_name}``.", "    ")
        uses = [  # a member may serve several unions: its facts are those of every use
            other.fields[index]
            for union, names in p.members.items()
            for index, used in enumerate(names)
            if used == member and union in p.sections
            for other in (p.sections[union][1],)
        ]
        facts = _fact_lines(("value", use) for use in uses)
        lines += ["", *facts] if facts else []
        lines += _slots_and_init([("value", annotation, default)])
    lines += ["", "", f"{name}: TypeAlias = {' | '.join(p.members[key])}"]
    lines += _doc(_title(d, key) + "\n\n" + (section.doc or ""), "")
    return lines


def main() -> None:
    """Rewrite the modules generated from the shipped DSDL
    (`veronte4x.dronecan.shipped_source`)."""
    from veronte4x.dronecan.shipped_source import main as write_all

    write_all()


if __name__ == "__main__":
    main()
