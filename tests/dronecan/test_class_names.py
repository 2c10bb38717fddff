"""The class name of every DroneCAN type: one class per type, never a standard type's name.

A vendor type climbs from its short name through its namespace components (the root last) to
its full name with ``_`` while its name is taken (`veronte4x.dronecan.generate`, documented in
docs/dronecan/types.md). These tests load adversarial roots beside the standard set (``esc``
and ``node`` holding a ``Status``, ``_``, ``uavcan`` itself) and two namespaces whose types
gave one class before (``ardupilot.gnss.Status`` and ``com.xacti.GnssStatus``, written here
with their public names and ids), and decode a transfer of each type through
`decode_frames`, the `Reassembler`, `capture.read`, `read_tables` and the CLI.
"""

from __future__ import annotations

import itertools
import json
import os
import pickle
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from tests.dsdl_support import write_namespace

import dronecan as dc
from veronte4x import capture
from veronte4x import dronecan as v4
from veronte4x.dronecan import DsdlError, TypeSet, standard
from veronte4x.dronecan.generate import plan, usable
from veronte4x.dronecan.parser import parse_text
from veronte4x.dronecan.vendor_roots import DSDL_ROOT

STANDARD = TypeSet.standard()
STANDARD_NAMES = set(standard.__all__)
PUBLIC_DSDL = Path(dc.__file__).parent / "dsdl_specs"
"""The public dronecan/DSDL namespaces the ``dronecan`` package ships (MIT)."""


def _gnss(parent: Path) -> tuple[Path, Path]:
    """``ardupilot/gnss/20003.Status`` and ``com/xacti/20305.GnssStatus`` (one field each)."""
    ardupilot = parent / "ardupilot"
    ardupilot.mkdir()
    write_namespace(ardupilot, "gnss", {"20003.Status": "uint32 error_codes\nbool healthy\n"})
    com = parent / "com"
    com.mkdir()
    write_namespace(com, "xacti", {"20305.GnssStatus": "uint16 gps_status\nint8 fix\n"})
    return ardupilot, com


def _frames(message: Any, types: TypeSet, transfer_id: int = 0) -> list[tuple[int, bytes]]:
    encoded = v4.encode(message, source_node_id=21, transfer_id=transfer_id, types=types)
    return [(f.can_id, f.data) for f in encoded]


def _candump(path: Path, frames: list[tuple[int, bytes]]) -> Path:
    path.write_text(
        "".join(
            f"({i / 1000:.6f}) can0 {can_id:08X}#{data.hex().upper()}\n"
            for i, (can_id, data) in enumerate(frames)
        )
    )
    return path


def _decoded_everywhere(messages: list[Any], types: TypeSet, tmp_path: Path) -> None:
    """Each message comes back as itself (its own class) from every decoding path."""
    frames = [_frames(m, types, i % 32) for i, m in enumerate(messages)]
    for message, own in zip(messages, frames, strict=True):
        assert v4.decode_frames(own, 0.0, types).message == message
        reassembler = v4.Reassembler(types=types)
        fed = [reassembler.feed(can_id, data, 0.0) for can_id, data in own]
        assert fed[-1] is not None and fed[-1].message == message
    path = _candump(tmp_path / "names.log", [f for own in frames for f in own])
    records = list(capture.read(path, types=types))
    assert [r.message for r in records] == messages
    assert [type(r.message) for r in records] == [type(m) for m in messages]
    tables = capture.read_tables(path, types=types)
    for message in messages:
        assert tables[type(message).__name__].num_rows == 1


def _run(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "veronte4x", *args],
        capture_output=True,
        text=True,
        check=False,
        env={**os.environ, "COLUMNS": "200"},
    )


# -- the standard set ----------------------------------------------------------------------


def test_every_standard_key_has_a_class_of_its_own() -> None:
    classes = list(STANDARD.classes.values())
    assert len({id(c) for c in classes}) == len(classes)
    assert len(set(STANDARD._names.values())) == len(classes)
    assert STANDARD["uavcan.equipment.esc.Status"].__name__ == "EscStatus"
    assert STANDARD["uavcan.protocol.NodeStatus"].__name__ == "NodeStatus"
    assert STANDARD["uavcan.equipment.actuator.Status"].__name__ == "ActuatorStatus"


# -- adversarial roots -----------------------------------------------------------------------


@pytest.mark.parametrize(
    ("root", "name"), [("esc", "esc_Status"), ("node", "node_Status"), ("camera", "CameraStatus")]
)
def test_a_vendor_status_beside_the_standard_ones(tmp_path: Path, root: str, name: str) -> None:
    """``esc.Status`` would be ``EscStatus``, the standard ESC status's name (it replaced it,
    and decoding failed with KeyError): every step of its ladder is taken but the last."""
    vendor = write_namespace(tmp_path, root, {"20100.Status": "uint8 a\nuint16 b\n"})
    types = STANDARD.with_dsdl(vendor)
    cls: Any = types[f"{root}.Status"]
    assert cls.__name__ == name
    assert cls is not STANDARD["uavcan.equipment.esc.Status"]
    assert types["uavcan.equipment.esc.Status"] is STANDARD["uavcan.equipment.esc.Status"]
    assert types["uavcan.protocol.NodeStatus"] is v4.NodeStatus
    messages = [
        cls(a=7, b=513),
        v4.EscStatus(error_count=3, voltage=24.0, rpm=1200, esc_index=2),
        v4.NodeStatus(uptime_sec=9, health=v4.Health.OK, mode=v4.Mode.OPERATIONAL),
    ]
    _decoded_everywhere(messages, types, tmp_path)


def test_a_root_named_uavcan_is_refused(tmp_path: Path) -> None:
    """The standard namespace is built in: a directory ``uavcan`` can neither replace nor
    extend it (a vendor ``uavcan.Foo`` would have loaded beside the standard types)."""
    root = write_namespace(tmp_path, "uavcan", {"20100.Extra": "uint8 a\n"})
    message = (
        f"{root}: uavcan is the standard root namespace, built into veronte4x: "
        "a vendor namespace needs a root of its own"
    )
    with pytest.raises(DsdlError) as error:
        STANDARD.with_dsdl(root)
    assert str(error.value) == message
    log = _candump(tmp_path / "x.log", _frames(v4.NodeStatus(), STANDARD))
    result = _run("decode", str(log), "--dsdl", str(root))
    assert (result.returncode, result.stderr) == (2, f"veronte4x: {message}\n")


def test_a_root_named_underscore_is_refused_in_one_line(tmp_path: Path) -> None:
    root = write_namespace(tmp_path, "_", {"20100.Status": "uint8 a\n"})
    with pytest.raises(DsdlError) as error:
        STANDARD.with_dsdl(root)
    assert str(error.value).startswith(f"{root}: ")
    assert "\n" not in str(error.value)


def test_names_that_are_no_usable_class_climb() -> None:
    """Below the loader's own checks: a namespace ``_`` adds nothing in CamelCase, a type
    ``None`` or ``ClassVar`` would break the generated module; each climbs its ladder."""
    definitions = {
        name: parse_text("uint8 a\n", name, 20100 + i, f"{name}.uavcan")
        for i, name in enumerate(
            ("_.Status", "_.x.Status", "acme.None", "acme.ClassVar", "acme.HtmlDisplay")
        )
    }
    everything = {**STANDARD.definitions, **definitions}
    names = plan(everything, STANDARD_NAMES, dict(STANDARD._names)).names
    assert {k: names[k] for k in definitions} == {
        "_.Status": "Status_2",
        "_.x.Status": "XStatus",
        "acme.None": "AcmeNone",
        "acme.ClassVar": "AcmeClassVar",
        "acme.HtmlDisplay": "AcmeHtmlDisplay",
    }


# -- two namespaces, one class -----------------------------------------------------------------


def test_ardupilot_gnss_status_and_xacti_gnss_status_loaded_together(tmp_path: Path) -> None:
    """Loaded in one call (as the CLI loads its ``--dsdl`` directories) both gave one class
    ``GnssStatus``; now both climb, in either order."""
    ardupilot, com = _gnss(tmp_path)
    for roots in ((ardupilot, com), (com, ardupilot)):
        types = STANDARD.with_dsdl(*roots)
        assert types["ardupilot.gnss.Status"].__name__ == "ArdupilotGnssStatus"
        assert types["com.xacti.GnssStatus"].__name__ == "XactiGnssStatus"
    gnss: Any = types["ardupilot.gnss.Status"]
    xacti: Any = types["com.xacti.GnssStatus"]
    _decoded_everywhere([gnss(error_codes=70000, healthy=True), xacti(1234, -3)], types, tmp_path)


def test_a_later_load_never_renames_a_loaded_class(tmp_path: Path) -> None:
    ardupilot, com = _gnss(tmp_path)
    first = STANDARD.with_dsdl(ardupilot).with_dsdl(com)
    assert first["ardupilot.gnss.Status"].__name__ == "GnssStatus"
    assert first["com.xacti.GnssStatus"].__name__ == "XactiGnssStatus"
    second = STANDARD.with_dsdl(com).with_dsdl(ardupilot)
    assert second["com.xacti.GnssStatus"].__name__ == "GnssStatus"
    assert second["ardupilot.gnss.Status"].__name__ == "ArdupilotGnssStatus"
    for types in (first, second):
        messages = [types["ardupilot.gnss.Status"](5, True), types["com.xacti.GnssStatus"](9, 1)]
        _decoded_everywhere(messages, types, tmp_path)


def test_a_pickled_set_keeps_its_class_names(tmp_path: Path) -> None:
    """A set goes to another process (Dask workers) by its directories, loaded there again
    call by call: loaded in one call, ardupilot's would be ``ArdupilotGnssStatus``."""
    ardupilot, com = _gnss(tmp_path)
    types = STANDARD.with_dsdl(ardupilot).with_dsdl(com)
    assert types.loads == ((ardupilot.resolve(),), (com.resolve(),))
    script = (
        "import pickle, sys\n"
        "types = pickle.loads(sys.stdin.buffer.read())\n"
        "print(types['ardupilot.gnss.Status'].__name__, types['com.xacti.GnssStatus'].__name__)"
    )
    result = subprocess.run(
        [sys.executable, "-c", script], input=pickle.dumps(types), capture_output=True, check=False
    )
    assert (result.returncode, result.stdout) == (0, b"GnssStatus XactiGnssStatus\n")


def test_cli_decodes_both_gnss_statuses(tmp_path: Path) -> None:
    ardupilot, com = _gnss(tmp_path)
    types = STANDARD.with_dsdl(ardupilot, com)
    frames = _frames(types["ardupilot.gnss.Status"](70000, True), types)
    frames += _frames(types["com.xacti.GnssStatus"](1234, -3), types, 1)
    log = _candump(tmp_path / "gnss.log", frames)
    dsdl = ("--dsdl", str(ardupilot), "--dsdl", str(com))
    result = _run("decode", str(log), "--output", "jsonl", *dsdl)
    assert result.returncode == 0
    *notes, summary = result.stderr.splitlines()
    assert notes == [  # the test's two types are not the shipped ones: they replace them
        f"veronte4x: note: {name}: {root.resolve() / path} replaces {DSDL_ROOT / root.name / path}"
        for name, root, path in (
            ("ardupilot.gnss.Status", ardupilot, "gnss/20003.Status.uavcan"),
            ("com.xacti.GnssStatus", com, "xacti/20305.GnssStatus.uavcan"),
        )
    ]
    assert summary.startswith("veronte4x: 2 records, 0 undecoded, 0 bad")
    rows = [json.loads(line) for line in result.stdout.splitlines()]
    assert [{k: r[k] for k in list(r)[4:]} for r in rows] == [
        {"message": "ArdupilotGnssStatus", "error_codes": 70000, "healthy": True},
        {"message": "XactiGnssStatus", "gps_status": 1234, "fix": -3},
    ]


# -- the public namespaces, and any tree -----------------------------------------------------


LOADABLE = ("ardupilot", "cuav", "dronecan", "mppt")
"""The public roots veronte4x loads today (``com`` needs ``OVERRIDE_SIGNATURE``)."""


def test_public_namespaces_together_in_any_order_one_class_each() -> None:
    expected: dict[str, str] | None = None
    for order in itertools.permutations(LOADABLE):
        types = STANDARD.with_dsdl(*(PUBLIC_DSDL / root for root in order))
        names = types._names  # a union's class is an alias of its members: no __name__
        assert len(set(names.values())) == len(names) == len(types.classes)
        vendor = {k: n for k, n in names.items() if not k.startswith("uavcan.")}
        assert not set(vendor.values()) & STANDARD_NAMES
        expected = expected or names
        assert names == expected
    assert expected is not None
    assert expected["ardupilot.gnss.Status"] == "GnssStatus"
    assert expected["ardupilot.indication.SafetyState"] == "SafetyState"


NAME_PARTS = st.sampled_from(["esc", "node", "gnss", "a", "ab", "b"])
TYPE_NAMES = st.sampled_from(["Status", "GnssStatus", "EscStatus", "NodeStatus", "B", "AB", "Ab"])


@settings(max_examples=40)
@given(
    st.lists(
        st.tuples(NAME_PARTS, st.lists(NAME_PARTS, max_size=2), TYPE_NAMES),
        min_size=1,
        max_size=8,
        unique_by=lambda t: (t[0], *t[1], t[2]),
    ),
    st.randoms(use_true_random=False),
)
def test_any_tree_gives_one_usable_class_per_type(
    types_: list[tuple[str, list[str], str]], random: Any
) -> None:
    """Roots, namespaces and type names drawn to collide with each other and with the standard
    names: every key gets a class of its own, a usable name no standard type has, the same
    whatever the order of the roots; every type decodes to its own class."""
    with tempfile.TemporaryDirectory() as tmp:
        base = Path(tmp)
        for i, (root, namespaces, name) in enumerate(types_):
            folder = base.joinpath(root, *namespaces)
            folder.mkdir(parents=True, exist_ok=True)
            (folder / f"{20100 + i}.{name}.uavcan").write_text(f"uint8 v{i}\n")
        roots = sorted({base / root for root, _, _ in types_})
        shuffled = random.sample(roots, len(roots))
        types = STANDARD.with_dsdl(*roots)
        other = STANDARD.with_dsdl(*shuffled)
        vendor = {k: c for k, c in types.classes.items() if not k.startswith("uavcan.")}
        names = [c.__name__ for c in vendor.values()]
        assert len(set(names)) == len(names) == len(types_)
        assert all(usable(n) for n in names)
        assert not set(names) & STANDARD_NAMES
        assert other._names == types._names
        for i, cls in enumerate(vendor.values()):
            message = cls(i)
            assert type(v4.decode_frames(_frames(message, types), 0.0, types).message) is cls
