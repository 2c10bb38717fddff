"""One bus dialect for every command that opens a bus (issue 37, item 7): the same options
with the same meanings for decode, stats, replay, monitor, play, record, esc and simulate; the
capture's channel filter is ``--only-channel``; the old spellings are refused in one line
naming the new one."""

from __future__ import annotations

from pathlib import Path

import pytest

from veronte4x import cli
from veronte4x.cli.options import bus_settings

CAPTURE = Path(__file__).resolve().parents[2] / "examples" / "capture.log"

LIVE_COMMANDS = [
    ["decode"],
    ["stats"],
    ["replay"],
    ["monitor"],
    ["play", str(CAPTURE)],
    ["record", "--to", "pydronecan", "bus.can"],
    ["esc", "nodes"],
    ["simulate", "esc"],
]


@pytest.mark.parametrize("command", LIVE_COMMANDS, ids=lambda c: " ".join(c[:2]))
@pytest.mark.parametrize(
    "options",
    [
        ["-i", "udp_multicast", "-c", "239.74.163.2", "-b", "1000000"],
        ["--interface", "udp_multicast", "--channel", "239.74.163.2", "--bitrate", "1000000"],
    ],
    ids=["short", "long"],
)
def test_every_live_command_takes_the_same_bus_options(
    command: list[str], options: list[str]
) -> None:
    args = cli._parser().parse_args(
        [*command, *options, "--can-config", "can.ini", "--bus-option", "port=43113"]
    )
    assert bus_settings(args) == {
        "interface": "udp_multicast",
        "channel": "239.74.163.2",
        "bitrate": 1000000,
        "config_file": "can.ini",
        "options": {"port": 43113},
    }


@pytest.mark.parametrize(
    ("argv", "line"),
    [
        (
            ["play", str(CAPTURE), "udp_multicast:239.74.163.2"],
            "play takes the bus as options now: --interface udp_multicast --channel "
            "239.74.163.2 (not udp_multicast:239.74.163.2)",
        ),
        (
            ["play", str(CAPTURE), "virtual:", "--speed", "2"],
            "play takes the bus as options now: --interface virtual (not virtual:)",
        ),
        *(
            (
                [command, str(CAPTURE), "--channel", "can0"],
                "--channel names a live bus's channel (with --interface); to keep only the "
                "frames of channel can0 of a capture, use --only-channel can0",
            )
            for command in ("decode", "stats", "replay", "monitor")
        ),
        *(
            (
                [*command, "--channel", "can0"],
                "--channel is now --only-channel (--only-channel can0)",
            )
            for command in (
                ["convert", str(CAPTURE), "--to", "parquet", "out"],
                ["plot", str(CAPTURE)],
            )
        ),
    ],
    ids=lambda v: v[0] if isinstance(v, list) else "",
)
def test_an_old_spelling_is_refused_naming_the_new_one(
    argv: list[str], line: str, capsys: pytest.CaptureFixture[str]
) -> None:
    assert cli.main(argv) == 2
    assert capsys.readouterr() == ("", f"veronte4x: {line}\n")
