"""DBC names that cannot collide: any signal, message or value-table name a DBC can hold
(through cantools' long-name attributes, any text) decodes, in `read` and `read_tables`,
to cantools' values, under a name made by the documented rule, the DBC name kept in the
class and in the table's metadata; no name reaches generated code as source."""

from __future__ import annotations

import keyword
import os
import tempfile
from pathlib import Path
from typing import Any

import cantools
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from tests.capture.columnar_support import assert_same_tables, write
from tests.capture.dbc_reference import cantools_fields
from veronte4x import capture
from veronte4x.capture import BusMap
from veronte4x.capture.busmap import RECORD_COLUMNS, reserved_names
from veronte4x.capture.dbc_in import DbcDecoder, DbcMessage, class_name, field_names, identifier

BUS_MAP = BusMap(dronecan=False)
MARKER = "DBC_NAME_MARKER"
ODD = [
    "UNITS", "RANGES", "SIGNALS", "CHOICES", "DBC_NAME", "__init__", "__slots__", "__class__",
    "__dict__", "__x", "_", "__", "timestamp", "timestamp_", "Timestamp", "CAN_ID", "class",
    "None", "True", "match", "self", "object", "speed", "Speed", "SPEED", "speed_name",
    "speed_2", "x²", "ﬁ", "Äpfel", "e\u0301", "1st", "", " ", "Status", "errors", "STATUS",
    f'x"); open("{MARKER}", "w"); ("', f"a\nimport os\nos.system('touch {MARKER}')\n",
    "__import__('os')", "'''", "\\N{BULLET}", "\\", "a.b", "made", "_cls", "get", "v",
]  # fmt: skip
NAMES = st.one_of(
    st.sampled_from(ODD), st.text(st.characters(codec="cp1252", exclude_characters='"'), max_size=8)
)


def long_names_dbc(messages: list[tuple[str, list[tuple[str, list[str]]]]]) -> str:
    """A DBC whose messages and signals take their names from cantools' long-name
    attributes (any text); each signal 8 bits, its value table naming 0, 1, 2, ..."""
    lines = ['VERSION ""', "", "NS_ :", "", "BS_:", "", "BU_: X", ""]
    extra = [
        'BA_DEF_ BO_ "SystemMessageLongSymbol" STRING ;',
        'BA_DEF_ SG_ "SystemSignalLongSymbol" STRING ;',
    ]
    for number, (message, signals) in enumerate(messages):
        ident = 0x400 + number
        lines.append(f"BO_ {ident} M{number}: {max(1, len(signals))} X")
        extra.append(f'BA_ "SystemMessageLongSymbol" BO_ {ident} "{message}";')
        for index, (signal, choices) in enumerate(signals):
            lines.append(f' SG_ s{index} : {8 * index}|8@1+ (1,0) [0|255] "" X')
            extra.append(f'BA_ "SystemSignalLongSymbol" SG_ {ident} s{index} "{signal}";')
            if choices:
                named = " ".join(f'{value} "{text}"' for value, text in enumerate(choices))
                extra.append(f"VAL_ {ident} s{index} {named} ;")
        lines.append("")
    return "\n".join([*lines, *extra, ""])


def check_names(cls: type[Any]) -> None:
    """The class's field names follow the rule's guarantees."""
    names = [f for f in cls.__dataclass_fields__]
    assert len({n.casefold() for n in names}) == len(names)
    for name in names:
        assert name.isidentifier() and not keyword.iskeyword(name), name
        assert not name.startswith("__") and name not in vars(DbcMessage), name
        assert name.casefold() not in {c.casefold() for c in RECORD_COLUMNS}, name
    assert cls.__name__.isidentifier() and not keyword.iskeyword(cls.__name__)
    assert cls.__name__.casefold() not in {r.casefold() for r in reserved_names()}


messages = st.lists(
    st.tuples(
        NAMES,
        st.lists(
            st.tuples(NAMES, st.one_of(st.just([]), st.lists(NAMES, min_size=1, max_size=3))),
            min_size=1,
            max_size=6,
        ),
    ),
    min_size=1,
    max_size=3,
)


@settings(max_examples=150, suppress_health_check=[HealthCheck.too_slow])
@given(messages, st.lists(st.binary(min_size=6, max_size=6), min_size=1, max_size=4))
def test_any_name_decodes_as_cantools_decodes(
    listed: list[tuple[str, list[tuple[str, list[str]]]]], payloads: list[bytes]
) -> None:
    text = long_names_dbc(listed)
    with tempfile.TemporaryDirectory() as folder:
        here = Path(folder)
        dbc = here / "names.dbc"
        dbc.write_bytes(text.encode("cp1252", "replace"))  # as cantools reads a file
        try:
            database: Any = cantools.database.load_file(str(dbc))
        except Exception:
            assume(False)  # not a DBC cantools reads: not this test's concern
        lines = []
        frames = []
        for number, message in enumerate(database.messages):
            for index, payload in enumerate(payloads):
                data = payload[: message.length]
                frames.append((message, data))
                lines.append(
                    f"({number + index / 10:.6f}) can0 {message.frame_id:03X}#{data.hex()}"
                )
        path = write(here / "x.log", lines)
        cwd = os.getcwd()
        os.chdir(folder)  # a marker would land here
        try:
            records = list(capture.read(path, BUS_MAP, dbc=[dbc]))
            tables = capture.read_tables(path, BUS_MAP, dbc=[dbc])
        finally:
            os.chdir(cwd)
        assert not (here / MARKER).exists()
    assert len(records) == len(frames)
    rows: dict[str, list[dict[str, Any]]] = {}
    for record, (message, data) in zip(records, frames, strict=True):
        cls = type(record.message)
        assert record.error is None and message.name == cls.DBC_NAME
        check_names(cls)
        expected = cantools_fields(message, data)  # by DBC signal name, "<name>_name"
        got = {}
        for field, signal in zip(cls.__dataclass_fields__, cls.SIGNALS, strict=True):
            key = f"{signal}_name" if field in cls.CHOICES.values() else signal
            got[key] = getattr(record.message, field)
        assert got == expected
        rows.setdefault(cls.__name__, []).append(
            {f: getattr(record.message, f) for f in cls.__dataclass_fields__}
        )
    for kind, expected_rows in rows.items():
        table = tables[kind]
        assert [{k: r[k] for k in expected_rows[0]} for r in table.to_pylist()] == expected_rows
        assert (
            table.schema.metadata[b"dbc_message"].decode()
            == type(next(r.message for r in records if type(r.message).__name__ == kind)).DBC_NAME
        )
    assert_same_tables(tables, capture.tables_from_records(iter(records)))


def test_the_names_of_the_issue() -> None:
    """The names that crashed: class attributes, dunders, record columns with their
    trailing-underscore twins, keywords, case-only twins, non-ASCII."""
    signals = ["UNITS", "RANGES", "SIGNALS", "CHOICES", "__SIGNAL_every_interval", "__init__",
               "timestamp", "timestamp_", "class", "None", "Speed", "speed", "gear", "gear_name",
               "Äpfel", "x²", "ﬁ", "1st", ""]  # fmt: skip
    numbers, names = field_names(signals, [s == "gear" for s in signals])
    assert numbers == [
        "UNITS_", "RANGES_", "SIGNALS_", "CHOICES_", "dbc__SIGNAL_every_interval",
        "dbc__init__", "timestamp_", "timestamp__2", "class_", "None_", "Speed", "speed_2",
        "gear", "gear_name", "Äpfel", "x_", "_", "_1st", "dbc__2",
    ]  # fmt: skip
    assert names == ["gear_name_2"]
    taken: set[str] = set()
    assert [class_name(n, taken) for n in ["Status", "status", "errors", "BMS", "bms", "a b"]] == [
        "Status_", "status__2", "errors_", "BMS", "bms_2", "a_b",
    ]  # fmt: skip
    assert identifier("e\u0301") == "e_"  # characters that compose under NFKC: ASCII only
    assert identifier("Ä ö") == "Ä_ö"


OPENDBC_NAMES = Path(__file__).with_name("data") / "opendbc_names.dbc"


def test_the_opendbc_messages_with_such_names(tmp_path: Path) -> None:
    """Messages of opendbc (toyota_prius_2010_pt: ``UNITS``; luxgen_s5_2015:
    ``__SIGNAL_every_interval``) that crashed `read`, `read_tables` and ``decode``."""
    database: Any = cantools.database.load_file(str(OPENDBC_NAMES))
    lines, frames = [], []
    for number, message in enumerate(database.messages):
        data = bytes(range(0x31, 0x31 + message.length))
        frames.append((message, data))
        lines.append(f"({number}.0) can0 {message.frame_id:03X}#{data.hex()}")
    path = write(tmp_path / "x.log", lines)
    records = list(capture.read(path, BUS_MAP, dbc=[OPENDBC_NAMES]))
    for record, (message, data) in zip(records, frames, strict=True):
        cls = type(record.message)
        expected = cantools_fields(message, data)
        got = {}
        for field, signal in zip(cls.__dataclass_fields__, cls.SIGNALS, strict=True):
            key = f"{signal}_name" if field in cls.CHOICES.values() else signal
            got[key] = getattr(record.message, field)
        assert got == expected
    tables = capture.read_tables(path, BUS_MAP, dbc=[OPENDBC_NAMES])
    assert_same_tables(tables, capture.tables_from_records(iter(records)))
    units = tables["UI_SEETING"].schema.field("UNITS_")
    assert units.metadata == {b"dbc_signal": b"UNITS"}
    luxgen = tables["dbc__trigger_every_range"].schema.field("dbc__SIGNAL_every_interval")
    assert luxgen.metadata == {b"dbc_signal": b"__SIGNAL_every_interval"}
    done = capture_cli("decode", str(path), "--dbc", str(OPENDBC_NAMES))
    assert done.returncode == 0, done.stderr
    assert "UNITS_=" in done.stdout and "dbc__SIGNAL_every_interval=" in done.stdout


def capture_cli(*args: str) -> Any:
    import subprocess
    import sys

    return subprocess.run(
        [sys.executable, "-m", "veronte4x", *args], capture_output=True, text=True, check=False
    )


def test_a_name_field_is_never_interpolated(tmp_path: Path) -> None:
    """Every text of a DBC reaches generated code as a literal or a checked identifier:
    a choice or signal name that is Python code runs nothing."""
    text = long_names_dbc(
        [(f"x'); open('{MARKER}', 'w'); ('", [(f"y\n__import__('os').system('touch {MARKER}')",
                                                [f"'); open('{MARKER}','w') #"])])]
    )  # fmt: skip
    dbc = tmp_path / "evil.dbc"
    dbc.write_bytes(text.encode("cp1252"))
    cwd = os.getcwd()
    os.chdir(tmp_path)
    try:
        decoder = DbcDecoder([dbc])
        message = decoder.decode(0x400, False, b"\x00")
    finally:
        os.chdir(cwd)
    assert not (tmp_path / MARKER).exists()
    assert message.SIGNALS[0].startswith("y\n__import__")
    assert list(message.__dataclass_fields__) == [
        "y___import____os___system__touch_DBC_NAME_MARKER__",
        "y___import____os___system__touch_DBC_NAME_MARKER___name",
    ]
    assert message.y___import____os___system__touch_DBC_NAME_MARKER___name == (
        f"'); open('{MARKER}','w') #"
    )


@pytest.mark.parametrize("count", [40_000])
def test_a_value_table_of_more_than_32768_names(tmp_path: Path, count: int) -> None:
    """A 16-bit signal whose table names 40,000 values, every one on the bus: the name
    column's dictionary holds them all (int32 indexes), as the numbers."""
    named = " ".join(f'{value} "v{value}"' for value in range(count))
    dbc = tmp_path / "wide.dbc"
    dbc.write_text(
        'VERSION ""\nNS_ :\nBS_:\nBU_: X\nBO_ 256 Axle: 2 X\n'
        ' SG_ speed : 0|16@1+ (1,0) [0|65535] "" X\n'
        f"VAL_ 256 speed {named} ;\n"
    )
    values = list(range(count + 100))  # and 100 values the table does not name
    path = write(
        tmp_path / "x.log", [f"(1.0) can0 100#{v.to_bytes(2, 'little').hex()}" for v in values]
    )
    tables = capture.read_tables(path, BUS_MAP, dbc=[dbc])
    axle = tables["Axle"]
    assert axle.column("speed").to_pylist() == values
    assert axle.column("speed_name").to_pylist() == [f"v{v}" if v < count else None for v in values]
    assert str(axle.schema.field("speed_name").type) == (
        "dictionary<values=string, indices=int32, ordered=0>"
    )
