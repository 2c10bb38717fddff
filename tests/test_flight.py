"""The example flight end to end: generate it, decode it, count it, replay it, tabulate it."""

from __future__ import annotations

import csv
import dataclasses
import datetime
import io
import json
import re
import runpy
import subprocess
import sys
from pathlib import Path

import pytest

from veronte4x import arbiter, capture, codec
from veronte4x.arbiter.config_file import load_config

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"


@pytest.fixture(scope="module")
def flight(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A 30 s flight whose selected autopilot fails at 15 s."""
    path = tmp_path_factory.mktemp("flight") / "flight.log"
    make = runpy.run_path(str(EXAMPLES / "make_capture.py"))
    make["generate"](0.5, 15.0, 4).write(path)
    return path


def run(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "veronte4x", *args], capture_output=True, text=True, check=False
    )


def test_stats_show_every_sender(flight: Path) -> None:
    result = run("stats", str(flight))
    assert result.returncode == 0
    out = result.stdout
    assert "errors: 0" in out
    for sender in ("AP1", "AP2", "AP3", "arbiter", "node 10", "node 20", "node 23"):
        assert f"  {sender} " in out
    for kind in ("ArbitrationVariable", "Status", "Score", "PwmSet", "RawCommand", "EscStatus",
                 "Temperature", "NodeStatus", "GetNodeInfoResponse"):  # fmt: skip
        assert f"  {kind} " in out


def test_decode_jsonl_has_both_protocols(flight: Path) -> None:
    result = run("decode", str(flight), "--output", "jsonl")
    assert result.returncode == 0
    lines = result.stdout.splitlines()
    assert any('"message": "EscStatus"' in line and '"sender": "node 21"' in line for line in lines)
    assert any('"message": "Status"' in line for line in lines)


def test_replay_explains_the_failure(flight: Path) -> None:
    result = run("replay", str(flight), "--config", str(EXAMPLES / "arbiter.toml"))
    assert result.returncode == 0
    timeline = result.stdout
    assert "switch      AP1 -> AP2: AP2 " in timeline
    assert "dead        AP2 dead: Ready missing for 0.1 s" in timeline
    assert "switch      AP2 -> AP3: AP2 is dead: AP3 (best score" in timeline
    assert "DISAGREES" not in timeline
    assert result.stderr.endswith(", 0 disagreements, 0 bad frames\n")


def test_replay_reports_an_injected_disagreement(flight: Path) -> None:
    """A Status that says AP1 is selected while the model selects AP2 is reported."""
    config = load_config(str(EXAMPLES / "arbiter.toml"))
    records = [r for r in capture.read(str(flight)) if r.error is None and r.node_id is None]
    start = records[0].timestamp
    assert start is not None
    frames = []
    injected = None
    for record in records:
        message = record.message
        assert record.timestamp is not None
        late = record.timestamp > start + 5.0
        if injected is None and late and isinstance(message, codec.Status):
            assert message.selected == 1
            message = dataclasses.replace(message, selected=0)
            injected = record.timestamp
        frames.append((record.timestamp, record.can_id, codec.encode(message)))
    result = arbiter.replay(frames, config)
    [disagreement] = result.disagreements
    assert (disagreement.start, disagreement.field) == (injected, "selected")
    assert (disagreement.recorded, disagreement.modelled) == (0, 1)
    assert "DISAGREES   selected: recorded AP1, model AP2" in result.timeline()


def test_notebook_example(flight: Path, tmp_path: Path) -> None:
    plot = tmp_path / "arbitration.png"
    result = subprocess.run(
        [sys.executable, str(EXAMPLES / "notebook.py"), str(flight), str(plot)],
        capture_output=True,
        text=True,
        check=True,
    )
    assert "Mean rpm and current per ESC" in result.stdout
    assert plot.stat().st_size > 10_000
    frame = capture.to_dataframe(capture.read(str(flight)))
    status = frame[frame.message == "Status"]
    assert str(status.selected.dtype) == "Int64"
    assert set(status.selected.dropna()) == {1, 2}
    assert str(status.alive_1.dtype) == "boolean"


def test_replay_without_config_says_what_it_assumed_and_fails_on_disagreements(
    flight: Path,
) -> None:
    result = run("replay", str(flight))
    assert result.returncode == 1
    first, last = result.stderr.splitlines()
    assert first.startswith("veronte4x: no --config: assuming the default arbiter configuration")
    assert first.endswith("pass the vehicle's arbiter configuration with --config FILE")
    assert re.fullmatch(r"veronte4x: \d+ decisions, [1-9]\d* disagreements, 0 bad frames", last)


def test_decode_output_people_read(flight: Path) -> None:
    """Enums by name, node names as text, units, in text, JSONL and CSV; floats exact in
    JSONL."""
    text = run("decode", str(flight)).stdout.splitlines()
    esc = next(line for line in text if "EscStatus(" in line)
    assert re.search(
        r"voltage=[\d.]+ V, current=[\d.]+ A, temperature=[\d.]+ K, rpm=-?\d+ rpm", esc
    )
    node = next(line for line in text if "GetNodeInfoResponse(" in line)
    assert "health=OK, mode=OPERATIONAL" in node and "name='iq_motion.esc'" in node
    assert text[0].startswith("2025-11-21T15:00:00.")
    rows = [
        json.loads(line)
        for line in run("decode", str(flight), "--output", "jsonl").stdout.splitlines()
    ]
    info = next(row for row in rows if row["message"] == "GetNodeInfoResponse")
    assert (info["name"], info["status.health"], info["status.mode"]) == (
        "iq_motion.esc",
        "OK",
        "OPERATIONAL",
    )
    decoded = [record for record in capture.read(flight) if record.error is None]
    assert len(rows) == len(decoded)
    for row, record in zip(rows, decoded, strict=True):  # floats exact, as capture.read's
        for name, value in capture.fields(record.message).items():
            if type(value) is float:
                assert repr(row[name]) == repr(value), (row, name)
    table = list(csv.DictReader(io.StringIO(run("decode", str(flight), "--output", "csv").stdout)))
    info_row = next(row for row in table if row["message"] == "GetNodeInfoResponse")
    assert (info_row["name"], info_row["status.health"]) == ("iq_motion.esc", "OK")
    info_message = next(
        r.message for r in capture.read(flight) if type(r.message).__name__ == "GetNodeInfoResponse"
    )
    assert set(capture.fields(info_message)) <= set(info_row)  # one column per field


def test_replay_times_iso_or_relative(flight: Path) -> None:
    config = str(EXAMPLES / "arbiter.toml")
    iso = run("replay", str(flight), "--config", config).stdout.splitlines()
    assert iso[0] == "2025-11-21T15:00:00.000085Z  mode        boot: Idle, checking the system"
    relative = run("replay", str(flight), "--config", config, "--time", "relative").stdout
    assert relative.splitlines()[0] == "0.000000  mode        boot: Idle, checking the system"
    switch = next(line for line in relative.splitlines() if "switch      AP2 -> AP3" in line)
    assert switch.startswith("15.08")  # AP2 falls silent at 15 s


def test_tables_example(flight: Path, tmp_path: Path) -> None:
    plot = tmp_path / "tables.png"
    result = subprocess.run(
        [sys.executable, str(EXAMPLES / "tables.py"), str(flight), str(plot)],
        capture_output=True,
        text=True,
        check=True,
    )
    assert "ESC node 20, 5-15 s from the start: 100 rows" in result.stdout
    assert "AP3" in result.stdout.split("Selected autopilot changes")[1]
    assert plot.stat().st_size > 10_000


def test_a_capture_replays_in_python_as_on_the_command_line(flight: Path) -> None:
    """`capture.replay(path, config)`: the CLI's timeline, with UTC datetimes."""
    from veronte4x.capture.arbitration import replay
    from veronte4x.times import format_time

    config = EXAMPLES / "arbiter.toml"
    result = replay(flight, config)
    assert result == replay(flight, load_config(config))
    cli = run("replay", str(flight), "--config", str(config)).stdout
    assert result.timeline(format_time) + "\n" == cli
    switch = next(d for d in result.decisions if d.reason.startswith("AP2 -> AP3"))
    assert switch.utc is not None and switch.utc.tzinfo is not None
    assert switch.utc.strftime("%Y-%m-%dT%H:%M:%S.%fZ") == format_time(switch.time)
    assert (
        switch.utc - datetime.datetime(2025, 11, 21, 15, tzinfo=datetime.timezone.utc)
    ).seconds == 15
