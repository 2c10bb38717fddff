"""Class names of the public vendor roots loaded together and one after another, in
several orders: each type its own class, each class its own name, the same names for the
same loads (the naming rule of `veronte4x.dronecan.generate`)."""

from __future__ import annotations

import itertools
from collections import Counter
from pathlib import Path

import pytest

from veronte4x import capture, dronecan
from veronte4x.dronecan import TypeSet
from veronte4x.dronecan.vendor_roots import DSDL_ROOT, SHIPPED
from veronte4x.errors import DsdlError

ORDERS = [SHIPPED[i:] + SHIPPED[:i] for i in range(len(SHIPPED))] + [SHIPPED[::-1]]
"""Every root first once, and the reverse order (all 120 orders take seconds)."""


def _names(types: TypeSet) -> dict[str, str]:
    """The class name of each key (a union's key, whose value is the union of its member
    classes, by that union's text)."""
    return {
        key: cls.__name__ if isinstance(cls, type) else str(cls)
        for key, cls in types.classes.items()
    }


def _apart(types: TypeSet) -> None:
    """No two keys share a class, no two classes or enums share a name."""
    assert len({id(cls) for cls in types.classes.values()}) == len(types.classes)
    classes = [cls.__name__ for cls in types.classes.values() if isinstance(cls, type)]
    names = [*classes, *(e.__name__ for e in types._enums.values())]
    assert [n for n, count in Counter(names).items() if count > 1] == []


def _together(order: tuple[str, ...]) -> TypeSet:
    return TypeSet.standard().with_dsdl(*(DSDL_ROOT / root for root in order))


def _one_by_one(order: tuple[str, ...]) -> TypeSet:
    types = TypeSet.standard()
    for root in order:
        types = types.with_dsdl(DSDL_ROOT / root)
    return types


def test_together_the_names_do_not_depend_on_the_order() -> None:
    first = _together(SHIPPED)
    _apart(first)
    for order in ORDERS[1:]:
        assert _names(_together(order)) == _names(first), order
    assert _names(first)["ardupilot.gnss.Status"] == "ArdupilotGnssStatus"
    assert _names(first)["com.xacti.GnssStatus"] == "XactiGnssStatus"


@pytest.mark.parametrize("order", ORDERS, ids="-".join)
def test_one_by_one_apart_and_never_renamed(order: tuple[str, ...]) -> None:
    """A later load never renames a class loaded before."""
    before = TypeSet.standard()
    for root in order:
        after = before.with_dsdl(DSDL_ROOT / root)
        assert {k: v for k, v in _names(after).items() if k in before.classes} == _names(before)
        before = after
    _apart(before)


def test_one_by_one_the_same_names_each_time() -> None:
    """The names are those of the order of the loads, the same each time."""
    assert _names(_one_by_one(SHIPPED[::-1])) == _names(_one_by_one(SHIPPED[::-1]))


def test_the_two_gnss_statuses_decode_to_their_own_classes(tmp_path: Path) -> None:
    """The issue's case: ardupilot and com in one load gave both one class."""
    types = _together(("ardupilot", "com"))
    keys = ("ardupilot.gnss.Status", "com.xacti.GnssStatus")
    messages = [types[key]() for key in keys]
    log = tmp_path / "gnss.log"
    lines = []
    for node, message in enumerate(messages, 10):
        frames = dronecan.encode(message, source_node_id=node, transfer_id=0, types=types)
        for frame in frames:
            lines.append(f"(0.000000) can0 {frame.can_id:08X}#{frame.data.hex().upper()}\n")
        decoded = dronecan.decode_frames([(f.can_id, f.data) for f in frames], types=types)
        assert type(decoded.message) is types[keys[node - 10]]
    log.write_text("".join(lines))
    read = [type(r.message) for r in capture.read(log, types=types)]
    assert read == [types[key] for key in keys]


def _write(path: Path, text: str = "uint8 a\n") -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    return path


def test_a_clash_that_remains_is_an_error_naming_both_files(tmp_path: Path) -> None:
    """``a.b_c.T`` and ``a_b.c.T`` climb to the same top name ``a_b_c_T`` while ``z.BCT``
    and ``z.CT`` take the steps between."""
    first = _write(tmp_path / "a" / "b_c" / "20001.T.uavcan")
    second = _write(tmp_path / "a_b" / "c" / "20002.T.uavcan")
    _write(tmp_path / "z" / "20003.BCT.uavcan")
    _write(tmp_path / "z" / "20004.CT.uavcan")
    roots = [tmp_path / name for name in ("a", "a_b", "z")]
    for order in itertools.permutations(roots):
        with pytest.raises(DsdlError) as caught:
            TypeSet.standard().with_dsdl(*order)
        assert str(first) in str(caught.value) and str(second) in str(caught.value)
