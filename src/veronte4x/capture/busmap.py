"""Which CAN IDs carry which Veronte role, and how the rest of a bus is read.

Defaults are the IDs of Embention's manuals and configuration templates: AP1, AP2,
AP3 and the external autopilot send on 8, 9, 10 and 11, the arbiter on 255, all with
standard 11-bit IDs. They are defaults only; a TOML file overrides them::

    [veronte]
    arbiter_id = 255
    autopilot_ids = [8, 9, 10, 11]   # AP1, AP2, AP3, external
    extended = false                 # true if the Veronte IDs are 29-bit
    pwm_packing = "lsb_first"        # or "msb_first" (an open point, see the docs)
    allow_excess = false             # ignore bytes past a layout (padded senders)

    [[veronte.layouts]]              # declared layouts for the payloads that are not public
    command = 5
    name = "ScorpionTelemetry"
    byte_order = "little"            # or "big"
    fields = [
        { kind = "unsigned", name = "throttle", bits = 8, scale = [0, 200, 0.0, 100.0] },
        { kind = "skip", bits = 4 },
        { kind = "signed", name = "current", bits = 12 },
        { kind = "float32", name = "voltage" },
        { kind = "constant", value = 165, bits = 8 },
    ]

    [dronecan]
    enabled = true                   # 29-bit frames that are not Veronte go to DroneCAN
    strict_transfers = false         # veronte4x's strict transfer rules, not libcanard's

    [dbc]                            # the DBC files given with --dbc (or BusMap.dbc)
    lax = false                      # read files cantools reads only with strict=False
    first = false                    # a CAN ID a DBC knows is the DBC's, even a Veronte
                                     # ID or a 29-bit ID DroneCAN would decode
"""

from __future__ import annotations

import dataclasses
import enum
import functools
import math
import os
import sys
import warnings
from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any, Literal

from veronte4x import codec
from veronte4x.codec.layouts import AUTOPILOTS
from veronte4x.dronecan.typeset import TypeSet
from veronte4x.errors import Veronte4xError, argument_type_error
from veronte4x.extras import require

AUTOPILOT_NAMES = tuple(name.removesuffix(" AP") for name in AUTOPILOTS)
"""The autopilots as senders, by index (``AP1`` .. ``external``): the names of their one
home, `veronte4x.codec.layouts.AUTOPILOTS`, the external one as records and tables have
always given their sender, ``external``."""


TextForm = Literal["string", "binary"]
"""How tables give the DroneCAN fields whose DSDL makes them text (their ``text`` option,
`veronte4x.dronecan.generate.is_text`): ``string``, Arrow strings (the default; a value that
is not UTF-8 is null, with a ``bad text`` row in ``errors`` holding its bytes);
``binary``, every ``uint8`` array as its exact bytes."""
TEXT_FORMS: tuple[TextForm, ...] = ("string", "binary")


def check_text_form(text: str) -> TextForm:
    """The ``text`` option, checked.

    Raises:
        ValueError: It is none of `TEXT_FORMS`.
    """
    if text not in TEXT_FORMS:
        raise ValueError(
            f"text={text!r}: give 'string' (text fields as strings, the default) or 'binary' "
            "(every uint8 array as its exact bytes)"
        )
    return text


class Role(enum.Enum):
    """What a frame is, by its CAN ID."""

    ARBITER = "arbiter"
    AUTOPILOT = "autopilot"
    DRONECAN = "dronecan"
    UNKNOWN = "unknown"


class BusMapError(Veronte4xError, ValueError):
    """A bus map file that cannot be used: unknown keys, wrong types, bad layouts."""


@dataclass(frozen=True)
class BusMap:
    """CAN IDs of the Veronte roles, and the codec choices for this installation.

    Attributes:
        arbiter_id: CAN ID the arbiter sends Status, Score and its other frames on.
        autopilot_ids: CAN IDs of AP1, AP2, AP3 and the external autopilot.
        extended: The Veronte IDs are 29-bit (extended) rather than 11-bit.
        pwm_packing: Packing order of the PWM set frames.
        allow_excess: Ignore bytes past a layout instead of reporting an error.
        layouts: Declared layouts for the commands whose payload is not public.
        dronecan: Decode the other 29-bit frames as DroneCAN.
        dronecan_types: The DroneCAN types to decode (a `veronte4x.dronecan.TypeSet`);
            None for the default set (the standard one, plus what
            `veronte4x.dronecan.load_dsdl` added).
        dbc: DBC files for the frames outside the bus map (see `veronte4x.capture.dbc_in`).
        dronecan_text: How tables give DroneCAN text fields (`TextForm`): ``string`` or
            ``binary``. Records keep their bytes either way.
        dbc_lax: Read the DBC files cantools reads only with ``strict=False`` (overlapping
            signals, a signal past its message) that way, with a
            `veronte4x.capture.dbc_in.DbcWarning` saying what the strict reading found.
        dbc_first: A frame on a CAN ID a DBC file knows is the DBC's, even on a Veronte
            ID or a 29-bit ID DroneCAN would decode. Without it such a DBC message is
            reported once (a ``DbcWarning``) and its frames stay the bus map's.
        strict_transfers: Reassemble DroneCAN transfers under veronte4x's strict rules
            (``Reassembler(strict=True)``) rather than libcanard's, the default: see
            "Transfer acceptance" in docs/dronecan/reassembly.md.
    """

    arbiter_id: int = 255
    autopilot_ids: tuple[int, int, int, int] = (8, 9, 10, 11)
    extended: bool = False
    pwm_packing: codec.PwmPacking = codec.PwmPacking.LSB_FIRST
    allow_excess: bool = False
    layouts: tuple[codec.Layout, ...] = ()
    dronecan: bool = True
    dronecan_types: TypeSet | None = None
    dbc: tuple[str, ...] = ()
    dronecan_text: TextForm = "string"
    dbc_lax: bool = False
    dbc_first: bool = False
    strict_transfers: bool = False
    _roles: dict[int, tuple[Role, int | None]] = field(
        init=False, repr=False, compare=False, default_factory=dict
    )
    _dbc_ids: frozenset[int] = field(init=False, repr=False, compare=False, default=frozenset())

    def __post_init__(self) -> None:
        check_text_form(self.dronecan_text)
        roles = self._roles
        roles[self.arbiter_id] = (Role.ARBITER, None)
        for index, can_id in enumerate(self.autopilot_ids):
            if can_id in roles:
                raise BusMapError(f"CAN ID {can_id} is given to two Veronte roles")
            roles[can_id] = (Role.AUTOPILOT, index)
        if self.dbc:
            self._take_dbc()

    def _take_dbc(self) -> None:
        """Read the DBC files (once, `veronte4x.capture.dbc_in.decoder_of`): with
        ``dbc_first``, give their CAN IDs to them; else report the messages shadowed."""
        from veronte4x.capture import dbc_in

        object.__setattr__(self, "dbc", tuple(dict.fromkeys(map(os.fspath, self.dbc))))
        if not self.dbc_first:
            for line in dbc_in.shadowed(self):
                warnings.warn(line, dbc_in.DbcWarning, stacklevel=4)
            return
        claimed = dbc_in.claimed(self)
        for can_id, extended in claimed:
            if extended == self.extended:
                self._roles.pop(can_id, None)
        object.__setattr__(self, "_dbc_ids", frozenset(i for i, extended in claimed if extended))

    @property
    def veronte_roles(self) -> Mapping[int, tuple[Role, int | None]]:
        """CAN ID to (role, autopilot index) for the Veronte IDs."""
        return MappingProxyType(self._roles)

    @property
    def dbc_ids(self) -> frozenset[int]:
        """The 29-bit CAN IDs DroneCAN leaves to the DBC files (``dbc_first``)."""
        return self._dbc_ids

    def role(self, can_id: int, extended: bool) -> tuple[Role, int | None]:
        """The role of a frame and, for an autopilot, its index (0 = AP1 .. 3 = external)."""
        if extended == self.extended:
            found = self._roles.get(can_id)
            if found is not None:
                return found
        if extended and self.dronecan and can_id not in self._dbc_ids:
            return Role.DRONECAN, None
        return Role.UNKNOWN, None

    def with_types(self, types: TypeSet | None) -> BusMap:
        """This bus map with the DroneCAN type set ``types`` (itself for None)."""
        if types is None:
            return self
        if not isinstance(types, TypeSet):
            raise argument_type_error("BusMap.with_types", "types", "a TypeSet", types)
        return dataclasses.replace(self, dronecan_types=types)

    def with_strict_transfers(self, strict: bool | None) -> BusMap:
        """This bus map with DroneCAN's strict transfer rules on or off (itself for None)."""
        if strict is None:
            return self
        if not isinstance(strict, bool):
            raise argument_type_error(
                "BusMap.with_strict_transfers", "strict", "a bool or None", strict
            )
        return dataclasses.replace(self, strict_transfers=strict)

    def with_text(self, text: TextForm | None) -> BusMap:
        """This bus map with the DroneCAN text form ``text`` (itself for None).

        Raises:
            ValueError: ``text`` is none of `TEXT_FORMS`.
        """
        if text is None:
            return self
        return dataclasses.replace(self, dronecan_text=check_text_form(text))

    def codec(self) -> codec.Codec:
        """A Veronte codec with this bus map's choices (made once for the same choices: a
        codec does not change once made, and making one compiles its decoders)."""
        return _codec(self.pwm_packing, tuple(self.layouts))

    @classmethod
    def from_toml(cls, path: str | os.PathLike[str]) -> BusMap:
        """Read a bus map from a TOML file (see the module docstring for the keys).

        Raises:
            BusMapError: Unknown keys, wrong types or bad layouts.
            MissingExtraError: Python 3.10 without tomli (the ``toml`` extra).
        """
        if sys.version_info >= (3, 11):
            import tomllib
        else:  # pragma: no cover - Python 3.10
            tomllib = require("tomli", "toml", "reading TOML on Python 3.10")
        with open(path, "rb") as file:
            try:
                document = tomllib.load(file)
            except tomllib.TOMLDecodeError as error:
                raise BusMapError(
                    f"{os.fspath(path)}: not a TOML file: {error}; fix the bus map (see 'The "
                    "bus map' in the captures docs)"
                ) from None
            except UnicodeDecodeError as error:
                raise BusMapError(
                    f"{os.fspath(path)}: not UTF-8 text (byte {error.start}): save the bus "
                    "map as UTF-8, as TOML requires"
                ) from None
        return cls.from_dict(document)

    @classmethod
    def from_dict(cls, document: Mapping[str, Any]) -> BusMap:
        """Build a bus map from the parsed TOML document, checking every key and value.

        Raises:
            BusMapError: Unknown keys, wrong types or bad layouts; the message names the key.
        """
        top = _table(document, "the bus map")
        _only(top, {"veronte", "dronecan", "dbc"}, "top level")
        veronte = _table(top.get("veronte", {}), "[veronte]")
        _only(
            veronte,
            {"arbiter_id", "autopilot_ids", "extended", "pwm_packing", "allow_excess", "layouts"},
            "[veronte]",
        )
        dronecan = _table(top.get("dronecan", {}), "[dronecan]")
        _only(dronecan, {"enabled", "text", "strict_transfers"}, "[dronecan]")
        dbc = _table(top.get("dbc", {}), "[dbc]")
        _only(dbc, {"lax", "first"}, "[dbc]")
        default = cls()
        ids = tuple(
            _int(i, "[veronte] autopilot_ids")
            for i in _list(veronte.get("autopilot_ids", []), "[veronte] autopilot_ids")
        )
        if ids and len(ids) != 4:
            raise BusMapError("[veronte] autopilot_ids needs 4 IDs: AP1, AP2, AP3, external")
        packing = veronte.get("pwm_packing", "lsb_first")
        choices = [p.value for p in codec.PwmPacking]
        if packing not in choices:
            raise BusMapError(
                f"[veronte] pwm_packing: {packing!r} is not one of {', '.join(choices)}"
            )
        decode_dronecan = _bool(dronecan.get("enabled", True), "[dronecan] enabled")
        text = dronecan.get("text", default.dronecan_text)
        if text not in TEXT_FORMS:
            raise BusMapError(f"[dronecan] text: {text!r} is not one of {', '.join(TEXT_FORMS)}")
        layouts = tuple(
            _layout(_table(entry, f"[[veronte.layouts]] number {number}"), number)
            for number, entry in enumerate(_list(veronte.get("layouts", []), "veronte.layouts"), 1)
        )
        _distinct_names(layouts)
        try:
            bus_map = cls(
                arbiter_id=_int(veronte.get("arbiter_id", default.arbiter_id), "arbiter_id"),
                autopilot_ids=ids or default.autopilot_ids,  # type: ignore[arg-type]
                extended=_bool(veronte.get("extended", False), "extended"),
                pwm_packing=codec.PwmPacking(packing),
                allow_excess=_bool(veronte.get("allow_excess", False), "allow_excess"),
                layouts=layouts,
                dronecan=decode_dronecan,
                dronecan_text=text,
                strict_transfers=_bool(
                    dronecan.get("strict_transfers", False), "[dronecan] strict_transfers"
                ),
                dbc_lax=_bool(dbc.get("lax", False), "[dbc] lax"),
                dbc_first=_bool(dbc.get("first", False), "[dbc] first"),
            )
            bus_map.codec()  # declared layouts are checked against the built-in ones here
        except (ValueError, TypeError) as error:
            if isinstance(error, BusMapError):
                raise
            raise BusMapError(f"bus map: {error}") from None
        return bus_map


def _only(table: Mapping[str, Any], allowed: set[str], where: str) -> None:
    unknown = set(table) - allowed
    if unknown:
        raise BusMapError(f"unknown key(s) in {where}: {', '.join(sorted(map(str, unknown)))}")


def _table(value: Any, where: str) -> Mapping[str, Any]:
    if not isinstance(value, Mapping):
        raise BusMapError(f"{where}: {value!r} is not a table of keys")
    return value


def _list(value: Any, where: str) -> list[Any]:
    if not isinstance(value, list):
        raise BusMapError(f"{where}: {value!r} is not a list")
    return value


def _int(value: Any, name: str) -> int:
    if not isinstance(value, int) or isinstance(value, bool) or not 0 <= value < 1 << 29:
        raise BusMapError(f"{name}: {value!r} is not a CAN ID")
    return value


def _bool(value: Any, name: str) -> bool:
    if not isinstance(value, bool):
        raise BusMapError(f"{name}: {value!r} is not true or false")
    return value


def _integer(spec: Mapping[str, Any], key: str, where: str, default: int | None = None) -> int:
    value = spec.get(key, default)
    if value is None:
        raise BusMapError(f"{where}: {key} is missing")
    if not isinstance(value, int) or isinstance(value, bool):
        raise BusMapError(f"{where}: {key} = {value!r} is not an integer")
    return value


def _text(spec: Mapping[str, Any], key: str, where: str) -> str:
    value = spec.get(key)
    if value is None:
        raise BusMapError(f"{where}: {key} is missing")
    if not isinstance(value, str):
        raise BusMapError(f"{where}: {key} = {value!r} is not text")
    return value


def reserved_names() -> frozenset[str]:
    """Names a declared layout may not take: the tables of `veronte4x.capture.read_tables`
    that are not messages (``errors``, ``unknown``), and every built-in message class,
    Veronte and DroneCAN (whose tables keep their names whether DroneCAN is decoded or not)."""
    from veronte4x.codec import layouts
    from veronte4x.dronecan.definitions import DATA_TYPES

    built_in = [layout.message for layout in layouts.ARBITRATION_AND_VERSION]
    built_in += [layout.message for layout in layouts.PWM_SET.values()]
    built_in += list(layouts.OPAQUE_CLASSES)
    names = {cls.__name__ for cls in built_in}
    names |= {t.schema.cls.__name__ for t in DATA_TYPES}
    return frozenset(names | {"errors", "unknown"})


RECORD_COLUMNS = frozenset(
    {"timestamp", "channel", "can_id", "sender", "node_id", "destination_node_id", "source"}
)
"""The columns every table of `veronte4x.capture.read_tables` starts with (``source`` in a
Parquet dataset): no declared field may take one of these names."""


def _layout(entry: Mapping[str, Any], number: int) -> codec.Layout:
    where = f"[[veronte.layouts]] number {number}"
    _only(entry, {"command", "name", "byte_order", "fields"}, where)
    name = _text(entry, "name", where)
    where = f"[[veronte.layouts]] {name!r}"
    if name in reserved_names():
        raise BusMapError(
            f"{where}: the name {name!r} is taken by veronte4x (a built-in message or a table "
            "of read_tables): choose another"
        )
    command = _integer(entry, "command", where)
    specs = _list(entry.get("fields", []), f"{where} fields")
    fields = [
        _field(_table(spec, f"{where} field {n}"), f"{where} field {n}")
        for n, spec in enumerate(specs, 1)
    ]
    order = entry.get("byte_order", "little")
    if order not in ("little", "big"):
        raise BusMapError(f"{where}: byte_order = {order!r} is not 'little' or 'big'")
    try:
        return codec.Layout(command, name, fields, codec.ByteOrder(order))
    except (ValueError, TypeError) as error:
        raise BusMapError(f"{where}: {error}") from None


def _distinct_names(layouts: tuple[codec.Layout, ...]) -> None:
    seen: set[str] = set()
    for layout in layouts:
        if layout.name in seen:
            raise BusMapError(f"[[veronte.layouts]]: the name {layout.name!r} is given twice")
        seen.add(layout.name)


def _field(spec: Mapping[str, Any], where: str) -> codec.Field:
    kind = spec.get("kind")
    _only(spec, {"kind", "name", "bits", "scale", "value"}, where)
    try:
        if kind == "constant":
            return codec.constant(
                _integer(spec, "value", where), _integer(spec, "bits", where, default=8)
            )
        if kind == "skip":
            return codec.skip(_integer(spec, "bits", where))
        name = _text(spec, "name", where) if kind in _NAMED else ""
        if name in RECORD_COLUMNS:
            raise BusMapError(
                f"{where}: the field name {name!r} is a column of every table: choose another"
            )
        if kind == "float32":
            return codec.float32(name)
        if kind in ("unsigned", "signed"):
            bits = _integer(spec, "bits", where)
            scale = spec.get("scale")
            linear = None if scale is None else _scale(scale, kind, bits, f"{where} scale")
            make = codec.unsigned if kind == "unsigned" else codec.signed
            return make(name, bits, scale=linear)
    except (ValueError, TypeError) as error:
        if isinstance(error, BusMapError):
            raise
        raise BusMapError(f"{where}: {error}") from None
    raise BusMapError(
        f"{where}: kind = {kind!r}: expected constant, skip, unsigned, signed or float32"
    )


_NAMED = ("float32", "unsigned", "signed")


def _scale(scale: Any, kind: str, bits: int, where: str) -> codec.Linear:
    """A field's ``scale = [encoded_min, encoded_max, decoded_min, decoded_max]``, checked so
    that every wire value of the field decodes to a finite number."""
    shape = "[encoded_min, encoded_max, decoded_min, decoded_max]"
    if not isinstance(scale, list) or len(scale) != 4:
        raise BusMapError(f"{where}: {scale!r} is not {shape}")
    low, high, decoded_min, decoded_max = scale
    if not all(isinstance(v, int) and not isinstance(v, bool) for v in (low, high)):
        raise BusMapError(f"{where}: the encoded values of {scale!r} are not integers")
    if not all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in scale[2:]):
        raise BusMapError(f"{where}: the decoded values of {scale!r} are not numbers")
    if low == high:
        raise BusMapError(f"{where}: encoded_min and encoded_max of {scale!r} are equal")
    if not (1 <= bits <= 64):
        raise BusMapError(f"{where}: a field of {bits} bits cannot be scaled")
    linear = codec.Linear(low, high, decoded_min, decoded_max)
    wire = (0, (1 << bits) - 1) if kind == "unsigned" else (-(1 << bits - 1), (1 << bits - 1) - 1)
    try:
        values = [decoded_min, decoded_max, linear.factor, linear.offset]
        values += [linear.offset + raw * linear.factor for raw in wire]
    except OverflowError:
        values = [math.inf]
    if not all(math.isfinite(v) for v in values):
        raise BusMapError(
            f"{where}: {scale!r} does not give a finite number for every {bits}-bit wire "
            "value: give finite decoded values of a smaller range"
        )
    return linear


@functools.lru_cache(maxsize=32)
def _codec(pwm_packing: codec.PwmPacking, layouts: tuple[codec.Layout, ...]) -> codec.Codec:
    return codec.Codec(pwm_packing=pwm_packing, layouts=layouts)
