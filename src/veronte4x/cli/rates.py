"""``--rates`` of ``stats`` and ``monitor``: rates, jitter, gaps and bus load per stream."""

from __future__ import annotations

import argparse
import math
import threading
from collections.abc import Iterable, Iterator

from veronte4x.capture.busmap import BusMap
from veronte4x.capture.decoder import CaptureDecoder
from veronte4x.capture.frames import BadLine, Frame
from veronte4x.capture.rates import RateTracker
from veronte4x.capture.readers.live import BusLoss
from veronte4x.capture.records import Record
from veronte4x.cli.options import open_frame_source, with_dbc
from veronte4x.words import counted


def add_options(parser: argparse.ArgumentParser) -> None:
    """``--rates`` and ``--data-bitrate``; the bus load takes the bus options'
    ``--bitrate`` if given."""
    parser.add_argument(
        "--rates",
        action="store_true",
        help="show per CAN ID or DroneCAN session: rate, jitter, longest gap, stopped and "
        "slow streams; and the bus load of every frame (data, remote, CAN FD, error) in %% "
        "of --bitrate (default: detected from the closest frames); monitor shows them live "
        "in its table",
    )
    parser.add_argument(
        "--data-bitrate",
        type=int,
        metavar="B",
        help="--rates: the CAN FD data bit rate in bit/s, for the data phase of frames with "
        "BRS (without it, a bus with such frames has no load figure)",
    )


def tracker(args: argparse.Namespace, bus_map: BusMap) -> RateTracker | None:
    """A tracker if ``--rates`` was given."""
    if not args.rates:
        return None
    return RateTracker(bus_map, getattr(args, "bitrate", None), args.data_bitrate)


def records(
    args: argparse.Namespace,
    bus_map: BusMap,
    rates: RateTracker,
    stop: threading.Event | None = None,
    loss: BusLoss | None = None,
) -> Iterator[Record]:
    """The command's records, decoded from frames that also feed ``rates`` (``loss``: as
    `veronte4x.cli.options.open_records` counts it)."""
    frames = open_frame_source(args, stop, loss)
    return with_dbc(args, CaptureDecoder(bus_map).decode(feed(frames, rates)))


def feed(frames: Iterable[Frame | BadLine], rates: RateTracker) -> Iterator[Frame | BadLine]:
    """Pass frames through, counting each timestamped frame in ``rates``."""
    for frame in frames:
        if isinstance(frame, Frame) and frame.timestamp is not None:
            rates.add(
                frame.timestamp,
                frame.can_id,
                frame.data,
                frame.extended,
                frame.channel,
                remote=frame.remote,
                fd=frame.fd,
                brs=frame.brs,
                error=frame.error,
            )
        yield frame


def report(rates: RateTracker, now: float | None = None) -> str:
    """The streams and the bus load as text, one line each."""
    lines = ["rates:"]
    for s in rates.streams(now):
        flags = f"  {', '.join(s.flags)}" if s.flags else ""
        gaps = f", {counted(s.gaps, 'gap')}" if s.gaps else ""
        longest = _duration(s.longest_gap) if s.count > 1 else "-"  # one frame: no period
        lines.append(
            f"  {s.channel or '-'} {s.label}: {s.count} at {_hz(s.rate)}, jitter "
            f"{_duration(s.jitter)}, longest gap {longest}{gaps}{flags}"
        )
    lines.append("bus load (worst-case bit stuffing):")
    for load in rates.load():
        if load.bitrate is None:
            rate = f"bit rate unknown: {load.reason}"
        else:
            how = "detected: the lowest that fits" if load.detected else "given"
            if load.data_bitrate is not None:
                how += f"; data phase at {load.data_bitrate / 1000:g} kbit/s"
            rate = f"{_percent(load.percent)} of {load.bitrate / 1000:g} kbit/s ({how})"
            if load.reason:
                rate += f": {load.reason}"
        lines.append(f"  {load.channel or '-'}: {counted(load.frames, 'frame')}, {rate}")
    return "\n".join(lines)


def load_text(rates: RateTracker) -> str:
    """The bus load of every channel in a few words: ``bus load can0 12.3 %``."""
    parts = []
    for load in rates.load():
        where = load.channel or "-"
        if load.bitrate is None:
            parts.append(f"{where} ? (give --bitrate)")
        elif load.data_bits and load.data_bitrate is None:
            parts.append(f"{where} ? (give --data-bitrate)")
        else:
            parts.append(f"{where} {_percent(load.percent)} of {load.bitrate / 1000:g} kbit/s")
    return "bus load " + (", ".join(parts) if parts else "-")


def _hz(value: float) -> str:
    return "-" if math.isnan(value) else f"{value:.4g} Hz"


def _duration(value: float) -> str:
    """Seconds in ms, or in µs below 1 ms (a jitter of ``64.89 µs``, not ``6.489e-05 ms``)."""
    if math.isnan(value):
        return "-"
    return f"{value * 1e6:.4g} µs" if 0 < abs(value) < 1e-3 else f"{value * 1000:.4g} ms"


def _percent(value: float) -> str:
    return "-" if math.isnan(value) else f"{value:.3g} %"
