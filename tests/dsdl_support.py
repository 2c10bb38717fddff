"""Small vendor DSDL namespaces written for a test."""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path


def write_namespace(parent: Path, name: str, files: Mapping[str, str]) -> Path:
    """The root namespace directory ``parent/name``, holding ``files`` (file stem, such as
    ``20950.One``, to its DSDL text) as ``.uavcan`` files."""
    root = parent / name
    root.mkdir()
    for stem, text in files.items():
        (root / f"{stem}.uavcan").write_text(text)
    return root
