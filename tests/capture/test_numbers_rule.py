"""The rule for numbers (`veronte4x.numbers`): exact values for machines, the shortest form at
the field's declared width for people, decided by the schema, never by the value; the sign
of zero kept."""

from __future__ import annotations

import math
import struct
from pathlib import Path

from hypothesis import given
from hypothesis import strategies as st

from veronte4x import capture, codec, dronecan
from veronte4x.capture.busmap import BusMap
from veronte4x.capture.monitor import MonitorState
from veronte4x.capture.readable import float_bits, format_message, readable_fields, shown
from veronte4x.display import to_html
from veronte4x.numbers import INFINITY, MINUS_INFINITY, NAN, exact, for_people, shortest

WHEEL = {
    "veronte": {
        "layouts": [
            {
                "command": 5,
                "name": "Wheel",
                "fields": [
                    {
                        "kind": "unsigned",
                        "name": "speed",
                        "bits": 16,
                        "scale": [0, 65535, 0.0, 1023.984375],
                    }
                ],
            },
            {"command": 6, "name": "Volts", "fields": [{"kind": "float32", "name": "volts"}]},
        ]
    }
}


def _records(tmp_path: Path, lines: list[str]) -> list[capture.Record]:
    log = tmp_path / "capture.log"
    log.write_text("".join(f"({i}.000000) can0 {line}\n" for i, line in enumerate(lines)))
    return list(capture.read(log, BusMap.from_dict(WHEEL)))


def test_a_scaled_veronte_field_is_a_float64_everywhere(tmp_path: Path) -> None:
    """``scale = [0, 65535, 0.0, 1023.984375]``, frame ``008#05FFFF``: 1023.984375 is a
    float32 too, and was printed 1023.9844 in its float32 shortest form."""
    (record,) = _records(tmp_path, ["008#05FFFF"])
    assert record.message.speed == 1023.984375
    assert float_bits(type(record.message), "speed") == 64
    assert readable_fields(record.message) == {"speed": 1023.984375}
    assert format_message(record.message) == "Wheel(speed=1023.984375)"
    assert "<td>speed</td><td>1023.984375</td>" in to_html(record.message)


def test_a_declared_float32_field_shows_at_32_bits(tmp_path: Path) -> None:
    (record,) = _records(tmp_path, ["008#06CDCCCC3D"])
    assert float_bits(type(record.message), "volts") == 32
    assert readable_fields(record.message) == {"volts": 0.10000000149011612}
    assert format_message(record.message) == "Volts(volts=0.1)"


def test_the_sign_of_zero_never_leaks_to_the_next_value(tmp_path: Path) -> None:
    """Two frames, ``008#000000000080`` then ``008#000000000000``: the second printed -0.0
    (a cache that took 0.0 and -0.0 for one key)."""
    records = _records(tmp_path, ["008#000000000080", "008#000000000000", "008#0600000080"])
    assert [format_message(r.message) for r in records] == [
        "ArbitrationVariable(number=0, value=-0.0)",
        "ArbitrationVariable(number=0, value=0.0)",
        "Volts(volts=-0.0)",
    ]
    assert [repr(readable_fields(r.message)["value"]) for r in records[:2]] == ["-0.0", "0.0"]
    state = MonitorState()
    for record in records[:2]:
        state.add(record)
    assert [row.fields for row in state.rows()] == ["number=0, value=0.0"]


@given(st.lists(st.floats(width=32) | st.sampled_from([0.0, -0.0]), min_size=1, max_size=50))
def test_the_shortest_form_reads_back_bit_for_bit_whatever_came_before(
    values: list[float],
) -> None:
    for bits, fmt in ((32, "<f"), (16, "<e")):
        for value in values:
            try:
                narrow = struct.unpack(fmt, struct.pack(fmt, value))[0]
            except OverflowError:  # beyond float16
                continue
            short = shortest(narrow, bits)
            if narrow != narrow:
                assert short != short
            else:
                assert struct.pack(fmt, short) == struct.pack(fmt, narrow), (bits, value)


def test_the_declared_width_decides_not_the_value() -> None:
    assert float_bits(codec.Score, "score") == 32
    assert float_bits(codec.ArbitrationVariable, "value") == 32
    assert float_bits(dronecan.EscStatus, "temperature") == 16
    assert float_bits(dronecan.StaticPressure, "static_pressure") == 32
    assert float_bits(dronecan.StaticPressure, "static_pressure_variance") == 16
    assert float_bits(dronecan.GlobalNavigationSolution, "longitude") == 64
    # A float64 that happens to be exactly a float32 keeps every digit for people too.
    solution = dronecan.GlobalNavigationSolution(longitude=1529498.25, latitude=1023.984375)
    text = format_message(solution)
    assert "longitude=1529498.25," in text and "latitude=1023.984375," in text
    assert shown(dronecan.GlobalNavigationSolution, "longitude", 1529498.25) == 1529498.25


def test_dronecan_floats_exact_for_machines_shortest_at_their_width_for_people() -> None:
    """float16 298.25 was written 298.2 and float32 101318.984375 was 101318.984 in JSON."""
    pressure = dronecan.StaticPressure(static_pressure=101318.984375, static_pressure_variance=2.5)
    temperature = dronecan.StaticTemperature(static_temperature=298.25)
    assert readable_fields(pressure) == {
        "static_pressure": 101318.984375,
        "static_pressure_variance": 2.5,
    }
    assert readable_fields(temperature)["static_temperature"] == 298.25
    assert format_message(pressure) == (
        "StaticPressure(static_pressure=101318.984, static_pressure_variance=2.5)"
    )
    assert format_message(temperature).startswith("StaticTemperature(static_temperature=298.2,")
    assert "<td>static_pressure</td><td>101318.984</td>" in to_html(pressure)


def test_non_finite_and_zero_for_machines_and_people() -> None:
    assert (exact(math.nan), exact(math.inf), exact(-math.inf)) == (NAN, INFINITY, MINUS_INFINITY)
    assert (NAN, INFINITY, MINUS_INFINITY) == ("NaN", "Infinity", "-Infinity")
    assert repr(exact(-0.0)) == "-0.0"
    assert repr(for_people(-0.0, 16)) == "-0.0" and repr(for_people(0.0, 16)) == "0.0"
    assert for_people(1529498.25, 64) == 1529498.25
    assert for_people(1529498.25, 32) == 1529498.2  # only where a field is declared float32
    message = codec.ArbitrationVariable(number=0, value=math.nan)
    assert readable_fields(message)["value"] == "NaN"
    assert format_message(message) == "ArbitrationVariable(number=0, value=nan)"
