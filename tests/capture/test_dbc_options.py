"""DBC options: a DBC message the bus map shadows is reported once and can win
(``dbc_first``); files cantools reads only with ``strict=False`` load with ``dbc_lax``;
a bus map that is not UTF-8 is one line and exit 2."""

from __future__ import annotations

import subprocess
import sys
import warnings
from pathlib import Path
from typing import Any

import cantools
import pytest
from cantools.database.errors import UnsupportedDatabaseFormatError

from tests.capture.columnar_support import assert_same_tables, write
from veronte4x import capture
from veronte4x.capture import BusMap, Role
from veronte4x.capture.dbc_in import DbcWarning
from veronte4x.errors import SourceError

HEAD = 'VERSION ""\nNS_ :\nBS_:\nBU_: X\n'
J1939 = HEAD + (
    "BO_ 2364539904 EEC1: 8 X\n"  # 0x0CF00400, 29-bit
    ' SG_ EngineSpeed : 24|16@1+ (0.125,0) [0|8031.875] "rpm" X\n'
    "BO_ 255 Clash: 1 X\n"
    ' SG_ a : 0|8@1+ (1,0) [0|255] "" X\n'
)
FRAMES = ["(1.0) can0 0CF00400#FFFFFF6812FFFFFF", "(1.1) can0 0FF#00FF8177FFFF"]


def run(*args: str, cwd: Path | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "veronte4x", *args],
        capture_output=True, text=True, check=False, cwd=cwd,
    )  # fmt: skip


def test_a_shadowed_message_is_reported_once_and_can_win(tmp_path: Path) -> None:
    dbc = tmp_path / "j1939.dbc"
    dbc.write_text(J1939)
    path = write(tmp_path / "x.log", FRAMES)
    with pytest.warns(DbcWarning) as caught:
        records = list(capture.read(path, dbc=[dbc]))
    assert [str(w.message) for w in caught] == [
        f"{dbc}: 2 DBC message(s) on CAN IDs the bus map decodes otherwise, not decoded by "
        "the DBC: EEC1 (0CF00400: DroneCAN), Clash (0FF: the Veronte arbiter); give "
        "--dbc-first (BusMap(dbc_first=True), [dbc] first = true) to let the DBC decode "
        "them; or [dronecan] enabled = false"
    ]
    assert [(r.kind, r.role) for r in records] == [
        ("unknown", Role.DRONECAN), ("Status", Role.ARBITER)
    ]  # fmt: skip
    first = BusMap(dbc_first=True)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # nothing to report
        records = list(capture.read(path, first, dbc=[dbc]))
        tables = capture.read_tables(path, first, dbc=[dbc])
    assert [r.kind for r in records] == ["EEC1", "Clash"]
    database: Any = cantools.database.load_file(str(dbc))
    speed = database.get_message_by_name("EEC1").decode(bytes.fromhex("FFFFFF6812FFFFFF"))
    assert records[0].message.EngineSpeed == speed["EngineSpeed"] == 589.0
    assert records[1].message.a == 0
    assert tables["EEC1"].column("EngineSpeed").to_pylist() == [589.0]
    assert_same_tables(tables, capture.tables_from_records(iter(records)))


def test_dbc_first_on_the_command_line_and_in_the_bus_map(tmp_path: Path) -> None:
    dbc = tmp_path / "j1939.dbc"
    dbc.write_text(J1939)
    path = write(tmp_path / "x.log", FRAMES)
    done = run("decode", str(path), "--dbc", str(dbc), "--output", "jsonl")
    assert done.returncode == 0, done.stderr
    warning, _ = done.stderr.splitlines()
    assert warning.startswith(f"veronte4x: warning: {dbc}: 2 DBC message(s) on CAN IDs")
    assert '"EEC1"' not in done.stdout
    bus_map = tmp_path / "bus.toml"
    bus_map.write_text("[dbc]\nfirst = true\n")
    for extra in (["--dbc-first"], ["--bus-map", str(bus_map)]):
        done = run("decode", str(path), "--dbc", str(dbc), *extra)
        assert done.returncode == 0, done.stderr
        assert done.stderr.startswith("veronte4x: 2 records, 0 undecoded"), done.stderr
        first, second = done.stdout.splitlines()
        assert first.endswith("EEC1(EngineSpeed=589.0)") and second.endswith("Clash(a=0)")


OVERLAP = HEAD + (
    "BO_ 256 Overlap: 2 X\n"
    ' SG_ a : 0|8@1+ (1,0) [0|255] "" X\n'
    ' SG_ b : 4|8@1+ (1,0) [0|255] "" X\n'
    "BO_ 257 Good: 1 X\n"
    ' SG_ c : 0|8@1+ (1,0) [0|255] "" X\n'
)


def test_a_file_cantools_reads_only_with_strict_false(tmp_path: Path) -> None:
    dbc = tmp_path / "overlap.dbc"
    dbc.write_text(OVERLAP)
    with pytest.raises(UnsupportedDatabaseFormatError) as strict:
        cantools.database.load_file(str(dbc))
    said = " ".join(str(strict.value).split())
    path = write(tmp_path / "x.log", ["(1.0) can0 100#A55A", "(1.1) can0 101#07"])
    with pytest.raises(SourceError) as refused:
        capture.read_tables(path, dbc=[dbc])
    assert str(refused.value) == (
        f"{dbc}: not a DBC file cantools reads strictly: {said}; give --dbc-lax "
        "(BusMap(dbc_lax=True), [dbc] lax = true) to read it as cantools does with strict=False"
    )
    with pytest.warns(DbcWarning) as caught:
        records = list(capture.read(path, BusMap(dbc_lax=True), dbc=[dbc]))
    assert [str(w.message) for w in caught] == [
        f"{dbc}: read as cantools does with strict=False: {said}"
    ]
    lax: Any = cantools.database.load_file(str(dbc), strict=False)
    with pytest.raises(cantools.database.DecodeError) as unpacking:
        lax.decode_message(256, b"\xa5\x5a")  # cantools reads the file, not those frames
    assert (records[0].error, records[0].detail) == ("decode error", f"Overlap: {unpacking.value}")
    assert records[1].message.c == lax.decode_message(257, b"\x07")["c"] == 7
    tables = capture.read_tables(path, BusMap(dbc_lax=True), dbc=[dbc])
    assert tables["Good"].column("c").to_pylist() == [7]
    assert tables["errors"].column("detail").to_pylist() == [records[0].detail]
    done = run("decode", str(path), "--dbc", str(dbc))
    assert (done.returncode, done.stdout) == (2, "")
    assert done.stderr == f"veronte4x: {refused.value}\n"
    done = run("decode", str(path), "--dbc", str(dbc), "--dbc-lax")
    assert done.returncode == 0, done.stderr
    assert done.stderr.splitlines()[0] == f"veronte4x: warning: {caught[0].message}"
    assert done.stdout.rstrip().endswith("Good(c=7)")
    bus_map = tmp_path / "bus.toml"
    bus_map.write_text("[dbc]\nlax = true\n")
    done = run("decode", str(path), "--dbc", str(dbc), "--bus-map", str(bus_map))
    assert done.returncode == 0, done.stderr


def test_a_file_cantools_cannot_read_even_laxly(tmp_path: Path) -> None:
    dbc = tmp_path / "bad.dbc"
    dbc.write_text("BO_ this is not a DBC\n")
    with pytest.raises(SourceError, match=r"bad\.dbc: not a DBC file cantools reads: "):
        capture.DbcDecoder([dbc], lax=True)


@pytest.mark.parametrize(
    "command",
    [
        ["decode", "x.log"],
        ["stats", "x.log"],
        ["convert", "x.log", "--to", "csv", "out.csv"],
        ["list"],
        ["export", "dbc"],
        ["replay", "x.log"],
        ["plot", "x.log"],
    ],
)
def test_a_bus_map_that_is_not_utf8(tmp_path: Path, command: list[str]) -> None:
    write(tmp_path / "x.log", ["(1.0) can0 0FF#00FF8177FFFF"])
    (tmp_path / "bus.toml").write_bytes(b"[veronte]\n# caf\xe9\narbiter_id = 255\n")
    done = run(*command, "--bus-map", "bus.toml", cwd=tmp_path)
    assert (done.returncode, done.stdout) == (2, "")
    assert done.stderr == (
        "veronte4x: bus.toml: not UTF-8 text (byte 15): save the bus map as UTF-8, as TOML "
        "requires\n"
    )


def test_signals_of_a_multiplexor_cantools_does_not_take(tmp_path: Path) -> None:
    """opendbc's vw_pq.dbc, Motor_2: signals under ``m0``, ``m1`` of a multiplexor written
    ``m`` (not ``M``), which cantools leaves out of every frame; the column-wise pass too."""
    dbc = tmp_path / "orphans.dbc"
    dbc.write_text(
        HEAD + "BO_ 256 Motor: 8 X\n"
        ' SG_ select m : 6|2@1+ (1,0) [0|3] "" X\n'
        ' SG_ code m0 : 0|6@1+ (1,0) [0|63] "" X\n'
        ' SG_ version m1 : 0|6@1+ (1,0) [0|63] "" X\n'
        ' SG_ temperature : 8|8@1+ (0.75,-48) [-48|143.25] "degC" X\n'
        "SG_MUL_VAL_ 256 code select 0-0;\nSG_MUL_VAL_ 256 version select 1-1;\n"
    )
    database: Any = cantools.database.load_file(str(dbc))
    assert database.decode_message(256, bytes.fromhex("0540000000000000")) == {
        "select": 0, "temperature": 0.0
    }  # fmt: skip
    path = write(
        tmp_path / "x.log", ["(1.0) can0 100#0540000000000000", "(1.1) can0 100#01FF000000000000"]
    )
    bus_map = BusMap()
    records = list(capture.read(path, bus_map, dbc=[dbc]))
    assert [(r.message.code, r.message.version, r.message.temperature) for r in records] == [
        (None, None, 0.0), (None, None, 143.25)
    ]  # fmt: skip
    tables = capture.read_tables(path, bus_map, dbc=[dbc])
    assert_same_tables(tables, capture.tables_from_records(iter(records)))
