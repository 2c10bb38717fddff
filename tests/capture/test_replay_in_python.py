"""`capture.replay(capture, config)`: the arbiter model over a capture as ``veronte4x replay``
runs it, from a path or from frames, with UTC datetimes (issue 39: a replay in Python
needed a generator written by hand over `open_frames`)."""

from __future__ import annotations

import datetime
from pathlib import Path

from veronte4x import arbiter, capture
from veronte4x.arbiter.config_file import load_config
from veronte4x.capture import BadLine, Frame

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
CAPTURE = EXAMPLES / "capture.log"
CONFIG = EXAMPLES / "arbiter.toml"


def test_a_path_and_a_config_file_give_the_switches_with_their_utc_times() -> None:
    result = capture.replay(CAPTURE, CONFIG)
    switches = [d for d in result.decisions if d.kind is arbiter.DecisionKind.SWITCH]
    assert [(d.utc, d.reason) for d in switches] == [
        (
            datetime.datetime(2025, 11, 21, 15, 0, 0, 28000, tzinfo=datetime.timezone.utc),
            "AP1 -> AP2: AP2 0.0257 < AP1 0.057 x (1 - 0.3)",
        ),
        (
            datetime.datetime(2025, 11, 21, 15, 0, 0, 112000, tzinfo=datetime.timezone.utc),
            "AP2 -> AP3: AP3 is the only one alive",
        ),
        (
            datetime.datetime(2025, 11, 21, 15, 0, 0, 112000, tzinfo=datetime.timezone.utc),
            "AP3 -> AP1: no autopilot alive: preferred AP1 selected",
        ),
    ]
    assert result == capture.replay(str(CAPTURE), load_config(CONFIG))


def test_frames_replay_as_their_file_does() -> None:
    items = list(capture.open_frames(CAPTURE))
    assert capture.replay(items, CONFIG) == capture.replay(CAPTURE, CONFIG)
    assert capture.replay(iter(items), CONFIG, channel="can0") == capture.replay(CAPTURE, CONFIG)


def test_a_channel_keeps_its_frames_only() -> None:
    items = list(capture.open_frames(CAPTURE))
    on_can1 = [item._replace(channel="can1") for item in items if isinstance(item, Frame)]
    joined = [*items, BadLine(0, "x", "not a frame"), *on_can1]
    assert capture.replay(joined, CONFIG, channel="can1") == capture.replay(CAPTURE, CONFIG)
    assert capture.replay(joined, CONFIG, channel="can9").decisions == ()
