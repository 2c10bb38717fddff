"""Progress bars on long work: tqdm's, in a terminal or a notebook, or none."""

from __future__ import annotations

import importlib.util
import sys
from typing import Any

from veronte4x.extras import require


class Bar:
    """A progress bar, or nothing where it is off.

    Args:
        enabled: Draw it; None draws it when standard error is a terminal or in a
            notebook and tqdm is installed.
        total: The amount of work.
        unit: What is counted: ``B`` (scaled to kB, MB, ...) or a word.
        description: Said before the bar.
        extra: The veronte4x extra that installs tqdm for this use, named in the error when
            a bar is asked for and tqdm is missing.
    """

    def __init__(
        self,
        enabled: bool | None,
        total: int,
        unit: str,
        description: str,
        extra: str = "parquet",
    ) -> None:
        self._bar: Any = None
        if enabled is None:
            enabled = _interactive() and importlib.util.find_spec("tqdm") is not None
        if enabled:
            auto = require("tqdm.auto", extra, "progress bars")
            self._bar = auto.tqdm(
                total=total, unit=unit, unit_scale=unit == "B", desc=description, leave=False
            )

    def update(self, amount: int) -> None:
        """Count ``amount`` more done."""
        if self._bar is not None and amount:
            self._bar.update(amount)

    def close(self) -> None:
        """Take the bar off the screen."""
        if self._bar is not None:
            self._bar.close()


def _interactive() -> bool:
    if _in_notebook():
        return True
    try:
        return sys.stderr.isatty()
    except (AttributeError, ValueError):
        return False


def _in_notebook() -> bool:
    """Whether this runs in a Jupyter kernel (not merely a process that imported one)."""
    ipython = sys.modules.get("IPython")
    shell = ipython.get_ipython() if ipython is not None else None
    return shell is not None and "IPKernelApp" in getattr(shell, "config", {})
