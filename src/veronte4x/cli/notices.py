"""Messages about the input itself, printed on standard error as a command meets them.

Every command that reads a capture file tells these the same way: where the input ends
early (a truncated gzip file, a damaged python-can log), a file that holds no CAN frame at
all (a `SourceError`: it is not a capture), and one whose lines are mostly not frames.
"""

from __future__ import annotations

import sys
from collections.abc import Iterable, Iterator

from veronte4x.capture.frames import BadLine, Frame, Truncation
from veronte4x.capture.records import Record
from veronte4x.errors import NotACaptureError
from veronte4x.words import counted


def tell(detail: str) -> None:
    """Print a notice about the input after the output so far."""
    sys.stdout.flush()
    print(f"veronte4x: {detail}", file=sys.stderr)


class InputWatch:
    """Counts what a capture gives, tells where it ends early, and refuses one with bad lines
    only.

    Args:
        path: The capture's path, ``-`` for standard input, or None for a live bus (whose
            frames are not watched).
    """

    def __init__(self, path: str | None) -> None:
        self.path = path
        self.frames = 0
        """Records (or frames) that came from CAN frames."""
        self.bad = 0
        """Lines that are not CAN frames."""

    @property
    def _name(self) -> str:
        return "standard input" if self.path == "-" else str(self.path)

    def records(self, records: Iterable[Record]) -> Iterator[Record]:
        """Pass records through; tell a ``truncated`` one (about the file, not a frame,
        whatever ``--on-error`` does with bad frames).

        Raises:
            NotACaptureError: At the end, when every record was a bad line.
        """
        for record in records:
            if record.error == "truncated":
                tell(record.detail or "the input ends early")
            elif record.error == "bad line":
                self.bad += 1
            else:
                self.frames += 1
            yield record
        self._check()

    def frame_items(self, items: Iterable[Frame | BadLine]) -> Iterator[Frame | BadLine]:
        """Pass frames and bad lines through; tell a `Truncation`.

        Raises:
            NotACaptureError: At the end, when every item was a bad line.
        """
        for item in items:
            if isinstance(item, Truncation):
                tell(item.reason)
            elif isinstance(item, BadLine):
                self.bad += 1
            else:
                self.frames += 1
            yield item
        self._check()

    def _check(self) -> None:
        if self.path is not None and self.bad and not self.frames:
            raise NotACaptureError(self._name, self.bad)

    def note(self) -> str | None:
        """A warning when most of the capture's lines are not frames, else None."""
        if self.path is None or self.bad <= self.frames:
            return None
        return (
            f"{self.bad} of {counted(self.bad + self.frames, 'line')} are not CAN frames: is "
            f"{self._name} a capture?"
        )


def channel_hint(path: str | None, channel: str | None, frames: int) -> str | None:
    """A hint when ``--only-channel`` kept no frame of a capture file: the channels it has (read
    again, only then); None otherwise, and for standard input or a live bus."""
    from veronte4x.capture.source import open_frames

    if path in (None, "-") or channel is None or frames:
        return None
    assert path is not None
    channels = sorted({f.channel for f in open_frames(path) if isinstance(f, Frame) and f.channel})
    if not channels:
        return None
    return (
        f"no frame of {path} is on channel {channel}: its channels are {', '.join(channels)}; "
        "give one of them to --only-channel, or leave it out"
    )
