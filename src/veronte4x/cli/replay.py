"""``veronte4x replay``: the arbiter model over a capture, its decisions and disagreements."""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable, Iterator
from itertools import chain
from typing import TYPE_CHECKING, Any

from veronte4x.arbiter.errors import ConfigError
from veronte4x.capture.busmap import BusMap
from veronte4x.cli.exit_codes import EXIT_FINDINGS, EXIT_NOT_IN_TIME_ORDER, EXIT_OK
from veronte4x.cli.notices import InputWatch, channel_hint
from veronte4x.cli.options import (
    add_capture_options,
    add_live_options,
    add_renamed_option,
    live,
    open_frame_source,
)
from veronte4x.errors import SourceError
from veronte4x.times import TIME_FORMS, TimeForm, format_time
from veronte4x.words import counted

if TYPE_CHECKING:
    from veronte4x.arbiter.config import ArbiterConfig


def add_parser(commands: Any) -> None:
    """Register the command."""
    parser = commands.add_parser(
        "replay", help="run the arbiter model on a capture; explain switches and disagreements"
    )
    parser.add_argument("file", nargs="?", help="capture file, or - for stdin")
    parser.add_argument(
        "--config",
        metavar="FILE",
        help="TOML arbiter configuration of the captured vehicle (without it, the defaults "
        "are assumed and disagreements may come from them)",
    )
    parser.add_argument(
        "--time",
        choices=TIME_FORMS,
        default="timestamp",
        help="timestamp: ISO 8601 in UTC to the microsecond (the default; a clock since boot "
        "as seconds), relative: seconds since the first frame, seconds: as logged",
    )
    add_renamed_option(parser, "--relative-time", "--time relative")
    add_capture_options(parser)
    add_live_options(parser)
    parser.set_defaults(run=run)


def run(args: argparse.Namespace, bus_map: BusMap) -> int:
    """Replay the capture through the arbiter model and print its timeline.

    Exit code 1 when the recorded arbiter disagrees with the model, as a checker does; 5
    when the capture is not in time order.
    """
    from veronte4x import arbiter
    from veronte4x.arbiter.config_file import load_config
    from veronte4x.arbiter.replay import DisorderedError
    from veronte4x.capture.arbitration import captured_frames

    if args.config:
        config = _load(args.config, load_config)
    else:
        config = arbiter.ArbiterConfig(
            autopilot_ids=bus_map.autopilot_ids,
            arbiter_id=bus_map.arbiter_id,
            extended_ids=bus_map.extended,
        )
    clock = _Clock(args.time)
    watch = InputWatch(None if live(args) else args.file)
    frames = (
        (clock.see(time), can_id, data)
        for time, can_id, data in captured_frames(
            watch.frame_items(open_frame_source(args)), config
        )
    )
    veronte = _Seen({*config.autopilot_ids, config.arbiter_id})
    steps = veronte.frames(frames)
    first = next(steps, None)  # an error about the capture comes before the warning
    if not args.config:
        print(NO_CONFIG, file=sys.stderr)
    try:
        result = arbiter.replay(chain((first,) if first else (), steps), config)
    except DisorderedError as error:
        sys.stdout.flush()
        print(
            f"veronte4x: {_name(args)} is not in time order ({counted(error.steps, 'step')} "
            f"back in {counted(error.frames, 'frame')}): replay needs it sorted by time; sort "
            "the capture first",
            file=sys.stderr,
        )
        return EXIT_NOT_IN_TIME_ORDER
    print(result.timeline(clock.format))
    summary = (
        f"veronte4x: {counted(len(result.decisions), 'decision')}, "
        f"{counted(len(result.disagreements), 'disagreement')}, "
        f"{counted(len(result.errors), 'bad frame')}"
    )
    if result.late:
        summary += f", {_count(result.late, 'frame')} out of time order (taken late)"
    if result.restarts:
        summary += f", {_count(len(result.restarts), 'restart')} (the time steps back)"
    note = watch.note()
    print(summary + (f"; {note}" if note else ""), file=sys.stderr)
    if not veronte.count and watch.path is not None:  # a capture file's
        hint = channel_hint(watch.path, args.only_channel, watch.frames) or _no_veronte(config)
        print(f"veronte4x: {hint}", file=sys.stderr)
    return EXIT_FINDINGS if result.disagreements else EXIT_OK


class _Seen:
    """Counts the frames on the arbiter's or an autopilot's CAN ID as they pass."""

    def __init__(self, ids: set[int]) -> None:
        self.ids = ids
        self.count = 0

    def frames(self, frames: Iterator[_Step]) -> Iterator[_Step]:
        for frame in frames:
            if frame[1] in self.ids:
                self.count += 1
            yield frame


_Step = tuple[float, int, bytes]
"""A frame as the arbiter model takes it: time, CAN ID, data."""


def _no_veronte(config: ArbiterConfig) -> str:
    """The hint for a capture without one frame on the arbiter's or an autopilot's CAN ID."""
    width = 8 if config.extended_ids else 3
    ids = ", ".join(f"{i:0{width}X}" for i in config.autopilot_ids)
    return (
        f"no frame has a Veronte 4x CAN ID (autopilots {ids}, arbiter "
        f"{config.arbiter_id:0{width}X}): is this a 4x capture? Other IDs: give the vehicle's "
        "--config (or --bus-map)"
    )


def _load(path: str, load: Callable[[str], ArbiterConfig]) -> ArbiterConfig:
    """The arbiter configuration of ``--config``; what is wrong with it in the file's words.

    Raises:
        SourceError: The file is not a valid arbiter configuration.
    """
    try:
        return load(path)
    except ConfigError as error:
        if error.field != "(file)":
            value = error.value
            if error.allowed == "a field of ArbiterConfig":
                what = f"[arbiter] {error.field} is not a setting of the arbiter"
            elif error.field.startswith("variables["):
                what = f"[arbiter] {error.field}: {_words(value)} are not settings of a "
                what += f"variable (expected {error.allowed})"
            else:
                shown = list(value) if isinstance(value, tuple) else value
                what = f"[arbiter] {error.field} = {shown!r}: expected {error.allowed}"
        elif error.allowed == "only an [arbiter] table":
            what = f"tables {_words(error.value)} are not read: only [arbiter] is"
        elif error.allowed.startswith("valid TOML"):
            what = f"not TOML: {error.allowed.removeprefix('valid TOML (').removesuffix(')')}"
        else:
            what = f"a value of the wrong type ({error.allowed})"
    except (TypeError, ValueError, AttributeError) as error:  # a table where a value goes
        what = f"not an arbiter configuration ({error})"
    raise SourceError(f"{path}: {what}; fix the arbiter configuration (see the Replay docs)")


def _words(value: object) -> str:
    return ", ".join(map(str, value)) if isinstance(value, (list, tuple)) else str(value)


def _count(number: int, noun: str) -> str:
    return f"{number} {noun}" if number == 1 else f"{number} {noun}s"


def _name(args: argparse.Namespace) -> str:
    return "the bus" if live(args) else "standard input" if args.file == "-" else args.file


NO_CONFIG = (
    "veronte4x: no --config: assuming the default arbiter configuration (no arbitration "
    "variables, method 'always best', AP1 preferred, no holding time or hysteresis), so "
    "disagreements may come from the vehicle's configuration rather than its arbiter; pass "
    "the vehicle's arbiter configuration with --config FILE"
)
"""The warning of a replay without ``--config``."""


class _Clock:
    """The timeline's times, as ``--time`` says (`veronte4x.cli.decode`'s forms)."""

    def __init__(self, form: TimeForm) -> None:
        self.form = form
        self.start: float | None = None

    def see(self, stamp: float) -> float:
        """Note a frame's time (the first one is the start); return it unchanged."""
        if self.start is None:
            self.start = stamp
        return stamp

    def format(self, stamp: float) -> str:
        """A time of the timeline, as people read it."""
        if self.form == "seconds":
            return f"{stamp:.6f}"
        return format_time(stamp, self.start if self.form == "relative" else None)
