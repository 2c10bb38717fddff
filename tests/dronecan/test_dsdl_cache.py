"""The disk cache of user DSDL (`veronte4x.dronecan.dsdl_cache`): a second load reads what
the first compiled; any change to a file or to veronte4x is another key; a directory that
cannot be written, or is missing, costs nothing but the compile; two processes fill it at
once; an entry whose bytes are not those its manifest names is never run, and is made again.

The user root is a copy of the shipped ``ardupilot`` tree (14 types), loaded into the
standard set (the shipped set has the same definitions, and so would compile nothing).
"""

from __future__ import annotations

import dataclasses
import hashlib
import linecache
import marshal
import os
import random
import shutil
import subprocess
import sys
import warnings
from pathlib import Path
from typing import Any

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from test_dronecan_compiled import messages
from tests.plain_data import same

from veronte4x import dronecan as v4
from veronte4x.codegen import compile_source
from veronte4x.dronecan import (
    TypeSet,
    compiled_load,
    dsdl_cache,
    generate,
    parsed_data,
    parser,
    typeset,
)
from veronte4x.dronecan.compiled import DECODE_FALLBACK, ENCODE_FALLBACK, compile_fast, transport_of
from veronte4x.dronecan.parser import parse_namespaces
from veronte4x.dronecan.typeset import DsdlOverrideWarning
from veronte4x.dronecan.vendor_roots import DSDL_ROOT, SHIPPED
from veronte4x.errors import DecodeError


@pytest.fixture
def root(tmp_path: Path) -> Path:
    """A user's copy of the shipped ``ardupilot`` root."""
    return Path(shutil.copytree(DSDL_ROOT / "ardupilot", tmp_path / "user" / "ardupilot"))


@pytest.fixture
def cache(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """The cache directory of the test (`dsdl_cache.ENVIRONMENT_VARIABLE` set to it)."""
    monkeypatch.setenv(dsdl_cache.ENVIRONMENT_VARIABLE, str(tmp_path / "cache"))
    return tmp_path / "cache" / "dronecan"


def _no_compiling(monkeypatch: pytest.MonkeyPatch) -> None:
    """Make any compile of DSDL fail: a load that succeeds read the cache."""

    def refuse(*args: Any) -> str:
        raise AssertionError("compiled DSDL instead of reading the cache")

    monkeypatch.setattr(generate, "module_source", refuse)  # what typeset compiles with


def _manifests(cache: Path) -> list[Path]:
    return sorted(cache.glob("load-*.manifest"))


def _entry(cache: Path) -> Path:
    [manifest] = _manifests(cache)
    return cache / f"{manifest.read_text().split()[-1]}.entry"


def _payloads(codec: v4.TypeCodec, count: int, seed: int) -> list[bytes]:
    """Payloads of every length up to the type's largest (at most 40 bytes), random bytes."""
    rng = random.Random(seed)
    longest = min(codec.max_payload, 40)
    return [rng.randbytes(rng.randint(0, longest)) for _ in range(count)]


def _decoded(types: TypeSet, seed: int = 7) -> list[Any]:
    """What each vendor type of ``types`` makes of the same payloads, as plain data: each
    value and its payload again, or the error's text (after the type's name, id, signature
    and file name)."""
    found: list[Any] = []
    for codec in types.codecs:
        if not codec.data_type.full_name.startswith("ardupilot."):
            continue
        t = codec.data_type
        found.append((t.full_name, t.kind.name, t.data_type_id, t.signature, Path(t.path).name))
        for payload in _payloads(codec, 30, seed):
            try:
                message = codec.decode(payload)
            except DecodeError as error:
                found.append(str(error))
                continue
            found.append((v4.to_builtin(message, types), codec.encode(message)))
    return found


def test_the_second_load_reads_the_cache_and_decodes_as_the_first(
    root: Path, cache: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    first = TypeSet.standard().with_dsdl(root)
    assert len(_manifests(cache)) == 1 and _entry(cache).is_file()
    _no_compiling(monkeypatch)
    second = TypeSet.standard().with_dsdl(root)
    assert second.classes.keys() == first.classes.keys()
    assert second.roots == first.roots
    assert second._names == first._names
    named = [(k, c.__name__) for k, c in first.classes.items() if isinstance(c, type)]
    assert named == [(k, c.__name__) for k, c in second.classes.items() if isinstance(c, type)]
    assert same(_decoded(second), _decoded(first))
    units = {c.__name__: u for c, u in second.units.items()}
    assert units == {c.__name__: u for c, u in first.units.items()}
    assert second.definitions.keys() == first.definitions.keys()  # parsed on first use


def test_cached_and_uncached_loads_decode_identically(
    root: Path, cache: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    TypeSet.standard().with_dsdl(root)
    cached = TypeSet.standard().with_dsdl(root)
    monkeypatch.setenv(dsdl_cache.ENVIRONMENT_VARIABLE, dsdl_cache.OFF)
    uncached = TypeSet.standard().with_dsdl(root)
    assert len(_decoded(cached, 3)) > 14 * 30
    assert same(_decoded(cached, 3), _decoded(uncached, 3))
    for a, b in zip(cached.codecs, uncached.codecs, strict=True):
        assert (a.max_payload, a.crc_seed) == (b.max_payload, b.crc_seed)


def test_a_changed_byte_of_a_dsdl_file_is_another_entry(
    root: Path, cache: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    TypeSet.standard().with_dsdl(root)
    before, entry = _manifests(cache), _entry(cache)
    heading = root / "gnss" / "20002.Heading.uavcan"
    heading.write_text(heading.read_text().replace("heading_rad", "heading_raX"))
    changed = TypeSet.standard().with_dsdl(root)
    assert len(_manifests(cache)) == 1 and _manifests(cache) != before  # the old one removed
    assert not entry.exists()
    fields = {f.name for f in dataclasses.fields(changed["ardupilot.gnss.Heading"])}
    assert "heading_raX" in fields and "heading_rad" not in fields
    _no_compiling(monkeypatch)
    again = TypeSet.standard().with_dsdl(root)
    assert "heading_raX" in {f.name for f in dataclasses.fields(again["ardupilot.gnss.Heading"])}


def test_a_changed_generator_or_format_is_another_entry(
    root: Path, cache: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    keys = [dsdl_cache.load_key((), [root])]
    TypeSet.standard().with_dsdl(root)
    monkeypatch.setattr(dsdl_cache, "source_digest", lambda: b"another veronte4x")
    keys.append(dsdl_cache.load_key((), [root]))
    TypeSet.standard().with_dsdl(root)
    monkeypatch.setattr(dsdl_cache, "FORMAT", dsdl_cache.FORMAT + 1)
    keys.append(dsdl_cache.load_key((), [root]))
    TypeSet.standard().with_dsdl(root)
    assert len(set(keys)) == 3
    assert [m.stem for m in _manifests(cache)] == keys[-1:]  # one entry for the roots


def test_the_key_covers_every_file_the_roots_and_veronte4x(root: Path) -> None:
    key = dsdl_cache.load_key((), [root])
    assert key is not None and key == dsdl_cache.load_key((), [root])
    other = dsdl_cache.load_key(((root,),), [root.parent])
    assert other is not None and other.rpartition("-")[0] != key.rpartition("-")[0]
    (root / "gnss" / "20099.New.uavcan").write_text("uint8 x\n")
    changed = dsdl_cache.load_key((), [root])
    assert changed is not None and changed != key
    assert changed.rpartition("-")[0] == key.rpartition("-")[0]  # the same roots
    assert len(dsdl_cache.source_digest()) == 32


def test_a_missing_cache_directory_is_made_for_this_user_alone(root: Path, cache: Path) -> None:
    assert not cache.parent.exists()
    TypeSet.standard().with_dsdl(root)
    assert cache.stat().st_mode & 0o777 == 0o700
    assert _entry(cache).stat().st_mode & 0o777 == 0o600


def test_a_cache_that_cannot_be_written_warns_once_and_compiles(
    root: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    blocked = tmp_path / "a file"
    blocked.write_text("not a directory")
    monkeypatch.setenv(dsdl_cache.ENVIRONMENT_VARIABLE, str(blocked / "cache"))
    monkeypatch.setattr(dsdl_cache, "_warned", False)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        first = TypeSet.standard().with_dsdl(root)
        second = TypeSet.standard().with_dsdl(root)
    assert [w.category for w in caught] == [dsdl_cache.DsdlCacheWarning]
    assert dsdl_cache.ENVIRONMENT_VARIABLE in str(caught[0].message)
    assert same(_decoded(first), _decoded(second))


def test_a_read_only_cache_is_read_and_never_fails_a_load(
    root: Path, cache: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    TypeSet.standard().with_dsdl(root)
    cache.chmod(0o500)
    other = Path(shutil.copytree(root, root.parent.parent / "other" / "ardupilot"))
    try:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            compiled = TypeSet.standard().with_dsdl(other)  # a miss: cannot be written
            _no_compiling(monkeypatch)
            read = TypeSet.standard().with_dsdl(root)  # a hit in the read-only directory
    finally:
        cache.chmod(0o700)
    assert len(caught) <= 1  # none where the user may write anyway (root)
    assert same(_decoded(compiled), _decoded(read))


def test_a_directory_others_may_write_is_not_trusted(
    root: Path, cache: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    TypeSet.standard().with_dsdl(root)
    cache.chmod(0o770)
    monkeypatch.setattr(dsdl_cache, "_warned", False)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        assert dsdl_cache.read(cache, _manifests(cache)[0].stem) is None
        types = TypeSet.standard().with_dsdl(root)  # compiled: the entry is not read
    assert [w.category for w in caught] == [dsdl_cache.DsdlCacheWarning]
    assert "ardupilot.gnss.Heading" in types


def _tampered(cache: Path, marker: Path) -> dict[str, Any]:
    """The cache's entry with code that makes ``marker`` in its module of classes and in
    every fast path."""
    entry: dict[str, Any] = marshal.loads(_entry(cache).read_bytes())
    attack = f"\nopen({str(marker)!r}, 'w').close()\n"
    filename, source, _ = entry["classes"]
    entry["classes"] = (filename, source + attack, compile(source + attack, filename, "exec"))
    entry["fast"] = tuple((f[0] + attack, f[1]) if f else f for f in entry["fast"])
    return entry


def test_a_tampered_entry_is_never_run_and_is_made_again(
    root: Path, cache: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    reference = _decoded(TypeSet.standard().with_dsdl(root))
    marker = tmp_path / "tampered code ran"
    tampered = marshal.dumps(_tampered(cache, marker))
    _entry(cache).write_bytes(tampered)
    types = TypeSet.standard().with_dsdl(root)
    assert same(_decoded(types), reference)
    assert not marker.exists()
    assert _entry(cache).read_bytes() != tampered  # made again (marshal's bytes may differ)
    assert dsdl_cache.read(cache, _manifests(cache)[0].stem) is not None
    _no_compiling(monkeypatch)  # made again: the next load reads it
    assert same(_decoded(TypeSet.standard().with_dsdl(root)), reference)
    assert not marker.exists()


def test_an_entry_others_may_write_is_never_run(root: Path, cache: Path, tmp_path: Path) -> None:
    """Even with a manifest that names its bytes: a file others may write is not ours."""
    TypeSet.standard().with_dsdl(root)
    marker = tmp_path / "tampered code ran"
    [manifest] = _manifests(cache)
    data = marshal.dumps({**_tampered(cache, marker), "key": manifest.stem})
    digest = hashlib.sha256(data).hexdigest()
    (cache / f"{digest}.entry").write_bytes(data)
    (cache / f"{digest}.entry").chmod(0o666)
    manifest.write_text(manifest.read_text().replace(_entry(cache).stem, digest))
    types = TypeSet.standard().with_dsdl(root)
    assert not marker.exists()
    assert "ardupilot.gnss.Heading" in types


_CHILD = """
import sys
from veronte4x.dronecan import TypeSet
types = TypeSet.standard().with_dsdl(sys.argv[1])
print(sum(c.data_type.full_name.startswith("ardupilot.") for c in types.codecs))
"""


def test_two_processes_fill_the_cache_at_once(
    root: Path, cache: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(sys.path)}
    children = [
        subprocess.Popen(
            [sys.executable, "-c", _CHILD, str(root)], env=env, stdout=subprocess.PIPE, text=True
        )
        for _ in range(2)
    ]
    outputs = [child.communicate(timeout=600)[0] for child in children]
    assert [child.returncode for child in children] == [0, 0]
    assert outputs == ["14\n", "14\n"]
    assert len(_manifests(cache)) == 1
    assert not list(cache.glob(".tmp-*"))
    monkeypatch.setenv(dsdl_cache.ENVIRONMENT_VARIABLE, dsdl_cache.OFF)
    uncached = TypeSet.standard().with_dsdl(root)
    monkeypatch.setenv(dsdl_cache.ENVIRONMENT_VARIABLE, str(cache.parent))
    _no_compiling(monkeypatch)
    assert same(_decoded(TypeSet.standard().with_dsdl(root)), _decoded(uncached))


@pytest.mark.parametrize(
    ("environ", "platform", "expected"),
    [
        ({"HOME": "/h"}, "linux", "/h/.cache/veronte4x/dronecan"),
        ({"HOME": "/h", "XDG_CACHE_HOME": "/x"}, "linux", "/x/veronte4x/dronecan"),
        ({"HOME": "/h", "XDG_CACHE_HOME": "relative"}, "linux", "/h/.cache/veronte4x/dronecan"),
        ({"HOME": "/h"}, "darwin", "/h/Library/Caches/veronte4x/dronecan"),
        ({"HOME": "/h", "LOCALAPPDATA": "/l"}, "win32", "/l/veronte4x/Cache/dronecan"),
        ({"HOME": "/h", "VERONTE4X_CACHE_DIR": "/c"}, "linux", "/c/dronecan"),
        ({"HOME": "/h", "VERONTE4X_CACHE_DIR": "off"}, "linux", None),
    ],
)
def test_the_cache_directory_of_each_platform(
    environ: dict[str, str], platform: str, expected: str | None
) -> None:
    found = dsdl_cache.directory(environ, platform)
    assert (None if found is None else found.as_posix()) == expected


def test_no_cache_reads_or_writes_nothing(
    root: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv(dsdl_cache.ENVIRONMENT_VARIABLE, dsdl_cache.OFF)
    monkeypatch.setenv("HOME", str(tmp_path / "home"))
    monkeypatch.delenv("XDG_CACHE_HOME", raising=False)
    TypeSet.standard().with_dsdl(root)
    assert not (tmp_path / "home").exists()


def test_the_command_line_says_in_one_line_that_the_cache_cannot_be_written(
    tmp_path: Path,
) -> None:
    blocked = tmp_path / "a file"
    blocked.write_text("not a directory")
    log = tmp_path / "empty.log"
    log.write_text("")
    root = shutil.copytree(DSDL_ROOT / "ardupilot", tmp_path / "user" / "ardupilot")
    env = {**os.environ, dsdl_cache.ENVIRONMENT_VARIABLE: str(blocked / "cache")}
    done = subprocess.run(
        [sys.executable, "-m", "veronte4x", "decode", str(log), "--dsdl", str(root)],
        env={**env, "PYTHONPATH": os.pathsep.join(sys.path)},
        capture_output=True,
        text=True,
    )
    assert done.returncode == 0, done.stderr
    [line] = [line for line in done.stderr.splitlines() if "warning" in line.lower()]
    assert line.startswith(f"veronte4x: warning: cannot write the DSDL cache in {blocked}")


def test_a_load_read_from_the_cache_warns_of_its_overrides_as_the_first(
    root: Path, cache: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    heading = root / "gnss" / "20002.Heading.uavcan"
    heading.write_text(heading.read_text().replace("heading_rad", "heading_raX"))
    found = []
    for _ in range(2):
        with pytest.warns(DsdlOverrideWarning) as caught:
            types = TypeSet.shipped().with_dsdl(root)
        found.append([str(w.message) for w in caught])
        assert "heading_raX" in {
            f.name for f in dataclasses.fields(types["ardupilot.gnss.Heading"])
        }
        _no_compiling(monkeypatch)
    assert (
        found[0]
        == found[1]
        == [
            f"ardupilot.gnss.Heading: {heading} replaces "
            f"{DSDL_ROOT / 'ardupilot' / 'gnss' / '20002.Heading.uavcan'}"
        ]
    )


def test_the_shipped_definitions_are_parsed_once_and_read_back_equal(
    cache: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    roots = [DSDL_ROOT / "uavcan", *(DSDL_ROOT / name for name in SHIPPED)]
    parsed = parse_namespaces(roots)
    assert parsed_data.definitions_of(parsed_data.definitions_data(parsed)) == parsed
    assert typeset._parse_shipped(roots)() == parsed  # parsed, and written

    def refuse(*args: Any, **kwargs: Any) -> None:
        raise AssertionError("parsed the shipped DSDL instead of reading the cache")

    monkeypatch.setattr(parser, "parse_namespaces", refuse)
    assert typeset._parse_shipped(roots)() == parsed


def test_without_veronte4x_source_files_nothing_is_cached(
    root: Path, cache: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A package with no source to hash (run from a zip) would reuse another version's."""
    monkeypatch.setattr(dsdl_cache, "source_digest", lambda: b"")
    assert dsdl_cache.load_key((), [root]) is None
    assert "ardupilot.gnss.Heading" in TypeSet.standard().with_dsdl(root)
    assert not cache.exists()


def _mine(types: TypeSet) -> list[v4.TypeCodec]:
    """The codecs of the user's ``ardupilot`` types."""
    return [c for c in types.codecs if c.data_type.full_name.startswith("ardupilot.")]


def test_a_load_compiles_no_fast_path_and_a_first_use_only_its_types(
    root: Path, cache: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    compiled: list[str] = []

    def counting(source: str, namespace: dict[str, Any], title: str) -> dict[str, Any]:
        compiled.append(title)
        return compile_source(source, namespace, title)

    monkeypatch.setattr(compiled_load, "compile_source", counting)
    first = TypeSet.standard().with_dsdl(root)  # compiled, and written
    second = TypeSet.standard().with_dsdl(root)  # read from the cache
    assert compiled == []
    for types in (first, second):
        mine = _mine(types)
        assert len(mine) == 14 and not any("fast" in vars(c) for c in mine)  # not yet made
        empty = types["ardupilot.gnss.Heading"]()
        heading = types.by_class[type(empty)]
        assert heading.decode(heading.generic.encode(empty)) == empty
        assert [c for c in mine if "fast" in vars(c)] == [heading]
    assert compiled == ["dsdl fast paths ardupilot.gnss.Heading message"] * 2
    code = heading.fast.decode.__code__
    assert code.co_filename.startswith("<veronte4x generated dsdl fast paths ardupilot.gnss")
    assert "def decode(buf):" in "".join(linecache.getlines(code.co_filename))


@pytest.fixture(scope="module")
def loaded_lazily(tmp_path_factory: pytest.TempPathFactory) -> tuple[TypeSet, TypeSet]:
    """A user's copy of ``ardupilot`` loaded into the standard set with an empty cache, then
    again from the cache: no fast path of either compiled yet."""
    folder = tmp_path_factory.mktemp("lazy")
    user = shutil.copytree(DSDL_ROOT / "ardupilot", folder / "user" / "ardupilot")
    with pytest.MonkeyPatch.context() as patch:
        patch.setenv(dsdl_cache.ENVIRONMENT_VARIABLE, str(folder / "cache"))
        return TypeSet.standard().with_dsdl(user), TypeSet.standard().with_dsdl(user)


def _outcome(function: Any, *args: Any) -> Any:
    """What a fast path gives: its result, or the fallback it raised (by type)."""
    try:
        return repr(function(*args))
    except (*ENCODE_FALLBACK, *DECODE_FALLBACK) as error:
        return type(error)


_ARDUPILOT = [
    (c.data_type.full_name, c.data_type.kind)
    for c in TypeSet.shipped().codecs
    if c.data_type.full_name.startswith("ardupilot.")
]


@pytest.mark.parametrize("loaded", ["first load", "from the cache"])
@pytest.mark.parametrize("key", _ARDUPILOT, ids=[name for name, _ in _ARDUPILOT])
@settings(max_examples=8, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data())
def test_a_first_use_gives_what_the_fast_paths_compiled_at_once_give(
    loaded_lazily: tuple[TypeSet, TypeSet],
    loaded: str,
    key: tuple[str, v4.TransferKind],
    data: st.DataObject,
) -> None:
    types = loaded_lazily[loaded == "from the cache"]
    [codec] = [c for c in types.codecs if (c.data_type.full_name, c.data_type.kind) == key]
    lazy, eager = codec.fast, compile_fast(codec.data_type.schema, transport_of(codec.data_type))
    assert (lazy.decode_frame is None) == (eager.decode_frame is None)
    message = data.draw(messages(codec.data_type.schema, faults=True), label="message")
    transport = (42, 17, 9, None if key[1] is v4.TransferKind.MESSAGE else 7)
    assert _outcome(lazy.payload, message) == _outcome(eager.payload, message)
    assert _outcome(lazy.frames, message, *transport) == _outcome(eager.frames, message, *transport)
    payload = data.draw(
        st.binary(max_size=codec.max_payload + 3)
        | st.builds(codec.generic.encode, messages(codec.data_type.schema, faults=False)),
        label="payload",
    )
    assert _outcome(lazy.decode, payload) == _outcome(eager.decode, payload)
    if lazy.decode_frame is not None and eager.decode_frame is not None and len(payload) <= 7:
        frame = payload + b"\xc5"
        assert _outcome(lazy.decode_frame, frame) == _outcome(eager.decode_frame, frame)
