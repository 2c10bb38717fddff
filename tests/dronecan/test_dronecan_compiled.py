"""The generated fast paths of every type against the generic serializer (the exact path).

Values are drawn from each type's definition alone: empty, full and partial arrays, every
union member, integers at and beyond both ends of their range, floats at the float16 and
float32 limits, infinities and NaNs; with faults mixed in (values of another type, NumPy
scalars, lists for tuples, bytearrays, arrays too long). Where the generated code gives a
result it must be the generic serializer's; where it gives up it may only raise what its
callers catch (`ENCODE_FALLBACK`, `DECODE_FALLBACK`), and then only on input the generic
serializer refuses or saturates. Valid values and payloads never leave the generated code.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given
from hypothesis import strategies as st
from tests.dsdl_support import write_namespace
from tests.soak import differential

from veronte4x import dronecan
from veronte4x.dronecan import transfer as transfer_module
from veronte4x.dronecan.codec import CODECS, TypeCodec
from veronte4x.dronecan.compiled import DECODE_FALLBACK, ENCODE_FALLBACK
from veronte4x.dronecan.fast_base import int_array_tables
from veronte4x.dronecan.schema import Scalar, Struct, Union, tao_min_bits
from veronte4x.errors import DecodeError, EncodeError

np: Any
try:
    import numpy

    np = numpy
except ImportError:  # pragma: no cover - NumPy is a dev dependency
    np = None

_IDS = [f"{c.data_type.full_name}-{c.data_type.kind.name}" for c in CODECS]

_FLOATS = st.one_of(
    st.floats(),
    st.floats(width=16),
    st.floats(width=32),
    st.sampled_from(
        [
            *(0.0, -0.0, 65504.0, 65519.99, 65520.0, -65520.0, 2.0**-24, 2.0**-25, 2.0**-26),
            *(3.4028234663852886e38, 3.4028235677973366e38, 1e39, -1e300, 1e-46),
            *(math.inf, -math.inf, math.nan, -math.nan),
        ]
    ),
    st.integers(-(2**70), 2**70),
)


def _ends(low: int, high: int) -> st.SearchStrategy[int]:
    return st.one_of(
        st.sampled_from((low, high, 0 if low <= 0 <= high else low)), st.integers(low, high)
    )


def _numpy_int(value: int) -> Any:
    for kind in (np.int8, np.uint8, np.int16, np.uint16, np.int32, np.uint32, np.int64):
        info = np.iinfo(kind)
        if info.min <= value <= info.max:
            return kind(value)
    return np.uint64(value) if 0 <= value < 2**64 else value


def _faulty(
    valid: st.SearchStrategy[Any], *faults: st.SearchStrategy[Any]
) -> st.SearchStrategy[Any]:
    """Mostly ``valid`` values, sometimes one of the faults."""
    return st.one_of(valid, valid, valid, *faults)


def _scalar(t: Scalar, enum: type | None, faults: bool) -> st.SearchStrategy[Any]:
    if t.kind == "float":
        valid: st.SearchStrategy[Any] = _FLOATS
        if not faults:
            return valid
        extra: list[st.SearchStrategy[Any]] = [st.sampled_from([True, None, "1.5", 1.5j])]
        if np is not None:
            extra.append(st.floats(width=32).map(np.float32))
            extra.append(st.floats(width=16).map(np.float16))
        return _faulty(valid, *extra)
    if t.kind == "bool":
        valid = st.booleans()
        if not faults:
            return valid
        extra = [st.sampled_from([0, 1, 2, None, 1.0])]
        if np is not None:
            extra.append(st.booleans().map(np.bool_))
        return _faulty(valid, *extra)
    valid = _ends(t.low, t.high)
    if enum is not None:
        valid = st.one_of(valid, st.sampled_from(list(enum)))  # type: ignore[call-overload]
    if not faults:
        return valid
    extra = [
        st.integers(t.low - 3, t.low - 1),
        st.integers(t.high + 1, t.high + 3),
        st.sampled_from([True, False, 1.0, None, "1"]),
    ]
    if np is not None:
        extra.append(_ends(t.low, t.high).map(_numpy_int))
        extra.append(st.booleans().map(np.bool_))
    return _faulty(valid, *extra)


def messages(t: Struct, faults: bool) -> st.SearchStrategy[Any]:
    """Instances of a struct's class, their fields drawn by `values`."""
    fields = {f.name: values(f.type, faults, f.enum) for f in t.fields if f.name}
    return st.builds(t.cls, **fields)


def values(t: Any, faults: bool, enum: type | None = None) -> st.SearchStrategy[Any]:
    """Python values of any schema type (message objects for structs)."""
    if isinstance(t, Scalar):
        return _scalar(t, enum, faults)
    if isinstance(t, Struct):
        built = messages(t, faults)
        return _faulty(built, st.just(None)) if faults else built
    if isinstance(t, Union):
        members = [
            values(m.type, faults)
            if isinstance(m.type, Struct)
            else st.builds(m.cls, values(m.type, faults))
            for m in t.members
        ]
        return st.one_of(members)
    item = values(t.item, faults)
    sizes = (
        st.just(t.max_size)
        if not t.dynamic
        else st.one_of(st.sampled_from((0, t.max_size)), st.integers(0, t.max_size))
    )
    items = sizes.flatmap(lambda n: st.lists(item, min_size=n, max_size=n))
    if t.is_bytes:
        size = t.max_size
        valid = st.binary(min_size=size, max_size=size)
        if t.dynamic:  # empty, full or in between
            valid = st.one_of(st.just(b""), valid, st.binary(max_size=size))
        if not faults:
            return valid
        return _faulty(
            valid,
            valid.map(bytearray),
            st.binary(min_size=size + 1, max_size=size + 2),
            st.just((1, 2)),
        )
    tuples: st.SearchStrategy[Any] = items.map(tuple)
    if not faults:
        return tuples
    too_many = st.lists(item, min_size=t.max_size + 1, max_size=t.max_size + 1).map(tuple)
    return _faulty(tuples, items, too_many, st.just(None))


def _same(a: Any, b: Any) -> bool:
    """Equal values, NaN equal to NaN (the repr of a float is exact; every NaN is 'nan')."""
    return repr(a) == repr(b)


def _generic_payload(codec: TypeCodec, message: Any) -> bytes | Exception:
    try:
        return codec.generic.encode(message)
    except EncodeError as error:
        return error


@pytest.mark.parametrize("codec", CODECS, ids=_IDS)
def test_every_type_has_generated_code(codec: TypeCodec) -> None:
    fast = codec.fast  # written ahead of time: a module of veronte4x.dronecan.fast
    assert codec.fast_module is not None
    module = sys.modules[codec.fast_module]
    assert fast.payload.__code__.co_filename == module.__file__
    assert fast.decode.__code__.co_filename == module.__file__
    # A frame decoder wherever the shortest payload may fit one frame.
    assert (fast.decode_frame is not None) == (tao_min_bits(codec.data_type.schema) <= 56)


def _transport(codec: TypeCodec) -> tuple[int, int, int, int | None]:
    service = codec.data_type.kind is not dronecan.TransferKind.MESSAGE
    return 42, 17, 9, 7 if service else None


@pytest.mark.parametrize("codec", CODECS, ids=_IDS)
@differential(30)
@given(data=st.data())
def test_valid_values_take_the_generated_code_both_ways(
    codec: TypeCodec, data: st.DataObject
) -> None:
    message = data.draw(messages(codec.data_type.schema, faults=False), label="message")
    payload = codec.fast.payload(message)  # never hands over: the values are valid
    assert payload == codec.generic.encode(message)
    source, tid, priority, destination = _transport(codec)
    frames = codec.fast.frames(message, source, tid, priority, destination)
    assert frames == transfer_module._encode_checked(
        message, source, tid, priority, destination, False
    )
    decoded = codec.fast.decode(payload)
    assert _same(decoded, codec.generic.decode(payload))
    assert type(decoded) is codec.data_type.schema.cls
    if len(payload) <= 7:
        assert codec.fast.decode_frame is not None
        assert _same(codec.fast.decode_frame(payload + bytes([0xC0 | tid])), decoded)


@pytest.mark.parametrize("codec", CODECS, ids=_IDS)
@pytest.mark.filterwarnings("ignore:overflow encountered:RuntimeWarning")  # NumPy float16
@differential(30)
@given(data=st.data())
def test_any_values_encode_as_the_generic_serializer(codec: TypeCodec, data: st.DataObject) -> None:
    message = data.draw(messages(codec.data_type.schema, faults=True), label="message")
    expected = _generic_payload(codec, message)
    try:
        payload = codec.fast.payload(message)
    except ENCODE_FALLBACK:
        pass  # the generic serializer decides (checked below through the public path)
    else:
        assert payload == expected
    source, tid, priority, destination = _transport(codec)
    try:
        frames = codec.fast.frames(message, source, tid, priority, destination)
    except ENCODE_FALLBACK:
        pass
    else:
        assert not isinstance(expected, Exception)
        assert frames == transfer_module._encode_checked(
            message, source, tid, priority, destination, False
        )
    if isinstance(expected, Exception):
        with pytest.raises(EncodeError):
            codec.encode(message)
    else:
        assert codec.encode(message) == expected


def _payloads(codec: TypeCodec) -> st.SearchStrategy[bytes]:
    """Arbitrary bytes, and valid payloads cut short, extended or with one byte changed."""
    valid = st.builds(codec.generic.encode, messages(codec.data_type.schema, faults=False))
    changed = st.tuples(valid, st.integers(0, 400), st.integers(1, 255)).map(
        lambda v: v[0] if not v[0] else _flip(*v)
    )
    return st.one_of(
        st.binary(max_size=codec.max_payload + 9),
        valid,
        st.tuples(valid, st.integers(1, 8)).map(lambda v: v[0][: -v[1]]),
        st.tuples(valid, st.binary(min_size=1, max_size=8)).map(lambda v: v[0] + v[1]),
        changed,
    )


def _flip(payload: bytes, index: int, mask: int) -> bytes:
    index %= len(payload)
    return payload[:index] + bytes([payload[index] ^ mask]) + payload[index + 1 :]


@pytest.mark.parametrize("codec", CODECS, ids=_IDS)
@differential(50)
@given(data=st.data())
def test_any_bytes_decode_as_the_generic_serializer(codec: TypeCodec, data: st.DataObject) -> None:
    payload = data.draw(_payloads(codec), label="payload")
    try:
        expected: Any = codec.generic.decode(payload)
    except DecodeError as error:
        expected = error
    try:
        decoded = codec.fast.decode(payload)
    except DECODE_FALLBACK:
        assert isinstance(expected, DecodeError)  # a valid payload never leaves the fast path
    else:
        assert _same(decoded, expected)
    if codec.fast.decode_frame is not None and len(payload) <= 7:
        try:
            decoded = codec.fast.decode_frame(payload + b"\xc5")
        except DECODE_FALLBACK:
            assert isinstance(expected, DecodeError)
        else:
            assert _same(decoded, expected)
    # The public path: a value or the library's own error, nothing else.
    try:
        assert _same(codec.decode(payload), expected)
    except DecodeError as error:
        assert str(error) == str(expected)


def test_float16_fields_in_array_items_keep_the_array(tmp_path: Path) -> None:
    # The float16 temporaries of an item once took the names of the encoder's array
    # variables (a1, ...): the array became an int before its last item, the generated
    # encoder raised TypeError and every such message took the generic serializer.
    root = write_namespace(
        tmp_path,
        "acme",
        {"Item": "uint8 x\nfloat16 f\nuint8[<=3] tail\n", "20000.Pack": "Item[2] items\n"},
    )
    types = dronecan.TypeSet.standard().with_dsdl(root)
    (codec,) = (c for c in types.codecs if c.data_type.full_name == "acme.Pack")
    items = [{"x": 1, "f": 1.5, "tail": [1, 2]}, {"x": 2, "f": -2.0, "tail": [3]}]
    message: Any = dronecan.from_builtin(types["acme.Pack"], {"items": items}, types=types)
    payload = codec.fast.payload(message)  # valid values never leave the generated code
    assert payload == codec.generic.encode(message)
    assert codec.fast.decode(payload) == message


@pytest.mark.parametrize("bits", range(9, 17))
def test_int_array_tables_by_their_definition(bits: int) -> None:
    """The tables of an int array made of ranges are those of their definition: each
    value's low byte, then its top bits (RawCommand's int14 is a 14-bit case)."""
    low, high = -(1 << (bits - 1)), (1 << (bits - 1)) - 1
    to_stream, from_stream = int_array_tables(low, high)
    mask, rest = (1 << bits) - 1, bits - 8
    expected = [((v & 0xFF) << rest) | ((v & mask) >> 8) for v in range(low, high + 1)]
    assert list(to_stream) == expected
    assert [from_stream[piece] for piece in expected] == list(range(low, high + 1))
    assert len(from_stream) == 1 << bits
    with pytest.raises(ValueError, match="no int type"):
        int_array_tables(low + 1, high)
