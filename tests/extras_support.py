"""The extras of pyproject.toml as the installed distributions and modules they bring: what a
process with only those extras installed can import."""

from __future__ import annotations

from importlib import metadata
from pathlib import Path

import tomli
from packaging.requirements import Requirement
from packaging.utils import canonicalize_name

ROOT = Path(__file__).resolve().parent.parent
EXTRAS: dict[str, list[str]] = tomli.loads((ROOT / "pyproject.toml").read_text())["project"][
    "optional-dependencies"
]
"""Each extra's requirements."""


def distributions(extras: list[str]) -> set[str]:
    """The installed distributions that these extras of veronte4x bring, with theirs."""
    todo = [Requirement(r) for name in extras for r in EXTRAS[name]]
    seen: set[str] = set()
    while todo:
        requirement = todo.pop()
        name = canonicalize_name(requirement.name)
        if name in seen:
            continue
        seen.add(name)
        try:
            found = metadata.distribution(name)
        except metadata.PackageNotFoundError:
            continue
        for text in found.requires or []:
            needed = Requirement(text)
            wanted = requirement.extras or {""}
            if needed.marker is None or any(needed.marker.evaluate({"extra": e}) for e in wanted):
                todo.append(needed)
    return seen


def modules(extras: list[str]) -> list[str]:
    """The top-level modules a process with only these extras may import: veronte4x's and
    those of the distributions the extras bring (the standard library aside)."""
    allowed = distributions(extras) | {"veronte4x"}
    return sorted(
        module
        for module, names in metadata.packages_distributions().items()
        if any(canonicalize_name(name) in allowed for name in names)
    )
