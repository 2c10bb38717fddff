"""The arbiter model over a capture file: `veronte4x.arbiter.replay` as the CLI runs it.

`veronte4x.arbiter.replay` is sans-IO: it takes (time, CAN ID, data) triples. This adapter
reads them from a capture in any format `open_frames` reads, with the frames the CLI's
``veronte4x replay`` keeps: timestamped data frames (no error, remote or CAN FD frame) whose
ID width is the configuration's.
"""

from __future__ import annotations

import os
from collections.abc import Iterable, Iterator
from typing import TYPE_CHECKING

from veronte4x.capture.frames import BadLine, Frame
from veronte4x.capture.source import open_frames

if TYPE_CHECKING:  # the arbiter loads when a replay runs, not with veronte4x.capture
    from veronte4x.arbiter.config import ArbiterConfig
    from veronte4x.arbiter.replay import CapturedFrame, ReplayResult

__all__ = ["captured_frames", "replay"]


def replay(
    source: str | os.PathLike[str] | Iterable[Frame | BadLine],
    config: ArbiterConfig | str | os.PathLike[str],
    channel: str | None = None,
) -> ReplayResult:
    """Run a capture through the arbiter model and compare it with the real arbiter, as
    ``veronte4x replay`` does.

    Args:
        source: The capture file (any format `veronte4x.capture.open_frames` reads), or its
            frames (what `open_frames` gives, filtered or joined as wanted).
        config: The captured vehicle's arbiter configuration, or the path of its TOML file
            (`veronte4x.arbiter.config_file.load_config`). ``ArbiterConfig()`` is the
            default configuration, with which disagreements may come from the
            configuration rather than the arbiter.
        channel: Keep only this interface's frames.

    Returns:
        As `veronte4x.arbiter.replay`; each decision's `Decision.utc` is its time as a UTC
        datetime.

    Raises:
        SourceError: The path is a directory or a file in no format veronte4x knows.
        ConfigError: The configuration file is not a valid arbiter configuration.
        DisorderedError: The capture is not in time order.

    Examples:
        >>> from veronte4x import capture
        >>> result = capture.replay("examples/capture.log", "examples/arbiter.toml")
        >>> switch = next(d for d in result.decisions if "->" in d.reason)
        >>> switch.reason
        'AP1 -> AP2: AP2 0.0257 < AP1 0.057 x (1 - 0.3)'
        >>> switch.utc.isoformat()
        '2025-11-21T15:00:00.028000+00:00'
    """
    from veronte4x.arbiter.config import ArbiterConfig
    from veronte4x.arbiter.config_file import load_config
    from veronte4x.arbiter.replay import replay as replay_frames

    if not isinstance(config, ArbiterConfig):
        config = load_config(config)
    if isinstance(source, (str, os.PathLike)):
        frames = open_frames(source, channel)
    else:
        frames = (
            f for f in source if channel is None or (isinstance(f, Frame) and f.channel == channel)
        )
    return replay_frames(captured_frames(frames, config), config)


def captured_frames(
    items: Iterable[Frame | BadLine], config: ArbiterConfig
) -> Iterator[CapturedFrame]:
    """The frames of a capture that the arbiter replay takes, as (time, CAN ID, data):
    timestamped data frames (no error, remote or CAN FD frame) whose ID width is
    ``config``'s."""
    for frame in items:
        if (
            isinstance(frame, Frame)
            and frame.timestamp is not None
            and not (frame.error or frame.remote or frame.fd)
            and frame.extended == config.extended_ids
        ):
            yield frame.timestamp, frame.can_id, frame.data
