"""The roots of the default type set (`veronte4x.dronecan.vendor_roots`): the shipped vendor
roots, the home directories the ``dronecan`` package and the DroneCAN GUI tool read, the
environment variable, in that order, and later roots overriding earlier ones type by type."""

from __future__ import annotations

import dataclasses
import os
import shutil
import warnings
from pathlib import Path

import pytest

from veronte4x.dronecan import TypeSet
from veronte4x.dronecan.parser import definition_files, parse_namespaces
from veronte4x.dronecan.typeset import DsdlOverrideWarning, default_set
from veronte4x.dronecan.vendor_roots import (
    DSDL_ROOT,
    ENVIRONMENT_VARIABLE,
    SHIPPED,
    Override,
    Roots,
    find_roots,
    overrides,
    shipped_roots,
    user_roots,
)
from veronte4x.errors import DsdlError

STATUS = "com/hobbywing/esc/20050.StatusMsg1.uavcan"
"""A shipped definition a user's root replaces below."""


def _write(path: Path, text: str = "uint8 a\n") -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    return path


def test_the_shipped_roots_alone(tmp_path: Path) -> None:
    assert find_roots({}, tmp_path) == Roots(shipped_roots(), ())
    assert overrides(definition_files(shipped_roots())) == ()  # find_roots counts on it
    assert [p.name for p in shipped_roots()] == list(SHIPPED)
    assert all((DSDL_ROOT / name).is_dir() for name in SHIPPED)
    assert sorted(p.name for p in DSDL_ROOT.iterdir() if p.is_dir()) == sorted(
        (*SHIPPED, "uavcan")
    )  # every root of dronecan/DSDL is shipped


def test_user_roots_in_order_hidden_and_empty_entries_left_out(tmp_path: Path) -> None:
    home = tmp_path / "home"
    for name in ("zeta", "acme", ".git"):
        (home / "dronecan_vendor_specific_types" / name).mkdir(parents=True)
    (home / "dronecan_vendor_specific_types" / "notes.txt").write_text("not a root")
    (home / "uavcan_vendor_specific_types" / "old").mkdir(parents=True)
    one, two = tmp_path / "env" / "one", tmp_path / "env" / "two"
    one.mkdir(parents=True)
    two.mkdir()
    gui = home / "dronecan_vendor_specific_types"
    variable = os.pathsep.join([str(one), "", str(two), str(gui / "acme")])
    found = find_roots({ENVIRONMENT_VARIABLE: variable}, home)
    assert found.roots == (
        *shipped_roots(),
        home / "uavcan_vendor_specific_types" / "old",
        gui / "acme",
        gui / "zeta",
        one,
        two,
    )  # acme again in the variable counts once, where it first comes
    assert user_roots(None) == ()
    assert user_roots(f"{one}{os.pathsep}") == (one,)


def test_a_root_that_is_no_directory_is_named(tmp_path: Path) -> None:
    with pytest.raises(DsdlError) as caught:
        find_roots({ENVIRONMENT_VARIABLE: str(tmp_path / "missing")}, tmp_path)
    assert str(caught.value) == f"{tmp_path / 'missing'}: not a directory of DSDL definitions"


def _user_com(tmp_path: Path) -> tuple[Path, Path]:
    """A user's ``com`` root: one new type beside the shipped ones, one shipped replaced."""
    root = tmp_path / "home" / "dronecan_vendor_specific_types" / "com"
    _write(root / "acme" / "20990.Beat.uavcan")
    replacing = _write(root.parent / STATUS, "uint16 only_this\n")
    return root, replacing


def test_a_later_root_overrides_type_by_type(tmp_path: Path) -> None:
    root, replacing = _user_com(tmp_path)
    found = find_roots({}, tmp_path / "home")
    assert found.roots == (*shipped_roots(), root)
    override = Override("com.hobbywing.esc.StatusMsg1", DSDL_ROOT / STATUS, replacing)
    assert found.overrides == (override,)
    assert str(override) == f"com.hobbywing.esc.StatusMsg1: {replacing} replaces " + str(
        DSDL_ROOT / STATUS
    )
    definitions = parse_namespaces(found.roots, override=True)
    assert definitions["com.hobbywing.esc.StatusMsg1"].path == str(replacing)
    assert "com.acme.Beat" in definitions and "com.hobbywing.esc.StatusMsg2" in definitions
    with pytest.raises(DsdlError) as caught:
        parse_namespaces(found.roots)
    assert str(caught.value) == (
        f"{replacing}: com.hobbywing.esc.StatusMsg1 also in {DSDL_ROOT / STATUS}"
    )


def test_two_roots_of_one_name_add_up_in_a_type_set(tmp_path: Path) -> None:
    root = tmp_path / "home" / "dronecan_vendor_specific_types" / "com"
    _write(root / "acme" / "20990.Beat.uavcan")
    types = TypeSet.standard().with_dsdl(*find_roots({}, tmp_path / "home").roots)
    assert types["com.acme.Beat"] is not types["com.hobbywing.esc.StatusMsg1"]
    assert types.definitions["com.acme.Beat"].path == str(root / "acme" / "20990.Beat.uavcan")


def test_an_override_loads_in_a_type_set(tmp_path: Path) -> None:
    _, replacing = _user_com(tmp_path)
    with pytest.warns(DsdlOverrideWarning) as caught:
        types = TypeSet.standard().with_dsdl(*find_roots({}, tmp_path / "home").roots)
    assert [str(w.message) for w in caught] == [
        f"com.hobbywing.esc.StatusMsg1: {replacing} replaces {DSDL_ROOT / STATUS}"
    ]
    assert types.definitions["com.hobbywing.esc.StatusMsg1"].path == str(replacing)


def test_the_default_set_is_the_shipped_one_then_the_users_roots(tmp_path: Path) -> None:
    """Shipped roots first (generated ahead of time, names fixed), the user's in a load of
    their own: a user's type is added, a user's definition of a shipped type replaces it
    with a note, and no other shipped class changes."""
    assert default_set({}, tmp_path) is TypeSet.shipped()
    root, replacing = _user_com(tmp_path)
    with pytest.warns(DsdlOverrideWarning) as caught:
        types = default_set({}, tmp_path / "home")
    assert [str(w.message) for w in caught] == [
        f"com.hobbywing.esc.StatusMsg1: {replacing} replaces {DSDL_ROOT / STATUS}"
    ]
    shipped = TypeSet.shipped()
    assert types.loads == (*shipped.loads, (root.resolve(),))
    replaced = types["com.hobbywing.esc.StatusMsg1"]
    assert replaced is not shipped["com.hobbywing.esc.StatusMsg1"]
    assert replaced.__name__ == shipped["com.hobbywing.esc.StatusMsg1"].__name__
    assert [f.name for f in dataclasses.fields(replaced)] == ["only_this"]
    assert types.definitions["com.hobbywing.esc.StatusMsg1"].path == str(replacing)
    assert "com.acme.Beat" in types
    for key, cls in shipped.classes.items():
        if key != "com.hobbywing.esc.StatusMsg1":
            assert types[key] is cls, key
    codec = types.by_class[replaced]
    assert codec.decode(codec.encode(replaced(only_this=513))) == replaced(only_this=513)
    assert sum(c.data_type.full_name == "com.hobbywing.esc.StatusMsg1" for c in types.codecs) == 1
    variable = {
        ENVIRONMENT_VARIABLE: str(tmp_path / "home" / "dronecan_vendor_specific_types" / "com")
    }
    with pytest.warns(DsdlOverrideWarning):
        assert default_set(variable, tmp_path).loads == types.loads


def test_the_same_definition_again_changes_nothing(tmp_path: Path) -> None:
    """The ``dronecan`` package's own copy of a shipped root (the same files elsewhere)."""
    copy = tmp_path / "ardupilot"
    shutil.copytree(DSDL_ROOT / "ardupilot", copy)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        types = TypeSet.shipped().with_dsdl(copy)
    assert types.classes == TypeSet.shipped().classes
