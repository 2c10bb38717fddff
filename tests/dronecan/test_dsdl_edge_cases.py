"""Odd but legal-looking DSDL: each case loads correctly or gives one `DsdlError` line
naming the file (and the line); where the ``dronecan`` package's parser decides, both
agree. The command line says the same line and exits 2."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import dronecan.dsdl
import pytest

from veronte4x.dronecan import DsdlError, TypeSet, encode
from veronte4x.dronecan.transfer import decode_frames

NAMESPACE = (
    "is not a namespace name (a lowercase ASCII letter, then lowercase letters, digits or _)"
)


def _tree(root: Path, files: dict[str, str]) -> Path:
    for relative, text in files.items():
        path = root / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")
    return root


def _dronecan_refuses(root: Path) -> bool:
    """Whether the ``dronecan`` package's parser refuses the namespace."""
    try:
        dronecan.dsdl.parse_namespaces([str(root)])
    except dronecan.dsdl.DsdlException:
        return True
    return False


@pytest.mark.parametrize(
    ("text", "line", "problem"),
    [
        ("float32 A = inf\n", 1, "inf: not a finite number"),
        ("float32 A = -inf\n", 1, "-inf: not a finite number"),
        ("float32 A = nan\n", 1, "nan: not a finite number"),
        ("float64 A = 1e999\n", 1, "1e999: not a finite number"),
        ("uint8 a\nfloat32 A = 1e39\n", 2, "1e39: out of range for float32"),
        ("float16 A = 65505\n", 1, "65505: out of range for float16"),
        ("float64 A = 1" + "0" * 400 + "\n", 1, "1" + "0" * 400 + ": out of range for float64"),
        ("uint8 A = \u0661\n", 1, "\u0661: not a constant value"),  # an Arabic-Indic one
    ],
)
def test_constants_out_of_their_type_name_the_line(
    tmp_path: Path, text: str, line: int, problem: str
) -> None:
    root = _tree(tmp_path / "vendor", {"20000.Foo.uavcan": text})
    with pytest.raises(DsdlError) as error:
        TypeSet.standard().with_dsdl(root)
    assert str(error.value) == f"{root.resolve() / '20000.Foo.uavcan'}:{line}: {problem}"
    assert _dronecan_refuses(root)


def test_digits_are_ascii_where_the_dronecan_package_takes_any(tmp_path: Path) -> None:
    """Its ``\\d`` reads ``uint\u0668`` (an Arabic-Indic eight) as ``uint8``; veronte4x reads
    DSDL's ASCII digits only."""
    root = _tree(tmp_path / "vendor", {"20000.Foo.uavcan": "uint\u0668 a\n"})
    with pytest.raises(DsdlError) as error:
        TypeSet.standard().with_dsdl(root)
    assert error.value.problem == "'uint\u0668' is not a type name"
    assert not _dronecan_refuses(root)


@pytest.mark.parametrize(
    ("directory", "shown"),
    [("2x", "2x"), ("x²", "x²"), ("Upper", "Upper"), ("a-b", "a-b"), ("a\nb", "a\\nb")],
)
def test_a_directory_that_is_no_namespace_name_is_refused(
    tmp_path: Path, directory: str, shown: str
) -> None:
    root = _tree(tmp_path / "vendor", {f"{directory}/20000.Foo.uavcan": "uint8 a\n"})
    with pytest.raises(DsdlError) as error:
        TypeSet.standard().with_dsdl(root)
    file = f"{root.resolve()}/{shown}/20000.Foo.uavcan"
    assert str(error.value) == f"{file}: directory name '{shown}' {NAMESPACE}"
    assert "\n" not in str(error.value)
    assert _dronecan_refuses(root)


def test_a_directory_name_that_is_not_utf8_is_one_printable_line(tmp_path: Path) -> None:
    root = tmp_path / "vendor"
    (root / os.fsdecode(b"\xff")).mkdir(parents=True)
    (root / os.fsdecode(b"\xff") / "20000.Foo.uavcan").write_text("uint8 a\n")
    with pytest.raises(DsdlError) as error:
        TypeSet.standard().with_dsdl(root)
    assert str(error.value) == (
        f"{root.resolve()}/\\xff/20000.Foo.uavcan: directory name '\\xff' {NAMESPACE}"
    )
    assert error.value.path == str(root.resolve() / os.fsdecode(b"\xff") / "20000.Foo.uavcan")


def test_a_root_under_a_directory_that_is_not_utf8_loads(tmp_path: Path) -> None:
    root = _tree(tmp_path / os.fsdecode(b"\xfe") / "vendor", {"20000.Foo.uavcan": "uint8 a\n"})
    types = TypeSet.standard().with_dsdl(root)
    assert types["vendor.Foo"](a=3).a == 3


def test_a_path_of_bytes_loads_or_names_the_bytes(tmp_path: Path) -> None:
    """A path as ``os.listdir(b".")`` gives it: decoded as ``os.fsdecode`` does."""
    parent = os.fsencode(tmp_path) + b"/\xfe"
    _tree(Path(os.fsdecode(parent + b"/vendor")), {"20000.Foo.uavcan": "uint8 a\n"})
    types = TypeSet.standard().with_dsdl(parent + b"/vendor")
    assert types["vendor.Foo"](a=3).a == 3
    (tmp_path / os.fsdecode(b"\xff")).mkdir()
    with pytest.raises(DsdlError) as error:
        TypeSet.standard().with_dsdl(os.fsencode(tmp_path) + b"/\xff")
    assert str(error.value) == f"{tmp_path}/\\xff: directory name '\\xff' {NAMESPACE}"


def test_a_full_name_longer_than_80_characters_is_refused(tmp_path: Path) -> None:
    name = "A" * (80 - len("vendor."))
    root = _tree(
        tmp_path / "vendor", {f"{name}.uavcan": "uint8 a\n", f"{name}B.uavcan": "uint8 a\n"}
    )
    with pytest.raises(DsdlError) as error:
        TypeSet.standard().with_dsdl(root)
    assert error.value.problem == f"full name vendor.{name}B longer than 80 characters"
    assert error.value.path.endswith(f"{name}B.uavcan")


def test_keyword_names_load_with_an_underscore(tmp_path: Path) -> None:
    """``class``, ``None``, ``True`` as constants and fields (SyntaxError before), and as
    the constants of an enumeration type: each gets ``_`` after it, the wire is DSDL's."""
    root = _tree(
        tmp_path / "vendor",
        {
            "20000.Foo.uavcan": "uint8 class = 1\nuint8 None = 2\nuint8 True = 3\n"
            "uint8 def\nbool False\n",
            "20001.Kind.uavcan": "uint8 None = 0\nuint8 True = 1\nuint8 mro = 2\nuint8 value\n",
        },
    )
    types = TypeSet.standard().with_dsdl(root)
    foo, kind = types["vendor.Foo"], types["vendor.Kind"]
    assert (foo.class_, foo.None_, foo.True_) == (1, 2, 3)  # type: ignore[attr-defined]
    message = foo(def_=7, False_=True)
    frames = encode(message, source_node_id=5, transfer_id=0, types=types)
    assert frames[0].data == bytes([7, 0x80, 0xC0])
    assert decode_frames(frames, types=types).message == message
    decoded = decode_frames(
        encode(kind(value=2), source_node_id=5, transfer_id=1, types=types),
        types=types,
    ).message
    assert decoded.value.name == "mro_" and decoded.value == 2
    assert [m.name for m in type(decoded.value)] == ["None_", "True_", "mro_"]
    assert not _dronecan_refuses(root)


def test_a_nul_and_quotes_in_comments_load_as_comments(tmp_path: Path) -> None:
    """A NUL in a comment gave SyntaxError (a docstring of the generated source)."""
    root = _tree(
        tmp_path / "vendor",
        {"20000.Foo.uavcan": '# head\0 """ \\N{x}\n\nuint8 a  # a\0b\nuint8 A = 1  # \\"\n'},
    )
    cls = TypeSet.standard().with_dsdl(root)["vendor.Foo"]
    assert cls.__doc__ == (
        '``vendor.Foo``, message 20000 (``20000.Foo.uavcan``).\n\nhead\0 """ \\N{x}'
    )
    assert cls.A == 1  # type: ignore[attr-defined]


def test_class_attributes_do_not_hide_the_classes_of_defaults(tmp_path: Path) -> None:
    """A field ``bytes`` before a byte array, a constant ``Bar`` before a ``Bar`` field:
    the defaults called the attribute (TypeError: 'int' object is not callable)."""
    root = _tree(
        tmp_path / "vendor",
        {
            "Bar.uavcan": "uint8 q\n",
            "20000.Foo.uavcan": "uint8 Bar = 1\nuint8 bytes\nuint8[4] data\nBar b\n",
        },
    )
    types = TypeSet.standard().with_dsdl(root)
    foo, bar = types["vendor.Foo"], types["vendor.Bar"]
    message = foo()
    assert (message.bytes, message.data, message.b) == (0, bytes(4), bar())
    assert foo.Bar == 1  # type: ignore[attr-defined]


def test_arrays_nested_30_deep_encode_and_decode(tmp_path: Path) -> None:
    """The generated fast path would nest 30 loops (Python compiles 20: SyntaxError on the
    first encode); the generic serializer does such a type."""
    files = {f"N{i}.uavcan": f"N{i + 1}[<=2] a\nuint8 tag\n" for i in range(1, 30)}
    files["N30.uavcan"] = "uint8 x\n"
    files["20000.Top.uavcan"] = "N1[<=2] a\nuint8 tag\n"
    types = TypeSet.standard().with_dsdl(_tree(tmp_path / "chain", files))
    top, inner = types["chain.Top"], types["chain.N1"]
    message = top(a=(inner(tag=5), inner(tag=6)), tag=7)
    frames = encode(message, source_node_id=5, transfer_id=0, types=types)
    assert decode_frames(frames, types=types).message == message
    assert frames[0].data[:4] == bytes([0x80, 0x50, 0x18, 0x1C])  # 10 00 00000101 00 ...


# -- the command line ---------------------------------------------------------------------


def _decode(tmp_path: Path, root: Path | str) -> subprocess.CompletedProcess[str]:
    log = tmp_path / "some.log"
    log.write_text("(0.000000) can0 10015501#0102C0\n")
    return subprocess.run(
        [sys.executable, "-m", "veronte4x", "decode", "--dsdl", str(root), str(log)],
        capture_output=True,
        text=True,
        check=False,
        cwd=tmp_path,
    )


@pytest.mark.parametrize(
    ("files", "problem"),
    [
        ({"20000.Foo.uavcan": "float32 A = inf\n"}, ":1: inf: not a finite number"),
        ({"2x/20000.Foo.uavcan": "uint8 a\n"}, f": directory name '2x' {NAMESPACE}"),
        (
            {'x""";__import__("os").system("touch MARKER");"""/20000.Foo.uavcan': "uint8 a\n"},
            ': directory name \'x""";__import__("os").system("touch MARKER");"""\' ' + NAMESPACE,
        ),
    ],
)
def test_the_command_line_exits_2_with_one_line(
    tmp_path: Path, files: dict[str, str], problem: str
) -> None:
    root = _tree(tmp_path / "vendor", files)
    result = _decode(tmp_path, root)
    assert result.returncode == 2, result.stderr
    assert result.stdout == ""
    [line] = result.stderr.splitlines()
    assert line.startswith(f"veronte4x: {root.resolve()}/") and line.endswith(problem)
    assert "Traceback" not in result.stderr
    assert not (tmp_path / "MARKER").exists()


def test_the_command_line_names_a_directory_that_is_not_utf8(tmp_path: Path) -> None:
    root = tmp_path / os.fsdecode(b"vendor\xff")
    _tree(root, {"20000.Foo.uavcan": "uint8 a\n"})
    result = _decode(tmp_path, root)
    assert result.returncode == 2
    assert (
        result.stderr
        == f"veronte4x: {tmp_path}/vendor\\xff: directory name 'vendor\\xff' {NAMESPACE}\n"
    )
