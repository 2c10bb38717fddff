"""MkDocs hook: the demo captures for the notebook pages, which mkdocs-jupyter executes.

``examples/flight.ipynb`` (shown as ``docs/flight.ipynb``, a link to it) opens the capture
named by ``VERONTE4X_FLIGHT``: this hook writes the flight of ``make demo`` with its arbiter
configuration into a temporary folder and names it there, unless it is set already; and
likewise the vehicle bus of ``examples/vehicle_bus.ipynb`` (``VERONTE4X_VEHICLE_BUS``).
Progress bars are off (``TQDM_DISABLE``): a page shows no widget.
"""

from __future__ import annotations

import os
import runpy
import shutil
import tempfile
from pathlib import Path
from typing import Any

_EXAMPLES = Path(__file__).resolve().parent.parent.parent / "examples"


def demo_flight(folder: Path) -> Path:
    """Write the demo flight of ``make demo`` and ``arbiter.toml`` into ``folder``."""
    generate = runpy.run_path(str(_EXAMPLES / "make_capture.py"))["generate"]
    path = folder / "flight.log"
    generate(2.0, 60.0, 4).write(path)
    shutil.copy(_EXAMPLES / "arbiter.toml", folder)
    return path


def vehicle_bus(folder: Path) -> Path:
    """Write the vehicle bus of ``make demo`` into ``folder``."""
    path = folder / "vehicle.log"
    runpy.run_path(str(_EXAMPLES / "make_vehicle_bus.py"))["write"](path)
    return path


_made: list[Path] = []
"""The temporary folders this hook made, removed when MkDocs shuts down."""


def on_config(config: Any, **_: Any) -> Any:
    """Name the flight for the notebook's kernel, which inherits this environment."""
    os.environ.setdefault("TQDM_DISABLE", "1")
    if "VERONTE4X_FLIGHT" not in os.environ:
        _made.append(Path(tempfile.mkdtemp(prefix="veronte4x-docs-")))
        os.environ["VERONTE4X_FLIGHT"] = str(demo_flight(_made[-1]))
    if "VERONTE4X_VEHICLE_BUS" not in os.environ:
        _made.append(Path(tempfile.mkdtemp(prefix="veronte4x-docs-")))
        os.environ["VERONTE4X_VEHICLE_BUS"] = str(vehicle_bus(_made[-1]))
    return config


def on_shutdown(**_: Any) -> None:
    """Remove the captures this hook wrote."""
    while _made:
        shutil.rmtree(_made.pop(), ignore_errors=True)
