"""Bad input anywhere gives records, never an exception."""

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.capture.columnar_support import BUS_MAPS, captures
from veronte4x.capture import BusMap
from veronte4x.capture.decoder import CaptureDecoder
from veronte4x.capture.frames import BadLine, Frame
from veronte4x.capture.readers import parse_candump
from veronte4x.capture.readers.candump import parse_line
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


def _respelled(line: str, how: str) -> str:
    """``line`` with the identifier of its log form respelled ``how``."""
    parts = line.split(" ")
    if len(parts) != 3 or "#" not in parts[2]:
        return line
    ident, _, rest = parts[2].partition("#")
    spelled = {
        "lower": ident.lower(),
        "0x": "0x" + ident[2:],
        "plus": "+" + ident[1:],
        "underscore": ident[:1] + "_" + ident[2:],
        "arabic digits": ident.translate(str.maketrans("0123456789", "٠١٢٣٤٥٦٧٨٩")),
        "short": ident[1:],
    }[how]
    return f"{parts[0]} {parts[1]} {spelled}#{rest}"


def _reference(decoder: CaptureDecoder, lines: list[str], channel: str | None) -> list[Record]:
    """The records of the exact, line-by-line parser (`parse_line`), with no fast path."""
    items: list[Frame | BadLine] = []
    for number, line in enumerate(lines, 1):
        if line.split():
            item = parse_line(line, number)
            if isinstance(item, BadLine) or channel is None or item.channel == channel:
                items.append(item)
    return list(decoder.decode(items))


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.data(), BUS_MAPS, st.sampled_from([None, "can0"]))
def test_fused_reader_agrees_with_the_exact_parser(
    data: st.DataObject, bus_map: BusMap, channel: str | None
) -> None:
    """The fast paths (`decode_candump`, `parse_candump`) against `parse_line` line by line,
    on generated captures: Veronte frames, DroneCAN transfers with drops, duplicates, swaps
    and bit flips, foreign IDs, odd lines, identifiers in lower case or not quite hex."""
    lines = data.draw(captures(bus_map))
    spellings = st.sampled_from(
        ["", "", "", "lower", "0x", "plus", "underscore", "arabic digits", "short"]
    )
    lines = [
        _respelled(line, how) if how else line for line in lines for how in [data.draw(spellings)]
    ]
    expected = [repr(r) for r in _reference(CaptureDecoder(bus_map), lines, channel)]
    fused = CaptureDecoder(bus_map)
    assert [repr(r) for r in fused.decode_candump(lines, channel)] == expected
    two_stage = CaptureDecoder(bus_map).decode(parse_candump(lines, channel))
    assert [repr(r) for r in two_stage] == expected


def test_identifiers_that_int_takes_but_are_not_hex_digits_are_bad_lines() -> None:
    for ident in ("0x123456", "+1234567", "1_234567", "٠١٢٣٤٥٦٧", "0x1", "+12"):
        line = f"(1.0) can0 {ident}#00"
        (item,) = parse_candump([line])
        assert isinstance(item, BadLine), ident
        assert item.reason == f"identifier {ident!r} is not 3 or 8 hex digits"
        (record,) = CaptureDecoder().decode_candump([line])
        assert record.kind == "error: bad line"


def test_lower_case_identifiers_decode_as_upper_case_ones() -> None:
    upper = ["(1.0) can0 00A#0000B19C453C", "(1.1) can0 1004060A#00000000000000C0"]
    lower = [line.lower() for line in upper]
    assert [r.message for r in CaptureDecoder().decode_candump(lower)] == [
        r.message for r in CaptureDecoder().decode_candump(upper)
    ]
