"""A distribution installed as pip installs one, without pip: its modules and a
``dist-info`` with its entry points, in a directory that goes on ``PYTHONPATH`` (the tests
of readers from other packages, the entry point group ``veronte4x.readers``)."""

from __future__ import annotations

from pathlib import Path


def install(
    site: Path,
    name: str,
    version: str,
    modules: dict[str, str],
    entry_points: dict[str, dict[str, str]],
) -> None:
    """Write ``modules`` (file name: source) into ``site``, beside the
    ``NAME-VERSION.dist-info`` of their distribution: its ``METADATA`` and its
    ``entry_points.txt`` (group: entry point name: ``module:attribute``)."""
    info = site / f"{name.replace('-', '_')}-{version}.dist-info"
    info.mkdir(parents=True)
    for file, source in modules.items():
        (site / file).write_text(source)
    (info / "METADATA").write_text(f"Metadata-Version: 2.1\nName: {name}\nVersion: {version}\n")
    groups = [
        f"[{group}]\n" + "".join(f"{point} = {value}\n" for point, value in points.items())
        for group, points in entry_points.items()
    ]
    (info / "entry_points.txt").write_text("\n".join(groups))
