"""`veronte4x.dronecan.messages` only re-exports generated classes; every generated class
shows itself in Jupyter (`veronte4x.display.HtmlDisplay`)."""

from __future__ import annotations

import ast
import dataclasses
import enum
import inspect
from pathlib import Path

import pytest

from veronte4x import dronecan
from veronte4x.display import HtmlDisplay
from veronte4x.dronecan import messages, standard


def test_messages_defines_no_class_of_its_own() -> None:
    tree = ast.parse(Path(messages.__file__).read_text(encoding="utf-8"))
    assert not [node for node in ast.walk(tree) if isinstance(node, ast.ClassDef)]
    for name in messages.__all__:
        if name not in ("Message", "HandNamedMessage"):  # the union of the classes
            assert getattr(messages, name) is getattr(standard, name), name


def test_names_fields_and_enums_of_before() -> None:
    status = dronecan.NodeStatus(7, dronecan.Health.OK, dronecan.Mode.OPERATIONAL, 0, 0)
    assert [f.name for f in dataclasses.fields(status)] == [
        "uptime_sec", "health", "mode", "sub_mode", "vendor_specific_status_code",
    ]  # fmt: skip
    assert [m.name for m in dronecan.Mode] == [
        "OPERATIONAL", "INITIALIZATION", "MAINTENANCE", "SOFTWARE_UPDATE", "OFFLINE",
    ]  # fmt: skip
    assert [(m.name, m.value) for m in dronecan.FileError][:3] == [
        ("OK", 0), ("UNKNOWN_ERROR", 32767), ("NOT_FOUND", 2),
    ]  # fmt: skip
    assert issubclass(dronecan.TemperatureErrorFlag, enum.IntFlag)
    assert dronecan.EntryTypeFlag.READABLE.value == 8
    assert dronecan.SoftwareVersionFlag.IMAGE_CRC.value == 2
    assert dronecan.FileReadResponse.MAX_DATA == 256
    assert ord("/") == dronecan.Path.SEPARATOR
    assert dronecan.RestartNodeRequest.MAGIC_NUMBER == 0xACCE551B1E
    assert dronecan.FileErrorCode().value == 0  # file.Error's value stays an int
    # Value and NumericValue share their member classes.
    assert dronecan.IntegerValue in dronecan.NumericValue.__args__
    assert dronecan.IntegerValue in dronecan.Value.__args__
    assert inspect.signature(dronecan.NodeStatus).parameters["health"].default is (
        dronecan.Health.OK
    )


_MEMBERS = [member for members in standard.UNION_MEMBERS.values() for member in members]
CLASSES = list(
    dict.fromkeys(c for c in [*standard.CLASSES.values(), *_MEMBERS] if isinstance(c, type))
)


@pytest.mark.parametrize("cls", CLASSES, ids=lambda c: c.__name__)
def test_every_generated_class_has_an_html_view(cls: type) -> None:
    assert issubclass(cls, HtmlDisplay)
    html = cls()._repr_html_()
    assert html.startswith('<table class="dataframe veronte4x">')
    assert f">{cls.__name__}</caption>" in html


def test_html_view_has_units_and_enum_names() -> None:
    status = dronecan.EscStatus(0, 12.5, 1.25, 300.0, 1200, 50, 3)
    html = status._repr_html_()
    assert "<td>voltage</td><td>12.5</td><td>V</td>" in html
    node = dronecan.NodeStatus(7, dronecan.Health.WARNING, dronecan.Mode.MAINTENANCE, 0, 0)
    assert "<td>health</td><td>WARNING</td>" in node._repr_html_()
    assert repr(node) == (
        "NodeStatus(uptime_sec=7, health=<Health.WARNING: 1>, mode=<Mode.MAINTENANCE: 2>, "
        "sub_mode=0, vendor_specific_status_code=0)"
    )


STANDARD = dronecan.TypeSet.standard()


@pytest.mark.parametrize("cls", sorted(STANDARD.by_class, key=str), ids=lambda c: c.__name__)
def test_every_class_built_with_its_defaults_encodes_and_decodes_back(cls: type) -> None:
    """A class's defaults are a valid value (a static ``uint8[16]`` defaults to 16 zero
    bytes, not to b"", which no encoder takes)."""
    message = cls()
    kind = STANDARD.by_class[cls].data_type.kind
    destination = None if kind is dronecan.TransferKind.MESSAGE else 9
    frames = dronecan.encode(
        message, source_node_id=5, transfer_id=0, destination_node_id=destination
    )
    assert dronecan.decode_frames([(f.can_id, f.data) for f in frames]).message == message


def test_the_constants_of_the_public_dsdl_that_the_dronecan_package_lacks() -> None:
    """dronecan/DSDL b4653c7 added BatteryInfo's STATE_OF_CHARGE_UNKNOWN; the ``dronecan``
    package 1.0.27 has only STATE_OF_HEALTH_UNKNOWN."""
    assert standard.BatteryInfo.STATE_OF_CHARGE_UNKNOWN == 127
    assert standard.BatteryInfo.STATE_OF_HEALTH_UNKNOWN == 127
