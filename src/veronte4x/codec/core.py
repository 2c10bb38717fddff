"""`Codec`: dispatch a frame to its layout by command byte and sender, and back.

Frame-length policy: a frame shorter than its layout is always a `DecodeError`. A longer
one (senders that pad every frame to 8 bytes exist) is a `DecodeError` too unless the
caller passes ``allow_excess=True``, in which case the bytes past the layout are ignored,
as cantools does by default. Strict is the default because a decoded message must
re-encode to the very bytes it came from.
"""

from __future__ import annotations

import operator
from collections.abc import Callable, Iterable

from veronte4x.codec import decoders, layouts
from veronte4x.codec.compiler import FrameDecoder, FrameEncoder, FrameLayout
from veronte4x.codec.declared import Layout
from veronte4x.codec.messages import Message, Sender
from veronte4x.codec.plan import plan
from veronte4x.codec.pwm import PwmPacking
from veronte4x.codec.routes import RouteTable
from veronte4x.errors import BytesLike, EncodeError, LayoutError, argument_type_error


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
        self._plan = plan(self.routes)
        self._checked = decoders.checked_decoder(self._plan)
        self.__dict__["decode"] = self._fast_decoder()
        self._decoders: dict[Sender, FrameDecoder] = {}  # made by `decoder` on first use

    def _fast_decoder(self, sender: Sender | None = None) -> Callable[..., Message]:
        """The generated fast `decode`, or with ``sender`` the one of `decoder`, named as
        the method it stands for in help(), Jupyter's ``?`` and tracebacks."""
        decode = decoders.fast_decoder(self._plan, self._checked, sender)
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
            decoder = self._decoders[sender] = self._fast_decoder(sender)
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
