"""Declared layouts get the same properties as the built-in ones, on random layouts."""

from __future__ import annotations

from dataclasses import dataclass

from hypothesis import given, settings
from hypothesis import strategies as st

from veronte4x import codec
from veronte4x.codec import ByteOrder, FieldKind


@dataclass
class Case:
    layout: codec.Layout
    widths: list[int]


@st.composite
def fields(draw: st.DrawFn, name: str, room: int) -> codec.Field:
    kinds = ["unsigned", "signed", "constant", "skip"] + (["float32"] if room >= 32 else [])
    kind = draw(st.sampled_from(kinds))
    if kind == "float32":
        return codec.float32(name)
    bits = draw(st.integers(1, min(room, 24)))
    if kind == "constant":
        return codec.constant(draw(st.integers(0, (1 << bits) - 1)), bits)
    if kind == "skip":
        return codec.skip(bits)
    scale = None
    if bits <= 16 and draw(st.booleans()):
        low = draw(st.floats(-1000, 1000))
        scale = codec.Linear(0, (1 << bits) - 1, low, low + draw(st.floats(0.5, 1000)))
    make = codec.unsigned if kind == "unsigned" else codec.signed
    return make(name, bits, scale=scale)


@st.composite
def layouts(draw: st.DrawFn) -> codec.Layout:
    chosen: list[codec.Field] = []
    room = 56
    while room and len(chosen) < 6 and (not chosen or draw(st.booleans())):
        field = draw(fields(f"f{len(chosen)}", room))
        chosen.append(field)
        room -= field.bits
    order = draw(st.sampled_from(ByteOrder))
    return codec.Layout(draw(st.sampled_from([5, 6, 16, 19, 200])), "Declared", chosen, order)


@st.composite
def valid_frames(draw: st.DrawFn, layout: codec.Layout) -> bytes:
    """Compose a frame field by field: constants as declared, padding zero, values random."""
    total = 8 + sum(f.bits for f in layout.fields)
    size = -(-total // 8)
    word = 0
    start = 8
    for f in layout.fields:
        raw = 0
        if f.kind is FieldKind.CONSTANT:
            raw = f.value
        elif f.kind is not FieldKind.PADDING:
            raw = draw(st.integers(0, (1 << f.bits) - 1))
        if layout.byte_order is ByteOrder.LITTLE:
            word |= raw << start
        else:
            word |= raw << (size * 8 - start - f.bits)
        start += f.bits
    if layout.byte_order is ByteOrder.LITTLE:
        word |= layout.command
    else:
        word |= layout.command << (size * 8 - 8)
    return word.to_bytes(size, layout.byte_order.value)


@settings(max_examples=300)
@given(data=st.data())
def test_declared_frames_round_trip(data: st.DataObject) -> None:
    layout = data.draw(layouts())
    frame = data.draw(valid_frames(layout))
    message = layout.decode(frame)
    assert layout.encode(message) == frame
    # Compared through their bytes: a NaN field makes a message unequal to itself.
    again = codec.Codec(layouts=[layout]).decode(frame, sender=codec.Sender.ARBITER)
    assert type(again) is layout.message_class
    assert layout.encode(again) == frame


@settings(max_examples=300)
@given(data=st.data())
def test_declared_arbitrary_bytes(data: st.DataObject) -> None:
    layout = data.draw(layouts())
    frame = data.draw(st.binary(max_size=8))
    try:
        message = layout.decode(frame)
    except codec.DecodeError:
        return
    encoded = layout.encode(message)
    assert layout.encode(layout.decode(encoded)) == encoded


@st.composite
def integer_layouts(draw: st.DrawFn) -> tuple[codec.Layout, list[tuple[str, int, bool]]]:
    """Unsigned and signed fields of 1 to 56 bits, with padding, in either byte order."""
    chosen: list[codec.Field] = []
    described: list[tuple[str, int, bool]] = []
    room = 56
    while room and (not chosen or draw(st.booleans())):
        bits = draw(st.integers(1, room))
        kind = draw(st.sampled_from(["unsigned", "signed", "skip"]))
        if kind == "skip":
            chosen.append(codec.skip(bits))
            described.append(("", bits, False))
        else:
            name = f"f{len(chosen)}"
            chosen.append((codec.unsigned if kind == "unsigned" else codec.signed)(name, bits))
            described.append((name, bits, kind == "signed"))
        room -= bits
    order = draw(st.sampled_from(ByteOrder))
    return codec.Layout(200, "Wide", chosen, order), described


@settings(max_examples=300)
@given(data=st.data())
def test_declared_integers_decode_to_the_values_put_in(data: st.DataObject) -> None:
    """Values are compared with the ones the frame was built from, not only round-tripped."""
    layout, described = data.draw(integer_layouts())
    total = 8 + sum(bits for _, bits, _ in described)
    size = -(-total // 8)
    word, start, expected = 0, 8, {}
    for name, bits, signed in described:
        raw = data.draw(st.integers(0, (1 << bits) - 1)) if name else 0
        if name:
            expected[name] = raw - (1 << bits) if signed and raw >> (bits - 1) else raw
        shift = start if layout.byte_order is ByteOrder.LITTLE else size * 8 - start - bits
        word |= raw << shift
        start += bits
    word |= 200 if layout.byte_order is ByteOrder.LITTLE else 200 << (size * 8 - 8)
    frame = word.to_bytes(size, layout.byte_order.value)
    message = layout.decode(frame)
    assert {name: getattr(message, name) for name in expected} == expected
    assert layout.encode(message) == frame
