"""The DSDL root namespace directories of the default type set, in the order they load.

1. The vendor roots shipped with the package (`SHIPPED`: dronecan/DSDL's ``ardupilot``,
   ``com``, ``cuav``, ``dronecan``, ``mppt``, in ``veronte4x/dronecan/dsdl`` beside the
   standard ``uavcan``; ``UPSTREAM.md`` there names the commit).
2. Each subdirectory of ``~/uavcan_vendor_specific_types`` and then of
   ``~/dronecan_vendor_specific_types`` (`HOME_DIRECTORIES`), by name, as the ``dronecan``
   package's ``load_dsdl`` (and so the DroneCAN GUI tool) reads them; names starting with
   ``.`` are left out.
3. Each entry of the environment variable `ENVIRONMENT_VARIABLE` (``VERONTE4X_DSDL_PATH``),
   root namespace directories separated by `os.pathsep`, in order (empty entries left
   out).

The command line's ``--dsdl`` directories come after these. A later root overrides an
earlier one type by type: a definition of the same full name replaces the earlier one
(`veronte4x.dronecan.parser.parse_namespaces` with ``override``), and `Roots.overrides`
says which; two roots of one name (a user's ``com`` beside the shipped one) otherwise add
up. A directory given twice counts once, where it first comes.

Only `find_roots` touches the file system, and only to list directories.
"""

from __future__ import annotations

import os
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

DSDL_ROOT = Path(__file__).with_name("dsdl")
"""The DSDL shipped with the package: the standard ``uavcan/`` and its ``LICENSE``, the
vendor roots of `SHIPPED`, and ``UPSTREAM.md``."""

SHIPPED = ("ardupilot", "com", "cuav", "dronecan", "mppt")
"""The vendor root namespaces shipped with the package, in the order they load."""

ENVIRONMENT_VARIABLE = "VERONTE4X_DSDL_PATH"
"""The environment variable of more root namespace directories (`os.pathsep` between)."""

HOME_DIRECTORIES = ("uavcan_vendor_specific_types", "dronecan_vendor_specific_types")
"""The directories of the home directory whose subdirectories are roots (the ``dronecan``
package's and the DroneCAN GUI tool's)."""


@dataclass(frozen=True, slots=True)
class Override:
    """A definition that replaces one of the same full name in an earlier root.

    Attributes:
        full_name: The DSDL full name, e.g. ``com.hobbywing.esc.StatusMsg1``.
        replaced: The earlier file, no longer used.
        by: The later file, used instead.
    """

    full_name: str
    replaced: Path
    by: Path

    def __str__(self) -> str:
        return f"{self.full_name}: {self.by} replaces {self.replaced}"


@dataclass(frozen=True, slots=True)
class Roots:
    """The root namespace directories to load, and the definitions later ones override.

    Attributes:
        roots: In load order: shipped, home directories, environment variable.
        overrides: Each definition replaced by a later root's, in the order of the roots.
    """

    roots: tuple[Path, ...]
    overrides: tuple[Override, ...]


def shipped_roots() -> tuple[Path, ...]:
    """The shipped vendor root namespace directories, in `SHIPPED` order."""
    return tuple(DSDL_ROOT / name for name in SHIPPED)


def user_roots(
    variable: str | None, home_listings: Sequence[Iterable[Path]] = ()
) -> tuple[Path, ...]:
    """The user's roots, in load order, from what `find_roots` read.

    Args:
        variable: The value of `ENVIRONMENT_VARIABLE`, or None where it is not set.
        home_listings: The subdirectories of each of `HOME_DIRECTORIES` that exists, in
            that order.
    """
    found: list[Path] = []
    for listing in home_listings:
        found += sorted(p for p in listing if not p.name.startswith("."))
    found += [Path(entry) for entry in (variable or "").split(os.pathsep) if entry]
    return tuple(found)


def overrides(files: Iterable[tuple[str, Path, int]]) -> tuple[Override, ...]:
    """The definitions a later root replaces, from `parser.definition_files`' listing
    (full name, file, root index), by the rule of ``parse_namespaces(..., override=True)``."""
    first: dict[str, tuple[Path, int]] = {}
    found = []
    for full_name, path, root in files:
        earlier = first.get(full_name)
        if earlier is not None and earlier[1] < root:
            found.append(Override(full_name, earlier[0], path))
        first[full_name] = (path, root)
    return tuple(found)


def find_roots(
    environ: Mapping[str, str] | None = None, home: str | os.PathLike[str] | None = None
) -> Roots:
    """The roots of the default type set and their overrides: lists directories only.

    Args:
        environ: The environment (`os.environ` if None).
        home: The home directory (`Path.home` if None).

    Raises:
        DsdlError: A root that is not a directory, or a directory or file name that no
            DSDL name can be (the path named).
    """
    environ = os.environ if environ is None else environ
    base = Path.home() if home is None else Path(home)
    listings = [
        [p for p in (base / name).iterdir() if p.is_dir()]
        for name in HOME_DIRECTORIES
        if (base / name).is_dir()
    ]
    given = (*shipped_roots(), *user_roots(environ.get(ENVIRONMENT_VARIABLE), listings))
    seen: set[Path] = set()
    roots = []
    for root in given:
        if root.resolve() not in seen:
            seen.add(root.resolve())
            roots.append(root)
    if len(roots) == len(SHIPPED):  # the shipped roots override nothing (a test checks)
        return Roots(tuple(roots), ())
    from veronte4x.dronecan.parser import definition_files  # the DSDL parser, for user roots

    return Roots(tuple(roots), overrides(definition_files(roots)))
