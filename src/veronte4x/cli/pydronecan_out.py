"""``veronte4x convert --to pydronecan FILE``: the frames of captures as a pydronecan capture
(`veronte4x.capture.readers.pydronecan`), which pydronecan's ``filein:`` driver plays."""

from __future__ import annotations

import argparse
import sys
from collections.abc import Iterator

from veronte4x import capture
from veronte4x.capture.frames import Frame
from veronte4x.capture.readers.pydronecan import write
from veronte4x.cli.exit_codes import EXIT_OK
from veronte4x.cli.notices import InputWatch
from veronte4x.words import counted


def run(args: argparse.Namespace, out: str) -> int:
    """Write the frames of every capture, one after the other, into ``out``; the lines that
    are no frame are left out and counted."""
    watches = [InputWatch(path) for path in args.files]
    channels: set[str] = set()

    def frames() -> Iterator[Frame]:
        for watch in watches:
            items = watch.frame_items(capture.open_frames(str(watch.path), args.only_channel))
            for item in items:
                if type(item) is Frame:
                    channels.add(item.channel)
                    yield item

    written = write(out, frames())
    bad = sum(watch.bad for watch in watches)
    left_out = f", {counted(bad, 'bad line')} left out" if bad else ""
    print(f"veronte4x: {counted(written, 'frame')} in {out}{left_out}", file=sys.stderr)
    if len(channels) > 1:
        names = ", ".join(sorted(channels))
        print(
            f"veronte4x: note: the frames of {len(channels)} channels ({names}) are in one file, "
            "which names no bus; --only-channel CHANNEL writes one",
            file=sys.stderr,
        )
    return EXIT_OK
