"""``--help`` as a person reads it: every command and ``esc`` action listed with its line,
the options named by what they take."""

from __future__ import annotations

import os
import subprocess
import sys

import pytest

COMMANDS = {
    "decode": "decode a capture, one record per line",
    "stats": "count frames and transfers per type and sender",
    "replay": "run the arbiter model on a capture; explain switches and disagreements",
    "monitor": "live table of a bus or a capture: latest fields, rates, errors",
    "plot": "plot a capture: arbitration timeline or ESC telemetry (PNG or window)",
    "list": "list message types: Veronte CAN IDs, commands, layouts; DroneCAN types",
    "esc": "find, configure, update and spin Vertiq ESCs (DroneCAN, live bus)",
    "simulate": "run simulated devices on a bus",
    "convert": "convert captures into a Parquet dataset: one directory per capture, a file per "
    "message type in it",
    "export": "write the bus map's Veronte frames for other tools (DBC)",
    "play": "send a capture's frames onto a CAN bus with their original spacing",
    "record": "record a live bus's frames into a file (pydronecan's capture file or candump text)",
}
ESC_ACTIONS = {
    "nodes": "list the nodes on the bus, from their NodeStatus",
    "info": "GetNodeInfo: name, versions, image CRC, unique id",
    "params": "every parameter: name, value, default, range",
    "apply": "restore parameters saved by params --save or the DroneCAN GUI tool: diff, "
    "check, set, read back, save",
    "get": "read one parameter by name (or by index with --by-index)",
    "set": "set one parameter by name (range checked first)",
    "save": "save the parameters to non-volatile storage (ExecuteOpcode)",
    "erase": "erase the stored parameters back to defaults (ExecuteOpcode)",
    "restart": "restart the node (RestartNode with the magic number)",
    "update": "update the firmware: the node pulls the image via file.Read",
    "spin": "spin motors with RawCommand at a rate (needs --yes)",
    "allocate": "serve dynamic node ID allocations (DroneCAN), the table kept in a file",
}


def _help(*args: str) -> str:
    """The help text, one line per entry (a terminal wide enough not to wrap)."""
    done = subprocess.run(
        [sys.executable, "-m", "veronte4x", *args, "--help"],
        capture_output=True,
        text=True,
        check=False,
        timeout=600,
        env=dict(os.environ, COLUMNS="300"),
    )
    assert (done.returncode, done.stderr) == (0, "")
    return done.stdout


def _listed(text: str) -> dict[str, str]:
    """The ``name  description`` lines under the positional arguments."""
    listed = {}
    for line in text.splitlines():
        if line.startswith("    ") and not line.startswith("     "):
            name, _, description = line.strip().partition(" ")
            listed[name] = description.strip()
    return listed


def test_every_command_is_listed_with_its_line() -> None:
    text = _help()
    assert "Decode Veronte 4x and Vertiq DroneCAN traffic from CAN captures." in text
    assert _listed(text) == COMMANDS


def test_every_esc_action_is_listed_with_its_line() -> None:
    """A mutation survivor: an action's help text made None vanished from this list."""
    assert _listed(_help("esc")) == ESC_ACTIONS


@pytest.mark.parametrize("action", sorted(ESC_ACTIONS))
def test_each_esc_action_describes_itself(action: str) -> None:
    text = _help("esc", action)
    assert text.startswith(f"usage: veronte4x esc {action} ")
    assert f"\n\n{ESC_ACTIONS[action]}\n\n" in text


@pytest.mark.parametrize("command", ["decode", "stats", "replay", "monitor", "plot"])
def test_capture_options_name_what_they_take(command: str) -> None:
    """A mutation survivor: ``--bus-map``'s metavar made None (``--bus-map BUS_MAP``)."""
    usage = _help(command).split("\n\n")[0]
    assert "[--bus-map FILE]" in usage and "[--dbc FILE]" in usage


@pytest.mark.parametrize("action", ["get", "set"])
def test_by_index_says_what_name_becomes(action: str) -> None:
    """A mutation survivor: ``--by-index``'s help made None."""
    text = _help("esc", action)
    assert (
        "--by-index            NAME is the parameter's index (discovery order; may change with "
        "the firmware)\n" in text
    )
