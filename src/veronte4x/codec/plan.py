"""The plan of a codec's decoders: what its route table asks of them, with no source text.

`plan` reads a `RouteTable` once and answers every question the decoders' generators
(`veronte4x.codec.decoders`) would otherwise put to it while writing source: which commands
are told apart by sender and byte 1, the forms of each route and their order, which layouts
several commands share, which commands keep their payload as bytes. The generators only
render this plan.
"""

from __future__ import annotations

from dataclasses import dataclass

from veronte4x.codec import layouts
from veronte4x.codec.compiler import FrameLayout, refuses
from veronte4x.codec.messages import Message, Sender
from veronte4x.codec.routes import Route, RouteTable, family, forms_of


@dataclass(frozen=True)
class Forms:
    """The forms of one message a frame may take, told apart by length.

    Attributes:
        routes: The forms' routes (one command, sender and header), largest layout first.
    """

    routes: tuple[Route, ...]

    @property
    def first(self) -> Route:
        """The largest form's route (the only one of a single-form message)."""
        return self.routes[0]

    @property
    def header(self) -> int | None:
        """The value byte 1 of these frames has, or None for any other value."""
        return self.routes[0].header


@dataclass(frozen=True)
class SenderRoutes:
    """Where one sender's frames of a command told apart by sender go.

    Attributes:
        sender: The sender.
        headed: The forms that need a value of byte 1, one per value.
        other: The forms taking any other byte 1, or None (such a frame is unknown).
        apart: The one headed route has the other's size and the other layout refuses its
            byte 1: the other's own decoding tells them apart (the fast decoder's shortcut).
    """

    sender: Sender
    headed: tuple[Forms, ...]
    other: Forms | None
    apart: bool


@dataclass(frozen=True)
class SenderCommand:
    """A command whose frames are told apart by sender or byte 1.

    Attributes:
        command: The command byte.
        family: The name of its frames for the error of a frame too short to have a byte 1,
            or None when no route needs byte 1.
        senders: Each sender's routes, in `Sender` order.
    """

    command: int
    family: str | None
    senders: tuple[SenderRoutes, ...]

    def of(self, sender: Sender) -> SenderRoutes:
        """The routes of one sender."""
        return next(routes for routes in self.senders if routes.sender is sender)


@dataclass(frozen=True)
class Shared:
    """A layout routed from several commands (PwmSet), told by no sender.

    Attributes:
        layout: The layout.
        commands: Its command bytes.
    """

    layout: FrameLayout
    commands: tuple[int, ...]


@dataclass(frozen=True)
class DecoderPlan:
    """Everything the decoders' generators need from a route table.

    Attributes:
        told_apart: The commands told apart by sender or byte 1, in table order.
        shared: The layouts of several commands, in table order.
        pwm: The PWM layout of the table's packing, or None.
        routed: The forms of each other command that has a decoder of its own (every
            command but those of shared layouts), in table order.
        opaque: The message class of each command that keeps its payload as raw bytes.
    """

    told_apart: tuple[SenderCommand, ...]
    shared: tuple[Shared, ...]
    pwm: FrameLayout | None
    routed: tuple[Forms, ...]
    opaque: tuple[tuple[int, type[Message]], ...]

    def singles(self) -> list[Route]:
        """The routes of one form and one command that are not opaque, in table order."""
        commands = {command for command, _ in self.opaque}
        return [
            forms.first
            for forms in self.routed
            if len(forms.routes) == 1 and forms.first.command not in commands
        ]


def plan(table: RouteTable) -> DecoderPlan:
    """The plan of the decoders of a route table."""
    told_apart = [c for c in table.commands() if table.by_sender(c)]
    plain = {
        layout: commands
        for layout, commands in table.layout_commands().items()
        if commands[0] not in told_apart
    }
    return DecoderPlan(
        told_apart=tuple(_sender_command(table, command) for command in told_apart),
        shared=tuple(Shared(layout, tuple(c)) for layout, c in plain.items() if len(c) > 1),
        pwm=next((layout for layout in plain if layout in layouts.PWM_SET.values()), None),
        routed=_routed(table, plain),
        opaque=tuple(
            (c[0], layout.message)
            for layout, c in plain.items()
            if len(c) == 1 and table.opaque(table.of(c[0])[0])
        ),
    )


def _routed(table: RouteTable, plain: dict[FrameLayout, list[int]]) -> tuple[Forms, ...]:
    """The forms of each command of ``plain`` (layouts not told apart by sender) that has a
    decoder of its own: all but the commands of a shared layout."""
    commands = [c for c in table.commands() if any(c in found for found in plain.values())]
    return tuple(
        Forms(tuple(forms_of(table.of(command))))
        for command in commands
        if len(table.of(command)) > 1 or len(plain[table.of(command)[0].frame]) == 1
    )


def _sender_command(table: RouteTable, command: int) -> SenderCommand:
    """The plan of a command told apart by sender or byte 1."""
    headed = any(r.header is not None for r in table.of(command))
    return SenderCommand(
        command,
        family(command, table) if headed else None,
        tuple(_sender_routes(table, command, sender) for sender in Sender),
    )


def _sender_routes(table: RouteTable, command: int, sender: Sender) -> SenderRoutes:
    """Where one sender's frames of a command go."""
    groups = [Forms(tuple(group)) for group in table.for_sender(command, sender)]
    headed = tuple(g for g in groups if g.header is not None)
    other = next((g for g in groups if g.header is None), None)
    apart = (
        len(headed) == 1
        and other is not None
        and other.first.frame.fixed_size == headed[0].first.frame.fixed_size
        and refuses(other.first.frame, 1, headed[0].header or 0)
    )
    return SenderRoutes(sender, headed, other, apart)
