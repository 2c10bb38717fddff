"""The candump reader on every form can-utils writes, odd lines included."""

from pathlib import Path

from hypothesis import given, settings
from hypothesis import strategies as st

from veronte4x.capture.frames import BadLine, Frame
from veronte4x.capture.readers import parse_candump
from veronte4x.capture.readers.candump import CAN_ERR_FLAG, log_line, parse_line
from veronte4x.capture.source import open_frames

ODD = Path(__file__).with_name("data") / "odd.log"
T = 1436509052.0
T1 = T + 0.249713


def test_every_line_of_the_odd_capture() -> None:
    items = list(open_frames(ODD))
    assert items == [
        Frame(T + 0.249713, "can0", 0xFF, bytes.fromhex("00ff8177ffff")),
        Frame(T + 0.25, "can0", 0x1004D42A, b"\xc0", extended=True),
        Frame(T + 0.2501, "can1", 0x123, b"", remote=True),
        Frame(T + 0.2502, "can0", 0x123, b"", remote=True, dlc=3),
        Frame(T + 0.2503, "can0", 0x123, bytes.fromhex("deadbeef"), fd=True, brs=True),
        Frame(T + 0.2504, "can0", 0x80, bytes(8), extended=True, error=True),
        Frame(T + 0.2505, "can0", 0x008, bytes.fromhex("00ff01")),
        Frame(T + 0.2506, "can0", 0x123, b""),
        Frame(T + 0.250700, "can0", 0xFF, bytes.fromhex("00ff8177ffff")),
        Frame(None, "can0", 0x009, bytes.fromhex("00ff01")),
        Frame(None, "can0", 0x123, b"", remote=True, dlc=2),
        Frame(None, "can0", 0x4, bytes.fromhex("0004000000000000"), extended=True, error=True),
        Frame(1436516252.249713, "can0", 0x00A, bytes.fromhex("00ff00")),
        BadLine(14, "garbage here", "expected 'interface ID [length] data'"),
        BadLine(15, "(12.0) can0 12#00", "identifier '12' is not 3 or 8 hex digits"),
        BadLine(
            16,
            "(12.0) can0 123#0",
            "not a candump frame: non-hexadecimal number found in fromhex() arg at position 1",
        ),
        BadLine(
            17, "\tcontroller-problem{rx-error-warning}", "expected 'interface ID [length] data'"
        ),
        Frame(T + 0.26, "can0", 0x008, bytes.fromhex("0400")),
    ]


def test_channel_filter_keeps_bad_lines_for_counting() -> None:
    items = list(parse_candump(ODD.read_text().splitlines(), "can1"))
    assert [i for i in items if isinstance(i, Frame)] == [
        Frame(T + 0.2501, "can1", 0x123, b"", remote=True)
    ]
    assert [i.line_number for i in items if isinstance(i, BadLine)] == [14, 15, 16, 17]


def test_gzip(tmp_path: Path) -> None:
    import gzip

    packed = tmp_path / "capture.log.gz"
    packed.write_bytes(gzip.compress(b"(1.5) can0 0FF#01\n"))
    assert list(open_frames(packed)) == [Frame(1.5, "can0", 0xFF, b"\x01")]


def _ascii(data: bytes) -> str:
    """candump -a's ASCII column: printable bytes as themselves, the rest as dots."""
    return "".join(chr(b) if 0x1F < b < 0x7F else "." for b in data)


_IDS = st.one_of(
    st.integers(0, 0x7FF).map(lambda ident: (ident, False)),
    st.integers(0, 2**29 - 1).map(lambda ident: (ident, True)),  # 29-bit: 8 hex digits
)


@settings(max_examples=300)
@given(
    st.binary(min_size=0, max_size=8),
    _IDS,
    st.sampled_from(["(1436509052.249713)  ", "(2015-07-10 08:17:32.249713)  ", ""]),
    st.booleans(),
)
def test_human_view_with_any_bytes_in_the_ascii_column(
    data: bytes, ident: tuple[int, bool], stamp: str, ascii_column: bool
) -> None:
    """A '#' (or anything else) in candump -a's ASCII column does not make a line a log line;
    11-bit and 29-bit ids alike, with or without the column."""
    can_id, extended = ident
    hexbytes = " ".join(f"{b:02X}" for b in data)
    text = f"{can_id:08X}" if extended else f"{can_id:03X}"
    column = f"   '{_ascii(data)}'" if ascii_column else ""
    line = f"{stamp}can0  {text}   [{len(data)}]  {hexbytes}{column}\n"
    [frame] = parse_candump([line])
    assert isinstance(frame, Frame)
    assert (frame.can_id, frame.data, frame.extended) == (can_id, data, extended)
    assert frame.timestamp == {"(1436509052.249713)  ": T + 0.249713, "": None}.get(
        stamp, 1436516252.249713
    )


@given(st.binary(min_size=0, max_size=8), _IDS, st.sampled_from(["can0", "vcan1", "can10"]))
def test_log_form_with_11_and_29_bit_ids(
    data: bytes, ident: tuple[int, bool], channel: str
) -> None:
    can_id, extended = ident
    text = f"{can_id:08X}" if extended else f"{can_id:03X}"
    [frame] = parse_candump([f"(1436509052.249713) {channel} {text}#{data.hex().upper()}\n"])
    assert frame == Frame(T + 0.249713, channel, can_id, data, extended)


def test_uavcan_file_read_transfer_with_hash_in_ascii_column() -> None:
    """A DroneCAN uavcan.protocol.file.Read response whose bytes include 0x23 ('#')."""
    lines = [
        "(1600000000.000100)  can0  1030427F   [8]  00 00 00 00 00 23 2F 88   '.....#/.'",
        "(1600000000.000200)  can0  1030427F   [3]  23 23 48   '##H'",
    ]
    frames = list(parse_candump(lines))
    assert frames == [
        Frame(1600000000.0001, "can0", 0x1030427F, bytes.fromhex("0000000000232f88"), True),
        Frame(1600000000.0002, "can0", 0x1030427F, bytes.fromhex("232348"), True),
    ]


_FORMS: tuple[str, ...] = (
    "plain",
    "direction",
    "remote",
    "remote_dlc",
    "fd",
    "raw_dlc",
    "error",
    "human",
)
_FORMS += ("human_remote", "human_error", "human_fd")


@settings(max_examples=200)
@given(
    st.binary(min_size=0, max_size=8),
    _IDS,
    st.sampled_from(_FORMS),
    st.sampled_from(["can0", "vcan1"]),
)
def test_every_candump_form_with_11_and_29_bit_ids(
    data: bytes, ident: tuple[int, bool], form: str, channel: str
) -> None:
    """Each form of the module docstring, for any id of either width: the frame's id, width
    and kind; parse_candump (with its fast path) and parse_line agree."""
    can_id, extended = ident
    text = f"{can_id:08X}" if extended else f"{can_id:03X}"
    error_text = f"{can_id | CAN_ERR_FLAG:08X}"
    hexbytes = data.hex().upper()
    spaced = " ".join(f"{b:02X}" for b in data)
    stamp = "(1436509052.249713)"
    line, expected = {
        "plain": (
            f"{stamp} {channel} {text}#{hexbytes}",
            Frame(T1, channel, can_id, data, extended),
        ),
        "direction": (
            f"{stamp} {channel} {text}#{hexbytes} T",
            Frame(T1, channel, can_id, data, extended),
        ),
        "remote": (
            f"{stamp} {channel} {text}#R",
            Frame(T1, channel, can_id, b"", extended, remote=True),
        ),
        "remote_dlc": (
            f"{stamp} {channel} {text}#R{len(data)}",
            Frame(T1, channel, can_id, b"", extended, remote=True, dlc=len(data)),
        ),
        "fd": (
            f"{stamp} {channel} {text}##1{hexbytes}",
            Frame(T1, channel, can_id, data, extended, fd=True, brs=True),
        ),
        "raw_dlc": (
            f"{stamp} {channel} {text}#{hexbytes}_{len(data) or 9:X}",
            Frame(T1, channel, can_id, data, extended),
        ),
        "error": (
            f"{stamp} {channel} {error_text}#{hexbytes}",
            Frame(T1, channel, can_id, data, True, error=True),
        ),
        "human": (
            f"{stamp}  {channel}  {text}   [{len(data)}]  {spaced}",
            Frame(T1, channel, can_id, data, extended),
        ),
        "human_remote": (
            f"  {channel}  {text}   [{len(data)}]  remote request",
            Frame(None, channel, can_id, b"", extended, remote=True, dlc=len(data)),
        ),
        "human_error": (
            f"  {channel}  {error_text}   [{len(data)}]  {spaced}   ERRORFRAME",
            Frame(None, channel, can_id, data, True, error=True),
        ),
        "human_fd": (
            f"{stamp}  {channel}  {text}  [{len(data) + 12:02d}]  {spaced} {'00 ' * 12}",
            Frame(T1, channel, can_id, data + bytes(12), extended, fd=True),
        ),
    }[form]
    assert list(parse_candump([line + "\n"])) == [expected]
    assert parse_line(line, 1) == expected
    assert list(parse_candump([line], "other")) == []


_stamps = st.integers(0, 2**42).map(lambda us: us / 1_000_000)
_channels = st.sampled_from(["can0", "vcan1", "mcast:0", "slcan0"])
_written = st.one_of(
    st.builds(
        lambda t, c, ext, ident, data: Frame(
            t, c, ident & (0x1FFFFFFF if ext else 0x7FF), data, ext
        ),
        _stamps, _channels, st.booleans(), st.integers(0, 0x1FFFFFFF), st.binary(max_size=8),
    ),
    st.builds(
        lambda t, c, ext, ident, dlc: Frame(
            t, c, ident & (0x1FFFFFFF if ext else 0x7FF), b"", ext, remote=True, dlc=dlc
        ),
        _stamps, _channels, st.booleans(), st.integers(0, 0x1FFFFFFF), st.integers(0, 8),
    ),
    st.builds(
        lambda t, c, ext, ident, data, brs, esi: Frame(
            t, c, ident & (0x1FFFFFFF if ext else 0x7FF), data, ext, fd=True, brs=brs, esi=esi
        ),
        _stamps, _channels, st.booleans(), st.integers(0, 0x1FFFFFFF),
        st.sampled_from([0, 1, 8, 12, 64]).flatmap(lambda n: st.binary(min_size=n, max_size=n)),
        st.booleans(), st.booleans(),
    ),
    st.builds(
        lambda t, c, ident, data: Frame(t, c, ident, data, True, error=True),
        _stamps, _channels, st.integers(0, 0x1FFFFFFF), st.binary(min_size=8, max_size=8),
    ),
)  # fmt: skip


@given(_written)
def test_a_written_log_line_reads_back_as_its_frame(frame: Frame) -> None:
    assert parse_line(log_line(frame), 1) == frame


def test_log_lines_as_candump_writes_them() -> None:
    assert [
        log_line(Frame(1436509052.249713, "can0", 0xFF, bytes.fromhex("00ff8177ffff"))),
        log_line(Frame(7.5, "can1", 0x1004D42A, b"\xc0", True)),
        log_line(Frame(0.0, "can0", 0x123, b"", remote=True, dlc=3)),
        log_line(Frame(1.0, "can0", 0x123, bytes.fromhex("deadbeef"), fd=True, brs=True)),
        log_line(Frame(1.0, "can0", 0x80, bytes(8), True, error=True)),
    ] == [
        "(1436509052.249713) can0 0FF#00FF8177FFFF",
        "(0000000007.500000) can1 1004D42A#C0",
        "(0000000000.000000) can0 123#R3",
        "(0000000001.000000) can0 123##1DEADBEEF",
        "(0000000001.000000) can0 20000080#0000000000000000",
    ]
