"""The generators of `Codec`'s decoders: they render a `DecoderPlan` as Python source.

Two decoders, each one function with the layouts' bodies inlined so that a frame costs one
Python call: the checked one makes every check and raises the precise error
(`compiler.inline_decoder`); the fast one tries optimistic bodies
(`compiler.optimistic_decoder`), one exact-size unpack for PWM frames and a slice for
opaque ones, and hands any frame out of the ordinary to the checked one.
"""

from __future__ import annotations

import struct
from collections.abc import Callable, Sequence
from typing import Any

from veronte4x.codec import layouts
from veronte4x.codec.compiler import (
    MAX_FRAME_BYTES,
    FrameDecoder,
    FrameLayout,
    inline_decoder,
    optimistic_decoder,
)
from veronte4x.codec.messages import Message, OpaqueMessage, PwmSet, Sender
from veronte4x.codec.plan import DecoderPlan, Forms, SenderCommand, SenderRoutes, Shared
from veronte4x.codec.routes import Route, length_error
from veronte4x.codegen import compile_source
from veronte4x.codegen import slot_builder as builder
from veronte4x.errors import DecodeError, UnknownCommandError, argument_type_error
from veronte4x.words import counted


def _as_bytes(data: object) -> bytes:
    """``data`` as bytes if it is bytes-like, else the `TypeError` of the policy."""
    if isinstance(data, (bytes, bytearray, memoryview)):
        return bytes(data)
    raise argument_type_error("decode", "data", "bytes-like", data)


def _check_types(data: object, sender: object) -> None:
    """Raise the `TypeError` of the policy if ``data`` or ``sender`` has the wrong type."""
    if not isinstance(data, (bytes, bytearray, memoryview)):
        raise argument_type_error("decode", "data", "bytes-like", data)
    if not isinstance(sender, Sender):
        raise argument_type_error("decode", "sender", "a Sender", sender)


class _Errors:
    """The errors the generated `Codec.decode` raises, built out of its hot path."""

    @staticmethod
    def empty(data: bytes) -> DecodeError:
        return DecodeError(None, f"0 bytes; a frame has 1 to {MAX_FRAME_BYTES}", data)

    @staticmethod
    def unknown(command: int, data: bytes) -> UnknownCommandError:
        return UnknownCommandError(command, data)

    @staticmethod
    def sender(sender: object) -> TypeError:
        return argument_type_error("decode", "sender", "a Sender", sender)


def _short(family: str) -> Callable[[bytes], DecodeError]:
    """The error of a frame too short to carry the byte 1 its routes are told apart by."""
    article = "an" if family[:1] in "aeiou" else "a"
    reason = f"{article} {family} frame has at least 2 bytes"

    def error(data: bytes) -> DecodeError:
        return DecodeError(None, reason, data)

    return error


def _lengths(forms: Sequence[Route]) -> Callable[[int, bytes], DecodeError]:
    """The error of a frame whose length is none of its message's forms'."""
    name, expected = forms[0].frame.name, length_error(list(forms))

    def error(n: int, data: bytes) -> DecodeError:
        return DecodeError(name, f"{counted(n, 'byte')}; {expected} expected", data)

    return error


def _is(command: int) -> str:
    """The test of the command byte."""
    return "not command" if command == 0 else f"command == {command}"


def _form_test(number: int, size: int) -> str:
    """The length test of the form ``number`` (largest first) of a message."""
    return f"n >= {size}" if number == 0 else f"n == {size} or (excess and n > {size})"


def _opaque_classes(
    opaque: Sequence[tuple[int, type[Message]]],
) -> tuple[type[Message] | None, ...]:
    """The message class of each opaque command byte, by command byte."""
    classes: list[type[Message] | None] = [None] * 256
    for command, cls in opaque:
        classes[command] = cls
    return tuple(classes)


def _compiled(lines: list[str], namespace: dict[str, Any], title: str) -> Any:
    """The ``decode`` function the lines define."""
    compile_source("\n".join(lines), namespace, title)
    return namespace["decode"]


# The checked decoder.

_CHECKED_HEAD = (
    "def decode(data, *, sender, allow_excess=False):",
    "    if data.__class__ is not _bytes:",
    "        data = _as_bytes(data)",
    "    excess = allow_excess",
    "    n = _len(data)",
    "    if not n:",
    "        raise _errors.empty(data)",
    "    command = data[0]",
)
_CHECKED_SENDER = (
    "    if sender.__class__ is not _Sender:",
    "        raise _errors.sender(sender)",
)
_CHECKED_OPAQUE = (
    "    cls = _opaque[command]",
    f"    if cls is not None and n <= {MAX_FRAME_BYTES}:",
    "        o = _opaque_builder()",
    "        o.payload = data[1:]",
    "        o.__class__ = cls",
    "        return o",
)
_CHECKED_TAIL = (
    "    decoder = _by_command[command]",
    "    if decoder is None:",
    "        raise _errors.unknown(command, data)",
    "    return decoder(data, excess)",
)


def checked_decoder(plan: DecoderPlan) -> Callable[..., Message]:
    """The checked ``decode(data, *, sender, allow_excess=False)``: every check, with the
    bodies of the layouts' decoders inlined."""
    render = _Checked()
    lines = list(_CHECKED_HEAD)
    for command in plan.told_apart:
        lines += [f"    if {_is(command.command)}:", *render.told_apart(command, 8)]
    lines += _CHECKED_SENDER
    for shared in plan.shared:
        lines += render.shared(shared)
    if plan.opaque:
        render.namespace["_opaque"] = _opaque_classes(plan.opaque)
        render.namespace["_opaque_builder"] = builder(OpaqueMessage)
        lines += _CHECKED_OPAQUE
    by_command: list[FrameDecoder | None] = [None] * 256
    for forms in plan.routed:
        by_command[forms.first.command] = forms_decoder(forms)
    render.namespace["_by_command"] = tuple(by_command)
    decode: Callable[..., Message] = _compiled(
        [*lines, *_CHECKED_TAIL], render.namespace, "decode Codec"
    )
    return decode


class _Checked:
    """The checked decoder's namespace as its lines are rendered, and the suffix of each
    inlined layout's names (``Status``, then ``Status_2`` for a second layout of that name)."""

    def __init__(self) -> None:
        self.namespace: dict[str, Any] = {
            "_bytes": bytes,
            "_as_bytes": _as_bytes,
            "_len": len,
            "_Sender": Sender,
            "_errors": _Errors,
        }
        self.namespace.update({f"_{sender.name}": sender for sender in Sender})
        self._suffixes: dict[int, str] = {}

    def body(self, layout: FrameLayout, indent: int) -> list[str]:
        """The inlined body of a layout's checked decoder."""
        suffix = self._suffixes.get(id(layout))
        if suffix is None:
            taken = sum(s.split("_")[0] == layout.name for s in self._suffixes.values())
            suffix = layout.name + (f"_{taken + 1}" if taken else "")
            self._suffixes[id(layout)] = suffix
        lines, names = inline_decoder(layout, suffix, indent)
        self.namespace.update(names)
        return lines

    def forms(self, forms: Forms, indent: int) -> list[str]:
        """Lines that decode a frame with one of a message's forms, by its length."""
        if len(forms.routes) == 1:
            return self.body(forms.first.frame, indent)
        pad = " " * indent
        lines: list[str] = []
        for number, route in enumerate(forms.routes):
            lines.append(f"{pad}if {_form_test(number, route.frame.fixed_size)}:")
            lines += self.body(route.frame, indent + 4)
        error = f"_lengths_{forms.first.frame.name}"
        self.namespace[error] = _lengths(forms.routes)
        return [*lines, f"{pad}raise {error}(n, data)"]

    def told_apart(self, command: SenderCommand, indent: int) -> list[str]:
        """A command's frames told apart by sender: the last sender is the only one left."""
        pad = " " * indent
        lines: list[str] = []
        if command.family is not None:
            short = f"_short_{command.command}"
            self.namespace[short] = _short(command.family)
            lines += [f"{pad}if n < 2:", f"{pad}    raise {short}(data)"]
        *first, last = command.senders
        for routes in first:
            lines += [f"{pad}if sender is _{routes.sender.name}:", *self.sender(routes, indent + 4)]
        lines += [
            f"{pad}if sender is not _{last.sender.name}:",
            f"{pad}    raise _errors.sender(sender)",
            *self.sender(last, indent),
        ]
        return lines

    def sender(self, routes: SenderRoutes, indent: int) -> list[str]:
        """One sender's frames of a command: by byte 1, then the other value's forms."""
        pad = " " * indent
        lines: list[str] = []
        for forms in routes.headed:
            lines += [f"{pad}if data[1] == 0x{forms.header:02X}:", *self.forms(forms, indent + 4)]
        if routes.other is None:
            return [*lines, f"{pad}raise _errors.unknown(command, data)"]
        return [*lines, *self.forms(routes.other, indent)]

    def shared(self, shared: Shared) -> list[str]:
        """A layout of several commands (PwmSet), inlined behind a table of its commands."""
        member = f"_is_{shared.layout.name}"
        self.namespace[member] = tuple(c in shared.commands for c in range(256))
        return [f"    if {member}[command]:", *self.body(shared.layout, 8)]


def forms_decoder(forms: Forms) -> FrameDecoder:
    """The decoder of one command's forms (a layout's own decoder for one form)."""
    if len(forms.routes) == 1:
        return forms.first.frame.functions[0]
    namespace: dict[str, Any] = {"_len": len, "_lengths": _lengths(forms.routes)}
    lines = ["def decode(data, excess):", "    n = _len(data)"]
    for number, route in enumerate(forms.routes):
        decode_form = f"_decode_{number}"
        namespace[decode_form] = route.frame.functions[0]
        lines.append(f"    if {_form_test(number, route.frame.fixed_size)}:")
        lines.append(f"        return {decode_form}(data, excess)")
    lines.append("    raise _lengths(n, data)")
    decode: FrameDecoder = _compiled(lines, namespace, f"decode {forms.first.frame.name} forms")
    return decode


# The fast decoder.

_TO_CHECKED = "_checked(data, sender=sender, allow_excess=allow_excess)"
_OTHERWISE = f"return {_TO_CHECKED}"
_SENDERS_BUSIEST_FIRST = (Sender.AUTOPILOT, Sender.ARBITER)
"""The order the fast decoder tries the senders in: three autopilots stream arbitration
variables, one arbiter sends Status and Score."""

_FAST_OPAQUE = (
    "            cls = _opaque[command]",
    "            if (",
    "                cls is not None",
    "                and data.__class__ is _bytes",
    f"                and _len(data) <= {MAX_FRAME_BYTES}",
    "            ):",
    "                o = _opaque_builder()",
    "                o.payload = data[_AFTER_COMMAND]",
    "                o.__class__ = cls",
    "                return o",
)
_FAST_TAIL = (
    # A memoryview of another shape or item format fails here and not in the
    # checked decoder, which reads its bytes.
    "    except (IndexError, _struct_error, NotImplementedError):",
    "        pass",
    "    except TypeError:",
    "        _check_types(data, sender)",
    "    return _checked(data, sender=sender, allow_excess=allow_excess)",
)


def fast_decoder(
    plan: DecoderPlan, checked: Callable[..., Message], sender: Sender | None = None
) -> Callable[..., Message]:
    """The fast ``decode(data, *, sender, allow_excess=False)``, falling back to
    ``checked``; with ``sender``, the same for that sender alone, as
    ``decode(data, allow_excess=False)``."""
    render = _Fast(checked, sender)
    if sender is None:
        head = ["def decode(data, *, sender, allow_excess=False):"]
    else:
        head = ["def decode(data, allow_excess=False):", "    sender = _SENDER"]
    lines = [
        *head,
        "    try:",
        "        command = data[0]",
        *render.dispatch(plan, sender),
        *render.either(plan),
        *_FAST_TAIL,
    ]
    # A header's frames decoded in a function of their own (Status, 26 fields): every
    # local of `decode` costs each call its frame's set-up and clearing, whatever the
    # frame's type.
    decode: Callable[..., Message] = _compiled(
        [*render.functions, *lines, ""], render.namespace, "decode Codec fast"
    )
    return decode


class _Fast:
    """The fast decoder's namespace and its functions besides ``decode``, as its lines are
    rendered."""

    def __init__(self, checked: Callable[..., Message], sender: Sender | None) -> None:
        self.namespace: dict[str, Any] = {
            "_SENDER": sender,
            "_checked": checked,
            "_check_types": _check_types,
            "_bytes": bytes,
            "_len": len,
            "_Sender": Sender,
            "_struct_error": struct.error,
            "_AFTER_COMMAND": slice(1, None),  # a constant slice: none built per frame
        }
        self.namespace.update({f"_{s.name}": s for s in Sender})
        self.functions: list[str] = []

    def body(
        self, layout: FrameLayout, indent: int, assume: set[str], fallback: str = _OTHERWISE
    ) -> list[str] | None:
        """The optimistic body of a layout's decoder, or None if it has none."""
        found = optimistic_decoder(
            layout, layout.message.__name__, indent, fallback, frozenset(assume)
        )
        if found is None:
            return None
        self.namespace.update(found[1])
        return found[0]

    def dispatch(self, plan: DecoderPlan, sender: Sender | None) -> list[str]:
        """The commands told apart by sender, then the test that opens the others."""
        lines: list[str] = []
        for command in plan.told_apart:
            lines.append(f"        {'elif' if lines else 'if'} {_is(command.command)}:")
            if sender is not None:
                lines += self.block(command.of(sender), 12)
                continue
            for who in _SENDERS_BUSIEST_FIRST:
                lines += [
                    f"            if sender is _{who.name}:",
                    *self.block(command.of(who), 16),
                ]
        if sender is None:
            return [*lines, f"        {'elif' if lines else 'if'} sender.__class__ is _Sender:"]
        return [*lines, "        else:" if lines else "        if True:"]

    def block(self, routes: SenderRoutes, indent: int) -> list[str]:
        """One sender's frames of a command told apart by sender."""
        if routes.apart:
            return self.apart(routes, indent)
        pad = " " * indent
        lines: list[str] = []
        for forms in routes.headed:
            inner = self.body(forms.first.frame, indent + 4, {"command", "header"})
            lines += [
                f"{pad}if data[1] == 0x{forms.header:02X}:",
                *(inner if inner is not None else [f"{pad}    {_OTHERWISE}"]),
            ]
        if routes.other is not None:
            lines += self.body(routes.other.first.frame, indent, {"command"}) or []
        return lines or [f"{pad}pass"]

    def apart(self, routes: SenderRoutes, indent: int) -> list[str]:
        """The other layout's body, its fallback calling a function of the header's frames:
        the other layout refuses their byte 1, so its own decoding tells the two apart."""
        first, other = routes.headed[0].first, routes.other
        assert other is not None
        name = f"_{first.frame.name.lower()}"
        own = self.body(first.frame, 4, {"command", "header"})
        assert own is not None
        self.functions += [f"def {name}(data, sender, allow_excess):", *own]
        fallback = (
            f"return {name}(data, sender, allow_excess) "
            f"if data[1] == 0x{first.header:02X} else {_TO_CHECKED}"
        )
        lines = self.body(other.first.frame, indent, {"command"}, fallback)
        return lines if lines is not None else [f"{' ' * indent}{_OTHERWISE}"]

    def either(self, plan: DecoderPlan) -> list[str]:
        """The frames decoded the same from either sender: PWM, opaque, single-form."""
        lines = [] if plan.pwm is None else _pwm_lines(plan.pwm, self.namespace)
        if plan.opaque:
            self.namespace["_opaque"] = _opaque_classes(plan.opaque)
            self.namespace["_opaque_builder"] = builder(OpaqueMessage)
            lines += _FAST_OPAQUE
        for route in plan.singles():
            body = self.body(route.frame, 16, {"command"})
            if body is not None:  # a single-form route: its optimistic body, bytes only
                lines += [
                    f"            if command == {route.command} and data.__class__ is _bytes:",
                    *body,
                ]
        return lines or ["            pass"]


def _pwm_lines(layout: FrameLayout, namespace: dict[str, Any]) -> list[str]:
    """The fast decoder's PWM frames: one exact-size unpack and the two tables of the
    packing (`layouts.PWM_VALUES`), the same values as the PWM layout's decoder."""
    packing = next(p for p, pwm in layouts.PWM_SET.items() if pwm is layout)
    namespace["_unpack_pwm"] = struct.Struct(layouts.PWM_FORMAT).unpack
    namespace["_first"], namespace["_second"] = layouts.pwm_tables(packing)
    namespace["_pwm_builder"] = builder(PwmSet)
    namespace["_PwmSet"] = PwmSet
    first_channel: list[int | None] = [None] * 256
    for wire, channel in layout.fields[0].mapping:
        first_channel[wire] = channel
    namespace["_first_channel"] = tuple(first_channel)
    return [
        "            first_channel = _first_channel[command]",
        "            if first_channel is not None:",
        "                b1, b2, b3, b4, b5, b6 = _unpack_pwm(data)",
        "                o = _pwm_builder()",
        "                o.first_channel = first_channel",
        f"                o.values = {layouts.PWM_VALUES}",
        "                o.__class__ = _PwmSet",
        "                return o",
    ]
