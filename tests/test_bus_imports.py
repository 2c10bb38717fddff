"""The bus I/O and the tools that talk on a bus load no capture engine (issue 37, item 2).

`veronte4x.canbus` opens buses and turns DroneCAN frames into ``can.Message`` with DroneCAN
alone; decoding a live bus into records lives in `veronte4x.capture.can_messages`. So the ESC
client and the simulator keep working when a capture module is broken, and load less.
Each module is imported in a fresh interpreter, where nothing else has loaded the package.
"""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

NOT_LOADED = ("veronte4x.capture", "veronte4x.codec", "veronte4x.cli")
"""Packages none of these modules may load: the capture engine, the Veronte codec, the CLI."""


def loaded_modules(module: str) -> list[str]:
    """The veronte4x modules a fresh interpreter holds after ``import module``."""
    script = (
        f"import json, sys, {module}; "
        "print(json.dumps(sorted(m for m in sys.modules if m.startswith('veronte4x'))))"
    )
    run = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, check=True)
    return list(json.loads(run.stdout))


@pytest.mark.parametrize(
    "module",
    [
        "veronte4x.canbus",
        "veronte4x.client.bus",
        "veronte4x.client.aio",
        "veronte4x.simulator.can_node",
    ],
)
def test_a_bus_module_loads_no_capture_module(module: str) -> None:
    loaded = loaded_modules(module)
    assert module in loaded
    assert "veronte4x.dronecan" in loaded
    assert [m for m in loaded if m.split(".")[:2] in (p.split(".") for p in NOT_LOADED)] == []


def test_the_decoding_side_is_in_capture() -> None:
    from veronte4x import canbus
    from veronte4x.capture import can_messages

    for name in ("DecodingListener", "decode_can_message", "to_can_message"):
        assert not hasattr(canbus, name)
        assert getattr(can_messages, name).__module__ == "veronte4x.capture.can_messages"
