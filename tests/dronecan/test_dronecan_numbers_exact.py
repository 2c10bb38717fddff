"""``veronte4x decode --output jsonl`` writes every standard type's fields as `capture.read`
decodes them and as the ``dronecan`` package does, bit for bit: a float16 298.25 is 298.25
(it was written 298.2), a float32 101318.984375 is 101318.984375 (it was 101318.984).

One capture holds a random message of every standard type; the CLI runs once per capture,
as a subprocess.
"""

from __future__ import annotations

import json
import math
import struct
import subprocess
import sys
from pathlib import Path
from typing import Any

from dronecan_oracle import CLASS_OF, reference_builtin, reference_decode
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from test_dronecan_differential import STRATEGIES

from veronte4x import capture, dronecan
from veronte4x.cli.decode import HEAD_COLUMNS

K = dronecan.TransferKind


def _json_form(value: Any) -> Any:
    """What the rule says a JSON line holds for a decoded value."""
    if type(value) is float and not math.isfinite(value):
        return "NaN" if value != value else ("Infinity" if value > 0 else "-Infinity")
    return value


def _floats(value: Any) -> list[float]:
    """The floats of plain data (dicts, lists), in order."""
    if isinstance(value, dict):
        return [f for item in value.values() for f in _floats(item)]
    if isinstance(value, list):
        return [f for item in value for f in _floats(item)]
    return [value] if type(value) is float else []


def _bits(value: Any) -> Any:
    if value == "NaN" or (type(value) is float and value != value):
        return "nan"  # JSON keeps no NaN payload
    return struct.pack("<d", value)


@given(data=st.data())
@settings(max_examples=3, suppress_health_check=[HealthCheck.function_scoped_fixture])
def test_json_lines_of_every_standard_type_are_capture_read_and_dronecan_values(
    tmp_path: Path, data: st.DataObject
) -> None:
    lines: list[str] = []
    references: list[Any] = []
    for number, key in enumerate(sorted(STRATEGIES, key=lambda k: (k[0], k[1].value))):
        fields = data.draw(STRATEGIES[key], label=f"{key[0]} {key[1].name}")
        message: Any = dronecan.from_builtin(CLASS_OF[key], fields)
        frames = [
            (f.can_id, f.data)
            for f in dronecan.encode(
                message,
                source_node_id=9,
                destination_node_id=None if key[1] is K.MESSAGE else 42,
                transfer_id=number % 32,
            )
        ]
        references.append(reference_builtin(reference_decode(frames)))
        lines += [f"({len(lines) / 1000:.6f}) can0 {i:08X}#{d.hex()}\n" for i, d in frames]
    log = tmp_path / "every_type.log"
    log.write_text("".join(lines), encoding="ascii")
    result = subprocess.run(
        [sys.executable, "-m", "veronte4x", "decode", str(log), "--output", "jsonl"],
        capture_output=True,
        text=True,
        check=False,
    )
    assert result.returncode == 0, result.stderr
    rows = [json.loads(line) for line in result.stdout.splitlines()]
    records = list(capture.read(log))
    assert len(rows) == len(records) == len(references) == len(STRATEGIES)
    for row, record, reference in zip(rows, records, references, strict=True):
        fields = capture.fields(record.message)
        written = {f"message.{k}" if k in HEAD_COLUMNS else k: v for k, v in fields.items()}
        assert [k for k in row if k not in HEAD_COLUMNS] == list(written)
        for name, value in written.items():  # floats exactly capture.read's
            if type(value) is float:
                assert repr(row[name]) == repr(_json_form(value)), (record.message, name)
        floats = [row[k] for k, v in written.items() if type(v) is float]
        assert [_bits(f) for f in floats] == [_bits(f) for f in _floats(reference)], reference
