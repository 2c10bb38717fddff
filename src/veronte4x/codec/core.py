"""`Codec`: dispatch a frame to its layout by command byte and sender, and back.

Frame-length policy: a frame shorter than its layout is always a `DecodeError`. A longer
one (senders that pad every frame to 8 bytes exist) is a `DecodeError` too unless the
caller passes ``allow_excess=True``, in which case the bytes past the layout are ignored,
as cantools does by default. Strict is the default because a decoded message must
re-encode to the very bytes it came from.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import NamedTuple

from veronte4x.codec import layouts
from veronte4x.codec.compiler import MAX_FRAME_BYTES, Decoder, Encoder
from veronte4x.codec.declared import Layout
from veronte4x.codec.messages import Message, PwmSet, Sender, Status
from veronte4x.codec.pwm import PWM_COMMANDS, PwmPacking
from veronte4x.errors import DecodeError, EncodeError, LayoutError, UnknownCommandError

_ARBITER = Sender.ARBITER


class Dispatch(NamedTuple):
    """Where a sender's frames go: by command byte, and for command 0 by byte 1.

    Attributes:
        by_command: Decoder for each command byte 1..255 (index 0 unused), None if unknown.
        header_ff: Decoder of command 0 frames whose byte 1 is 0xFF (Status or Ready).
        other: Decoder of the other command 0 frames (Score or ArbitrationVariable).
    """

    by_command: tuple[Decoder | None, ...]
    header_ff: Decoder
    other: Decoder


_AUTOPILOT = Sender.AUTOPILOT


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
        self.pwm_packing = pwm_packing
        self.layouts = tuple(layouts)
        self._by_command: list[Decoder | None] = [None] * 256
        self._encoders: dict[type[Message], Encoder] = {}
        self._install_built_in()
        for declared in self.layouts:
            self._install_declared(declared)

    def _install_built_in(self) -> None:
        status_4x, encode_4x = layouts.STATUS_4X.functions
        status_cex, encode_cex = layouts.STATUS_CEX.functions
        self._score, encode_score = layouts.SCORE.functions
        self._ready, encode_ready = layouts.READY.functions
        self._variable, encode_variable = layouts.ARBITRATION_VARIABLE.functions
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

        self._status = decode_status
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

    def decode(self, data: bytes, *, sender: Sender, allow_excess: bool = False) -> Message:
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
        """
        if not data:
            raise DecodeError(None, f"0 bytes; a frame has 1 to {MAX_FRAME_BYTES}", data)
        command = data[0]
        if command:
            decode = self._by_command[command]
            if decode is None:
                raise UnknownCommandError(command, data)
            return decode(data, allow_excess)
        if len(data) < 2:
            raise DecodeError(None, "an arbitration frame has at least 2 bytes", data)
        if sender is _ARBITER:
            return (self._status if data[1] == 0xFF else self._score)(data, allow_excess)
        if sender is _AUTOPILOT:
            return (self._ready if data[1] == 0xFF else self._variable)(data, allow_excess)
        raise TypeError(f"sender must be a Sender, not {sender!r}")

    def dispatch(self, sender: Sender) -> Dispatch:
        """The decoders `decode` chooses from for one sender, for loops that inline dispatch.

        Each decoder is called as ``decoder(data, allow_excess)``; a missing one (None) is
        where `decode` raises `UnknownCommandError`.
        """
        if sender is _ARBITER:
            return Dispatch(tuple(self._by_command), self._status, self._score)
        return Dispatch(tuple(self._by_command), self._ready, self._variable)

    def encode(self, message: Message) -> bytes:
        """Encode a message into a frame's data bytes, validating every field.

        Raises:
            EncodeError: A field is out of range or of the wrong kind (the error names the
                message type, the field, the value and what is allowed), or the message is
                not a Veronte message this codec knows.
        """
        encode = self._encoders.get(type(message))
        if encode is None:
            raise EncodeError(
                type(message).__name__, "message", message, "a veronte4x.codec message"
            )
        return encode(message)
