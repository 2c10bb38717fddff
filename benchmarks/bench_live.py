"""Benchmark: a full 1 Mbit/s bus, live: do ``veronte4x decode`` and ``veronte4x monitor``
read every frame of a ``udp_multicast`` bus?

A DroneCAN vehicle bus (``examples/make_vehicle_bus.py``) has its first frames retimed to
``--rate`` frames a second (8,800: a full 1 Mbit/s bus of 8-byte frames) and written as a
candump log. For each reader, in processes of their own: a raw socket on the group counts
the datagrams that arrive (the bus's truth), the reader runs (``decode --interface
udp_multicast ... > records.txt``, or ``monitor`` with plain output to a file),
``--busy`` processes spin (``while True: pass``), and ``veronte4x play`` sends the log onto
the bus. When play has ended and the readers' receive queues are empty, the readers get
Ctrl-C and print their summary.

Each row: the datagrams the raw socket received, the records the reader wrote and those
``veronte4x decode`` gives for the log itself, the frames the kernel dropped on the
reader's socket (its own count, as the reader says it, and ``/proc/net/udp``'s), the
reader's CPU time (its start included) per frame it read, what play says of its timing,
and the load average before and after; the other processes busiest meanwhile are listed
(the machine may be shared). A figure, never a test.

Run it where the multicast group stays on loopback, e.g. in a network namespace of its
own: ``tests/on_loopback env PYTHONPATH=src .venv/bin/python benchmarks/bench_live.py
[--seconds 60] [--rate 8800] [--readers decode monitor] [--busy 1]``.
"""

from __future__ import annotations

import argparse
import itertools
import os
import platform
import re
import signal
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
GROUP = "239.74.163.2"
"""python-can's default IPv4 group for ``udp_multicast``."""
PORT = 43113
"""python-can's default ``udp_multicast`` port."""
VEHICLE_RATE = 2_900
"""About the frames a second of ``make_vehicle_bus.py``'s bus (to size its capture)."""

RAW_RECEIVER = """
import signal, socket, struct, sys
group, port = sys.argv[1], int(sys.argv[2])
s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEPORT, 1)
s.setsockopt(socket.SOL_SOCKET, getattr(socket, "SO_RCVBUFFORCE", 33), 64 << 20)
s.bind(("", port))
s.setsockopt(socket.IPPROTO_IP, socket.IP_ADD_MEMBERSHIP,
             socket.inet_aton(group) + struct.pack("@I", socket.INADDR_ANY))
count = 0
def done(*_):
    drops = struct.unpack_from("9I", s.getsockopt(socket.SOL_SOCKET, 55, 36))[8]
    print(count, drops, flush=True)
    sys.exit(0)
signal.signal(signal.SIGTERM, done)
while True:
    s.recv(4096)
    count += 1
"""
"""Counts the group's datagrams until SIGTERM, then prints ``count drops`` (its kernel
drops)."""

BUSY = "while True: pass"


def make_capture(path: Path, frames: int, rate: float) -> None:
    """The first ``frames`` frames of the vehicle bus, ``rate`` a second, as a candump log."""
    source = path.with_suffix(".vehicle.log")
    seconds = int(frames / VEHICLE_RATE) + 5
    subprocess.run(
        [sys.executable, str(ROOT / "examples" / "make_vehicle_bus.py"), str(source),
         "--seconds", str(seconds)],
        check=True, capture_output=True,
    )  # fmt: skip
    written = 0
    with source.open() as lines, path.open("w") as out:
        for line in lines:
            if written == frames:
                break
            _, rest = line.split(" ", 1)
            out.write(f"({1_700_000_000 + written / rate:.6f}) {rest}")
            written += 1
    source.unlink()
    if written < frames:
        raise SystemExit(f"the vehicle bus gave {written} frames, not {frames}")


def veronte4x(*args: str) -> list[str]:
    return [sys.executable, "-m", "veronte4x", *args]


def udp_sockets() -> list[tuple[int, int, int]]:
    """(inode, receive queue bytes, drops) of every UDP socket bound to the port."""
    found = []
    for line in Path("/proc/net/udp").read_text().splitlines()[1:]:
        parts = line.split()
        if int(parts[1].split(":")[1], 16) == PORT:
            found.append((int(parts[9]), int(parts[4].split(":")[1], 16), int(parts[12])))
    return found


def wait_for(check: object, what: str, seconds: float = 120.0) -> None:
    end = time.monotonic() + seconds
    while not check():  # type: ignore[operator]
        if time.monotonic() > end:
            raise SystemExit(f"gave up waiting for {what}")
        time.sleep(0.2)


def load() -> str:
    return " ".join(Path("/proc/loadavg").read_text().split()[:3])


def busiest(exclude: set[int]) -> list[tuple[float, str]]:
    """The other processes using most CPU now (``ps``)."""
    done = subprocess.run(
        ["ps", "-eo", "pid,pcpu,etime,args", "--sort=-pcpu"], capture_output=True, text=True
    )
    rows: list[tuple[float, str]] = []
    for line in done.stdout.splitlines()[1:]:
        pid, cpu, _, command = line.split(None, 3)
        if int(pid) in exclude or float(cpu) < 5.0:
            continue
        rows.append((float(cpu), command[:90]))
    return rows[:6]


@dataclass
class Run:
    """One reader's run: what was sent, received and said."""

    reader: str
    raw: int
    records: int
    summary: str
    lost_said: int | None
    lost_proc: int
    cpu: float
    play_said: str
    loads: tuple[str, str]
    others: list[str]


def run_reader(reader: str, capture: Path, seconds: float, work: Path, busy: int) -> Run:
    """One run of ``reader`` on the bus while play sends ``capture`` (``seconds`` long)."""
    before = {inode for inode, _, _ in udp_sockets()}
    raw = subprocess.Popen(
        [sys.executable, "-c", RAW_RECEIVER, GROUP, str(PORT)],
        stdout=subprocess.PIPE, text=True,
    )  # fmt: skip
    wait_for(lambda: len(udp_sockets()) >= len(before) + 1, "the raw receiver's socket")
    with_raw = {inode for inode, _, _ in udp_sockets()}
    bus = ["--interface", "udp_multicast", "--channel", GROUP]
    command = {
        "decode": veronte4x("decode", *bus),
        "monitor": veronte4x("monitor", *bus, "--interval", "1"),
    }[reader]
    out = (work / f"{reader}.out").open("w")
    started = subprocess.Popen(command, stdout=out, stderr=subprocess.PIPE, text=True)
    wait_for(lambda: len(udp_sockets()) >= len(with_raw) + 1, f"{reader}'s socket")
    (mine,) = {inode for inode, _, _ in udp_sockets()} - with_raw
    spinners = [subprocess.Popen([sys.executable, "-c", BUSY]) for _ in range(busy)]
    loads = [load()]
    others: dict[str, float] = {}
    try:
        time.sleep(2.0)  # the reader's first look at the bus
        begun = time.monotonic()
        play = subprocess.Popen(
            veronte4x("play", str(capture), *bus), stdout=subprocess.DEVNULL,
            stderr=subprocess.PIPE, text=True,
        )  # fmt: skip
        ours = {os.getpid(), raw.pid, started.pid, play.pid, *(s.pid for s in spinners)}
        looks = [seconds * part for part in (0.25, 0.5, 0.75)]
        while play.poll() is None:
            time.sleep(1.0)
            if looks and time.monotonic() - begun > looks[0]:
                looks.pop(0)
                for cpu, other in busiest(ours):
                    others[other] = max(cpu, others.get(other, 0.0))
        play_said = (play.stderr.read() if play.stderr else "").strip().splitlines()[-1]
        if play.returncode != 0:
            raise SystemExit(f"play failed: {play_said}")

        def drained() -> bool:
            return all(queue == 0 for inode, queue, _ in udp_sockets() if inode == mine)

        wait_for(drained, f"{reader} to read its receive queue", 600.0)
        time.sleep(1.0)
        loads.append(load())
        lost_proc = next(drops for inode, _, drops in udp_sockets() if inode == mine)
    finally:
        for spinner in spinners:
            spinner.kill()
            spinner.wait()
    started.send_signal(signal.SIGINT)
    _, _, usage = os.wait4(started.pid, 0)
    out.close()
    summary = (started.stderr.read() if started.stderr else "").strip().splitlines()[-1]
    raw.terminate()
    raw_text, _ = raw.communicate()
    raw_count, raw_drops = (int(word) for word in raw_text.split())
    if raw_drops:
        raise SystemExit(f"the raw receiver itself lost {raw_drops} datagrams")
    said = re.search(r"(\d+) frames? lost by the bus layer", summary)
    return Run(
        reader, raw_count, records_in(summary), summary,
        int(said.group(1)) if said else None, lost_proc,
        usage.ru_utime + usage.ru_stime, play_said, (loads[0], loads[1]),
        [f"{cpu:.0f}% {other}" for other, cpu in sorted(others.items(), key=lambda o: -o[1])],
    )  # fmt: skip


def records_in(summary: str) -> int:
    """The records a reader's summary line counts (-1: none said)."""
    found = re.search(r"([\d,]+) records?", summary)
    return int(found.group(1).replace(",", "")) if found else -1


def stages(capture: Path, count: int, work: Path) -> list[tuple[str, float]]:
    """CPU per frame of each stage of a live reader, on ``count`` frames of ``capture``
    sent onto the bus while nothing reads, so that the reader finds them all waiting
    (its receive buffer full: where a reader that falls behind is)."""
    import can

    from veronte4x.canbus import open_bus
    from veronte4x.capture.busmap import BusMap
    from veronte4x.capture.decoder import CaptureDecoder
    from veronte4x.capture.frames import Frame
    from veronte4x.capture.monitor import MonitorState
    from veronte4x.capture.readers.live import read_bus
    from veronte4x.capture.readers.pythoncan import frame_from_message
    from veronte4x.capture.source import open_frames
    from veronte4x.capture.stats import Stats
    from veronte4x.cli import decode
    from veronte4x.sockets import frame_socket, kernel_drops

    log = [f for f in open_frames(str(capture)) if isinstance(f, Frame)][:count]
    messages = [
        can.Message(timestamp=f.timestamp or 0.0, arbitration_id=f.can_id, data=f.data,
                    is_extended_id=f.extended)
        for f in log
    ]  # fmt: skip
    port = PORT + 1
    rows: list[tuple[str, float]] = []

    def fill(bus: object) -> None:
        with can.Bus(interface="udp_multicast", channel=GROUP, port=port) as sender:
            for message in messages:
                sender.send(message)
        duplicate = frame_socket(bus)
        assert duplicate is not None
        with duplicate:
            if kernel_drops(duplicate):
                raise SystemExit("the receive buffer did not hold the frames: lower --stage-frames")

    def per_frame(name: str, started: float) -> None:
        rows.append((name, (time.process_time() - started) / count * 1e6))

    with open_bus("udp_multicast", GROUP, options={"port": port}) as bus:
        fill(bus)
        started = time.process_time()
        for _ in range(count):
            frame_from_message(bus.recv(timeout=600.0))
        per_frame("read: python-can recv, frame_from_message", started)
    with open_bus("udp_multicast", GROUP, options={"port": port}) as bus:
        fill(bus)
        started = time.process_time()
        frames = []
        for frame in read_bus(bus, duration=600.0):
            frames.append(frame)
            if len(frames) == count:
                break
        per_frame("read: read_bus (DatagramReader)", started)
    started = time.process_time()
    records = list(CaptureDecoder().decode(frames))
    per_frame("CaptureDecoder, first pass (tables built)", started)
    started = time.process_time()
    records = list(CaptureDecoder().decode(frames))
    per_frame("CaptureDecoder", started)
    with (work / "records.txt").open("w") as out:
        write, _ = decode._text_writer(out, decode._Clock("timestamp"), decode._Ids(BusMap()))
        counts = Stats()
        started = time.process_time()
        for record in records:
            counts.add(record)
            write(record)
        out.flush()
        per_frame("decode: count, write text", started)
    state = MonitorState()
    started = time.process_time()
    for record in records:
        state.add(record)
    per_frame("monitor: MonitorState.add", started)
    with (
        open_bus("udp_multicast", GROUP, options={"port": port}) as bus,
        (work / "records.txt").open("w") as out,
    ):
        fill(bus)
        write, _ = decode._text_writer(out, decode._Clock("timestamp"), decode._Ids(BusMap()))
        counts = Stats()
        started = time.process_time()
        stream = read_bus(bus, duration=600.0, idle=out.flush)  # as decode writes out
        taken = itertools.islice(stream, count)
        for record in CaptureDecoder().decode(taken):
            counts.add(record)
            write(record)
        out.flush()
        stream.close()
        per_frame("decode's stages in one pipeline, frame by frame (tables built)", started)
    return rows


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=60.0, help="seconds of frames (60)")
    parser.add_argument("--rate", type=float, default=8_800.0, help="frames a second (8800)")
    parser.add_argument("--readers", nargs="*", default=["decode", "monitor"])
    parser.add_argument("--busy", type=int, default=1, help="spinning processes (1)")
    parser.add_argument("--capture", type=Path, help="a retimed log to reuse (else made)")
    parser.add_argument(
        "--stage-frames", type=int, default=30_000, help="frames of the per-stage CPU (30000)"
    )
    args = parser.parse_args()
    frames = int(args.seconds * args.rate)
    print(
        f"{time.strftime('%Y-%m-%d %H:%M', time.gmtime())} UTC, Python "
        f"{platform.python_version()}, {os.cpu_count()} CPUs, {args.busy} busy, load {load()}"
    )
    with tempfile.TemporaryDirectory(prefix="bench-live-") as tmp:
        work = Path(tmp)
        capture = args.capture or work / "full_bus.log"
        if not capture.exists():
            make_capture(capture, frames, args.rate)
        print(f"CPU per frame of each stage, {args.stage_frames:,} frames found waiting:")
        print("| stage | CPU per frame |\n|---|---|")
        for name, micros in stages(capture, min(args.stage_frames, frames), work):
            print(f"| {name} | {micros:.1f} µs |")
        expected = records_in(
            subprocess.run(
                veronte4x("decode", str(capture)), stdout=subprocess.DEVNULL,
                stderr=subprocess.PIPE, text=True,
            ).stderr
        )  # fmt: skip
        print(f"\n{frames:,} frames at {args.rate:,.0f}/s; decode of the log: {expected:,} records")
        print("| reader | load average before, after | raw socket | records | lost (said) "
              "| lost (/proc/net/udp) | reader CPU per frame read | play |")  # fmt: skip
        print("|---|---|---|---|---|---|---|---|")
        for reader in args.readers:
            run = run_reader(reader, capture, args.seconds, work, args.busy)
            per_read = run.cpu / max(1, frames - run.lost_proc) * 1e6
            said = "not said" if run.lost_said is None else f"{run.lost_said:,}"
            print(
                f"| {reader} | {run.loads[0]}; {run.loads[1]} | {run.raw:,} | {run.records:,} "
                f"| {said} ({run.lost_proc / frames:.1%}) | {run.lost_proc:,} | {per_read:.1f} µs "
                f"| {run.play_said.removeprefix('veronte4x: ')} |",
                flush=True,
            )
            print(f"  {run.summary}")
            for other in run.others:
                print(f"  also running: {other}")


if __name__ == "__main__":
    main()
