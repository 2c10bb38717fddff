"""Bus maps as people write them, right and wrong: loading gives a map or a `BusMapError`
naming the key, never another exception, and a map that loads decodes every frame in both
`capture.read` and `capture.read_tables`."""

from __future__ import annotations

import math
import re
from pathlib import Path
from typing import Any

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.inputs.support import run
from veronte4x import capture
from veronte4x.capture.busmap import BusMap, BusMapError


def _layout(**changes: Any) -> dict[str, Any]:
    field = {"kind": "unsigned", "name": "throttle", "bits": 8, "scale": [0, 200, 0.0, 100.0]}
    layout = {"command": 5, "name": "Telemetry", "fields": [field]}
    return {"veronte": {"layouts": [{**layout, **changes}]}}


def _scaled(scale: list[Any]) -> dict[str, Any]:
    return _layout(fields=[{"kind": "unsigned", "name": "t", "bits": 8, "scale": scale}])


MALFORMED = [
    (_scaled([0, 200, 0.0, math.inf]), "[[veronte.layouts]] 'Telemetry' field 1 scale: "),
    (_scaled([0, 200, 0.0, math.nan]), "field 1 scale: [0, 200, 0.0, nan] does not give a finite"),
    (_scaled([0, 200, -1.7e308, 1.7e308]), "does not give a finite number for every 8-bit wire"),
    (_scaled([0, 200, 0.0, 1.7e308]), "does not give a finite number"),
    (_scaled([0, 0, 0.0, 1.0]), "encoded_min and encoded_max of [0, 0, 0.0, 1.0] are equal"),
    (_scaled([0, 200, 0.0]), "is not [encoded_min, encoded_max, decoded_min, decoded_max]"),
    (_scaled([0, 200, "a", 1.0]), "the decoded values of [0, 200, 'a', 1.0] are not numbers"),
    (_layout(name="errors"), "[[veronte.layouts]] 'errors': the name 'errors' is taken"),
    (_layout(name="unknown"), "the name 'unknown' is taken by veronte4x"),
    (_layout(name="Status"), "the name 'Status' is taken by veronte4x"),
    (_layout(name="EscStatus"), "the name 'EscStatus' is taken by veronte4x"),
    (_layout(name=5), "[[veronte.layouts]] number 1: name = 5 is not text"),
    (_layout(command="5"), "[[veronte.layouts]] 'Telemetry': command = '5' is not an integer"),
    (_layout(fields="abc"), "[[veronte.layouts]] 'Telemetry' fields: 'abc' is not a list"),
    (_layout(fields=[1]), "[[veronte.layouts]] 'Telemetry' field 1: 1 is not a table of keys"),
    (_layout(fields=[{"kind": "float32", "name": "sender"}]), "the field name 'sender' is a col"),
    (_layout(byte_order="middle"), "byte_order = 'middle' is not 'little' or 'big'"),
    ({"veronte": 1}, "[veronte]: 1 is not a table of keys"),
    ({"dronecan": [1]}, "[dronecan]: [1] is not a table of keys"),
    ({"veronte": {"layouts": {"a": 1}}}, "veronte.layouts: {'a': 1} is not a list"),
    ({"veronte": {"autopilot_ids": 8}}, "[veronte] autopilot_ids: 8 is not a list"),
]


@pytest.mark.parametrize(("document", "error"), MALFORMED)
def test_a_malformed_map_is_refused_naming_the_key(document: dict[str, Any], error: str) -> None:
    with pytest.raises(BusMapError, match=re.escape(error)):
        BusMap.from_dict(document)


def test_the_command_line_says_it_in_one_line(tmp_path: Path) -> None:
    path = tmp_path / "bus.toml"
    path.write_text(
        "[[veronte.layouts]]\ncommand = 5\nname = 'T'\nfields = [\n"
        "  { kind = 'unsigned', name = 't', bits = 8, scale = [0, 200, 0.0, inf] },\n]\n"
    )
    log = tmp_path / "flight.log"
    log.write_text("(1.0) can0 009#0580\n")
    for command in ("decode", "stats", "list"):
        args = [command, "--bus-map", str(path)] + ([] if command == "list" else [str(log)])
        result = run(*args)
        assert result.returncode == 2
        assert result.stderr == (
            "veronte4x: [[veronte.layouts]] 'T' field 1 scale: [0, 200, 0.0, inf] does not give "
            "a finite number for every 8-bit wire value: give finite decoded values of a "
            "smaller range\n"
        )


_ANY: st.SearchStrategy[Any] = st.recursive(
    st.none() | st.booleans() | st.integers(-(2**70), 2**70) | st.floats() | st.text(max_size=8),
    lambda inner: (
        st.lists(inner, max_size=4) | st.dictionaries(st.text(max_size=6), inner, max_size=4)
    ),
    max_leaves=8,
)


def _maybe(strategy: st.SearchStrategy[Any]) -> st.SearchStrategy[Any]:
    """Mostly the right shape, sometimes anything."""
    return st.one_of(*[strategy] * 9, _ANY)


_NUMBER = st.one_of(st.integers(-(2**40), 2**40), st.floats(), st.sampled_from([1.7e308, -1.7e308]))


def _name(spec: Any) -> str:
    return repr(spec.get("name")) if isinstance(spec, dict) else repr(spec)


_FIELD = st.fixed_dictionaries(
    {
        "kind": _maybe(st.sampled_from(["unsigned", "signed", "float32", "skip", "constant"])),
        "name": _maybe(st.sampled_from(["a", "b", "c", "x_1", "timestamp", "Status", "1x", "if"])),
        "bits": _maybe(st.integers(1, 16) | st.integers(-2, 70)),
    },
    optional={
        "scale": _maybe(st.lists(_NUMBER, min_size=4, max_size=4)),
        "value": _maybe(st.integers(-5, 300)),
    },
)
_LAYOUT = st.fixed_dictionaries(
    {
        "command": _maybe(st.integers(5, 12) | st.integers(-1, 260)),
        "name": _maybe(st.sampled_from(["Telemetry", "errors", "unknown", "Status", "Score", "T"])),
        "fields": _maybe(st.lists(_maybe(_FIELD), max_size=4, unique_by=_name)),
    },
    optional={"byte_order": _maybe(st.sampled_from(["little", "big"]))},
)
_MAP = st.fixed_dictionaries(
    {},
    optional={
        "veronte": _maybe(
            st.fixed_dictionaries(
                {},
                optional={
                    "layouts": _maybe(st.lists(_maybe(_LAYOUT), max_size=3, unique_by=_name)),
                    "extended": _maybe(st.booleans()),
                    "pwm_packing": _maybe(st.sampled_from(["lsb_first", "msb_first"])),
                },
            )
        ),
        "dronecan": _maybe(st.fixed_dictionaries({}, optional={"enabled": _maybe(st.booleans())})),
    },
)


_NAMED = ("unsigned", "signed", "float32")
_SHAPED_FIELD = st.fixed_dictionaries(
    {
        "kind": st.sampled_from(["unsigned", "signed", "float32", "skip", "constant"]),
        "name": st.sampled_from(["a", "b", "c", "x_1"]),
        "bits": st.integers(1, 16),
    },
    optional={"scale": st.lists(_NUMBER, min_size=4, max_size=4), "value": st.integers(0, 3)},
).map(lambda spec: {k: v for k, v in spec.items() if k != "name" or spec["kind"] in _NAMED})
_SHAPED = st.fixed_dictionaries(
    {
        "veronte": st.fixed_dictionaries(
            {
                "layouts": st.lists(
                    st.fixed_dictionaries(
                        {
                            "command": st.integers(5, 12),
                            "name": st.sampled_from(["T", "U", "errors", "Status", "NodeStatus"]),
                            "fields": st.lists(_SHAPED_FIELD, max_size=4, unique_by=_name),
                        }
                    ),
                    max_size=3,
                    unique_by=_name,
                )
            }
        ),
        "dronecan": st.fixed_dictionaries({"enabled": st.booleans()}),
    }
)
"""Maps of the right shape, whose values (scales, names, widths) may be wrong."""


@settings(max_examples=300, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(document=_MAP | _SHAPED, payloads=st.lists(st.binary(max_size=8), min_size=1, max_size=4))
def test_a_map_loads_or_is_refused_and_a_loaded_map_decodes(
    tmp_path: Path, document: dict[str, Any], payloads: list[bytes]
) -> None:
    try:
        bus_map = BusMap.from_dict(document)
    except BusMapError:
        return
    commands = [layout.command for layout in bus_map.layouts] or [5]
    width = 8 if bus_map.extended else 3
    lines = [
        f"({n}.0) can0 {9:0{width}X}#{bytes([command]).hex()}{payload.hex()}\n"
        for n, (command, payload) in enumerate(((c, p) for c in commands for p in payloads), 1)
    ]
    path = tmp_path / "flight.log"
    path.write_text("".join(lines))
    records = list(capture.read(path, bus_map))
    assert len(records) == len(lines)
    tables = capture.read_tables(path, bus_map)
    assert sum(table.num_rows for table in tables.values()) == len(lines)
