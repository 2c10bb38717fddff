"""Every `Record` is built by a factory of `veronte4x.capture.records`: the same record the
named tuple's constructor builds, with its source readable, and built nowhere else."""

from __future__ import annotations

import inspect
import re
from pathlib import Path

import pytest

from veronte4x.capture.busmap import Role
from veronte4x.capture.records import (
    Record,
    error_record,
    factory,
    transfer_record,
    veronte_record,
)

SOURCE = Path(__file__).resolve().parents[2] / "src" / "veronte4x"


def test_the_factories_build_what_the_constructor_builds() -> None:
    assert veronte_record(1.5, "can0", 8, Role.AUTOPILOT, 1, "m", b"\1", False) == Record(
        1.5, "can0", 8, Role.AUTOPILOT, 1, None, "m", None, "", b"\1", None, False
    )
    assert transfer_record(2.0, "can1", 0x1234, 5, "m", b"\2", 7) == Record(
        2.0, "can1", 0x1234, Role.DRONECAN, None, 5, "m", None, "", b"\2", 7, True
    )
    made = error_record(None, "", 0, Role.UNKNOWN, None, None, "bad line", "line 1", b"", False)
    assert made == Record(None, "", 0, Role.UNKNOWN, None, None, None, "bad line", "line 1", b"")
    for record in (made, transfer_record(0.0, "", 0, 1, None, b"", None)):
        assert type(record) is Record and len(record) == len(Record._fields)


def test_a_factory_is_readable_generated_code() -> None:
    text = inspect.getsource(transfer_record)
    assert text.startswith("def transfer_record(timestamp, channel, can_id, node_id, message,")
    assert "_role" in text


def test_a_factory_refuses_what_it_cannot_fill() -> None:
    with pytest.raises(ValueError, match="not fields of Record: colour"):
        factory("f", ("timestamp", "channel", "can_id", "role", "colour"))
    with pytest.raises(ValueError, match="the Record field role has no default: give it"):
        factory("f", ("timestamp", "channel", "can_id"))


def test_records_are_built_by_the_factories_only() -> None:
    """A field added to `Record` (and its default) is then in every record the package
    builds: no module builds the tuple itself."""
    pattern = re.compile(r"\bRecord\(|new\(\s*Record\b|Record\._make")
    builders = [
        f"{path.relative_to(SOURCE)}:{number}"
        for path in SOURCE.rglob("*.py")
        if path.name != "records.py"
        for number, line in enumerate(path.read_text().splitlines(), 1)
        if pattern.search(line) and not line.lstrip().startswith(("class ", "#"))
    ]
    assert builders == []
