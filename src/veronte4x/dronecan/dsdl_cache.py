"""The disk cache of the DSDL namespaces a user loads: where it is, its keys, its files.

`veronte4x.dronecan.TypeSet.with_dsdl` (and so ``load_dsdl`` and ``--dsdl``) compiles a
user's root namespaces once: what it made (`veronte4x.dronecan.compiled_load`) is written
here, and the next process that loads the same files into the same set reads it instead of
parsing and compiling again.

- Where: `directory` (``$XDG_CACHE_HOME/veronte4x/dronecan`` or
  ``~/.cache/veronte4x/dronecan`` on Linux, ``~/Library/Caches/veronte4x/dronecan`` on
  macOS, ``%LOCALAPPDATA%\\veronte4x\\Cache\\dronecan`` on Windows), moved by the
  environment variable `ENVIRONMENT_VARIABLE` (``VERONTE4X_CACHE_DIR``), turned off by its
  value ``off``. Never beside the user's files.
- Key (`key`): a SHA-256 of the path and bytes of every ``.uavcan`` file of the set's roots
  and of the new ones, the roots in order, the source of veronte4x's own modules that make
  and run the code (`source_digest`: it stands for the version, since any release that
  changes that code changes it, and it catches a copy edited in place; the version string
  itself is not read, its lookup through `importlib.metadata` costing more than a whole
  load from the cache) and the Python version. Any change to any of them is another key.
  A key starts with a hash of the roots alone: writing an entry removes those of the same
  roots under other keys, so the cache holds one entry per set of roots (delete the
  directory to clear it).
- Kinds: ``load``, what `with_dsdl` made of some roots added to a set; ``definitions``,
  the parsed shipped definitions every first load of a user's root is named and checked
  against. A key reads ``<kind>-<hash of the roots>-<hash of everything>``.
- Files: ``<key>.manifest`` names the SHA-256 of the entry's bytes;
  ``<sha256>.entry`` holds them. Both are written to a temporary file and moved in place
  (`os.replace`), so two processes filling the cache at once each leave a whole file, and
  an entry's name is its content: a manifest never names another process's bytes.
- Trust: an entry is used only if its bytes hash to what its manifest says and both files
  (and the directory) belong to this user and no one else may write them; anything else is
  ignored and made again. Its bytes are read once, checked, and only then unmarshalled.
- Failure: a directory that cannot be made or written costs one `DsdlCacheWarning` per
  process, and every load compiles as if there were no cache; reading never raises.
"""

from __future__ import annotations

import functools
import hashlib
import marshal
import os
import stat
import sys
import warnings
from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import Any

ENVIRONMENT_VARIABLE = "VERONTE4X_CACHE_DIR"
"""The environment variable that moves the cache to another directory, or turns it off
with the value `OFF`."""

OFF = "off"
"""The value of `ENVIRONMENT_VARIABLE` that turns the cache off."""

FORMAT = 2
"""The layout of an entry (`veronte4x.dronecan.compiled_load`); part of every key."""

_MANIFEST = f"veronte4x DSDL cache manifest {FORMAT}"
"""The first line of a manifest; the second is the SHA-256 of its entry, in hexadecimal."""

_PACKAGE = Path(__file__).resolve().parent.parent
"""The directory of the ``veronte4x`` package."""


class DsdlCacheWarning(UserWarning):
    """The DSDL cache directory could not be written: each load compiles again."""


def directory(environ: Mapping[str, str] | None = None, platform: str | None = None) -> Path | None:
    """The cache directory of compiled DSDL, or None where `ENVIRONMENT_VARIABLE` is `OFF`.

    Args:
        environ: The environment (`os.environ` if None).
        platform: `sys.platform` if None.
    """
    environ = os.environ if environ is None else environ
    given = environ.get(ENVIRONMENT_VARIABLE)
    if given == OFF:
        return None
    if given:
        return Path(given) / "dronecan"
    platform = sys.platform if platform is None else platform
    home = Path(environ.get("HOME") or Path.home())
    if platform == "win32":
        local = environ.get("LOCALAPPDATA")
        base = Path(local) if local else home / "AppData" / "Local"
        return base / "veronte4x" / "Cache" / "dronecan"
    if platform == "darwin":
        return home / "Library" / "Caches" / "veronte4x" / "dronecan"
    xdg = environ.get("XDG_CACHE_HOME", "")
    base = Path(xdg) if os.path.isabs(xdg) else home / ".cache"
    return base / "veronte4x" / "dronecan"


@functools.cache
def source_digest() -> bytes:
    """The SHA-256 of the modules of ``veronte4x`` and ``veronte4x.dronecan`` (those that
    generate and run the code of an entry, and the generated standard and vendor modules
    it builds on): any change to veronte4x that could change an entry changes it. Empty
    where the package is no directory of source files (a zip): no key then."""
    paths = sorted([*_PACKAGE.glob("*.py"), *_PACKAGE.glob("dronecan/*.py")])
    digest = hashlib.sha256()
    for path in paths:
        data = path.read_bytes()
        digest.update(f"{path.relative_to(_PACKAGE).as_posix()}\0{len(data)}\0".encode())
        digest.update(data)
    return digest.digest() if paths else b""


def key(
    loads: Iterable[Iterable[Path]], files: Iterable[tuple[str | Path, bytes]], what: str = "load"
) -> str:
    """The key of a load: ``loads`` the root namespace directories of the set and then the
    new ones, ``files`` the path and bytes of every DSDL file under them; ``what`` the kind
    of entry (``load``, or ``definitions``: the parsed definitions of the roots alone). It
    is ``what``, a hash of the roots alone (shared by every key of the same roots and kind:
    `write` keeps one) and the hash of everything, joined by ``-``."""
    roots = what.encode() + b"".join(
        b"\1" + "\0".join(str(root) for root in load).encode("utf-8", "surrogateescape")
        for load in loads
    )
    digest = hashlib.sha256(
        f"veronte4x DSDL cache {FORMAT} {sys.implementation.cache_tag}\0".encode()
    )
    digest.update(source_digest())
    digest.update(roots)
    for path, data in files:
        name = str(path).encode("utf-8", "surrogateescape")
        digest.update(b"\2%d\0%s%d\0" % (len(name), name, len(data)))
        digest.update(data)
    return f"{what}-{hashlib.sha256(roots).hexdigest()[:16]}-{digest.hexdigest()}"


def load_key(
    loads: Iterable[Iterable[Path]], new: Iterable[Path], what: str = "load"
) -> str | None:
    """The `key` of loading the roots ``new`` into a set of ``loads`` (of ``what``), or None
    where a file cannot be read (the load itself then says what is wrong)."""
    everything = (*(tuple(load) for load in loads), tuple(new))
    if not source_digest():
        return None
    files = []
    try:
        for path in _files(root for load in everything for root in load):
            with open(path, "rb") as file:
                files.append((path, file.read()))
    except OSError:
        return None
    return key(everything, files, what)


def _files(roots: Iterable[Path]) -> list[str]:
    """Every ``.uavcan`` file under each root, as `veronte4x.dronecan.parser` finds them
    (symbolic links to directories not followed), sorted within each root (plain strings:
    a `Path` each costs more than reading the file)."""
    found: list[str] = []
    for root in roots:
        found += sorted(
            os.path.join(folder, name)
            for folder, _, names in os.walk(root)
            for name in names
            if name.endswith(".uavcan")
        )
    return found


def _trusted(status: os.stat_result) -> bool:
    """Whether a file or directory is this user's and no one else may write it (on
    Windows, where modes are emulated and owners not reported, the user's local
    application data directory is theirs)."""
    if os.name == "nt":
        return True
    writable = status.st_mode & (stat.S_IWGRP | stat.S_IWOTH)
    return not writable and status.st_uid == os.getuid()


def _read(path: Path) -> bytes:
    """The bytes of a regular file we may trust (see `_trusted`); OSError otherwise."""
    descriptor = os.open(
        path, os.O_RDONLY | getattr(os, "O_NOFOLLOW", 0) | getattr(os, "O_BINARY", 0)
    )
    with os.fdopen(descriptor, "rb") as file:
        status = os.fstat(file.fileno())
        if not stat.S_ISREG(status.st_mode) or not _trusted(status):
            raise PermissionError(f"{path} is not this user's alone")
        return file.read()


def read(folder: Path, entry_key: str) -> dict[str, Any] | None:
    """The entry of ``entry_key``, or None: none, or not to be trusted (see the module
    docstring)."""
    try:
        if not _trusted(os.stat(folder)):
            return None
        head, _, digest = _read(folder / f"{entry_key}.manifest").decode("ascii").partition("\n")
        digest = digest.strip()
        if head != _MANIFEST or len(digest) != 64 or not digest.isalnum():
            return None
        data = _read(folder / f"{digest}.entry")
        if hashlib.sha256(data).hexdigest() != digest:
            return None
        entry = marshal.loads(data)  # only bytes we wrote: their hash is the manifest's
    except (OSError, ValueError, TypeError, EOFError):
        return None
    if not isinstance(entry, dict) or entry.get("key") != entry_key:
        return None
    return entry


_warned = False


def write(folder: Path, entry_key: str, entry: dict[str, Any]) -> None:
    """Store ``entry`` (marshal's types only) under ``entry_key``; on failure warn once per
    process and go on."""
    data = marshal.dumps({**entry, "key": entry_key})
    digest = hashlib.sha256(data).hexdigest()
    manifest = f"{_MANIFEST}\n{digest}\n".encode()
    try:
        folder.mkdir(mode=0o700, parents=True, exist_ok=True)
        if not _trusted(os.stat(folder)):
            raise PermissionError("another user may write it")
        _replace(folder / f"{digest}.entry", data)
        _replace(folder / f"{entry_key}.manifest", manifest)
        _prune(folder, entry_key, digest)
    except OSError as error:
        global _warned
        if not _warned:
            _warned = True
            warnings.warn(
                f"cannot write the DSDL cache in {folder} ({error}): each run compiles the "
                f"DSDL again; set {ENVIRONMENT_VARIABLE} to another directory or to {OFF}",
                DsdlCacheWarning,
                stacklevel=3,
            )


def _prune(folder: Path, entry_key: str, digest: str) -> None:
    """Remove the entries of the same roots under other keys (a file changed since, another
    veronte4x): one entry per set of roots."""
    roots = entry_key.rpartition("-")[0]
    for other in folder.glob(f"{roots}-*.manifest"):
        if other.stem == entry_key:
            continue
        try:
            old = other.read_text("ascii").split()[-1]
            other.unlink()
            if old != digest and len(old) == 64 and old.isalnum():
                (folder / f"{old}.entry").unlink(missing_ok=True)
        except (OSError, ValueError, IndexError):
            continue  # another process's, or gone already


def _replace(path: Path, data: bytes) -> None:
    """Write ``path`` whole: a new temporary file of this user's only, then moved in place."""
    temporary = path.with_name(f".tmp-{os.urandom(8).hex()}")
    flags = os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_BINARY", 0)
    descriptor = os.open(temporary, flags, 0o600)
    try:
        with os.fdopen(descriptor, "wb") as file:
            file.write(data)
        os.replace(temporary, path)
    except BaseException:
        os.unlink(temporary)
        raise
