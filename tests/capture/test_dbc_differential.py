"""`read` and `read_tables` against cantools, bit for bit, over generated DBCs: factors that
are powers of two, float32 and float64 signals, -0.0, NaN and infinities on the wire,
value tables that give one name to several numbers."""

from __future__ import annotations

import csv
import io
import json
import math
import struct
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import Any

import cantools
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.capture.columnar_support import write
from tests.capture.dbc_reference import cantools_fields
from veronte4x import capture
from veronte4x.capture import BusMap

BUS_MAP = BusMap(dronecan=False)
FACTORS = st.one_of(
    st.integers(-12, 12).map(lambda k: 2.0**k), st.sampled_from([1, 2, 4, -1, 0.1, 0.001, 1e-7])
)
OFFSETS = st.sampled_from([0, -1, 7, 0.5, -0.25, 1e-3, 2.0**-20])
SPECIAL = [struct.pack("<f", f) for f in (float("nan"), -0.0, float("inf"), float("-inf"))] + [
    struct.pack("<f", 3.4e38)
]


@st.composite
def message(draw: st.DrawFn) -> tuple[list[str], list[str]]:
    """The SG_ lines and the VAL_/SIG_VALTYPE_ lines of message 256, 8 bytes."""
    signals, extra, cursor = [], [], 0
    for index in range(draw(st.integers(1, 4))):
        kind = draw(st.sampled_from(["int", "int", "float32", "float64"]))
        if kind == "float64" and cursor:
            break
        length = {"float32": 32, "float64": 64}.get(kind) or draw(st.integers(1, 32))
        order = draw(st.sampled_from(["1", "0"])) if kind == "int" else "1"
        if order == "0":
            cursor = -(-cursor // 8) * 8  # a Motorola signal from a byte's top bit
        if cursor + length > 64:
            break
        start = cursor if order == "1" else cursor + 7
        cursor += length if order == "1" else -(-length // 8) * 8
        sign = "-" if kind != "int" or draw(st.booleans()) else "+"
        factor, offset = (1, 0) if kind != "int" else (draw(FACTORS), draw(OFFSETS))
        signals.append(
            f' SG_ s{index} : {start}|{length}@{order}{sign} ({factor},{offset}) [0|0] "" X'
        )
        if kind != "int":
            extra.append(f"SIG_VALTYPE_ 256 s{index} : {1 if kind == 'float32' else 2};")
        elif draw(st.booleans()):
            names = draw(st.lists(st.sampled_from(["off", "on", "fault"]), min_size=1, max_size=6))
            pairs = " ".join(f'{value} "{name}"' for value, name in enumerate(names))
            extra.append(f"VAL_ 256 s{index} {pairs} ;")
    return signals, extra


def bits(value: Any) -> Any:
    """A value as its type and, for a float, its 64 bits (NaN and -0.0 compared exactly)."""
    return (float, struct.pack("<d", value)) if isinstance(value, float) else (type(value), value)


@settings(max_examples=150, suppress_health_check=[HealthCheck.too_slow])
@given(
    message(),
    st.lists(
        st.one_of(
            st.binary(min_size=8, max_size=8),
            st.tuples(st.sampled_from(SPECIAL), st.sampled_from(SPECIAL)).map(
                lambda p: b"".join(p)
            ),
        ),
        min_size=1,
        max_size=20,
    ),
)
def test_read_and_tables_equal_cantools_bit_for_bit(
    shape: tuple[list[str], list[str]], payloads: list[bytes]
) -> None:
    signals, extra = shape
    text = "\n".join(
        ['VERSION ""', "NS_ :", "BS_:", "BU_: X", "BO_ 256 M: 8 X", *signals, "", *extra, ""]
    )
    with tempfile.TemporaryDirectory() as folder:
        dbc = Path(folder) / "g.dbc"
        dbc.write_text(text)
        database: Any = cantools.database.load_file(str(dbc))
        lines = [f"({1 + i / 100:.6f}) can0 100#{data.hex()}" for i, data in enumerate(payloads)]
        path = write(Path(folder) / "x.log", lines)
        records = list(capture.read(path, BUS_MAP, dbc=[dbc]))
        tables = capture.read_tables(path, BUS_MAP, dbc=[dbc])
    message_ = database.get_message_by_frame_id(256)
    expected = [cantools_fields(message_, data) for data in payloads]
    got = [
        {
            (f"{s}_name" if f in type(r.message).CHOICES.values() else s): getattr(r.message, f)
            for f, s in zip(
                type(r.message).__dataclass_fields__, type(r.message).SIGNALS, strict=True
            )
        }
        for r in records
    ]
    assert [{k: bits(v) for k, v in row.items()} for row in got] == [
        {k: bits(v) for k, v in row.items()} for row in expected
    ]
    fields = list(type(records[0].message).__dataclass_fields__)
    rows = [{f: bits(row[f]) for f in fields} for row in tables["M"].to_pylist()]
    assert rows == [{f: bits(getattr(r.message, f)) for f in fields} for r in records]


def _number_text(value: Any) -> str:
    """A value as the numbers rule writes it in CSV (docs/captures.md)."""
    if isinstance(value, float) and not math.isfinite(value):
        return "NaN" if value != value else ("Infinity" if value > 0 else "-Infinity")
    return "" if value is None else repr(value) if isinstance(value, float) else str(value)


def _from_json(value: Any) -> Any:
    named = {"NaN": math.nan, "Infinity": math.inf, "-Infinity": -math.inf}
    return named.get(value, value) if isinstance(value, str) else value


@settings(max_examples=5, suppress_health_check=[HealthCheck.too_slow])
@given(message(), st.lists(st.binary(min_size=8, max_size=8), min_size=1, max_size=20))
def test_the_command_lines_json_lines_and_csv_equal_read_bit_for_bit(
    shape: tuple[list[str], list[str]], payloads: list[bytes]
) -> None:
    """``veronte4x decode --dbc`` as a subprocess: each signal of its JSON lines and CSV is
    `capture.read`'s value (which the test above holds to cantools), NaN and -0.0 included."""
    signals, extra = shape
    text = "\n".join(
        ['VERSION ""', "NS_ :", "BS_:", "BU_: X", "BO_ 256 M: 8 X", *signals, "", *extra, ""]
    )
    payloads = [*payloads, SPECIAL[0] + SPECIAL[1], SPECIAL[1] + SPECIAL[2]]
    with tempfile.TemporaryDirectory() as folder:
        dbc = Path(folder) / "g.dbc"
        dbc.write_text(text)
        lines = [f"({1 + i / 100:.6f}) can0 100#{data.hex()}" for i, data in enumerate(payloads)]
        path = write(Path(folder) / "x.log", lines)
        records = [r for r in capture.read(path, dbc=[dbc]) if r.error is None]
        runs = [
            subprocess.run(
                [sys.executable, "-m", "veronte4x", "decode", str(path), "--dbc", str(dbc),
                 "--output", output],
                capture_output=True, text=True, check=False, timeout=600,
            )
            for output in ("jsonl", "csv")
        ]  # fmt: skip
    assert [run.returncode for run in runs] == [0, 0], runs[0].stderr + runs[1].stderr
    outputs = [run.stdout for run in runs]
    fields = list(type(records[0].message).__dataclass_fields__)
    expected = [{f: getattr(r.message, f) for f in fields} for r in records]
    decoded = [json.loads(line) for line in outputs[0].splitlines()]
    assert [{f: bits(_from_json(row[f])) for f in fields} for row in decoded] == [
        {f: bits(value) for f, value in row.items()} for row in expected
    ]
    table = list(csv.DictReader(io.StringIO(outputs[1])))
    assert [{f: row[f] for f in fields} for row in table] == [
        {f: _number_text(value) for f, value in row.items()} for row in expected
    ]
