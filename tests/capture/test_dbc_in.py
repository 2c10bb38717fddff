"""DBC in: frames outside the bus map decoded through cantools into records and tables."""

from __future__ import annotations

import math
import subprocess
import sys
from pathlib import Path
from typing import Any

import cantools
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.capture.columnar_support import write
from tests.capture.dbc_reference import cantools_fields
from veronte4x import capture
from veronte4x.capture import BusMap, DbcDecoder, Role
from veronte4x.capture.dbc_in import DbcWarning

DBC = Path(__file__).with_name("data") / "payload.dbc"
ROOT = Path(__file__).resolve().parents[2]
BUS_MAP = BusMap(dronecan=False)  # the gimbal's 29-bit frames are not DroneCAN
DATABASE: Any = cantools.database.load_file(str(DBC))


def want(can_id: int, extended: bool, data: bytes) -> dict[str, Any] | str:
    """What cantools itself says of a frame: its signals' numbers (``decode_choices=False``)
    and a value table's names (``<signal>_name``), or the error text."""
    message = DATABASE.get_message_by_frame_id(can_id | (0x80000000 if extended else 0))
    try:
        return cantools_fields(message, data)
    except Exception as error:
        return f"{message.name}: {error}"


def same(got: Any, expected: Any) -> bool:
    if isinstance(expected, float) and math.isnan(expected):
        return isinstance(got, float) and math.isnan(got)
    return bool(got == expected)


frames = st.one_of(
    st.tuples(st.just(0x123), st.just(False), st.binary(max_size=8)),
    st.tuples(st.just(0x18FF1234), st.just(True), st.binary(max_size=8)),
    st.tuples(st.integers(0x100, 0x7FF), st.booleans(), st.binary(max_size=8)),
)


@settings(max_examples=150, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(st.lists(frames, max_size=30))
def test_records_and_tables_as_cantools_decodes(
    tmp_path: Path, listed: list[tuple[int, bool, bytes]]
) -> None:
    lines = [
        f"({1.0 + i / 100:.6f}) can0 {c:{'08X' if e else '03X'}}#{d.hex()}"
        for i, (c, e, d) in enumerate(listed)
    ]
    path = write(tmp_path / "payload.log", [*lines, "(9.000000) can0 0FF#00FF8177FFFF"])
    records = list(capture.read(path, BUS_MAP, dbc=[DBC]))
    plain = list(capture.read(path, BUS_MAP))
    assert len(records) == len(plain)
    rows: dict[str, list[dict[str, Any]]] = {}
    for record, before, (can_id, extended, data) in zip(records, plain, listed, strict=False):
        if before.role is not Role.UNKNOWN or not DATABASE_KNOWS(can_id, extended):
            assert record == before
            continue
        expected = want(can_id, extended, data)
        if isinstance(expected, str):
            assert (record.error, record.detail, record.message) == ("decode error", expected, None)
            continue
        assert record.error is None
        assert record.kind == type(record.message).DBC_NAME
        got = {name: getattr(record.message, name) for name in expected}
        assert all(same(got[k], v) for k, v in expected.items()), (got, expected)
        # the rest of the record is the unknown one's, its detail gone; the message is an
        # ordinary instance of its class (built by generated code, not its __init__)
        assert record._replace(message=None) == before._replace(detail="")
        rebuilt = type(record.message)(**got)
        if all(same(v, v) for v in got.values()):  # NaN is never equal to itself
            assert record.message == rebuilt and hash(record.message) == hash(rebuilt)
        assert repr(record.message) == repr(rebuilt)
        rows.setdefault(record.kind, []).append(got)
    assert records[-1].kind == "Status"  # the bus map's frames stay veronte4x's
    tables = capture.read_tables(path, BUS_MAP, dbc=[DBC])
    for kind, expected_rows in rows.items():
        table = tables[kind].to_pylist()
        assert [{k: r[k] for k in expected_rows[0]} for r in table] == expected_rows
    errors = sum(1 for r in records if r.error)
    assert (len(tables["errors"]) if "errors" in tables else 0) == errors
    unknown = sum(1 for r in records if r.kind == "unknown")
    assert (len(tables["unknown"]) if "unknown" in tables else 0) == unknown


def DATABASE_KNOWS(can_id: int, extended: bool) -> bool:
    return (can_id, extended) in {(0x123, False), (0x18FF1234, True)}


def test_units_choices_and_multiplexing() -> None:
    decoder = DbcDecoder([DBC])
    bms = decoder.decode(0x123, False, bytes.fromhex("E803F6FF01190000"))
    assert (bms.voltage, bms.current, bms.state, bms.temperature) == (10.0, -6.0, 1, 25)
    assert bms.state_name == "charging"
    assert type(bms).UNITS == {"voltage": "V", "current": "A", "temperature": "degC"}
    gimbal = decoder.decode(0x18FF1234, True, bytes.fromhex("02ECFF00"))
    assert (gimbal.mode, gimbal.pitch, gimbal.yaw) == (2, None, -0.2)
    assert not decoder.knows(0x18FF1234, False)


def test_without_a_dbc_nothing_changes(tmp_path: Path) -> None:
    path = write(tmp_path / "x.log", ["(1.0) can0 123#E803F6FF01190000"])
    (record,) = capture.read(path)
    assert record.kind == "unknown"
    assert list(capture.read_tables(path)) == ["unknown"]


def run(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "veronte4x", *args], capture_output=True, text=True, check=False
    )


def test_cli_decode_and_stats_with_a_dbc(tmp_path: Path) -> None:
    path = write(
        tmp_path / "x.log", ["(1.0) can0 123#E803F6FF01190000", "(1.1) can0 0FF#00FF8177FFFF"]
    )
    done = run("decode", str(path), "--dbc", str(DBC))
    assert done.returncode == 0
    warning, summary = done.stderr.splitlines()
    assert warning == (
        f"veronte4x: warning: {DBC}: 1 DBC message(s) on CAN IDs the bus map decodes "
        "otherwise, not decoded by the DBC: Gimbal (18FF1234: DroneCAN); give --dbc-first "
        "(BusMap(dbc_first=True), [dbc] first = true) to let the DBC decode them; or "
        "[dronecan] enabled = false"
    )
    assert summary.startswith("veronte4x: 2 records, 0 undecoded")
    assert done.stdout.splitlines()[0].endswith(
        "BmsStatus(voltage=10.0, current=-6.0, state=1, state_name=charging, temperature=25)"
    )
    done = run("stats", str(path), "--dbc", str(DBC))
    assert "  BmsStatus                             1" in done.stdout.splitlines()
    out = tmp_path / "x.csv"
    done = run("convert", str(path), "--to", "csv", str(out), "--every", "100ms", "--dbc", str(DBC))
    assert done.returncode == 0, done.stderr
    assert '"BmsStatus/unknown/voltage"' in out.read_text().splitlines()[0]


def test_cli_bad_dbc_files(tmp_path: Path) -> None:
    path = write(tmp_path / "x.log", ["(1.0) can0 123#00"])
    done = run("decode", str(path), "--dbc", str(tmp_path / "missing.dbc"))
    assert (done.returncode, done.stdout) == (2, "")
    assert done.stderr == f"veronte4x: {tmp_path / 'missing.dbc'}: No such file or directory\n"
    bad = tmp_path / "bad.dbc"
    bad.write_text("BO_ this is not a DBC\n")
    done = run("decode", str(path), "--dbc", str(bad))
    assert done.returncode == 2
    assert done.stderr.startswith(f"veronte4x: {bad}: not a DBC file cantools reads: ")
    assert len(done.stderr.splitlines()) == 1


def test_missing_extra_names_it() -> None:
    script = (
        "import sys; sys.modules['cantools'] = None\n"
        "from veronte4x import capture\n"
        "try:\n    capture.DbcDecoder(['x.dbc'])\n"
        "except ImportError as e:\n    print(e)\n"
    )
    done = subprocess.run(
        [sys.executable, "-c", script], capture_output=True, text=True, cwd=ROOT, check=True
    )
    assert done.stdout.strip() == (
        "decoding frames with a DBC needs the 'cantools' package: pip install 'veronte4x[dbc]'"
    )


@pytest.mark.parametrize("extended", [False, True])
def test_a_dbc_never_takes_a_veronte_id(extended: bool, tmp_path: Path) -> None:
    dbc = tmp_path / "clash.dbc"
    flag = 0x80000000 if extended else 0
    dbc.write_text(
        f'VERSION ""\nNS_ :\nBS_:\nBU_: X\nBO_ {255 | flag} Clash: 8 X\n'
        ' SG_ a : 0|8@1+ (1,0) [0|255] "" Vector__XXX\n'
    )
    bus_map = BusMap(extended=extended)
    ident = "000000FF" if extended else "0FF"
    path = write(tmp_path / "x.log", [f"(1.0) can0 {ident}#00FF8177FFFF"])
    with pytest.warns(DbcWarning, match=rf"Clash \({ident}: the Veronte arbiter\)"):
        (record,) = capture.read(path, bus_map, dbc=[dbc])
    assert record.kind == "Status"
