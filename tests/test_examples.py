"""The example that the README's main command runs decodes every message type of its capture."""

import runpy
from pathlib import Path

import pytest

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"


def test_decode_frames_covers_every_message_type(capsys: pytest.CaptureFixture[str]) -> None:
    module = runpy.run_path(str(EXAMPLES / "decode_frames.py"))
    bad = module["main"](str(EXAMPLES / "capture.log"))
    out, err = capsys.readouterr()
    lines = out.splitlines()
    assert len(lines) == 39
    assert bad == 1
    assert err == "1 frame(s) could not be decoded\n"
    assert lines[-2] == (
        "1763737200.500000 0FF arbiter     ERROR frame.command: command byte 4 is reserved or "
        "unknown (data: 04 01)"
    )
    assert lines[2] == "1763737200.010000 008 AP1         Ready(ready=True)"
    names = {line[34:].split("(")[0].split()[0] for line in lines}
    assert names == {
        "VersionRequest", "VersionResponse", "Ready", "ArbitrationVariable", "Status", "Score",
        "PwmSet", "ScorpionEscTelemetry", "JetiEscTelemetry", "JetiBecTelemetry1",
        "JetiBecTelemetry2", "JetiTemperature", "McuCommand", "MaintenanceCommand",
        "StickSelection", "McuTelemetry1", "McuTelemetry2", "ERROR",
    }  # fmt: skip
