"""The Veronte 4x route table: which layout decodes a frame, written once as data.

A frame goes to a layout by its command byte (byte 0), who sent it (`Sender`), its byte 1
(the 0xFF header of command 0) and its length. The codec's decoders (checked and fast), the
column-wise decoder of `veronte4x.capture`, ``veronte4x list`` and the protocol pages of the
docs are all generated from `ROUTES`; a new built-in frame type is a message class, a layout
and a route here (see the contributors' page "Adding a frame type").

Source: Veronte Autopilot 4x Software Manual, section 3 "CAN Bus protocol" (message-type
table, sections 3.1.1-3.1.4).

How a frame finds its route, for one command byte:

1. Routes of the frame's sender come before routes of either sender (``sender=None``).
2. Routes that need a value of byte 1 (``header``) come before those that take any other
   value; a frame of one byte cannot be told and is a `DecodeError`.
3. Routes left with the same command, sender and header are forms of one message told
   apart by length: a frame takes the form of the largest layout it holds; a smaller form
   takes the lengths up to the next form's only with ``allow_excess``. Any other length is
   a `DecodeError` that names the forms.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, replace

from veronte4x.codec import layouts
from veronte4x.codec.compiler import FrameLayout
from veronte4x.codec.declared import Layout
from veronte4x.codec.fields import FieldKind
from veronte4x.codec.messages import Sender
from veronte4x.codec.pwm import PWM_COMMANDS, PwmPacking
from veronte4x.errors import LayoutError

HEADER = 0xFF
"""The byte 1 of the command-0 frames that are not a Score or an arbitration variable."""


@dataclass(frozen=True)
class Route:
    """One line of the route table.

    Attributes:
        command: The command byte (byte 0).
        layout: The layout, or one layout per PWM packing (the codec's choice).
        sender: Who sends the frame, or None for either sender.
        header: The value byte 1 must have, or None for any other value.
        form: The name of this form where one message has forms of several lengths.
    """

    command: int
    layout: FrameLayout | Mapping[PwmPacking, FrameLayout]
    sender: Sender | None = None
    header: int | None = None
    form: str = ""

    @property
    def frame(self) -> FrameLayout:
        """The layout of a resolved route (see `RouteTable`)."""
        assert isinstance(self.layout, FrameLayout), "resolve the route first"
        return self.layout

    @property
    def key(self) -> tuple[int, Sender | None, int | None]:
        """What tells this route from the others: command, sender, header."""
        return self.command, self.sender, self.header


ROUTES: tuple[Route, ...] = (
    Route(0, layouts.STATUS_4X, Sender.ARBITER, HEADER, form="4x form"),
    Route(0, layouts.STATUS_CEX, Sender.ARBITER, HEADER, form="CEX form"),
    Route(0, layouts.SCORE, Sender.ARBITER),
    Route(0, layouts.READY, Sender.AUTOPILOT, HEADER),
    Route(0, layouts.ARBITRATION_VARIABLE, Sender.AUTOPILOT),
    Route(1, layouts.VERSION_REQUEST, form="request"),
    Route(1, layouts.VERSION_RESPONSE, form="response"),
    *(Route(command, layouts.PWM_SET) for command in PWM_COMMANDS.values()),
    *(Route(command, layout) for command, layout in layouts.OPAQUE.items()),
)
"""Every built-in route; the order is that of ``veronte4x list`` and of the docs."""


def _ranges(commands: Iterable[int]) -> str:
    """Command bytes as the docs write them: ``5-10, 16-19``, ``4, 14, 15``."""
    runs: list[list[int]] = []
    for command in sorted(commands):
        if runs and runs[-1][-1] == command - 1:
            runs[-1].append(command)
        else:
            runs.append([command])
    parts: list[str] = []
    for run in runs:
        parts += [f"{run[0]}-{run[-1]}"] if len(run) > 2 else [str(c) for c in run]
    return ", ".join(parts)


def _and(parts: list[str]) -> str:
    return parts[0] if len(parts) == 1 else ", ".join(parts[:-1]) + " and " + parts[-1]


class RouteTable:
    """The routes of one codec: `ROUTES` with its PWM packing and its declared layouts.

    A declared layout takes over its command's opaque route, or routes a command that has
    none, from either sender.

    Args:
        pwm_packing: The packing of the PWM layouts.
        declared: The declared layouts.
        routes: The routes before both, `ROUTES` by default.

    Raises:
        LayoutError: A declared layout for a command whose layout is public.
    """

    def __init__(
        self,
        pwm_packing: PwmPacking = PwmPacking.LSB_FIRST,
        declared: Iterable[Layout] = (),
        routes: Iterable[Route] | None = None,
    ) -> None:
        routes = ROUTES if routes is None else routes
        resolved = [
            route
            if isinstance(route.layout, FrameLayout)
            else replace(route, layout=route.layout[pwm_packing])
            for route in routes
        ]
        for route in resolved:
            _check(route)
        opaque = {r.command for r in resolved if self._opaque(r)}
        routed = {r.command for r in resolved}
        for layout in declared:
            command = layout.command
            if command in routed and command not in opaque:
                free = _ranges(set(range(256)) - routed)
                raise LayoutError(
                    f"{layout.name}: command {command} has a public layout; only commands "
                    f"{_and([_ranges(opaque) + ' (layout not public)', free])} can be declared"
                )
            own = Route(command, layout.frame)
            if command in opaque:
                resolved = [own if r.command == command else r for r in resolved]
                opaque.discard(command)
            else:
                resolved = [r for r in resolved if r.command != command] + [own]
                routed.add(command)
        self.routes: tuple[Route, ...] = tuple(resolved)
        """The resolved routes: each with one `FrameLayout`."""
        groups: dict[tuple[int, Sender | None, int | None], list[Route]] = {}
        for route in self.routes:
            groups.setdefault(route.key, []).append(route)
        for group in groups.values():
            sizes = {r.frame.fixed_size for r in group}
            if len(group) > 1 and (len(sizes) < len(group) or not all(r.form for r in group)):
                raise LayoutError(
                    f"{group[0].frame.name}: routes of one command, sender and header are "
                    "forms told apart by length: each needs a form name and a length of its own"
                )

    @staticmethod
    def _opaque(route: Route) -> bool:
        return layouts.OPAQUE.get(route.command) is route.layout

    def opaque(self, route: Route) -> bool:
        """Whether the route keeps its payload as raw bytes (an `OpaqueMessage`)."""
        return self._opaque(route)

    def commands(self) -> list[int]:
        """The routed command bytes, in table order."""
        return list(dict.fromkeys(r.command for r in self.routes))

    def of(self, command: int) -> list[Route]:
        """The routes of one command byte, in table order."""
        return [r for r in self.routes if r.command == command]

    def by_sender(self, command: int) -> bool:
        """Whether the command's frames are told apart by sender or byte 1."""
        return any(r.sender is not None or r.header is not None for r in self.of(command))

    def for_sender(self, command: int, sender: Sender) -> list[list[Route]]:
        """The groups of forms one sender's frames of a command go to, header groups first.

        Each group holds the forms of one (command, sender, header), largest layout first.
        """
        mine = [r for r in self.of(command) if r.sender is sender]
        either = [r for r in self.of(command) if r.sender is None]
        groups: dict[int | None, list[Route]] = {}
        for route in mine + either:
            if route.header not in groups or groups[route.header][0].sender is route.sender:
                groups.setdefault(route.header, []).append(route)
        ordered = sorted(groups.items(), key=lambda item: item[0] is None)
        return [forms_of(group) for _, group in ordered]

    def layouts(self) -> list[FrameLayout]:
        """Every layout of the table, each once, in table order."""
        return list(dict.fromkeys(r.frame for r in self.routes))

    def layout_commands(self) -> dict[FrameLayout, list[int]]:
        """The command bytes each layout is routed from."""
        found: dict[FrameLayout, list[int]] = {}
        for route in self.routes:
            commands = found.setdefault(route.frame, [])
            if route.command not in commands:
                commands.append(route.command)
        return found


def _check(route: Route) -> None:
    """Raise `LayoutError` unless the route's layout starts with its command byte."""
    first = route.frame.fields[0] if route.frame.fields else None
    if (
        first is None
        or first.bits != 8
        or not (
            (first.kind is FieldKind.CONSTANT and first.value == route.command)
            or (first.kind is FieldKind.MAPPED and route.command in dict(first.mapping))
        )
    ):
        raise LayoutError(
            f"{route.frame.name}: a route of command {route.command} needs a layout whose "
            f"first field is that command byte"
        )
    if route.header is not None and not 0 <= route.header <= 255:
        raise LayoutError(f"{route.frame.name}: header {route.header!r} is not a byte")


def forms_of(group: list[Route]) -> list[Route]:
    """The forms of one message, largest layout first."""
    return sorted(group, key=lambda r: -r.frame.fixed_size)


def length_error(forms: list[Route]) -> str:
    """What a frame of none of the forms' lengths is told: ``4 (CEX form) or 6 (4x form)``."""
    sizes = [f"{r.frame.fixed_size} ({r.form})" for r in reversed(forms)]
    return " or ".join(sizes)


def family(command: int, table: RouteTable) -> str:
    """The name of a command's frames, from its layouts' command constant (``t_arbitration``)."""
    for route in table.of(command):
        description = route.frame.fields[0].description
        if description.startswith("message type t_"):
            return description.removeprefix("message type t_")
    return f"command-{command}"


def sender_names(route: Route) -> str:
    """Who sends a route's frames, as ``veronte4x list`` and the docs say it."""
    if route.sender is Sender.ARBITER:
        return "arbiter"
    if route.sender is Sender.AUTOPILOT:
        return "autopilots"
    return "any Veronte ID"
