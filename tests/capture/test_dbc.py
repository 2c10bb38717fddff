"""DBC out: cantools and asammdf decode captures through the DBC to veronte4x's values."""

from __future__ import annotations

import dataclasses
import math
import random
import runpy
import subprocess
import sys
from pathlib import Path
from typing import Any

import can
import cantools
import pytest
from asammdf import MDF
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.capture.columnar_support import BUS_MAPS, DECLARED, captures, write
from veronte4x import capture, codec
from veronte4x.capture import BusMap, Record, Role
from veronte4x.capture.dbc import export_dbc, write_dbc
from veronte4x.codec.declared import DeclaredMessage

ROOT = Path(__file__).resolve().parents[2]
NAMES = ("AP1", "AP2", "AP3", "external")
FLAGS = [name for name, _ in codec.layouts.STATUS_FLAGS]

BIG_DECLARED = codec.Layout(
    20,
    "BigEndianTelemetry",
    [
        codec.signed("altitude", 14, scale=codec.Linear(-8192, 8191, -819.2, 819.1)),
        codec.skip(2),
        codec.float32("airspeed"),
        codec.unsigned("mode", 3),
        codec.constant(5, 5),
    ],
    codec.ByteOrder.BIG,
)
"""A big-endian declared layout: Motorola signals, a float among them."""

ALL_KINDS = BusMap(
    pwm_packing=codec.PwmPacking.MSB_FIRST, layouts=(DECLARED, BIG_DECLARED), extended=True
)


@pytest.fixture(scope="module")
def flight(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """Twenty seconds of the example flight."""
    path = tmp_path_factory.mktemp("flight") / "flight.log"
    make = runpy.run_path(str(ROOT / "examples" / "make_capture.py"))
    make["generate"](1 / 3, 15.0, 4).write(path)
    return path


def expected(record: Record) -> dict[str, Any]:
    """The signals a DBC tool should give for a frame veronte4x decoded, written by hand."""
    message = record.message
    out: dict[str, Any] = {"command": record.data[0]}
    if isinstance(message, codec.Status):
        out["header"] = 0xFF
        out["selected"] = message.selected
        out["arbitrating"] = message.arbitrating
        for i, name in enumerate(NAMES):
            out[f"alive_{name}"] = message.alive[i]
            out[f"ready_{name}"] = message.ready[i]
        for flag in FLAGS:
            if getattr(message, flag) is not None:
                out[flag] = getattr(message, flag)
    elif isinstance(message, codec.Score):
        out["header"] = message.autopilot
        out[f"score_{NAMES[message.autopilot]}"] = message.score
    elif isinstance(message, codec.Ready):
        out["header"] = 0xFF
        out["ready"] = message.ready
    elif isinstance(message, codec.ArbitrationVariable):
        out["header"] = message.number
        out[f"variable_{message.number}"] = message.value
    elif isinstance(message, codec.VersionResponse):
        out["application_code"] = message.application_code
    elif isinstance(message, codec.PwmSet):
        for i, value in enumerate(message.values):
            out[f"pwm_{message.first_channel + i}"] = value
    elif isinstance(message, DeclaredMessage):
        declared: Any = message
        for f in dataclasses.fields(declared):
            out[f"{type(message).__name__}_{f.name}"] = getattr(message, f.name)
    return out


def same(got: Any, want: Any) -> bool:
    if isinstance(want, float) and math.isnan(want):
        return isinstance(got, float) and math.isnan(got)
    if isinstance(want, float) and not float(want).is_integer():
        return math.isclose(float(got), want, rel_tol=1e-12, abs_tol=1e-12)
    return bool(got == want)


def assert_same(got: dict[str, Any], want: dict[str, Any], where: object) -> None:
    assert sorted(got) == sorted(want), where
    for name, value in want.items():
        assert same(got[name], value), (where, name, got[name], value)


def veronte(records: list[Record]) -> list[Record]:
    return [
        r
        for r in records
        if r.role in (Role.ARBITER, Role.AUTOPILOT) and r.error is None and r.message is not None
    ]


def check_cantools(path: Path, bus_map: BusMap) -> int:
    database: Any = cantools.database.load_string(export_dbc(bus_map), "dbc")
    decoded = veronte(list(capture.read(path, bus_map)))
    for record in decoded:
        got = database.decode_message(
            record.can_id,
            record.data,
            decode_choices=False,
            allow_truncated=True,
            force_extended_id=bus_map.extended,
        )
        want = expected(record)
        # A frame longer than one form of its type and shorter than the next (a 5-byte
        # Status with allow_excess: the 4-byte CEX form and an excess byte) leaves the
        # longer form's fields None; cantools, decoding truncated frames, reads the bits of
        # the exported (longest) form that the frame holds. Only those may be extra.
        absent = {
            name for name in got if name not in want and getattr(record.message, name, 0) is None
        }
        assert_same({k: v for k, v in got.items() if k not in absent}, want, record)
    return len(decoded)


def test_golden_lines() -> None:
    lines = export_dbc(ALL_KINDS).splitlines()
    for line in [
        "BO_ 2147483903 Arbiter: 8 Arbiter",
        ' SG_ command M : 0|8@1+ (1,0) [0|255] "" Vector__XXX',
        ' SG_ header m0M : 8|8@1+ (1,0) [0|255] "" Vector__XXX',
        ' SG_ selected m255 : 16|7@1+ (1,0) [0|3] "" Vector__XXX',
        ' SG_ score_AP2 m1 : 16|32@1- (1,0) [0|0] "" Vector__XXX',
        # MSB first: channel 0 is byte 1 and the high nibble of byte 2 (Motorola MSB 15).
        ' SG_ pwm_0 m2 : 15|12@0+ (1,0) [0|4095] "" Vector__XXX',
        ' SG_ pwm_1 m2 : 19|12@0+ (1,0) [0|4095] "" Vector__XXX',
        ' SG_ ScorpionTelemetry_throttle m5 : 8|8@1+ (0.5,0) [0|127.5] "" Vector__XXX',
        ' SG_ BigEndianTelemetry_altitude m20 : 15|14@0- (0.1,0) [-819.2|819.1] "" Vector__XXX',
        ' SG_ variable_31 m31 : 16|32@1- (1,0) [0|0] "" Vector__XXX',
        "SIG_VALTYPE_ 2147483903 score_AP1 : 1;",
        "SG_MUL_VAL_ 2147483903 header command 0-0;",
        "SG_MUL_VAL_ 2147483656 ready header 255-255;",
        "SG_MUL_VAL_ 2147483656 pwm_19 command 13-13;",
        'VAL_ 2147483903 selected 0 "AP1" 1 "AP2" 2 "AP3" 3 "external AP" ;',
    ]:
        assert line in lines, line
    assert any(
        line.startswith('CM_ SG_ 2147483903 selected "selected AP') and "section 3.1.1" in line
        for line in lines
    )


def test_write_dbc_writes_the_text(tmp_path: Path) -> None:
    write_dbc(tmp_path / "veronte.dbc")
    assert (tmp_path / "veronte.dbc").read_text() == export_dbc()
    database: Any = cantools.database.load_file(str(tmp_path / "veronte.dbc"))
    assert database.get_message_by_name("AP1").frame_id == 8


def test_cantools_decodes_the_flight_as_veronte4x(flight: Path) -> None:
    assert check_cantools(flight, BusMap()) > 2000


@settings(
    max_examples=60,
    suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow],
)
@given(st.data())
def test_cantools_decodes_generated_captures_as_veronte4x(
    tmp_path: Path, data: st.DataObject
) -> None:
    bus_map = data.draw(st.one_of(BUS_MAPS, st.just(ALL_KINDS)))
    path = write(tmp_path / "generated.log", data.draw(captures(bus_map)))
    check_cantools(path, bus_map)


def random_frames(bus_map: BusMap, seed: int, count: int) -> list[tuple[int, bytes]]:
    """Frames of every layout kind of a bus map, NaN and short forms included."""
    rng = random.Random(seed)
    encoder = bus_map.codec()

    def f32() -> float:
        return rng.choice([math.nan, math.inf, -0.0, rng.uniform(-1e6, 1e6), 0.5])

    def arbiter() -> codec.Message:
        if rng.random() < 0.5:
            flags = [rng.random() < 0.5 for _ in FLAGS] if rng.random() < 0.7 else [None] * 16
            return codec.Status(
                rng.randrange(4),
                rng.random() < 0.5,
                tuple(rng.random() < 0.5 for _ in range(4)),  # type: ignore[arg-type]
                tuple(rng.random() < 0.5 for _ in range(4)),  # type: ignore[arg-type]
                *flags,
            )
        return codec.Score(rng.randrange(4), f32())

    def autopilot() -> codec.Message:
        if rng.random() < 0.3:
            return codec.Ready(rng.random() < 0.5)
        return codec.ArbitrationVariable(rng.randrange(32), f32())

    def either() -> codec.Message:
        kind = rng.randrange(5)
        if kind == 0:
            values = tuple(rng.randrange(4096) for _ in range(4))
            return codec.PwmSet(rng.choice([0, 4, 8, 12, 16]), values)  # type: ignore[arg-type]
        if kind == 1:
            return rng.choice([codec.VersionRequest(), codec.VersionResponse(9, b"\x01\x02")])
        if kind == 2 and DECLARED in bus_map.layouts:
            made: codec.Message = DECLARED.message_class(
                rng.randrange(201) * 0.5, rng.randrange(-128, 128), f32()
            )
            return made
        if kind == 3 and BIG_DECLARED in bus_map.layouts:
            cls = BIG_DECLARED.message_class
            big: codec.Message = cls(rng.randrange(-8192, 8192) / 10, f32(), rng.randrange(8))
            return big
        return codec.McuCommand(bytes(rng.randrange(256) for _ in range(rng.randrange(8))))

    frames = []
    for _ in range(count):
        index = rng.randrange(5)
        message = (arbiter if index == 0 else autopilot)() if rng.random() < 0.6 else either()
        can_id = (bus_map.arbiter_id, *bus_map.autopilot_ids)[index]
        frames.append((can_id, encoder.encode(message)))
    return frames


ASAMMDF_UNSIGNED = {"ScorpionTelemetry_current"}
"""Signals asammdf decodes differently (the docs' "where tools differ")."""


def check_asammdf(frames: list[tuple[int, bytes]], bus_map: BusMap, tmp_path: Path) -> None:
    """Write the frames 1 ms apart into an MF4, decode it with asammdf through the DBC, and
    compare every frame's signals with veronte4x's (asammdf reads a short frame's missing
    bytes as zeros: those signals must be 0, the others equal)."""
    log = tmp_path / "frames.log"
    mf4 = tmp_path / "frames.mf4"
    dbc = tmp_path / "veronte.dbc"
    flag = "08X" if bus_map.extended else "03X"
    write(log, [f"({i / 1000:.6f}) can0 {c:{flag}}#{d.hex()}" for i, (c, d) in enumerate(frames)])
    with can.Logger(str(mf4)) as logger:
        for message in can.CanutilsLogReader(str(log)):
            logger.on_message_received(message)
    write_dbc(dbc, bus_map)
    database: Any = cantools.database.load_file(str(dbc))
    names = {m.name: m for m in database.messages}
    out: Any = MDF(str(mf4)).extract_bus_logging({"CAN": [(str(dbc), 0)]})
    by_frame: dict[tuple[int, int], dict[str, Any]] = {}
    start = math.inf
    samples = []
    for index, group in enumerate(out.groups):
        for channel in group.channels[1:]:
            names_in = out.get(channel.name, group=index, raw=True).display_names
            found = names[next(n for n in names_in if n.count(".") == 1).split(".")[0]]
            # A value table's names are not compared: take its numbers, and scale the rest.
            raw = bool(found.get_signal_by_name(channel.name).choices)
            signal = out.get(channel.name, group=index, raw=raw)
            samples.append((found.frame_id, channel.name, signal))
            start = min(start, *signal.timestamps)
    for message, name, signal in samples:
        for time, value in zip(signal.timestamps, signal.samples.tolist(), strict=True):
            frame = round((time - start) * 1000)
            by_frame.setdefault((message, frame), {})[name] = value
    records = list(capture.read(log, bus_map))
    assert len(veronte(records)) == len(frames)
    for frame, record in enumerate(records):
        got = by_frame[(record.can_id, frame)]
        want = expected(record)
        truncated = database.decode_message(
            record.can_id,
            record.data,
            decode_choices=False,
            allow_truncated=True,
            force_extended_id=bus_map.extended,
        )
        assert_same(truncated, want, record)
        padded = {k: v for k, v in got.items() if k not in want}
        # Signals of other multiplexor values come out as NaN; those past the frame as 0.
        assert all((isinstance(v, float) and math.isnan(v)) or v == 0 for v in padded.values()), (
            record,
            padded,
        )
        for name in ASAMMDF_UNSIGNED.intersection(want):
            # asammdf 8 reads this signed 8-bit signal, which straddles two bytes, unsigned.
            want[name] %= 256
        assert_same({k: got[k] for k in want}, want, record)


def test_asammdf_decodes_the_flight_as_veronte4x(flight: Path, tmp_path: Path) -> None:
    records = veronte(list(capture.read(flight)))[:1500]
    check_asammdf([(r.can_id, r.data) for r in records], BusMap(), tmp_path)


@pytest.mark.parametrize(
    "bus_map",
    [BusMap(), ALL_KINDS, BusMap(layouts=(DECLARED,), arbiter_id=0x100)],
    ids=["default", "msb-first-declared-extended", "lsb-first-declared"],
)
def test_asammdf_decodes_every_layout_kind_as_veronte4x(bus_map: BusMap, tmp_path: Path) -> None:
    check_asammdf(random_frames(bus_map, 7, 600), bus_map, tmp_path)


def test_cli_writes_the_bus_maps_dbc(tmp_path: Path) -> None:
    bus_map = tmp_path / "bus.toml"
    bus_map.write_text('[veronte]\narbiter_id = 256\npwm_packing = "msb_first"\n')
    out = tmp_path / "veronte.dbc"
    done = subprocess.run(
        [
            sys.executable,
            "-m",
            "veronte4x",
            "export",
            "dbc",
            "--bus-map",
            str(bus_map),
            "-o",
            str(out),
        ],
        capture_output=True,
        text=True,
        check=False,
    )
    assert (done.returncode, done.stderr, done.stdout) == (0, "", "")
    assert out.read_text() == export_dbc(BusMap.from_toml(bus_map))
    shown = subprocess.run(
        [sys.executable, "-m", "veronte4x", "export", "dbc"],
        capture_output=True,
        text=True,
        check=True,
    )
    assert shown.stdout == export_dbc()


def test_cli_names_a_bad_bus_map(tmp_path: Path) -> None:
    bus_map = tmp_path / "bus.toml"
    bus_map.write_text("[veronte]\narbiter = 256\n")
    done = subprocess.run(
        [sys.executable, "-m", "veronte4x", "export", "dbc", "--bus-map", str(bus_map)],
        capture_output=True,
        text=True,
        check=False,
    )
    assert (done.returncode, done.stdout) == (2, "")
    assert done.stderr == "veronte4x: unknown key(s) in [veronte]: arbiter\n"
