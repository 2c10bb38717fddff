"""Jupyter's HTML views (`_repr_html_`): well-formed, escaped, readable; repr unchanged."""

from __future__ import annotations

import dataclasses
import importlib
import xml.etree.ElementTree as ET
from collections import Counter
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from veronte4x import capture, codec, dronecan
from veronte4x.capture.stats import Stats
from veronte4x.client.nodes import NodeEntry, NodeTable
from veronte4x.display import HtmlDisplay, to_html

CAPTURE = Path(__file__).resolve().parent.parent / "examples" / "capture.log"


def _cells(html: str) -> list[list[str]]:
    """The rows of every table (header cells included), parsed as XML: the HTML must be
    well-formed and every text escaped."""
    root = ET.fromstring(f"<div>{html}</div>")
    return [["".join(cell.itertext()) for cell in row] for row in root.iter("tr")]


def _captions(html: str) -> list[str]:
    return ["".join(c.itertext()) for c in ET.fromstring(f"<div>{html}</div>").iter("caption")]


def test_a_decoded_veronte_message_shows_its_fields() -> None:
    status = codec.decode(bytes.fromhex("00ff8177ffff"), sender=codec.Sender.ARBITER)
    assert isinstance(status, HtmlDisplay)
    html = status._repr_html_()
    assert _captions(html) == ["Status"]
    rows = _cells(html)
    assert rows[0] == ["field", "value", "unit"]
    assert ["selected", "1 (AP2)", ""] in rows  # the index, its name beside it
    assert ["alive", "(True, True, True, False)", ""] in rows
    assert repr(status).startswith("Status(selected=1, arbitrating=True, alive=(True, True")


@pytest.mark.parametrize(("autopilot", "shown"), [(0, "0 (AP1)"), (3, "3 (external AP)")])
def test_an_autopilot_index_shows_its_name_in_a_message_and_in_a_record(
    autopilot: int, shown: str, tmp_path: Path
) -> None:
    score = codec.Score(autopilot=autopilot, score=0.5)
    assert ["autopilot", shown, ""] in _cells(score._repr_html_())
    log = tmp_path / "score.log"
    log.write_text(f"(1.0) can0 0FF#{codec.encode(score).hex()}\n", encoding="ascii")
    [record] = capture.read(log)
    assert ["autopilot", shown, ""] in _cells(record._repr_html_())
    assert ["CAN ID", "0FF"] in _cells(record._repr_html_())  # as candump prints it
    assert ["score", "0.5", ""] in _cells(score._repr_html_())  # a float has no name


def test_floats_in_shortest_form_and_repr_unchanged() -> None:
    message = codec.decode(bytes.fromhex("0000cdcccc3d"), sender=codec.Sender.AUTOPILOT)
    assert _cells(message._repr_html_())[1:] == [["number", "0", ""], ["value", "0.1", ""]]
    assert repr(message) == "ArbitrationVariable(number=0, value=0.10000000149011612)"


def test_slotted_frozen_messages_keep_their_layout() -> None:
    ready = codec.Ready(ready=True)
    assert not hasattr(ready, "__dict__")
    with pytest.raises(dataclasses.FrozenInstanceError):
        ready.ready = False  # type: ignore[misc]
    assert HtmlDisplay.__slots__ == ()


def test_dronecan_units_and_enum_names() -> None:
    status = dronecan.EscStatus(0, 16.203125, 2.5, 310.25, 1200, 40, 2)
    rows = _cells(to_html(status))
    assert ["voltage", "16.2", "V"] in rows
    assert ["temperature", "310.2", "K"] in rows
    node = dronecan.NodeStatus(7, dronecan.Health.WARNING, dronecan.Mode.OPERATIONAL, 0, 0)
    assert ["health", "WARNING", ""] in _cells(to_html(node))
    assert ["uptime_sec", "7", "s"] in _cells(to_html(node))


def test_text_is_escaped() -> None:
    response = dronecan.GetNodeInfoResponse(
        status=dronecan.NodeStatus(1, dronecan.Health.OK, dronecan.Mode.OPERATIONAL, 0, 0),
        software_version=dronecan.SoftwareVersion(1, 2, 0, 0, 0),
        hardware_version=dronecan.HardwareVersion(1, 0, bytes(16), b""),
        name=b"<script>alert(1)</script> & co",
    )
    html = to_html(response)
    assert "<script>" not in html
    assert ["name", "<script>alert(1)</script> & co", ""] in _cells(html)
    assert ["status.uptime_sec", "1", "s"] in _cells(html)


def test_records_of_every_kind() -> None:
    records = list(capture.read(CAPTURE))
    for record in records:
        assert _captions(record._repr_html_())[0] == f"Record: {record.kind}"
    decoded = next(r for r in records if r.kind == "Ready")
    html = decoded._repr_html_()
    assert _captions(html) == ["Record: Ready", "Ready"]
    assert ["time", "2025-11-21T15:00:00.010000Z"] in _cells(html)
    assert ["sender", "AP1"] in _cells(html)
    error = next(r for r in records if r.error is not None)
    assert ["error", "unknown command"] in _cells(error._repr_html_())


def test_stats_as_tables() -> None:
    stats = capture.stats(capture.read(CAPTURE))
    html = stats._repr_html_()
    assert _captions(html) == ["Stats", "by message type", "by sender", "errors by kind"]
    rows = _cells(html)
    assert ["records", str(stats.records)] in rows
    assert ["unknown command", "1"] in rows
    assert ["Ready", str(stats.by_type["Ready"])] in rows
    empty = Stats()
    assert _cells(empty._repr_html_()) == [["records", "0"], ["undecoded", "0"], ["errors", "0"]]
    assert Stats(errors=Counter({"bad line": 2})).report().startswith("records: 0")


def test_a_decoded_transfer() -> None:
    message = dronecan.NodeStatus(42, dronecan.Health.OK, dronecan.Mode.OPERATIONAL, 0, 0)
    frames = dronecan.encode(message, source_node_id=21, transfer_id=3)
    transfer = dronecan.decode_frames(frames, timestamp=1763737200.5)
    html = transfer._repr_html_()
    assert _captions(html) == ["Transfer: NodeStatus", "NodeStatus"]
    rows = _cells(html)
    assert ["from node", "21"] in rows
    assert ["transfer id", "3"] in rows
    assert ["kind", "message"] in rows
    assert ["mode", "OPERATIONAL", ""] in rows


def test_the_node_table() -> None:
    table = NodeTable()
    status = dronecan.NodeStatus(5, dronecan.Health.OK, dronecan.Mode.OPERATIONAL, 0, 0)
    table.observe_status(21, status, 1763737200.0)
    table.observe_status(22, status, 1763737201.0)
    rows = _cells(table._repr_html_())
    assert rows[0][:3] == ["node", "health", "mode"]
    assert [row[0] for row in rows[1:]] == ["21", "22"]
    assert rows[1][1:3] == ["OK", "OPERATIONAL"]
    assert rows[2][7] == "2025-11-21T15:00:01.000000Z"
    entry = table.get(21)
    assert entry is not None
    assert _captions(entry._repr_html_()) == ["node 21"]


def test_anything_else_is_its_escaped_repr() -> None:
    assert to_html("<b>") == "<pre>&#x27;&lt;b&gt;&#x27;</pre>"
    assert to_html(Stats) == "<pre>&lt;class &#x27;veronte4x.capture.stats.Stats&#x27;&gt;</pre>"
    record = next(iter(capture.read(CAPTURE)))
    assert to_html(record) == record._repr_html_()  # its own view


def _status() -> dronecan.NodeStatus:
    return dronecan.NodeStatus(5, dronecan.Health.OK, dronecan.Mode.OPERATIONAL, 0, 0)


def _transfer() -> dronecan.Transfer:
    frames = dronecan.encode(_status(), source_node_id=21, transfer_id=3)
    return dronecan.decode_frames(frames, timestamp=1763737200.5)


def _entry() -> NodeEntry:
    entry = NodeTable().observe_status(21, _status(), 1763737200.0)
    return entry


@pytest.mark.parametrize(
    ("make", "module", "view"),
    [
        (lambda: codec.Score(autopilot=1, score=0.5), "veronte4x.display", "message_html"),
        (_status, "veronte4x.display", "message_html"),
        (lambda: next(iter(capture.read(CAPTURE))), "veronte4x.capture.records", "record_html"),
        (Stats, "veronte4x.capture.stats", "stats_html"),
        (_transfer, "veronte4x.dronecan.view", "transfer_html"),
        (NodeTable, "veronte4x.client.nodes", "nodes_html"),
        (_entry, "veronte4x.client.nodes", "nodes_html"),
    ],
    ids=["veronte", "dronecan", "record", "stats", "transfer", "node table", "node entry"],
)
def test_each_class_shows_itself_through_the_view_of_its_package(
    make: Callable[[], Any], module: str, view: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    shown = make()
    monkeypatch.setattr(importlib.import_module(module), view, lambda *args: f"{view} called")
    assert shown._repr_html_() == f"{view} called"


def test_the_span_of_a_capture_and_the_destination_of_a_service(tmp_path: Path) -> None:
    """Mutation survivors: the span rows and the "to node" row dropped."""
    stats = capture.stats(capture.read(CAPTURE))
    rows = _cells(stats._repr_html_())
    assert ["from", "2025-11-21T15:00:00.000000Z"] in rows
    assert ["span", "0.501 s"] in rows
    assert "errors by kind:\n  unknown command" in stats.report()
    request = dronecan.GetNodeInfoRequest()
    frames = dronecan.encode(request, source_node_id=127, destination_node_id=21, transfer_id=1)
    lines = "".join(f"(1.0) can0 {f.can_id:08X}#{f.data.hex().upper()}\n" for f in frames)
    (tmp_path / "request.log").write_text(lines)
    (record,) = capture.read(tmp_path / "request.log")
    assert ["to node", "21"] in _cells(record._repr_html_())


def test_the_arbiter_state_shows_the_selected_autopilot_by_name() -> None:
    from veronte4x import arbiter

    model = arbiter.Arbiter(arbiter.ArbiterConfig())
    model.receive(9, bytes.fromhex("00ff01"), 0.0)  # AP2's Ready
    rows = _cells(model.state._repr_html_())
    assert ["selected", "0 (AP1)", ""] in rows
    assert _captions(model.state._repr_html_()) == ["ArbiterState"]


def test_a_dronecan_record_shows_its_29_bit_id_as_candump_does(tmp_path: Path) -> None:
    log = tmp_path / "node.log"
    log.write_text("(1.0) can0 00015514#00000000000000C0\n", encoding="ascii")
    [record] = capture.read(log)
    assert record.kind == "NodeStatus"
    assert ["CAN ID", "00015514"] in _cells(record._repr_html_())
