"""Bus load of every frame: remote, CAN FD (each phase at its own bit rate) and error frames,
with bit counts worked out by hand from the frame layouts, and a detection that says why it
found no bit rate."""

import math
from pathlib import Path

import pytest

from tests.client.cli_support import veronte4x
from veronte4x.capture.rates import (
    ERROR_FRAME_BITS,
    RateTracker,
    fd_frame_bits,
    frame_bits,
)


@pytest.mark.parametrize(
    ("data_bytes", "extended", "stuffed", "bare"),
    [
        # 11-bit: g = 34 (SOF, ID 11, RTR, IDE, r0, DLC 4, CRC-15), then 13 unstuffed bits;
        # 1 byte: 34 + 8 + 13 = 55, and floor((34 + 8 - 1) / 4) = 10 stuff bits.
        (1, False, 65, 55),
        # 29-bit: g = 54; 3 bytes: 54 + 24 + 13 = 91, and floor(77 / 4) = 19.
        (3, True, 110, 91),
    ],
)
def test_classic_frames(data_bytes: int, extended: bool, stuffed: int, bare: int) -> None:
    assert frame_bits(data_bytes, extended) == stuffed
    assert frame_bits(data_bytes, extended, stuffing=False) == bare


def test_a_remote_frame_has_no_data_field_whatever_its_dlc() -> None:
    tracker = RateTracker(bitrate=500_000)
    tracker.add(0.0, 0x123, b"", False, "can0", remote=True)  # DLC 5 asked: no data sent
    tracker.add(1.0, 0x1234567, b"", True, "can0", remote=True)
    (load,) = tracker.load()
    # 34 + 13 + floor(33 / 4) = 55, and 54 + 13 + floor(53 / 4) = 80.
    assert (load.frames, load.bits, load.data_bits) == (2, 55 + 80, 0)
    assert tracker.streams() == []  # a request, not the stream's message


def test_fd_frame_bits_by_hand() -> None:
    # 11-bit ID, 8 bytes. Arbitration phase SOF, ID 11, RRS, IDE, FDF, res, BRS = 17 bits,
    # plus CRC delimiter, ACK slot and delimiter, EOF 7, intermission 3 = 13, plus the
    # stuff bits of the 17: floor(16 / 4) = 4: 34. Data phase ESI, DLC 4, data 64, stuff
    # count 4, CRC-17, 6 fixed stuff bits = 96, plus the dynamic stuff bits of SOF to the
    # data's end (17 + 5 + 64 = 86 bits: floor(85 / 4) = 21) less the arbitration's 4: 113.
    assert fd_frame_bits(8, False) == (34, 113)
    assert fd_frame_bits(8, False, stuffing=False) == (30, 96)
    # 29-bit ID, 20 bytes: 36 arbitration bits (SOF, 11, SRR, IDE, 18, RRS, FDF, res, BRS),
    # CRC-21 and 7 fixed stuff bits above 16 bytes.
    nominal = 36 + 13 + 35 // 4  # 57
    data = 5 + 160 + 4 + 21 + 7 + (36 + 5 + 160 - 1) // 4 - 35 // 4  # 197 + 42 = 239
    assert fd_frame_bits(20, True) == (nominal, data) == (57, 239)
    # 29-bit ID, 8 bytes (the table of docs/other-tools.md): 96 + floor(104 / 4) - 8.
    assert fd_frame_bits(8, True) == (57, 114)
    # 10 bytes go on the bus as 12 (the DLC gives no 10); 0 bytes still have their CRC.
    assert fd_frame_bits(10, False) == fd_frame_bits(12, False) == (34, 128 + 25)
    assert fd_frame_bits(0, False) == (34, 5 + 4 + 17 + 6 + (22 - 1) // 4 - 4)  # (34, 33)
    assert fd_frame_bits(64, False, stuffing=False) == (30, 5 + 512 + 4 + 21 + 7)


def test_fd_phases_at_their_own_bit_rates() -> None:
    tracker = RateTracker(bitrate=500_000, data_bitrate=2_000_000)
    tracker.add(0.0, 0x100, bytes(8), False, "can0", fd=True, brs=True)
    tracker.add(0.01, 0x100, bytes(8), False, "can0", fd=True)  # no BRS: all nominal
    (load,) = tracker.load()
    assert (load.frames, load.bits, load.data_bits) == (2, 147 + 147, 113)
    busy = (294 - 113) / 500_000 + 113 / 2_000_000
    assert load.percent == pytest.approx(100 * busy / 0.01, rel=1e-12)
    assert (load.bitrate, load.data_bitrate, load.reason) == (500_000, 2_000_000, "")
    (stream,) = tracker.streams()
    assert (stream.label, stream.count) == ("100", 2)  # FD data frames are a stream


def test_brs_without_a_data_bit_rate_says_so() -> None:
    tracker = RateTracker(bitrate=500_000)
    tracker.add(0.0, 0x100, bytes(8), False, "can0", fd=True, brs=True)
    tracker.add(0.01, 0x100, bytes(8), False, "can0", fd=True, brs=True)
    (load,) = tracker.load()
    assert math.isnan(load.percent)
    assert load.reason == "CAN FD frames with BRS: data bit rate unknown; give --data-bitrate"


def test_four_kinds_of_frame_in_the_load_and_its_span() -> None:
    tracker = RateTracker(bitrate=500_000, data_bitrate=2_000_000)
    tracker.add(0.0, 0x100, bytes(8), False, "can0")  # 135
    tracker.add(0.001, 0x101, b"", False, "can0", remote=True)  # 55
    tracker.add(0.002, 0x102, bytes(8), False, "can0", fd=True, brs=True)  # 34 + 113
    tracker.add(0.003, 0, b"", True, "can0", error=True)  # 23
    (load,) = tracker.load()
    assert ERROR_FRAME_BITS == 6 + 6 + 8 + 3
    assert (load.frames, load.bits, load.data_bits) == (4, 135 + 55 + 34 + 113 + 23, 113)
    assert load.seconds == 0.003
    busy = (135 + 55 + 34 + 23) / 500_000 + 113 / 2_000_000
    assert load.percent == pytest.approx(100 * busy / 0.003, rel=1e-12)  # 18.35 %
    assert [s.label for s in tracker.streams()] == ["100", "102"]


def test_detection_says_frames_are_too_close() -> None:
    tracker = RateTracker()
    tracker.add(1.0, 0x100, bytes(8), False, "can0")
    tracker.add(1.00001, 0x101, bytes(8), False, "can0")
    (load,) = tracker.load()
    assert (load.bitrate, load.detected) == (None, True)
    assert load.reason == "frames 10 µs apart: faster than any standard bit rate; give --bitrate"


def test_detection_with_one_frame_says_there_is_nothing_to_detect_from() -> None:
    tracker = RateTracker()
    tracker.add(1.0, 0x100, bytes(8), False, "can0")
    tracker.add(1.0, 0x100, b"", False, "can0", error=True)  # error frames are left out
    (load,) = tracker.load()
    assert (load.bitrate, load.frames) == (None, 2)
    assert load.reason == "no two frames at different times to detect it from; give --bitrate"


def test_detection_takes_the_data_phase_at_the_data_bit_rate() -> None:
    tracker = RateTracker(data_bitrate=2_000_000)
    time = 0.0
    for _ in range(20):  # back to back at 500 kbit/s nominal, 2 Mbit/s data
        tracker.add(time, 0x100, bytes(8), False, "can0", fd=True, brs=True)
        time += 34 / 500_000 + 113 / 2_000_000
    (load,) = tracker.load()
    # Without the data phase's time, the 30 unstuffed nominal bits in 124.5 µs would need
    # only 241 kbit/s: 250 kbit/s, and a load over 100 %.
    assert (load.bitrate, load.detected) == (500_000, True)
    assert load.percent == pytest.approx(100 * 20 / 19, rel=1e-9)


def test_stats_rates_counts_every_frame(tmp_path: Path) -> None:
    capture = tmp_path / "kinds.log"
    capture.write_text(
        "(1.000000) can0 100#0000000000000000\n"
        "(1.001000) can0 101#R5\n"
        "(1.002000) can0 102##10000000000000000\n"
        "(1.003000) can0 20000004#0004000000000000\n",
        encoding="utf-8",
    )
    result = veronte4x(
        "stats", str(capture), "--rates", "--bitrate", "500000", "--data-bitrate", "2000000"
    )
    assert result.returncode == 0, result.stderr
    assert result.stdout.splitlines()[-1] == (
        "  can0: 4 frames, 18.4 % of 500 kbit/s (given; data phase at 2000 kbit/s)"
    )


def test_stats_rates_says_why_no_bit_rate_was_detected(tmp_path: Path) -> None:
    capture = tmp_path / "close.log"
    capture.write_text(
        "(1.000000) can0 100#0000000000000000\n(1.000010) can0 101#0000000000000000\n",
        encoding="utf-8",
    )
    result = veronte4x("stats", str(capture), "--rates")
    assert result.returncode == 0, result.stderr
    assert result.stdout.splitlines()[-1] == (
        "  can0: 2 frames, bit rate unknown: frames 10 µs apart: faster than any standard "
        "bit rate; give --bitrate"
    )
