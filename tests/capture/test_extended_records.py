"""A record carries its frame's IDE bit (`Record.extended`), not a guess from its ID or its
detail: an 11-bit and a 29-bit frame with the same numeric ID keep theirs through the
per-frame decoder (frames, text, bytes), a DBC, the tables, the record HTML, the monitor's
rows and decode's text."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from tests.capture.columnar_support import write
from veronte4x import capture
from veronte4x.capture import BusMap
from veronte4x.capture.decoder import CaptureDecoder
from veronte4x.capture.monitor import MonitorState
from veronte4x.capture.records import record_html

BUS_MAP = BusMap(dronecan=False)  # a 29-bit frame outside the bus map is foreign traffic
LINES = [
    "(1.000000) can0 07F#01",
    "(1.000001) can0 0000007F#02",
    "(1.000002) can0 07F#R",
    "(1.000003) can0 0000007F#R",
]
EXPECTED = [
    (0x7F, False, None, "11-bit CAN ID 0x7f"),
    (0x7F, True, None, "29-bit CAN ID 0x7f"),
    (0x7F, False, "remote frame", "remote frame"),
    (0x7F, True, "remote frame", "remote frame"),
]
DBC = """VERSION ""

NS_ :

BS_:

BU_: N

BO_ 127 Narrow: 1 N
 SG_ a : 0|8@1+ (1,0) [0|255] "" N

BO_ 2147483775 Wide: 1 N
 SG_ b : 0|8@1+ (1,0) [0|255] "" N
"""


def _seen(records: object) -> list[tuple[int, bool, str | None, str]]:
    return [(r.can_id, r.extended, r.error, r.detail) for r in records]  # type: ignore[attr-defined]


def test_the_per_frame_decoder_keeps_each_frames_bit(tmp_path: Path) -> None:
    path = write(tmp_path / "capture.log", LINES)
    text = "".join(line + "\n" for line in LINES).encode()
    assert _seen(capture.read(path, BUS_MAP)) == EXPECTED
    assert _seen(CaptureDecoder(BUS_MAP).decode_candump(LINES)) == EXPECTED
    assert _seen(CaptureDecoder(BUS_MAP).decode_chunks([text])) == EXPECTED


def test_veronte_and_dronecan_records_carry_their_bit(tmp_path: Path) -> None:
    lines = Path("examples/capture.log").read_text().splitlines()[:3]
    wide = [line.replace(" can0 ", " can0 00000") for line in lines]
    narrow = list(capture.read(write(tmp_path / "narrow.log", lines)))
    extended = list(capture.read(write(tmp_path / "wide.log", wide), BusMap(extended=True)))
    assert all(r.error is None and r.message is not None for r in [*narrow, *extended])
    assert [r.kind for r in extended] == [r.kind for r in narrow]
    assert [(r.extended, s.extended) for r, s in zip(narrow, extended, strict=True)] == [
        (False, True)
    ] * 3
    dronecan = list(capture.read(write(tmp_path / "node.log", ["(1.000000) can0 0000007F#02"])))
    assert [(r.detail, r.extended) for r in dronecan] == [("DroneCAN data type 0", True)]


def test_a_dbc_decodes_each_id_by_its_bit(tmp_path: Path) -> None:
    pytest.importorskip("cantools")
    dbc = tmp_path / "two.dbc"
    dbc.write_text(DBC)
    path = write(tmp_path / "capture.log", LINES[:2])
    records = list(capture.read(path, BUS_MAP, dbc=[dbc]))
    assert [(r.kind, r.can_id, r.extended) for r in records] == [
        ("Narrow", 0x7F, False),
        ("Wide", 0x7F, True),
    ]
    assert ["<td>07F</td>" in record_html(r) for r in records] == [True, False]
    assert ["<td>0000007F</td>" in record_html(r) for r in records] == [False, True]


def test_the_tables_tell_the_two_apart_as_the_records_do(tmp_path: Path) -> None:
    pytest.importorskip("pyarrow")
    path = write(tmp_path / "capture.log", LINES)
    tables = capture.read_tables(path, BUS_MAP)
    assert tables["unknown"].column("detail").to_pylist() == [EXPECTED[0][3], EXPECTED[1][3]]
    assert tables["errors"].column("can_id").to_pylist() == [0x7F, 0x7F]
    per_frame = capture.tables_from_records(capture.read(path, BUS_MAP))
    assert tables["unknown"].equals(per_frame["unknown"])


def test_the_monitor_rows_and_decode_text_show_each_frames_width(tmp_path: Path) -> None:
    path = write(tmp_path / "capture.log", LINES)
    state = MonitorState()
    for record in capture.read(path, BUS_MAP):
        state.add(record)
    assert [(r.kind, r.extended) for r in state.rows()] == [
        ("11-bit CAN ID 0x7f", False),
        ("29-bit CAN ID 0x7f", True),
    ]
    result = subprocess.run(
        [sys.executable, "-m", "veronte4x", "decode", str(path), "--on-error", "keep"],
        capture_output=True, text=True, check=True, timeout=600,
    )  # fmt: skip
    assert [line.split()[2] for line in result.stdout.splitlines()] == [
        "07F", "0000007F", "07F", "0000007F"
    ]  # fmt: skip
