"""No DSDL tree runs code: names, comments, constants, directory and file names from the
whole of Unicode load correctly or give the library's own one-line error, and nothing of
them runs (a payload that would create a marker file never does)."""

from __future__ import annotations

import keyword
import os
import tempfile
from pathlib import Path
from unittest import mock

import pytest
from hypothesis import HealthCheck, event, given, settings
from hypothesis import strategies as st

from veronte4x.dronecan import DsdlError, TypeSet, encode
from veronte4x.dronecan.transfer import decode_frames
from veronte4x.errors import Veronte4xError

PAYLOAD = '__import__("pathlib").Path(__import__("os").environ["V4X_MARKER"]).touch()'
"""Creates the marker file where it runs (no ``/``: it fits in a directory name)."""

ATTACKS = [
    f'x""";{PAYLOAD};"""',
    f"x''';{PAYLOAD};'''",
    f'x"""\n{PAYLOAD}\n"""',
    f"x\\\n{PAYLOAD}",
    f"\\N{{{PAYLOAD}}}",
    f'"}}{{{PAYLOAD}}}',
    f"x\0{PAYLOAD}",
]
"""Texts that would break out of a string or a docstring of generated source."""


def _namespace(root: Path, files: dict[str, str]) -> Path:
    for relative, text in files.items():
        path = root / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(text.encode("utf-8", "surrogatepass"))  # a surrogate: not UTF-8
    return root


def _load(root: Path) -> TypeSet | DsdlError:
    """The set with ``root``, or the library's error; the marker must not appear."""
    marker = root.parent / "MARKER"
    with mock.patch.dict(os.environ, {"V4X_MARKER": str(marker)}):
        try:
            types: TypeSet | DsdlError = TypeSet.standard().with_dsdl(root)
        except DsdlError as error:
            types = error
    assert not marker.exists()
    if isinstance(types, DsdlError):
        assert str(types).isprintable(), str(types)  # one line
    return types


@pytest.mark.parametrize("attack", ATTACKS)
def test_a_directory_name_that_is_code_is_refused_and_runs_nothing(
    tmp_path: Path, attack: str
) -> None:
    """The attack of issue 41: the first one created the marker when loaded."""
    directory = _file_name(attack)
    root = _namespace(tmp_path / "vendor", {f"{directory}/20000.Foo.uavcan": "uint8 A = 1\n"})
    error = _load(root)
    assert isinstance(error, DsdlError)
    assert error.problem.startswith("directory name '")
    assert error.problem.endswith(
        "' is not a namespace name (a lowercase ASCII letter, then lowercase letters, digits or _)"
    )


@pytest.mark.parametrize("attack", ATTACKS)
def test_comments_that_are_code_load_as_comments(tmp_path: Path, attack: str) -> None:
    comment = " ".join(attack.splitlines())  # a comment ends at the line
    text = f"# {comment}\n\nuint8 A = 1  # {comment}\nuint8 B = 2\nuint8 value  # {comment}\n"
    types = _load(_namespace(tmp_path / "vendor", {"20000.Foo.uavcan": text}))
    assert isinstance(types, TypeSet)
    cls = types["vendor.Foo"]
    assert (cls.A, cls.B) == (1, 2)  # type: ignore[attr-defined]
    frames = encode(cls(value=2), source_node_id=5, transfer_id=0, types=types)
    assert decode_frames(frames, types=types).message.value.name == "B"


def test_a_root_that_is_code_is_refused(tmp_path: Path) -> None:
    root = _namespace(tmp_path / _file_name(ATTACKS[0]), {"20000.Foo.uavcan": "uint8 a\n"})
    error = _load(root)
    assert isinstance(error, DsdlError)
    assert error.path == str(root.resolve())


# -- any text -----------------------------------------------------------------------------

_ANY = st.characters(codec=None, exclude_categories=())
"""Every code point, lone surrogates included."""

_texts = st.one_of(
    st.sampled_from(
        [
            *ATTACKS,
            "class",
            "None",
            "True",
            "mro",
            "bytes",
            "Foo",
            "ok",
            "inf",
            "nan",
            "1e999",
            "-0x10",
            "'\\''",
            "\\N{BULLET}",
            "a\nb",
            "\udcff",
            "²",
        ]
    ),
    st.text(_ANY, max_size=12),
    st.text(st.sampled_from("\"'\\\n\r\0#={}[]<>. _aZ9²\u2028\udc80"), max_size=12),
)


def _file_name(text: str) -> str:
    """``text`` as a name the file system takes: ``/`` and NUL out, and each surrogate
    that no byte stands for replaced by one that does (``os.fsencode`` keeps those)."""
    chars = []
    for char in text.replace("/", "_").replace("\0", "_"):
        code = ord(char)
        if 0xD800 <= code <= 0xDFFF and not 0xDC80 <= code <= 0xDCFF:
            char = chr(0xDC80 + code % 0x80)
        chars.append(char)
    name = "".join(chars)
    return name if name not in ("", ".", "..") else "x"


_types = st.sampled_from(["uint8", "int16", "float32", "float16", "bool", "uint3"])

_grammar = st.from_regex(r"[a-zA-Z][a-zA-Z0-9_]{0,5}", fullmatch=True)
_names = st.one_of(
    _grammar,
    _grammar,
    _grammar,
    st.sampled_from(["class", "None", "True", "mro", "bytes", "Inner", "A", "value"]),
    _texts,
)
"""Field and constant names: mostly of the grammar (keywords too), or any text."""

_values = st.one_of(
    st.integers(0, 1).map(str),
    st.integers(0, 1).map(str),
    st.integers(-2, 300).map(str),
    st.floats().map(repr),
    st.sampled_from(["inf", "-inf", "nan", "1e999", "1e39", "65505", "true", "'a'", "'\\0'"]),
    _texts,
)

_line = _texts.map(lambda text: " ".join(text.splitlines()))
_comments = st.one_of(_line, _line, _line, _texts)
"""Mostly the text of one line (a line break in a comment starts a line of code)."""


@st.composite
def _trees(draw: st.DrawFn) -> dict[str, str]:
    """A namespace of one message, perhaps in a subdirectory, with a nested type."""
    lines = [f"# {draw(_comments)}", ""]
    for _ in range(draw(st.integers(0, 2))):
        kind, name, value, comment = draw(_types), draw(_names), draw(_values), draw(_comments)
        lines.append(f"{kind} {name} = {value}  # {comment}")
    for _ in range(draw(st.integers(1, 2))):
        lines.append(f"{draw(_types)} {draw(_names)}  # {draw(_comments)}")
    lines.append(f"{draw(st.sampled_from(['Inner'] * 4 + [_file_name(draw(_texts))]))} inner")
    directory = draw(st.sampled_from(["", "", "sub/", "sub/", _file_name(draw(_texts)) + "/"]))
    short = draw(st.sampled_from(["Outer"] * 3 + ["None", "Bytes", _file_name(draw(_texts))]))
    inner = draw(st.sampled_from(["Inner"] * 4 + [_file_name(draw(_texts))]))
    return {
        f"{directory}20000.{short}.uavcan": "\n".join(lines) + "\n",
        f"{directory}{inner}.uavcan": f"uint8 x  # {draw(_comments)}\n",
    }


@settings(max_examples=200, suppress_health_check=[HealthCheck.too_slow])
@given(
    tree=_trees(),
    root=st.sampled_from(["vendor"] * 6 + [ATTACKS[0], "2x", "x²", "\udcff", "Vendor"]),
)
def test_any_tree_loads_or_gives_the_library_error_and_runs_nothing(
    tree: dict[str, str], root: str
) -> None:
    with tempfile.TemporaryDirectory() as tmp:
        directory = _namespace(Path(tmp) / _file_name(root), tree)
        types = _load(directory)
        event("error" if isinstance(types, Veronte4xError) else "loaded")
        if isinstance(types, Veronte4xError):
            return
        new = [key for key in types.classes if key not in TypeSet.standard().classes]
        assert len(new) == 2
        [codec] = types.codecs[len(TypeSet.standard().codecs) :]
        message = codec.data_type.schema.cls()
        frames = encode(message, source_node_id=5, transfer_id=0, types=types)
        assert decode_frames(frames, types=types).message == message


_one_line = st.text(st.characters(codec="utf-8"), max_size=20).map(
    lambda text: " ".join(text.splitlines())
)
"""A comment: any text of one line (NUL, quotes, backslashes, ``\\N``)."""


@settings(max_examples=100)
@given(
    names=st.lists(
        st.one_of(_grammar, st.sampled_from(["class", "None", "True", "mro", "bytes", "Inner"])),
        min_size=1,
        max_size=5,
        unique=True,
    ),
    values=st.lists(st.integers(0, 7), min_size=5, max_size=5),
    comments=st.lists(_one_line, min_size=6, max_size=6),
)
def test_names_of_the_grammar_and_any_comment_load_exactly(
    names: list[str], values: list[int], comments: list[str]
) -> None:
    """Constants of any name of the grammar, then a field: the class has each constant's
    value, under its name or, for a Python keyword, its name with ``_`` after it (more where
    that is taken: the naming rule's), and its docstring holds the comment as written."""
    lines = [f"# {comments[-1]}", ""]
    lines += [f"uint3 {n} = {v}  # {c}" for n, v, c in zip(names, values, comments, strict=False)]
    lines.append("uint3 field_of_the_test")
    with tempfile.TemporaryDirectory() as tmp:
        types = _load(_namespace(Path(tmp) / "vendor", {"20000.Foo.uavcan": "\n".join(lines)}))
    assert isinstance(types, TypeSet)
    cls = types["vendor.Foo"]
    constants = {
        n: getattr(cls, n) for n, a in cls.__annotations__.items() if a.startswith("ClassVar[")
    }
    assert len(constants) == len(names)
    for name, value in zip(names, values, strict=False):
        if keyword.iskeyword(name):
            name = next(n for n in constants if n.rstrip("_") == name)
        assert constants.pop(name) == value
    assert comments[-1].strip().replace('"""', "'''") in (cls.__doc__ or "")
