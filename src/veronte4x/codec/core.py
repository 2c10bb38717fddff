"""`Codec`: dispatch a frame to its layout by command byte and sender, and back.

Frame-length policy: a frame shorter than its layout is always a `DecodeError`. A longer
one (senders that pad every frame to 8 bytes exist) is a `DecodeError` too unless the
caller passes ``allow_excess=True``, in which case the bytes past the layout are ignored,
as cantools does by default. Strict is the default because a decoded message must
re-encode to the very bytes it came from.
"""

from __future__ import annotations

import struct
from collections.abc import Callable, Iterable
from typing import Any

from veronte4x.codec import layouts
from veronte4x.codec.compiler import (
    MAX_FRAME_BYTES,
    Decoder,
    Encoder,
    FrameLayout,
    inline_decoder,
    optimistic_decoder,
)
from veronte4x.codec.declared import Layout
from veronte4x.codec.messages import Message, OpaqueMessage, PwmSet, Sender, Status
from veronte4x.codec.pwm import PWM_COMMANDS, PwmPacking
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

_ARBITER = Sender.ARBITER
_AUTOPILOT = Sender.AUTOPILOT


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
    def short(data: bytes) -> DecodeError:
        return DecodeError(None, "an arbitration frame has at least 2 bytes", data)

    @staticmethod
    def unknown(command: int, data: bytes) -> UnknownCommandError:
        return UnknownCommandError(command, data)

    @staticmethod
    def sender(sender: object) -> TypeError:
        return argument_type_error("decode", "sender", "a Sender", sender)


class Codec:
    """Encoder and decoder for Veronte 4x frames, with the open choices made explicit.

    Args:
        pwm_packing: Packing order of the four 12-bit PWM values (an open point).
        layouts: Declared layouts for commands whose payload layout is not public; a
            frame with such a command decodes to the layout's message class.
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
        self._by_command: list[Decoder | None] = [None] * 256
        self._encoders: dict[type[Message], Encoder] = {}
        self._install_built_in()
        for declared in self.layouts:
            self._install_declared(declared)
        # An instance attribute over the method below: generated functions with the
        # arbitration, PWM and opaque layouts inlined, so a frame costs one Python call.
        self._checked = self._compile_checked()
        self.__dict__["decode"] = self._compile_fast(self._checked)
        self._decoders: dict[Sender, Decoder] = {}  # made by `decoder` on first use

    def _install_built_in(self) -> None:
        status_4x, encode_4x = layouts.STATUS_4X.functions
        status_cex, encode_cex = layouts.STATUS_CEX.functions
        encode_score = layouts.SCORE.functions[1]
        encode_ready = layouts.READY.functions[1]
        encode_variable = layouts.ARBITRATION_VARIABLE.functions[1]
        request, encode_request = layouts.VERSION_REQUEST.functions
        response, encode_response = layouts.VERSION_RESPONSE.functions

        def decode_status(data: bytes, excess: bool) -> Message:
            n = len(data)
            if n == 4 or (n == 5 and excess):
                return status_cex(data, excess)
            if n < 4 or n == 5:
                raise DecodeError(
                    "Status", f"{n} bytes; 4 (CEX form) or 6 (4x form) expected", data
                )
            return status_4x(data, excess)

        def encode_status(message: Message) -> bytes:
            assert isinstance(message, Status)
            return (encode_4x if message.cbit_ok is not None else encode_cex)(message)

        def decode_version(data: bytes, excess: bool) -> Message:
            return request(data, excess) if len(data) == 1 else response(data, excess)

        # The generated decode tries the 6-byte form first; shorter frames go on to this.
        self._status_short = decode_status
        self._by_command[1] = decode_version
        self._encoders.update(
            {
                layouts.STATUS_4X.message: encode_status,
                layouts.SCORE.message: encode_score,
                layouts.READY.message: encode_ready,
                layouts.ARBITRATION_VARIABLE.message: encode_variable,
                layouts.VERSION_REQUEST.message: encode_request,
                layouts.VERSION_RESPONSE.message: encode_response,
            }
        )
        decode_pwm, self._encoders[PwmSet] = layouts.PWM_SET[self.pwm_packing].functions
        for command in PWM_COMMANDS.values():
            self._by_command[command] = decode_pwm
        for command, layout in layouts.OPAQUE.items():
            self._by_command[command], self._encoders[layout.message] = layout.functions

    def _install_declared(self, declared: Layout) -> None:
        command = declared.command
        if command not in layouts.OPAQUE and not (
            command in layouts.RESERVED_COMMANDS or command > 19
        ):
            raise LayoutError(
                f"{declared.name}: command {command} has a public layout; only commands "
                "5-10, 16-19 (layout not public), 4, 14, 15 and 20-255 can be declared"
            )
        decode, encode = declared.frame.functions
        self._by_command[command] = decode
        self._encoders[declared.message_class] = encode

    def _compile_checked(self) -> Callable[..., Message]:
        """Generate the checked `decode`: every check and the dispatch of the method below,
        with the bodies of the arbitration, PWM and opaque decoders inlined
        (`compiler.inline_decoder`)."""
        namespace: dict[str, Any] = {
            "_bytes": bytes,
            "_as_bytes": _as_bytes,
            "_len": len,
            "_Sender": Sender,
            "_ARBITER": Sender.ARBITER,
            "_AUTOPILOT": Sender.AUTOPILOT,
            "_by_command": tuple(self._by_command),
            "_is_pwm": tuple(c in PWM_COMMANDS.values() for c in range(256)),
            "_errors": _Errors,
        }

        def body(layout: FrameLayout, indent: int, shorter: Decoder | None = None) -> list[str]:
            lines, names = inline_decoder(layout, layout.message.__name__, indent, shorter)
            namespace.update(names)
            return lines

        namespace["_opaque"] = self._opaque_classes()
        namespace["_opaque_builder"] = builder(OpaqueMessage)
        lines = [
            "def decode(data, *, sender, allow_excess=False):",
            "    if data.__class__ is not _bytes:",
            "        data = _as_bytes(data)",
            "    excess = allow_excess",
            "    n = _len(data)",
            "    if not n:",
            "        raise _errors.empty(data)",
            "    command = data[0]",
            "    if command:",
            "        if sender.__class__ is not _Sender:",
            "            raise _errors.sender(sender)",
            "        if _is_pwm[command]:",
            *body(layouts.PWM_SET[self.pwm_packing], 12),
            "        cls = _opaque[command]",
            f"        if cls is not None and n <= {MAX_FRAME_BYTES}:",
            "            o = _opaque_builder()",
            "            o.payload = data[1:]",
            "            o.__class__ = cls",
            "            return o",
            "        decoder = _by_command[command]",
            "        if decoder is None:",
            "            raise _errors.unknown(command, data)",
            "        return decoder(data, excess)",
            "    if n < 2:",
            "        raise _errors.short(data)",
            "    if sender is _ARBITER:",
            "        if data[1] == 0xFF:",
            *body(layouts.STATUS_4X, 12, self._status_short),
            *body(layouts.SCORE, 8),
            "    if sender is not _AUTOPILOT:",
            "        raise _errors.sender(sender)",
            "    if data[1] == 0xFF:",
            *body(layouts.READY, 8),
            *body(layouts.ARBITRATION_VARIABLE, 4),
        ]
        compile_source("\n".join(lines), namespace, "decode Codec")
        decode: Callable[..., Message] = namespace["decode"]
        return decode

    def _compile_fast(
        self, checked: Callable[..., Message], sender: Sender | None = None
    ) -> Callable[..., Message]:
        """Generate `decode`: optimistic bodies (`compiler.optimistic_decoder`) for the
        arbitration frames, one exact-size unpack for PWM frames, a slice for opaque ones;
        any frame out of the ordinary goes to ``checked``, which decides and raises the
        precise error. With ``sender``, the same function for that sender alone, called as
        ``decode(data, allow_excess)`` (`decoder`)."""
        namespace: dict[str, Any] = {
            "_SENDER": sender,
            "_checked": checked,
            "_check_types": _check_types,
            "_bytes": bytes,
            "_len": len,
            "_Sender": Sender,
            "_ARBITER": Sender.ARBITER,
            "_AUTOPILOT": Sender.AUTOPILOT,
            "_opaque": self._opaque_classes(),
            "_opaque_builder": builder(OpaqueMessage),
            "_struct_error": struct.error,
            "_AFTER_COMMAND": slice(1, None),  # a constant slice: none built per frame
        }
        to_checked = "_checked(data, sender=sender, allow_excess=allow_excess)"
        to_status = "_status(data, sender, allow_excess)"
        otherwise = f"return {to_checked}"

        def body(
            layout: FrameLayout, indent: int, assume: set[str], fallback: str = otherwise
        ) -> list[str]:
            found = optimistic_decoder(
                layout, layout.message.__name__, indent, fallback, frozenset(assume)
            )
            assert found is not None, layout.name
            namespace.update(found[1])
            return found[0]

        # Command 0 (the arbitration frames): Score first for the arbiter, since a Status has
        # 0xFF where a Score has its autopilot (0..3); Ready, then ArbitrationVariable for
        # an autopilot.
        arbiter = body(
            layouts.SCORE,
            12,
            {"command"},
            f"return {to_status} if data[1] == 0xFF else {to_checked}",
        )
        autopilot = [
            "            if data[1] == 0xFF:",
            *body(layouts.READY, 16, {"command", "header"}),
            *body(layouts.ARBITRATION_VARIABLE, 12, {"command"}),
        ]
        # Other commands: PWM frames (one exact-size unpack and two tables of the packing,
        # PWM_VALUES) and opaque ones (a slice), the same whoever sent them.
        either = [
            "            first_channel = _first_channel[command]",
            "            if first_channel is not None:",
            "                b1, b2, b3, b4, b5, b6 = _unpack_pwm(data)",
            "                o = _pwm_builder()",
            "                o.first_channel = first_channel",
            f"                o.values = {layouts.PWM_VALUES}",
            "                o.__class__ = _PwmSet",
            "                return o",
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
        namespace["_unpack_pwm"] = struct.Struct(layouts.PWM_FORMAT).unpack
        namespace["_first"], namespace["_second"] = layouts.pwm_tables(self.pwm_packing)
        namespace["_pwm_builder"] = builder(PwmSet)
        namespace["_PwmSet"] = PwmSet
        first_channel: list[int | None] = [None] * 256
        for channel, command in PWM_COMMANDS.items():
            first_channel[command] = channel
        namespace["_first_channel"] = tuple(first_channel)
        if sender is None:
            dispatch = [
                "def decode(data, *, sender, allow_excess=False):",
                "    try:",
                "        command = data[0]",
                "        if not command:",
                # The autopilots' frames first: three of them stream arbitration variables.
                "            if sender is _AUTOPILOT:",
                *_indented(autopilot, 4),
                "            if sender is _ARBITER:",
                *_indented(arbiter, 4),
                "        elif sender.__class__ is _Sender:",
                *either,
            ]
        else:
            # One sender's decoder: its own arbitration branch, no check of the sender.
            dispatch = [
                "def decode(data, allow_excess=False):",
                "    sender = _SENDER",
                "    try:",
                "        command = data[0]",
                "        if not command:",
                *(arbiter if sender is Sender.ARBITER else autopilot),
                "        else:",
                *either,
            ]
        lines = [
            *dispatch,
            # A memoryview of another shape or item format fails here and not in the
            # checked decoder, which reads its bytes.
            "    except (IndexError, _struct_error, NotImplementedError):",
            "        pass",
            "    except TypeError:",
            "        _check_types(data, sender)",
            "    return _checked(data, sender=sender, allow_excess=allow_excess)",
        ]
        # Status, with its 26 fields, in a function of its own: every local of `decode`
        # costs each call its frame's set-up and clearing, whatever the frame's type.
        status = [
            "def _status(data, sender, allow_excess):",
            *body(layouts.STATUS_4X, 4, {"command", "header"}),
        ]
        source = "\n".join(status + lines) + "\n"
        compile_source(source, namespace, "decode Codec fast")
        decode: Callable[..., Message] = namespace["decode"]
        return decode

    def _opaque_classes(self) -> tuple[type[Message] | None, ...]:
        """The class of each command decoded as an opaque payload, else None.

        Opaque commands share one layout (a payload after the command byte), so one
        builder fills them all, unless a declared layout took the command over.
        """
        opaque: list[type[Message] | None] = [None] * 256
        for command, layout in layouts.OPAQUE.items():
            if self._by_command[command] is layout.functions[0]:
                opaque[command] = layout.message
        return tuple(opaque)

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

    def decoder(self, sender: Sender) -> Decoder:
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


def _indented(lines: list[str], spaces: int) -> list[str]:
    """Source lines moved right by ``spaces``."""
    return [" " * spaces + line for line in lines]
