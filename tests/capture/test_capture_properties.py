"""Bad input anywhere gives records, never an exception."""

import io

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


BREAKS = st.sampled_from(["\n", "\n", "\n", "\r\n", "\r"])
"""Line breaks as files have them: mostly LF, some CRLF, a lone CR now and then."""


def _as_bytes(data: st.DataObject, lines: list[str]) -> bytes:
    """``lines`` as a file holds them: each with a drawn line break, the last one maybe
    without; UTF-8, lone surrogates as the bytes a bad encoder writes."""
    text = "".join(line + data.draw(BREAKS) for line in lines)
    if text and data.draw(st.booleans()):
        text = text.rstrip("\r\n")
    return text.encode("utf-8", "surrogatepass")


def _chunked(data: st.DataObject, raw: bytes) -> list[bytes]:
    """``raw`` cut at drawn places: inside lines, between CR and LF, inside characters."""
    cuts = sorted(data.draw(st.lists(st.integers(0, len(raw)), max_size=8)))
    return [raw[a:b] for a, b in zip([0, *cuts], [*cuts, len(raw)], strict=True)]


def _text_mode_lines(raw: bytes) -> list[str]:
    """The lines `open` gives for ``raw`` in text mode, as `capture.read` used to read."""
    return list(io.TextIOWrapper(io.BytesIO(raw), "utf-8", "replace"))


@settings(max_examples=400)
@given(st.data(), lines, st.sampled_from([None, "can0"]))
def test_any_text_gives_records(data: st.DataObject, text: list[str], channel: str | None) -> None:
    raw = _as_bytes(data, text)
    fused = list(CaptureDecoder().decode_chunks(_chunked(data, raw), channel))
    two_stage = list(CaptureDecoder().decode(parse_candump(_text_mode_lines(raw), channel)))
    assert fused == two_stage
    assert all(_well_formed(r) for r in fused)


@settings(max_examples=200)
@given(st.data(), lines)
def test_where_chunks_are_cut_changes_nothing(data: st.DataObject, text: list[str]) -> None:
    raw = _as_bytes(data, text)
    whole = list(CaptureDecoder().decode_chunks([raw]))
    assert list(CaptureDecoder().decode_chunks(_chunked(data, raw))) == whole
    assert list(CaptureDecoder().decode_chunks(raw[i : i + 1] for i in range(len(raw)))) == whole


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


def _inserted(data: st.DataObject, line: str, text: str) -> str:
    """``line`` with ``text`` inserted at a drawn place (inside a token or between two)."""
    at = data.draw(st.integers(0, len(line))) if text else 0
    return line[:at] + text + line[at:]


def _reference(decoder: CaptureDecoder, lines: list[str], channel: str | None) -> list[Record]:
    """The records of the exact, line-by-line parser (`parse_line`), with no fast path."""
    items: list[Frame | BadLine] = []
    for number, line in enumerate(lines, 1):
        if line.split():
            item = parse_line(line, number)
            if isinstance(item, BadLine) or channel is None or item.channel == channel:
                items.append(item)
    return list(decoder.decode(items))


@settings(max_examples=300, suppress_health_check=[HealthCheck.too_slow])
@given(st.data(), BUS_MAPS, st.sampled_from([None, "can0"]))
def test_fused_reader_agrees_with_the_exact_parser(
    data: st.DataObject, bus_map: BusMap, channel: str | None
) -> None:
    """The fast paths (`decode_chunks` on bytes, `parse_candump`) against `parse_line` line
    by line, on generated captures: Veronte frames, DroneCAN transfers with drops,
    duplicates, swaps and bit flips, foreign IDs, odd lines, identifiers in lower case or
    not quite hex, any line break, bytes that are not ASCII or not UTF-8, chunks cut
    anywhere."""
    lines = data.draw(captures(bus_map))
    spellings = st.sampled_from(
        ["", "", "", "lower", "0x", "plus", "underscore", "arabic digits", "short"]
    )
    lines = [
        _respelled(line, how) if how else line for line in lines for how in [data.draw(spellings)]
    ]
    odd = st.sampled_from(["", "", "", "", "", "", " é", "\x1c", "\x1f", "\x00", " \udcff"])
    lines = [_inserted(data, line, data.draw(odd)) for line in lines]
    raw = _as_bytes(data, lines)
    read = _text_mode_lines(raw)
    expected = [repr(r) for r in _reference(CaptureDecoder(bus_map), read, channel)]
    fused = CaptureDecoder(bus_map).decode_chunks(_chunked(data, raw), channel)
    assert [repr(r) for r in fused] == expected
    two_stage = CaptureDecoder(bus_map).decode(parse_candump(read, channel))
    assert [repr(r) for r in two_stage] == expected


def test_identifiers_that_int_takes_but_are_not_hex_digits_are_bad_lines() -> None:
    for ident in ("0x123456", "+1234567", "1_234567", "٠١٢٣٤٥٦٧", "0x1", "+12"):
        line = f"(1.0) can0 {ident}#00"
        (item,) = parse_candump([line])
        assert isinstance(item, BadLine), ident
        assert item.reason == f"identifier {ident!r} is not 3 or 8 hex digits"
        (record,) = CaptureDecoder().decode_chunks([line.encode()])
        assert record.kind == "error: bad line"


def test_lower_case_identifiers_decode_as_upper_case_ones() -> None:
    upper = ["(1.0) can0 00A#0000B19C453C", "(1.1) can0 1004060A#00000000000000C0"]
    lower = [line.lower() for line in upper]

    def messages(lines: list[str]) -> list[object]:
        text = "\n".join(lines).encode()
        return [r.message for r in CaptureDecoder().decode_chunks([text])]

    assert messages(lower) == messages(upper)


def test_a_line_longer_than_many_chunks_is_one_line() -> None:
    frame = b"(1.0) can0 009#00FF01\n"
    long = b"(2.0) can0 009#" + b"00" * 100_000 + b"\n"
    raw = frame + long + frame
    chunks = [raw[i : i + 4096] for i in range(0, len(raw), 4096)]
    records = list(CaptureDecoder().decode_chunks(chunks))
    assert [r.kind for r in records] == ["Ready", "error: decode error", "Ready"]
    assert records[1].data == bytes(100_000)
