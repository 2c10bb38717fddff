"""Bad input anywhere gives records, never an exception."""

from hypothesis import given, settings
from hypothesis import strategies as st

from veronte4x.capture.decoder import CaptureDecoder
from veronte4x.capture.frames import Frame
from veronte4x.capture.readers import parse_candump
from veronte4x.capture.records import Record

hex_digits = st.text("0123456789ABCDEFabcdef", max_size=20)
candump_like = st.builds(
    lambda stamp, iface, ident, sep, data, tail: f"({stamp}) {iface} {ident}{sep}{data}{tail}",
    st.one_of(st.floats(allow_nan=True).map(str), st.text(max_size=5)),
    st.sampled_from(["can0", "vcan1", ""]),
    st.one_of(hex_digits, st.sampled_from(["0FF", "008", "009", "00A", "1004D42A", "20000080"])),
    st.sampled_from(["#", "##", "", "#R", "##1"]),
    hex_digits,
    st.sampled_from(["", " R", " T", "_E", " x y"]),
)
lines = st.lists(st.one_of(candump_like, st.text(max_size=40)), max_size=30)


@settings(max_examples=400)
@given(lines, st.sampled_from([None, "can0"]))
def test_any_text_gives_records(text: list[str], channel: str | None) -> None:
    decoder = CaptureDecoder()
    fused = list(decoder.decode_candump(text, channel))
    two_stage = list(CaptureDecoder().decode(parse_candump(text, channel)))
    assert fused == two_stage
    assert all(_well_formed(r) for r in fused)


frames = st.builds(
    Frame,
    st.one_of(st.none(), st.floats(0, 1e6)),
    st.sampled_from(["can0", "can1"]),
    st.one_of(st.sampled_from([8, 9, 10, 11, 255]), st.integers(0, (1 << 29) - 1)),
    st.binary(max_size=9),
    st.booleans(),
    st.booleans(),
    st.booleans(),
    st.booleans(),
)


@settings(max_examples=400)
@given(st.lists(frames, max_size=40))
def test_any_frames_give_records(stream: list[Frame]) -> None:
    records = list(CaptureDecoder().decode(stream))
    assert all(_well_formed(r) for r in records)


def _well_formed(record: Record) -> bool:
    """Decoded, undecoded foreign traffic naming what it was, or an error: one of the three."""
    if record.error is not None:
        return record.message is None and record.kind == f"error: {record.error}"
    if record.message is None:
        return record.kind == "unknown" and record.detail.startswith(
            ("11-bit", "29-bit", "DroneCAN")
        )
    return record.kind == type(record.message).__name__
