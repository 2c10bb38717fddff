"""The candump reader on every form can-utils writes, odd lines included."""

from pathlib import Path

from veronte4x.capture.frames import BadLine, Frame
from veronte4x.capture.readers import parse_candump
from veronte4x.capture.source import open_frames

ODD = Path(__file__).with_name("data") / "odd.log"
T = 1436509052.0


def test_every_line_of_the_odd_capture() -> None:
    items = list(open_frames(ODD))
    assert items == [
        Frame(T + 0.249713, "can0", 0xFF, bytes.fromhex("00ff8177ffff")),
        Frame(T + 0.25, "can0", 0x1004D42A, b"\xc0", extended=True),
        Frame(T + 0.2501, "can1", 0x123, b"", remote=True),
        Frame(T + 0.2502, "can0", 0x123, b"", remote=True),
        Frame(T + 0.2503, "can0", 0x123, bytes.fromhex("deadbeef"), fd=True),
        Frame(T + 0.2504, "can0", 0x80, bytes(8), extended=True, error=True),
        Frame(T + 0.2505, "can0", 0x008, bytes.fromhex("00ff01")),
        Frame(T + 0.2506, "can0", 0x123, b""),
        Frame(T + 0.250700, "can0", 0xFF, bytes.fromhex("00ff8177ffff")),
        Frame(None, "can0", 0x009, bytes.fromhex("00ff01")),
        Frame(None, "can0", 0x123, b"", remote=True),
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
