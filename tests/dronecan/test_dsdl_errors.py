"""The DSDL parser's errors, each naming the file, the line and the problem in exact words,
and the constants it reads (character literals, escapes, ``#`` inside a literal, bools,
floats, hex), for the vendor definitions a user adds."""

from __future__ import annotations

from pathlib import Path

import pytest

from veronte4x.dronecan.parser import (
    PrimitiveType,
    check_references,
    parse_namespaces,
    signature,
)
from veronte4x.errors import DsdlError

THING = "vendor/20000.Thing.uavcan"
D = "veronte4x reads @union and OVERRIDE_SIGNATURE 0x<16 hex digits>"
"""What the error of an unsupported directive says is supported."""
TAKES = f"takes one hexadecimal signature of 64 bits: {D}"


def _write(root: Path, relative: str, text: str | bytes) -> Path:
    path = root / relative
    path.parent.mkdir(parents=True, exist_ok=True)
    if isinstance(text, bytes):
        path.write_bytes(text)
    else:
        path.write_text(text)
    return path


@pytest.mark.parametrize(
    ("text", "line", "problem"),
    [
        ("uint8 a\ntruncated void3\n", 2, "void3: void fields take no cast mode"),
        ("uint8[2][3] a\n", 1, "uint8[2][3]: arrays of arrays are not allowed"),
        ("void8[<=4] a\n", 1, "void8[<=4]: arrays of void are not allowed"),
        ("uint8[<1] a\n", 1, "uint8[<1]: an array holds at least one item"),
        ("Foo-bar a\n", 1, "'Foo-bar' is not a type name"),
        ("truncated Foo a\n", 1, "truncated Foo: a cast mode applies to primitive types only"),
        ("float24 a\n", 1, "float24: no such type (bit length out of range)"),
        ("int1 a\n", 1, "int1: no such type (bit length out of range)"),
        ("uint8 C = 'ab'\n", 1, "'ab': a character literal holds one character"),
        ("uint8 C = abc\n", 1, "abc: not a constant value"),
        ("bool B = 2\n", 1, "2: not a bool"),
        ("uint8 X = 1.5\n", 1, "1.5: not an integer for uint8"),
        ("uint8 X = true\n", 1, "true: not an integer for uint8"),
        ("int8 X = -129\n", 1, "-129: out of range for int8"),
        ("uint8 a\n---\nuint8 b\n---\n", 4, "a second '---'"),
        ("uint8 a\n@union\nuint8 b\n", 2, "@union must come before the fields"),
        ("@union\n@union\nuint8 a\nuint8 b\n", 2, "@union must come before the fields"),
        ("Foo X = 1\n", 1, "constant X: not of a primitive type"),
        ("uint8[2] X = 1\n", 1, "constant X: not of a primitive type"),
        ("void2 X = 1\n", 1, "constant X: not of a primitive type"),
        ("uint8 X =\n", 1, "cannot read constant 'uint8 X ='"),
        ("# a comment\nuint8\n", 2, "field 'uint8' has no name"),
        ("@union\nuint8 a\nvoid3\nuint8 b\n", 3, "a union has no void fields"),
        ("void3 pad\n", 1, "void fields have no name"),
        ("uint8 2a\n", 1, "'2a' is not a valid name"),
        ("uint8 A = 1\nuint16 A = 2\n", 2, "A defined twice"),
        ("uint8 a\n@sealed\n", 2, f"unsupported directive @sealed ({D})"),
        ("OVERRIDE_DTID 0x10\nuint8 a\n", 1, f"unsupported directive OVERRIDE_DTID ({D})"),
        ("uint8 a\nOVERRIDE_SIGNATURE\n", 2, f"OVERRIDE_SIGNATURE {TAKES}"),
        ("OVERRIDE_SIGNATURE 0x1 0x2\n", 1, f"OVERRIDE_SIGNATURE {TAKES}"),
        ("OVERRIDE_SIGNATURE 0x10000000000000000\n", 1, f"OVERRIDE_SIGNATURE {TAKES}"),
        ("OVERRIDE_SIGNATURE -0x1\n", 1, f"OVERRIDE_SIGNATURE {TAKES}"),
        ("OVERRIDE_SIGNATURE 0xG1\n", 1, f"OVERRIDE_SIGNATURE {TAKES}"),
    ],
)
def test_each_malformed_line_is_named_with_its_problem(
    tmp_path: Path, text: str, line: int, problem: str
) -> None:
    path = _write(tmp_path, THING, text)
    with pytest.raises(DsdlError) as caught:
        parse_namespaces([tmp_path / "vendor"])
    assert str(caught.value) == f"{path}:{line}: {problem}"
    assert (caught.value.path, caught.value.line, caught.value.problem) == (
        str(path),
        line,
        problem,
    )


@pytest.mark.parametrize(
    ("name", "text", "problem"),
    [
        ("65536.Big.uavcan", "uint8 a\n", "message id 65536 above 65535"),
        ("256.Ask.uavcan", "uint8 a\n---\nuint8 b\n", "service id 256 above 255"),
        ("Bad.uavcan", b"uint8 \xff\n", "cannot read: 'utf-8' codec can't decode byte 0xff in "
         "position 6: invalid start byte"),
    ],
)  # fmt: skip
def test_problems_of_a_whole_file(
    tmp_path: Path, name: str, text: str | bytes, problem: str
) -> None:
    path = _write(tmp_path, f"vendor/{name}", text)
    with pytest.raises(DsdlError) as caught:
        parse_namespaces([tmp_path / "vendor"])
    assert str(caught.value) == f"{path}: {problem}"
    assert caught.value.line is None


def test_the_largest_ids_are_taken(tmp_path: Path) -> None:
    _write(tmp_path, "vendor/65535.Big.uavcan", "uint8 a\n")
    _write(tmp_path, "vendor/255.Ask.uavcan", "uint8 a\n---\nuint8 b\n")
    found = parse_namespaces([tmp_path / "vendor"])
    assert (found["vendor.Big"].default_id, found["vendor.Ask"].default_id) == (65535, 255)


def test_a_root_that_is_no_directory(tmp_path: Path) -> None:
    path = _write(tmp_path, THING, "uint8 a\n")
    for root in (path, tmp_path / "missing"):
        with pytest.raises(DsdlError) as caught:
            parse_namespaces([root])
        assert str(caught.value) == f"{root}: not a directory of DSDL definitions"


def test_a_service_is_no_nested_type_and_a_type_cannot_contain_itself(tmp_path: Path) -> None:
    _write(tmp_path, "vendor/200.Ask.uavcan", "uint8 a\n---\nuint8 b\n")
    user = _write(tmp_path, THING, "uint8 a\n# the service, by mistake\nAsk b\n")
    with pytest.raises(DsdlError) as caught:
        check_references(parse_namespaces([tmp_path / "vendor"]))
    assert str(caught.value) == f"{user}:3: vendor.Ask is a service, not a nested type"
    user.unlink()
    first = _write(tmp_path, "vendor/A.uavcan", "uint8 a\nB[<=2] b\n")
    _write(tmp_path, "vendor/B.uavcan", "vendor.A a\n")
    with pytest.raises(DsdlError) as caught:
        check_references(parse_namespaces([tmp_path / "vendor"]))
    assert str(caught.value) == f"{first}: vendor.A contains itself"


def test_constants_of_every_form(tmp_path: Path) -> None:
    text = (
        "uint8 HASH = '#'  # a hash in a literal is no comment\n"
        "uint8 NEWLINE = '\\n'\n"
        "uint8 QUOTE = '\\''\n"
        "uint8 HEX = 0x1F\n"
        "int8 LOW = -128\n"
        "bool YES = true\n"
        "bool ONE = 1\n"
        "saturated bool NO = FALSE\n"
        "float32 F = 2\n"
        "float16 G = 0.5  # half\n"
        "uint8 a\n"
    )
    _write(tmp_path, THING, text)
    [section] = parse_namespaces([tmp_path / "vendor"])["vendor.Thing"].sections
    got = {c.name: (c.value, type(c.value).__name__) for c in section.constants}
    assert got == {
        "HASH": (35, "int"),
        "NEWLINE": (10, "int"),
        "QUOTE": (39, "int"),
        "HEX": (31, "int"),
        "LOW": (-128, "int"),
        "YES": (True, "bool"),
        "ONE": (True, "bool"),
        "NO": (False, "bool"),
        "F": (2.0, "float"),
        "G": (0.5, "float"),
    }
    comments = {c.name: c.comment for c in section.constants if c.comment}
    assert comments == {"HASH": "a hash in a literal is no comment", "G": "half"}
    assert section.constants[7].type == PrimitiveType("bool", 1, "saturated")
    assert [f.name for f in section.fields] == ["a"]


def test_override_signature_as_the_dronecan_package_reads_it(tmp_path: Path) -> None:
    """``OVERRIDE_SIGNATURE`` stands for the CRC of the normalized definition, wherever it
    is in the file (after ``---`` too), with or without ``0x``, the last one winning; the
    nested types' signatures still extend it, and a type nesting it uses the overridden one
    (dronecan/dsdl/parser.py: ``get_dsdl_signature``, ``get_data_type_signature``)."""
    dsdl = pytest.importorskip("dronecan.dsdl")
    _write(tmp_path, "vendor/Inner.uavcan", "OVERRIDE_SIGNATURE 0123456789abcdef\nuint8 a\n")
    _write(tmp_path, "vendor/Plain.uavcan", "uint8 a\n")
    texts = {
        "vendor/20000.Outer.uavcan": "# doc\nInner i\nOVERRIDE_SIGNATURE 0xFFFFFFFFFFFFFFFF\n",
        "vendor/20001.Holder.uavcan": "Inner[<=2] i\nPlain p\n",
        "vendor/200.Ask.uavcan": "Inner i\n---\nOVERRIDE_SIGNATURE 0x1\nOVERRIDE_SIGNATURE 0x2\n",
    }
    for name, text in texts.items():
        _write(tmp_path, name, text)
    ours = parse_namespaces([tmp_path / "vendor"])
    check_references(ours)
    theirs = {t.full_name: t for t in dsdl.parse_namespaces([str(tmp_path / "vendor")])}
    assert set(ours) == set(theirs)
    assert ours["vendor.Ask"].override_signature == 2
    assert ours["vendor.Inner"].override_signature == 0x0123456789ABCDEF
    assert ours["vendor.Plain"].override_signature is None
    known: dict[str, int] = {}
    for name in ours:
        assert signature(name, ours, known) == theirs[name].get_data_type_signature(), name
    assert known["vendor.Inner"] == 0x0123456789ABCDEF
