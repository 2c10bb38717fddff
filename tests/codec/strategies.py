"""Hypothesis strategies for Veronte messages and valid frames."""

from __future__ import annotations

from hypothesis import strategies as st

from veronte4x import codec
from veronte4x.codec.layouts import OPAQUE, STATUS_FLAGS

FLAG_NAMES = [name for name, _ in STATUS_FLAGS]
flags4 = st.tuples(st.booleans(), st.booleans(), st.booleans(), st.booleans())
float32s = st.floats(width=32, allow_nan=False)


@st.composite
def statuses(draw: st.DrawFn) -> codec.Status:
    flags = draw(st.one_of(st.none(), st.lists(st.booleans(), min_size=16, max_size=16)))
    values = [None] * 16 if flags is None else flags
    extra = dict(zip(FLAG_NAMES, values, strict=True))
    return codec.Status(
        selected=draw(st.integers(0, 3)),
        arbitrating=draw(st.booleans()),
        alive=draw(flags4),
        ready=draw(flags4),
        **extra,
    )


opaque_messages = st.one_of(
    [st.builds(layout.message, payload=st.binary(max_size=7)) for layout in OPAQUE.values()]
)

MESSAGES: dict[str, st.SearchStrategy[codec.Message]] = {
    "Status": statuses(),
    "Score": st.builds(codec.Score, autopilot=st.integers(0, 3), score=float32s),
    "Ready": st.builds(codec.Ready, ready=st.booleans()),
    "ArbitrationVariable": st.builds(
        codec.ArbitrationVariable, number=st.integers(0, 31), value=float32s
    ),
    "VersionRequest": st.just(codec.VersionRequest()),
    "VersionResponse": st.builds(
        codec.VersionResponse, application_code=st.integers(0, 255), rest=st.binary(max_size=6)
    ),
    "PwmSet": st.builds(
        codec.PwmSet,
        first_channel=st.sampled_from([0, 4, 8, 12, 16]),
        values=st.tuples(*[st.integers(0, 4095)] * 4),
    ),
    "Opaque": opaque_messages,
}


def _frame(*parts: st.SearchStrategy[bytes]) -> st.SearchStrategy[bytes]:
    return st.tuples(*parts).map(b"".join)


def _byte(strategy: st.SearchStrategy[int]) -> st.SearchStrategy[bytes]:
    return strategy.map(lambda b: bytes([b]))


_selected_byte = st.tuples(st.integers(0, 3), st.booleans()).map(lambda t: t[0] | t[1] << 7)

VALID_FRAMES: dict[str, tuple[codec.Sender, st.SearchStrategy[bytes]]] = {
    "Status 4x": (
        codec.Sender.ARBITER,
        _frame(st.just(b"\x00\xff"), _byte(_selected_byte), st.binary(min_size=3, max_size=3)),
    ),
    "Status CEX": (
        codec.Sender.ARBITER,
        _frame(st.just(b"\x00\xff"), _byte(_selected_byte), st.binary(min_size=1, max_size=1)),
    ),
    "Score": (
        codec.Sender.ARBITER,
        _frame(st.just(b"\x00"), _byte(st.integers(0, 3)), st.binary(min_size=4, max_size=4)),
    ),
    "Ready": (codec.Sender.AUTOPILOT, st.sampled_from([b"\x00\xff\x00", b"\x00\xff\x01"])),
    "ArbitrationVariable": (
        codec.Sender.AUTOPILOT,
        _frame(st.just(b"\x00"), _byte(st.integers(0, 31)), st.binary(min_size=4, max_size=4)),
    ),
    "Version": (
        codec.Sender.AUTOPILOT,
        _frame(st.just(b"\x01"), st.binary(max_size=7)),
    ),
    "PwmSet": (
        codec.Sender.AUTOPILOT,
        _frame(_byte(st.sampled_from([2, 3, 11, 12, 13])), st.binary(min_size=6, max_size=6)),
    ),
    "Opaque": (
        codec.Sender.ARBITER,
        _frame(_byte(st.sampled_from(sorted(OPAQUE))), st.binary(max_size=7)),
    ),
}
