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
"""

from __future__ import annotations

import enum
import os
import sys
from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any

from veronte4x import codec
from veronte4x.errors import Veronte4xError
from veronte4x.extras import require

AUTOPILOT_NAMES = ("AP1", "AP2", "AP3", "external")
"""Autopilot names by index, as the Status message orders them."""


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
    """

    arbiter_id: int = 255
    autopilot_ids: tuple[int, int, int, int] = (8, 9, 10, 11)
    extended: bool = False
    pwm_packing: codec.PwmPacking = codec.PwmPacking.LSB_FIRST
    allow_excess: bool = False
    layouts: tuple[codec.Layout, ...] = ()
    dronecan: bool = True
    _roles: dict[int, tuple[Role, int | None]] = field(
        init=False, repr=False, compare=False, default_factory=dict
    )

    def __post_init__(self) -> None:
        roles = self._roles
        roles[self.arbiter_id] = (Role.ARBITER, None)
        for index, can_id in enumerate(self.autopilot_ids):
            if can_id in roles:
                raise BusMapError(f"CAN ID {can_id} is given to two Veronte roles")
            roles[can_id] = (Role.AUTOPILOT, index)

    @property
    def veronte_roles(self) -> Mapping[int, tuple[Role, int | None]]:
        """CAN ID to (role, autopilot index) for the Veronte IDs."""
        return MappingProxyType(self._roles)

    def role(self, can_id: int, extended: bool) -> tuple[Role, int | None]:
        """The role of a frame and, for an autopilot, its index (0 = AP1 .. 3 = external)."""
        if extended == self.extended:
            found = self._roles.get(can_id)
            if found is not None:
                return found
        if extended and self.dronecan:
            return Role.DRONECAN, None
        return Role.UNKNOWN, None

    def codec(self) -> codec.Codec:
        """A Veronte codec with this bus map's choices."""
        return codec.Codec(pwm_packing=self.pwm_packing, layouts=self.layouts)

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
                raise BusMapError(f"{os.fspath(path)}: {error}") from None
        return cls.from_dict(document)

    @classmethod
    def from_dict(cls, document: Mapping[str, Any]) -> BusMap:
        """Build a bus map from the parsed TOML document.

        Raises:
            BusMapError: Unknown keys, wrong types or bad layouts.
        """
        _only(document, {"veronte", "dronecan"}, "top level")
        veronte = dict(document.get("veronte", {}))
        _only(
            veronte,
            {"arbiter_id", "autopilot_ids", "extended", "pwm_packing", "allow_excess", "layouts"},
            "[veronte]",
        )
        dronecan = dict(document.get("dronecan", {}))
        _only(dronecan, {"enabled"}, "[dronecan]")
        default = cls()
        try:
            ids = tuple(_int(i, "autopilot_ids") for i in veronte.get("autopilot_ids", ()))
            if ids and len(ids) != 4:
                raise BusMapError("autopilot_ids needs 4 IDs: AP1, AP2, AP3, external")
            bus_map = cls(
                arbiter_id=_int(veronte.get("arbiter_id", default.arbiter_id), "arbiter_id"),
                autopilot_ids=ids or default.autopilot_ids,  # type: ignore[arg-type]
                extended=_bool(veronte.get("extended", False), "extended"),
                pwm_packing=codec.PwmPacking(veronte.get("pwm_packing", "lsb_first")),
                allow_excess=_bool(veronte.get("allow_excess", False), "allow_excess"),
                layouts=tuple(_layout(entry) for entry in veronte.get("layouts", ())),
                dronecan=_bool(dronecan.get("enabled", True), "[dronecan] enabled"),
            )
            bus_map.codec()  # declared layouts are checked against the built-in ones here
            return bus_map
        except (ValueError, TypeError, KeyError) as error:
            if isinstance(error, BusMapError):
                raise
            raise BusMapError(f"bus map: {error}") from None


def _only(table: Mapping[str, Any], allowed: set[str], where: str) -> None:
    unknown = set(table) - allowed
    if unknown:
        raise BusMapError(f"unknown key(s) in {where}: {', '.join(sorted(unknown))}")


def _int(value: Any, name: str) -> int:
    if not isinstance(value, int) or isinstance(value, bool) or not 0 <= value < 1 << 29:
        raise BusMapError(f"{name}: {value!r} is not a CAN ID")
    return value


def _bool(value: Any, name: str) -> bool:
    if not isinstance(value, bool):
        raise BusMapError(f"{name}: {value!r} is not true or false")
    return value


def _layout(entry: Mapping[str, Any]) -> codec.Layout:
    _only(entry, {"command", "name", "byte_order", "fields"}, "[[veronte.layouts]]")
    fields = [_field(spec) for spec in entry.get("fields", ())]
    order = codec.ByteOrder(entry.get("byte_order", "little"))
    return codec.Layout(int(entry["command"]), str(entry["name"]), fields, order)


def _field(spec: Mapping[str, Any]) -> codec.Field:
    kind = spec.get("kind")
    _only(spec, {"kind", "name", "bits", "scale", "value"}, f"a {kind} field")
    if kind == "constant":
        return codec.constant(int(spec["value"]), int(spec.get("bits", 8)))
    if kind == "skip":
        return codec.skip(int(spec["bits"]))
    if kind == "float32":
        return codec.float32(str(spec["name"]))
    if kind in ("unsigned", "signed"):
        scale = spec.get("scale")
        linear = None
        if scale is not None:
            encoded_min, encoded_max, decoded_min, decoded_max = scale
            linear = codec.Linear(int(encoded_min), int(encoded_max), decoded_min, decoded_max)
        make = codec.unsigned if kind == "unsigned" else codec.signed
        return make(str(spec["name"]), int(spec["bits"]), scale=linear)
    raise BusMapError(f"field kind {kind!r}: expected constant, skip, unsigned, signed, float32")
