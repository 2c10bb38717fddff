"""The Arrow schema of every table `read_tables` gives, fixed in advance from the layouts.

Veronte tables take their columns from the codec's frame layouts (the same data the codec
compiles), DroneCAN tables from the DSDL definitions. Column names are those of
`veronte4x.capture.fields`: tuple attributes become ``name_0``, ``name_1``..., nested
structs ``outer.inner``. Types follow the wire: the smallest unsigned or signed integer
that holds the field, ``float32`` for float32 and float16 (every float16 is a float32;
Polars and DuckDB read no float16), ``float64`` for scaled integers, ``bool``, ``binary``
for raw bytes and uint8 arrays, ``string`` for DroneCAN text fields, a ``list`` for other
arrays (RawCommand's ``cmd``), and dictionary-encoded names for enums, whose dictionary
lists every wire value (a value without a member is named by its number).

A DSDL union (param ``Value``, ``NumericValue``) becomes ``name.type``, the member's
name, and one nullable column per member with a value: ``name.integer_value`` (int64),
``name.real_value`` (float32), ``name.boolean_value`` (uint8), ``name.string_value``
(string); ``empty``, a struct without named fields, has no column. A member's column holds
its value as a list's struct holds a field (`value_type`): a struct member as an Arrow
struct, an array member as a list (binary for ``uint8``). Inside a list's struct a union
is a struct of those columns (`union_type`): ``type`` and a field per member.

Every DroneCAN type of a type set (standard or vendor) has its table, by the same rules:
nested structs flattened (``timestamp.usec`` of ``gnss.Fix2``), arrays of structs as lists
of Arrow structs (``commands`` of ``actuator.ArrayCommand``, enums there by name as at
the top level), other arrays as lists (``covariance``), ``uint8`` arrays as ``binary``,
but for text. DSDL v0 has no text type; a ``uint8[<=N]`` field is text by the rule of
`veronte4x.dronecan.generate.is_text` (its name or its comment says so: ``name`` of
``GetNodeInfoResponse``, ``path`` of ``file.Path``, ``text`` and ``source`` of
``debug.LogMessage``, the union member ``string_value``), applied here to every type set,
vendor namespaces included. With the text form ``string`` (`TextForm`, the default) those
columns are Arrow ``string``, checked by `veronte4x.capture.columnar.text`; with
``binary`` they keep their exact bytes. Text fields inside lists of structs and inside a
union's struct member stay binary (the standard set has none). A field named as a head
column (``HEAD_NAMES``: ``timestamp``, ``channel``, ``can_id``, ``sender``, ``node_id``,
``destination_node_id``) or as a column a Parquet dataset adds (``DATASET_NAMES``:
``source``, ``capture``) becomes ``message.`` and its name (``message.node_id`` of
``dynamic_node_id.Allocation``, ``message.source`` of ``debug.LogMessage``, a vendor type's
``message.channel``); fields inside lists of structs, and those named ``error``,
``detail`` or ``data`` (columns of the ``errors`` and ``unknown`` tables only), keep their
names.
"""

from __future__ import annotations

import dataclasses
import functools
import weakref
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from operator import attrgetter
from typing import Any, TypeAlias, cast

import numpy as np
import numpy.typing as npt
import pyarrow as pa

from veronte4x.capture.busmap import AUTOPILOT_NAMES, TextForm
from veronte4x.capture.columnar.veronte import layout_list
from veronte4x.codec import Codec
from veronte4x.codec.compiler import FrameLayout
from veronte4x.codec.fields import Field, FieldKind
from veronte4x.codec.layouts import AUTOPILOT_FIELDS, AUTOPILOTS
from veronte4x.dronecan.can_id import TransferKind
from veronte4x.dronecan.schema import Array, Member, Scalar, Struct, StructField, Union
from veronte4x.dronecan.serializer import TABLE_BITS, enum_table
from veronte4x.dronecan.typeset import TypeSet, types_or_default
from veronte4x.units import unit

SENDERS: tuple[str, ...] = (
    "arbiter",
    *AUTOPILOT_NAMES,
    "autopilot",
    "dronecan",
    "unknown",
    *(f"node {n}" for n in range(128)),
)
"""Every value of the ``sender`` column, in dictionary order."""
SENDER_INDEX = {name: index for index, name in enumerate(SENDERS)}
NODE_SENDER = SENDER_INDEX["node 0"]
"""Dictionary index of ``node 0``; node N is this plus N."""

CHANNEL = pa.dictionary(pa.int32(), pa.string())
SENDER = pa.dictionary(pa.int16(), pa.string())
ERROR = pa.dictionary(pa.int16(), pa.string())

TIME = pa.timestamp("us", tz="UTC")
"""The ``timestamp`` column: the capture's time in microseconds, UTC. candump logs have
microseconds; python-can's readers give float seconds, which hold a time of today to about
0.24 us: they are taken to the nearest microsecond."""
SECONDS = pa.field("timestamp", pa.float64(), metadata={"unit": "s"})
"""The ``timestamp`` column as float seconds (``time="seconds"`` or ``"relative"``)."""

HEAD = (
    pa.field("timestamp", TIME),
    pa.field("channel", CHANNEL),
    pa.field("can_id", pa.uint32()),
    pa.field("sender", SENDER),
)
"""The columns every table starts with, as `veronte4x.capture.Record` has them."""
NODE_ID = pa.field("node_id", pa.uint8())
DESTINATION = pa.field("destination_node_id", pa.uint8())
PROBLEM = (
    pa.field("error", ERROR),
    pa.field("detail", pa.string()),
    pa.field("data", pa.binary()),
)
UNKNOWN = (pa.field("detail", pa.string()), pa.field("data", pa.binary()))
HEAD_NAMES = frozenset(f.name for f in (*HEAD, NODE_ID, DESTINATION))
"""The head columns of a DroneCAN table."""
DATASET_NAMES = frozenset({"source", "capture"})
"""The columns a Parquet dataset adds to every table: the capture's file (``source``) and
the key of its directory (``capture=``)."""


@dataclass(frozen=True)
class Column:
    """One field column of a table.

    Attributes:
        name: Column name.
        type: Arrow type.
        get: Its value from a message object (for a dictionary column, the index).
        names: The dictionary of a dictionary column.
        text: A DroneCAN text field as ``string``: its values are bytes, made strings
            (and checked) as the table is built.
        dsdl: The DSDL type of the values ``get`` gives (None standing for null), where
            they hold structs or unions: made Arrow by `arrow_values`.
        source: A dictionary column whose indices are the values of column ``source``
            (the name beside a number: ``selected_name`` beside ``selected``).
    """

    name: str
    type: pa.DataType
    get: Callable[[Any], Any]
    names: tuple[str, ...] | None = None
    text: bool = False
    dsdl: Scalar | Array | Struct | Union | None = None
    source: str | None = None

    def values(self, messages: Sequence[Any]) -> Any:
        """The column's values of ``messages`` as a table takes them: a list, or an Arrow
        array (`arrow_values`) where they hold structs or unions."""
        values = [self.get(message) for message in messages]
        return values if self.dsdl is None else arrow_values(self.dsdl, values)


Making: TypeAlias = tuple[str, pa.DataType, str, str, tuple[str, ...] | None]
"""How `veronte4x.capture.columnar.tables.Tables.add_columns` makes one column
(`TableSpec.plan`)."""


@dataclass(frozen=True)
class TableSpec:
    """The schema of one message type's table.

    Attributes:
        kind: The table's name, `veronte4x.capture.Record.kind` of its rows.
        head: The record columns it starts with.
        columns: The message's field columns.
    """

    kind: str
    head: tuple[pa.Field, ...]
    columns: tuple[Column, ...]

    @functools.cached_property
    def schema(self) -> pa.Schema:
        """The table's Arrow schema; fields with a physical unit carry it in their metadata
        (``unit``: ``V``, ``A``, ``K``, ``rpm``, ``%``, ``s``). Made once per spec."""
        fields = [pa.field(c.name, c.type, metadata=_unit(self.kind, c.name)) for c in self.columns]
        return pa.schema([*self.head, *fields])

    @functools.cached_property
    def plan(self) -> tuple[Making, ...]:
        """How each column of `schema` is made, in order: (name, Arrow type, where from,
        the key there, enum names). Where from: ``text`` (a text field's bytes), ``head``
        (a head column) or ``field`` (a field's values; a dictionary column's key is its
        `Column.source`, if any). Made once per spec."""
        columns = {c.name: c for c in self.columns}
        plan: list[Making] = []
        for field in self.schema:
            column = columns.get(field.name)
            if column is None:
                plan.append((field.name, field.type, "head", field.name, None))
            elif column.text:
                plan.append((field.name, field.type, "text", field.name, None))
            else:
                key = column.source or column.name
                plan.append((field.name, field.type, "field", key, column.names))
        return tuple(plan)


def _unit(kind: str, name: str) -> dict[str, str] | None:
    symbol = unit(kind, name)
    return None if symbol is None else {"unit": symbol}


def integer_type(low: int, high: int) -> pa.DataType:
    """The smallest Arrow integer type holding ``low..high``."""
    for bits in (8, 16, 32, 64):
        if low >= 0 and high < 1 << bits:
            return pa.from_numpy_dtype(f"uint{bits}")
        if -(1 << (bits - 1)) <= low and high < 1 << (bits - 1):
            return pa.from_numpy_dtype(f"int{bits}")
    raise ValueError(f"no Arrow integer holds {low}..{high}")


# Veronte ---------------------------------------------------------------------------------


def veronte_layouts(codec: Codec) -> dict[str, list[FrameLayout]]:
    """The frame layouts of each Veronte message type this codec decodes, by type name."""
    found: dict[str, list[FrameLayout]] = {}
    for layout in layout_list(codec):
        found.setdefault(layout.name, []).append(layout)
    return found


def veronte_spec(kind: str, variants: list[FrameLayout]) -> TableSpec:
    """The table of a Veronte message type, from the layouts that decode to it."""
    by_attr: dict[str, list[Field]] = {}
    for layout in variants:
        for f in layout.fields:
            if f.attr is not None:
                by_attr.setdefault(f.attr, []).append(f)
    columns: list[Column] = []
    for dc_field in dataclasses.fields(cast(Any, variants[0].message)):
        attr = dc_field.name
        fields = sorted({f.index or 0: f for f in by_attr[attr]}.items())
        for index, f in fields:
            tupled = f.index is not None
            name = f"{attr}_{index}" if tupled else attr
            get = _item(attr, index) if tupled else attrgetter(attr)
            columns.append(Column(name, veronte_type(f), get))
            if attr in AUTOPILOT_FIELDS:  # the name beside, as the exported DBC's value table
                named = Column(f"{name}_name", enum_type(AUTOPILOTS), get, AUTOPILOTS, source=name)
                columns.append(named)
    return TableSpec(kind, HEAD, tuple(columns))


def _item(attr: str, index: int) -> Callable[[Any], Any]:
    return lambda message: getattr(message, attr)[index]


def veronte_type(f: Field) -> pa.DataType:
    """The Arrow type of a Veronte field's decoded values."""
    if f.kind in (FieldKind.UNSIGNED, FieldKind.SIGNED):
        if f.scale is not None:
            return pa.float64()
        if f.kind is FieldKind.SIGNED:
            return integer_type(-(1 << (f.bits - 1)), (1 << (f.bits - 1)) - 1)
        return integer_type(0, f.maximum if f.maximum is not None else (1 << f.bits) - 1)
    if f.kind is FieldKind.BOOL:
        return pa.bool_()
    if f.kind is FieldKind.FLOAT32:
        return pa.float32()
    if f.kind is FieldKind.BYTES:
        return pa.binary()
    if f.kind is FieldKind.MAPPED:
        values = [value for _, value in f.mapping]
        return integer_type(min(values), max(values))
    raise ValueError(f"field {f.label} of kind {f.kind.value} holds no value")


# DroneCAN --------------------------------------------------------------------------------


def dronecan_specs(types: TypeSet | None = None, text: TextForm = "string") -> dict[str, TableSpec]:
    """The table of every DroneCAN type of a type set (None: the default), by class name,
    text fields in the form ``text``."""
    types = types_or_default(types, "dronecan_specs")
    forms = _SPECS.setdefault(types, {})
    specs = forms.get(text)
    if specs is None:
        specs = forms[text] = _dronecan_specs(types, types.text_fields if text == "string" else {})
    return dict(specs)


_SPECS: weakref.WeakKeyDictionary[TypeSet, dict[str, dict[str, TableSpec]]] = (
    weakref.WeakKeyDictionary()
)
"""The tables of each type set, by text form, kept as long as the set lives."""


def _dronecan_specs(types: TypeSet, texts: Texts) -> dict[str, TableSpec]:
    specs = {}
    for data_type in types.data_types:
        head: tuple[pa.Field, ...] = (*HEAD, NODE_ID)
        if data_type.kind is not TransferKind.MESSAGE:
            head = (*head, DESTINATION)
        kind = data_type.schema.cls.__name__
        columns = _struct_columns(data_type.schema, "", (), texts)
        named = (dataclasses.replace(c, name=field_column(c.name)) for c in columns)
        specs[kind] = TableSpec(kind, head, tuple(named))
    return specs


Texts = Mapping[type, frozenset[str]]
"""The text fields to give as strings: the attributes of each class (`TypeSet.text_fields`),
or none."""


def _struct_columns(
    struct: Struct, prefix: str, path: tuple[str, ...], texts: Texts
) -> list[Column]:
    """The columns of a struct's fields, ``texts`` as strings."""
    columns: list[Column] = []
    for f in struct.fields:
        if not f.name:
            continue  # void padding
        name, where = prefix + f.name, (*path, f.name)
        t = f.type
        if isinstance(t, Struct):
            columns += _struct_columns(t, name + ".", where, texts)
        elif isinstance(t, Union):
            columns += _union_columns(t, name, where, texts)
        elif isinstance(t, Array) and not isinstance(t.item, Scalar):
            columns.append(Column(name, value_type(t), _path(where), dsdl=t))
        elif f.name in texts.get(struct.cls, ()):
            columns.append(Column(name, pa.string(), _path(where), text=True))
        elif isinstance(t, Array):
            columns.append(Column(name, value_type(t), _path(where)))
        elif (names := field_enum_names(f)) is not None:
            columns.append(Column(name, enum_type(names), _enum_index(where), names))
        else:
            columns.append(Column(name, scalar_type(t), _path(where)))
    return columns


def field_column(name: str) -> str:
    """The column of a DroneCAN field: its name, or ``message.`` and its name for a field
    named as a head column (``node_id`` of ``dynamic_node_id.Allocation``) or as a column a
    dataset adds (``source`` of ``debug.LogMessage``)."""
    return f"message.{name}" if name in HEAD_NAMES or name in DATASET_NAMES else name


def struct_type(struct: Struct) -> pa.DataType:
    """The Arrow struct of a struct inside a list or a union (enums as their names, as at
    the top level; unions as `union_type`)."""
    return pa.struct([pa.field(f.name, field_type(f)) for f in struct.fields if f.name])


def field_type(f: StructField) -> pa.DataType:
    """The Arrow type of a field of a struct inside a list or a union: `enum_type` for an
    enum field, else `value_type`."""
    names = field_enum_names(f)
    return value_type(f.type) if names is None else enum_type(names)


def field_enum_names(f: StructField) -> tuple[str, ...] | None:
    """The `enum_names` of an enum field; None for another field, and for an enum field
    wider than `TABLE_BITS` (``ardupilot.gnss.Status.status``, 23 bits of flags): its column
    holds the number, as a dictionary of every wire value would not fit."""
    if f.enum is None or not isinstance(f.type, Scalar) or f.type.bits > TABLE_BITS:
        return None
    return enum_names(f.enum, f.type.bits)


def union_type(union: Union) -> pa.DataType:
    """The Arrow struct of a union inside a list's struct: ``type``, the member's name
    (dictionary-encoded, indexed by the tag), and a field per member with a value
    (`valued_members`), null but for the member set: the top-level columns
    ``name.type``, ``name.<member>`` as the fields of a struct ``name``."""
    names = tuple(member.name for member in union.members)
    fields = [pa.field(field, value_type(m.type)) for field, m in valued_members(union)]
    return pa.struct([pa.field("type", enum_type(names)), *fields])


def valued_members(union: Union) -> tuple[tuple[str, Member], ...]:
    """The members of a union that hold a value, each with the name of its field or
    column: all but structs without named fields (``Empty``), whose name says it all. The
    name is the member's, but ``type_`` for a member named ``type``, the tag's name (no
    other member is named ``type_``: their classes would take one name, which
    `veronte4x.dronecan.load_dsdl` refuses)."""
    return tuple(
        ("type_" if m.name == "type" else m.name, m)
        for m in union.members
        if not (isinstance(m.type, Struct) and not any(f.name for f in m.type.fields))
    )


def value_type(t: Scalar | Array | Struct | Union) -> pa.DataType:
    """The Arrow type of a DSDL type's values inside a list or a union: structs and unions
    as Arrow structs, ``uint8`` arrays as binary, other arrays as lists."""
    if isinstance(t, Struct):
        return struct_type(t)
    if isinstance(t, Array):
        if t.is_bytes:
            return pa.binary()
        return pa.list_(value_type(t.item))
    if isinstance(t, Union):
        return union_type(t)
    return scalar_type(t)


def struct_array(struct: Struct, children: list[pa.Array], size: int) -> pa.Array:
    """``size`` values of a struct from its named fields' arrays (`struct_type`)."""
    if not children:  # a struct without named fields: its values are empty
        return pa.StructArray.from_buffers(struct_type(struct), size, [None], children=[])
    return pa.StructArray.from_arrays(children, fields=list(struct_type(struct)))


def union_array(union: Union, tag: npt.NDArray[np.int64], members: list[pa.Array]) -> pa.Array:
    """A union's values (`union_type`) from each element's tag and an array per valued
    member (null where another member is set). A tag without a member (a refused
    transfer's) counts as the first member's."""
    names = tuple(member.name for member in union.members)
    children = [enum_array(names, np.where(tag < len(names), tag, 0)), *members]
    return pa.StructArray.from_arrays(children, fields=list(union_type(union)))


def enum_array(names: tuple[str, ...], indices: npt.ArrayLike) -> pa.Array:
    """Values of an enum column (`enum_type` of ``names``) from their wire values."""
    index = pa.array(indices, enum_type(names).index_type)
    return pa.DictionaryArray.from_arrays(index, pa.array(names, pa.string()))


def field_values(f: StructField, values: Sequence[Any]) -> pa.Array:
    """Decoded values of a struct's field (`field_type`), as `arrow_values` makes them."""
    names = field_enum_names(f)
    if names is None:
        return arrow_values(f.type, values)
    return enum_array(names, np.array([int(value) for value in values], np.int64))


def spread(values: pa.Array, chosen: npt.NDArray[np.int64], size: int) -> pa.Array:
    """``size`` values: ``values`` at the positions ``chosen``, null elsewhere."""
    index = np.full(size, -1, np.int64)
    index[chosen] = np.arange(len(chosen))
    return values.take(pa.array(index, mask=index < 0))


def arrow_values(t: Scalar | Array | Struct | Union, values: Sequence[Any]) -> pa.Array:
    """Decoded values of a DSDL type (None: null) as an Arrow array of `value_type`, the
    form the column-wise decoder gives them: how the per-frame path makes its columns of
    structs and unions."""
    present = np.array([i for i, value in enumerate(values) if value is not None], np.int64)
    if len(present) < len(values):
        return spread(arrow_values(t, [values[i] for i in present]), present, len(values))
    if isinstance(t, Struct):
        children = [
            field_values(f, [getattr(value, f.name) for value in values])
            for f in t.fields
            if f.name
        ]
        return struct_array(t, children, len(values))
    if isinstance(t, Union):
        classes = {member.cls: index for index, member in enumerate(t.members)}
        tag = np.array([classes[type(value)] for value in values], np.int64)
        valued = [member for _, member in valued_members(t)]
        members = []
        for index, member in enumerate(t.members):
            if member not in valued:
                continue
            chosen = np.flatnonzero(tag == index)
            inner = [_member_value(member, values[i]) for i in chosen.tolist()]
            members.append(spread(arrow_values(member.type, inner), chosen, len(values)))
        return union_array(t, tag, members)
    if isinstance(t, Array) and not t.is_bytes:
        offsets = np.zeros(len(values) + 1, np.int32)
        np.cumsum([len(value) for value in values], out=offsets[1:])
        items = arrow_values(t.item, [item for value in values for item in value])
        return pa.ListArray.from_arrays(pa.array(offsets), items)
    return pa.array(list(values), value_type(t))


def _member_value(member: Member, value: Any) -> Any:
    """The value of a union member from the object that holds it (a struct member's
    object is its value)."""
    return value if isinstance(member.type, Struct) else value.value


def _union_columns(union: Union, name: str, where: tuple[str, ...], texts: Texts) -> list[Column]:
    members = tuple(member.name for member in union.members)
    classes = {member.cls: index for index, member in enumerate(union.members)}
    get_value = _path(where)
    columns = [
        Column(f"{name}.type", enum_type(members), lambda m: classes[type(get_value(m))], members)
    ]
    for field, member in valued_members(union):
        get = _member(get_value, member)
        if "value" in texts.get(member.cls, ()):
            columns.append(Column(f"{name}.{field}", pa.string(), get, text=True))
            continue
        t = member.type
        nested = isinstance(t, Struct) or (isinstance(t, Array) and not isinstance(t.item, Scalar))
        dsdl = t if nested else None
        columns.append(Column(f"{name}.{field}", value_type(t), get, dsdl=dsdl))
    return columns


def _member(get_value: Callable[[Any], Any], member: Member) -> Callable[[Any], Any]:
    def get(message: Any) -> Any:
        value = get_value(message)
        return _member_value(member, value) if type(value) is member.cls else None

    return get


def _path(where: tuple[str, ...]) -> Callable[[Any], Any]:
    return attrgetter(".".join(where))


def _enum_index(where: tuple[str, ...]) -> Callable[[Any], Any]:
    get = _path(where)
    return lambda message: int(get(message))


def scalar_type(t: Scalar) -> pa.DataType:
    """The Arrow type of a DSDL scalar's decoded values."""
    if t.kind == "float":
        return pa.float64() if t.bits == 64 else pa.float32()
    if t.kind == "bool":
        return pa.bool_()
    return integer_type(t.low, t.high)


_ENUM_NAMES: weakref.WeakKeyDictionary[type, dict[int, tuple[str, ...]]] = (
    weakref.WeakKeyDictionary()
)


def enum_names(enum: type, bits: int) -> tuple[str, ...]:
    """The name of every wire value of an enum field: the member's, or the number (made
    once per enum and width: the column-wise decoders ask for them per batch)."""
    known = _ENUM_NAMES.setdefault(enum, {})
    found = known.get(bits)
    if found is None:
        table = enum_table(enum, bits)
        found = known[bits] = tuple(str(getattr(v, "name", None) or int(v)) for v in table)
    return found


def enum_type(names: tuple[str, ...]) -> pa.DataType:
    """Dictionary-encoded names, indexed by the wire value."""
    return pa.dictionary(integer_type(0, len(names) - 1), pa.string())


def all_specs(
    codec: Codec, types: TypeSet | None = None, text: TextForm = "string"
) -> dict[str, TableSpec]:
    """Every message table a capture decoded with this codec and these DroneCAN types
    (None: the default set) can give, by kind, DroneCAN text fields in the form ``text``."""
    specs = {
        kind: veronte_spec(kind, variants) for kind, variants in veronte_layouts(codec).items()
    }
    specs.update(dronecan_specs(types, text))
    return specs


ERRORS = TableSpec("errors", (*HEAD, *PROBLEM), ())
"""The table of every record whose ``error`` is set."""
UNDECODED = TableSpec("unknown", (*HEAD, *UNKNOWN), ())
"""The table of undecoded traffic: records with neither a message nor an error."""
