"""`Codec`: dispatch a frame to its layout by command byte and sender, and back.

Frame-length policy: a frame shorter than its layout is always a `DecodeError`. A longer
one (senders that pad every frame to 8 bytes exist) is a `DecodeError` too unless the
caller passes ``allow_excess=True``, in which case the bytes past the layout are ignored,
as cantools does by default. Strict is the default because a decoded message must
re-encode to the very bytes it came from.
"""

from __future__ import annotations

import operator
import struct
from collections.abc import Callable, Iterable
from typing import Any

from veronte4x.codec import layouts
from veronte4x.codec import routes as routes_module
from veronte4x.codec.compiler import (
    MAX_FRAME_BYTES,
    FrameDecoder,
    FrameEncoder,
    FrameLayout,
    inline_decoder,
    optimistic_decoder,
    refuses,
)
from veronte4x.codec.declared import Layout
from veronte4x.codec.messages import Message, OpaqueMessage, PwmSet, Sender
from veronte4x.codec.pwm import PwmPacking
from veronte4x.codec.routes import Route, RouteTable
from veronte4x.codegen import compile_source
from veronte4x.codegen import slot_builder as builder
from veronte4x.errors import (
    BytesLike,
    DecodeError,
    EncodeError,
    LayoutError,
    UnknownCommandError,
    argument_type_error,
)
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


def _lengths(forms: list[Route]) -> Callable[[int, bytes], DecodeError]:
    """The error of a frame whose length is none of its message's forms'."""
    name, expected = forms[0].frame.name, routes_module.length_error(forms)

    def error(n: int, data: bytes) -> DecodeError:
        return DecodeError(name, f"{counted(n, 'byte')}; {expected} expected", data)

    return error


_SENDERS_BUSIEST_FIRST = (Sender.AUTOPILOT, Sender.ARBITER)
"""The order the fast decoder tries the senders in: three autopilots stream arbitration
variables, one arbiter sends Status and Score."""


class Codec:
    """FrameEncoder and decoder for Veronte 4x frames, with the open choices made explicit.

    Its decoders and encoders are generated from its route table (`routes`, built from
    `veronte4x.codec.routes.ROUTES`, the PWM packing and the declared layouts).

    Args:
        pwm_packing: Packing order of the four 12-bit PWM values (an open point).
        layouts: Declared layouts for commands whose payload layout is not public; a
            frame with such a command decodes to the layout's message class.

    Attributes:
        routes: The route table of this codec.
    """

    def __init__(
        self,
        *,
        pwm_packing: PwmPacking = PwmPacking.LSB_FIRST,
        layouts: Iterable[Layout] = (),
    ) -> None:
        if not isinstance(pwm_packing, PwmPacking):
            raise argument_type_error("Codec", "pwm_packing", "a PwmPacking", pwm_packing)
        self.pwm_packing = pwm_packing
        self.layouts = tuple(layouts)
        for declared in self.layouts:
            if not isinstance(declared, Layout):
                raise argument_type_error("Codec", "layouts", "Layout objects", declared)
        self.routes = RouteTable(pwm_packing, self.layouts)
        self._encoders = _encoders(self.routes)
        # An instance attribute over the method below: generated functions with the
        # layouts' bodies inlined, so a frame costs one Python call.
        self._checked = self._compile_checked()
        self.__dict__["decode"] = self._compile_fast(self._checked)
        self._decoders: dict[Sender, FrameDecoder] = {}  # made by `decoder` on first use

    def _compile_checked(self) -> Callable[..., Message]:
        """Generate the checked `decode` from the route table: every check, with the
        bodies of the layouts' decoders inlined (`compiler.inline_decoder`)."""
        table = self.routes
        namespace: dict[str, Any] = {
            "_bytes": bytes,
            "_as_bytes": _as_bytes,
            "_len": len,
            "_Sender": Sender,
            "_errors": _Errors,
        }
        namespace.update({f"_{sender.name}": sender for sender in Sender})
        suffixes: dict[int, str] = {}

        def body(layout: FrameLayout, indent: int) -> list[str]:
            suffix = suffixes.get(id(layout))
            if suffix is None:
                taken = sum(s.split("_")[0] == layout.name for s in suffixes.values())
                suffix = layout.name + (f"_{taken + 1}" if taken else "")
                suffixes[id(layout)] = suffix
            lines, names = inline_decoder(layout, suffix, indent)
            namespace.update(names)
            return lines

        def forms(group: list[Route], indent: int) -> list[str]:
            """Lines that decode a frame with one of a message's forms, by its length."""
            if len(group) == 1:
                return body(group[0].frame, indent)
            pad = " " * indent
            lines: list[str] = []
            above: int | None = None
            for route in group:
                size = route.frame.fixed_size
                if above is None:
                    lines.append(f"{pad}if n >= {size}:")
                else:
                    lines.append(f"{pad}if n == {size} or (excess and n > {size}):")
                lines += body(route.frame, indent + 4)
                above = size
            error = f"_lengths_{group[0].frame.name}"
            namespace[error] = _lengths(group)
            return [*lines, f"{pad}raise {error}(n, data)"]

        def by_sender(command: int, indent: int) -> list[str]:
            pad = " " * indent
            lines: list[str] = []
            if any(r.header is not None for r in table.of(command)):
                short = f"_short_{command}"
                namespace[short] = _short(routes_module.family(command, table))
                lines += [f"{pad}if n < 2:", f"{pad}    raise {short}(data)"]
            *first, last = list(Sender)
            for sender in [*first, last]:
                inner = indent
                if sender is not last:
                    lines.append(f"{pad}if sender is _{sender.name}:")
                    inner += 4
                else:
                    lines += [
                        f"{pad}if sender is not _{sender.name}:",
                        f"{pad}    raise _errors.sender(sender)",
                    ]
                step = " " * inner
                groups = table.for_sender(command, sender)
                for group in groups:
                    header = group[0].header
                    if header is None:
                        lines += forms(group, inner)
                    else:
                        lines.append(f"{step}if data[1] == 0x{header:02X}:")
                        lines += forms(group, inner + 4)
                if not groups or groups[-1][0].header is not None:
                    lines.append(f"{step}raise _errors.unknown(command, data)")
            return lines

        lines = [
            "def decode(data, *, sender, allow_excess=False):",
            "    if data.__class__ is not _bytes:",
            "        data = _as_bytes(data)",
            "    excess = allow_excess",
            "    n = _len(data)",
            "    if not n:",
            "        raise _errors.empty(data)",
            "    command = data[0]",
        ]
        for command in table.commands():
            if table.by_sender(command):
                test = "not command" if command == 0 else f"command == {command}"
                lines.append(f"    if {test}:")
                lines += by_sender(command, 8)
        lines += ["    if sender.__class__ is not _Sender:", "        raise _errors.sender(sender)"]
        by_command: list[FrameDecoder | None] = [None] * 256
        opaque: list[type[Message] | None] = [None] * 256
        for layout, commands in table.layout_commands().items():
            if table.by_sender(commands[0]):
                continue
            if len(commands) > 1:  # one layout for several commands (PwmSet): inlined
                member = f"_is_{layout.name}"
                namespace[member] = tuple(c in commands for c in range(256))
                lines += [f"    if {member}[command]:", *body(layout, 8)]
            elif table.opaque(table.of(commands[0])[0]):
                opaque[commands[0]] = layout.message
        for command in table.commands():
            group = table.of(command)
            if table.by_sender(command):
                continue
            if len(group) > 1 or len(table.layout_commands()[group[0].frame]) == 1:
                by_command[command] = self._forms_decoder(routes_module.forms_of(group))
        namespace["_by_command"] = tuple(by_command)
        if any(opaque):
            namespace["_opaque"] = tuple(opaque)
            namespace["_opaque_builder"] = builder(OpaqueMessage)
            lines += [
                "    cls = _opaque[command]",
                f"    if cls is not None and n <= {MAX_FRAME_BYTES}:",
                "        o = _opaque_builder()",
                "        o.payload = data[1:]",
                "        o.__class__ = cls",
                "        return o",
            ]
        lines += [
            "    decoder = _by_command[command]",
            "    if decoder is None:",
            "        raise _errors.unknown(command, data)",
            "    return decoder(data, excess)",
        ]
        compile_source("\n".join(lines), namespace, "decode Codec")
        decode: Callable[..., Message] = namespace["decode"]
        return decode

    @staticmethod
    def _forms_decoder(group: list[Route]) -> FrameDecoder:
        """The decoder of one command's forms (a layout's own decoder for one form)."""
        if len(group) == 1:
            return group[0].frame.functions[0]
        namespace: dict[str, Any] = {"_len": len, "_lengths": _lengths(group)}
        lines = ["def decode(data, excess):", "    n = _len(data)"]
        above: int | None = None
        for number, route in enumerate(group):
            size = route.frame.fixed_size
            decode_form = f"_decode_{number}"
            namespace[decode_form] = route.frame.functions[0]
            if above is None:
                lines.append(f"    if n >= {size}:")
            else:
                lines.append(f"    if n == {size} or (excess and n > {size}):")
            lines.append(f"        return {decode_form}(data, excess)")
            above = size
        lines.append("    raise _lengths(n, data)")
        compile_source("\n".join(lines), namespace, f"decode {group[0].frame.name} forms")
        decode: FrameDecoder = namespace["decode"]
        return decode

    def _compile_fast(
        self, checked: Callable[..., Message], sender: Sender | None = None
    ) -> Callable[..., Message]:
        """Generate `decode` from the route table: optimistic bodies
        (`compiler.optimistic_decoder`) for the frames told apart by sender, one exact-size
        unpack for PWM frames, a slice for opaque ones, optimistic bodies for the other
        single-form routes; any frame out of the ordinary goes to ``checked``, which
        decides and raises the precise error. With ``sender``, the same function for that
        sender alone, called as ``decode(data, allow_excess)`` (`decoder`)."""
        table = self.routes
        namespace: dict[str, Any] = {
            "_SENDER": sender,
            "_checked": checked,
            "_check_types": _check_types,
            "_bytes": bytes,
            "_len": len,
            "_Sender": Sender,
            "_struct_error": struct.error,
            "_AFTER_COMMAND": slice(1, None),  # a constant slice: none built per frame
        }
        namespace.update({f"_{s.name}": s for s in Sender})
        to_checked = "_checked(data, sender=sender, allow_excess=allow_excess)"
        otherwise = f"return {to_checked}"
        functions: list[str] = []

        def body(
            layout: FrameLayout, indent: int, assume: set[str], fallback: str = otherwise
        ) -> list[str] | None:
            found = optimistic_decoder(
                layout, layout.message.__name__, indent, fallback, frozenset(assume)
            )
            if found is None:
                return None
            namespace.update(found[1])
            return found[0]

        def block(command: int, who: Sender, indent: int) -> list[str]:
            """One sender's frames of a command told apart by sender."""
            pad = " " * indent
            groups = table.for_sender(command, who)
            headers = [g for g in groups if g[0].header is not None]
            rest = [g for g in groups if g[0].header is None]
            other = rest[0][0].frame if rest else None
            if (
                len(headers) == 1
                and other is not None
                and other.fixed_size == headers[0][0].frame.fixed_size
                and refuses(other, 1, headers[0][0].header or 0)
            ):
                # The other layout has the header's size and refuses its byte 1: its own
                # decoding tells the two apart, and the header's frames go to a function of
                # their own, named in its fallback.
                first = headers[0][0]
                name = f"_{first.frame.name.lower()}"
                own = body(first.frame, 4, {"command", "header"})
                assert own is not None
                functions.extend([f"def {name}(data, sender, allow_excess):", *own])
                fallback = (
                    f"return {name}(data, sender, allow_excess) "
                    f"if data[1] == 0x{first.header:02X} else {to_checked}"
                )
                lines = body(other, indent, {"command"}, fallback)
                return lines if lines is not None else [f"{pad}{otherwise}"]
            lines = []
            for group in headers:
                inner = body(group[0].frame, indent + 4, {"command", "header"})
                lines += [
                    f"{pad}if data[1] == 0x{group[0].header:02X}:",
                    *(inner if inner is not None else [f"{pad}    {otherwise}"]),
                ]
            if other is not None:
                lines += body(other, indent, {"command"}) or []
            return lines or [f"{pad}pass"]

        dispatch: list[str] = []
        for command in table.commands():
            if not table.by_sender(command):
                continue
            test = "not command" if command == 0 else f"command == {command}"
            dispatch.append(f"        {'elif' if dispatch else 'if'} {test}:")
            if sender is None:
                for who in _SENDERS_BUSIEST_FIRST:
                    dispatch += [f"            if sender is _{who.name}:", *block(command, who, 16)]
            else:
                dispatch += block(command, sender, 12)
        if sender is None:
            dispatch.append(f"        {'elif' if dispatch else 'if'} sender.__class__ is _Sender:")
        else:
            dispatch.append("        else:" if dispatch else "        if True:")
        either: list[str] = []
        commands = table.layout_commands()
        for layout in commands:
            if layout in layouts.PWM_SET.values():
                either += _pwm_lines(layout, namespace)
        opaque: list[type[Message] | None] = [None] * 256
        for route in table.routes:
            if table.opaque(route):
                opaque[route.command] = route.frame.message
        if any(opaque):
            namespace["_opaque"] = tuple(opaque)
            namespace["_opaque_builder"] = builder(OpaqueMessage)
            either += [
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
            ]
        for command in table.commands():
            group = table.of(command)
            route = group[0]
            if (
                len(group) > 1
                or table.by_sender(command)
                or table.opaque(route)
                or len(commands[route.frame]) > 1
            ):
                continue
            lines = body(route.frame, 16, {"command"})
            if lines is not None:  # a single-form route: its optimistic body, bytes only
                either += [
                    f"            if command == {command} and data.__class__ is _bytes:",
                    *lines,
                ]
        if sender is None:
            head = ["def decode(data, *, sender, allow_excess=False):"]
        else:
            head = ["def decode(data, allow_excess=False):", "    sender = _SENDER"]
        lines = [
            *head,
            "    try:",
            "        command = data[0]",
            *dispatch,
            *(either or ["            pass"]),
            # A memoryview of another shape or item format fails here and not in the
            # checked decoder, which reads its bytes.
            "    except (IndexError, _struct_error, NotImplementedError):",
            "        pass",
            "    except TypeError:",
            "        _check_types(data, sender)",
            "    return _checked(data, sender=sender, allow_excess=allow_excess)",
        ]
        # A header's frames decoded in a function of their own (Status, 26 fields): every
        # local of `decode` costs each call its frame's set-up and clearing, whatever the
        # frame's type.
        source = "\n".join(functions + lines) + "\n"
        compile_source(source, namespace, "decode Codec fast")
        decode: Callable[..., Message] = namespace["decode"]
        # What help(), Jupyter's ``?`` and tracebacks show: the method it stands for.
        method = Codec.decode if sender is None else Codec.decoder
        decode.__module__ = __name__
        decode.__qualname__ = method.__qualname__
        decode.__doc__ = method.__doc__
        return decode

    def decode(self, data: BytesLike, *, sender: Sender, allow_excess: bool = False) -> Message:
        """Decode one Veronte frame's data bytes.

        Args:
            data: The frame's data field (byte 0 is the message type), 1..8 bytes (more
                only with ``allow_excess``).
            sender: Who sent the frame; it tells Status from Ready and Score from
                ArbitrationVariable. Frames of other types decode the same for both.
            allow_excess: Ignore bytes past the layout instead of rejecting the frame.

        Returns:
            The message.

        Raises:
            UnknownCommandError: The command byte is reserved or unknown (and no layout was
                declared for it); the error carries the command byte and the data.
            DecodeError: The frame is empty, too short, too long, or a field is out of range.
            TypeError: ``data`` is not bytes-like, or ``sender`` is not a `Sender`.
        """
        # Each instance holds its generated decoder under this name (see __init__); this
        # method is reached only through the class, as in ``Codec.decode(codec, ...)``.
        generated: Callable[..., Message] = self.__dict__["decode"]
        return generated(data, sender=sender, allow_excess=allow_excess)

    def decoder(self, sender: Sender) -> FrameDecoder:
        """`decode` for one sender's frames, called as ``decoder(data, allow_excess)``.

        The same generated function as `decode`, with the sender fixed and positional
        arguments only: for loops over many frames of a known sender (a capture reader
        routes by CAN ID). It returns and raises exactly what `decode` does.

        Raises:
            TypeError: ``sender`` is not a `Sender`.
        """
        if not isinstance(sender, Sender):
            raise argument_type_error("decoder", "sender", "a Sender", sender)
        decoder = self._decoders.get(sender)
        if decoder is None:
            decoder = self._decoders[sender] = self._compile_fast(self._checked, sender)
        return decoder

    def encode(self, message: Message) -> bytes:
        """Encode a message into a frame's data bytes, validating every field.

        Raises:
            EncodeError: A field is out of range or of the wrong kind (the error names the
                message type, the field, the value and what is allowed), or the message is
                of a declared class this codec does not hold.
            TypeError: ``message`` is not a Veronte message at all.
        """
        encode = self._encoders.get(type(message))
        if encode is None:
            if not isinstance(message, Message):
                raise argument_type_error("encode", "message", "a Veronte message", message)
            raise EncodeError(
                type(message).__name__, "message", message, "a veronte4x.codec message"
            )
        return encode(message)


def _encoders(table: RouteTable) -> dict[type[Message], FrameEncoder]:
    """The encoder of each message class of a route table.

    Opaque messages are encoded even when a declared layout decodes their command. A class
    with several layouts (Status: the 4x and the CEX forms) is encoded with the
    layout whose first implied attribute the message carries (``cbit_ok is None``: CEX),
    else with the layout that implies nothing.
    """
    by_class: dict[type[Message], list[FrameLayout]] = {}
    for layout in table.layouts():
        by_class.setdefault(layout.message, []).append(layout)
    # An opaque message keeps its encoder when a declared layout takes its command over:
    # its payload bytes are still a frame of that command.
    encoders: dict[type[Message], FrameEncoder] = {
        layout.message: layout.functions[1] for layout in layouts.OPAQUE.values()
    }
    for cls, found in by_class.items():
        plain = [layout for layout in found if not layout.implied]
        implied = [layout for layout in found if layout.implied]
        if not implied:
            encoders[cls] = found[0].functions[1]
            continue
        if len(plain) != 1 or len(implied) != 1 or implied[0].implied[0][1] is not None:
            raise LayoutError(f"{cls.__name__}: no rule picks one of its layouts to encode")
        get = operator.attrgetter(implied[0].implied[0][0])
        encode_plain, encode_implied = plain[0].functions[1], implied[0].functions[1]

        def encode(
            message: Message,
            get: Callable[[Message], object] = get,
            encode_plain: FrameEncoder = encode_plain,
            encode_implied: FrameEncoder = encode_implied,
        ) -> bytes:
            return (encode_plain if get(message) is not None else encode_implied)(message)

        encoders[cls] = encode
    return encoders


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
