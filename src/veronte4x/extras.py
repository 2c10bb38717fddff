"""Optional dependencies, imported on first use with an error that names the extra to install."""

from __future__ import annotations

import importlib
from types import ModuleType

from veronte4x.errors import MissingExtraError


def require(module: str, extra: str, needed_for: str) -> ModuleType:
    """Import an optional dependency.

    Args:
        module: The module to import, such as ``can``.
        extra: The veronte4x extra that installs it, such as ``can``.
        needed_for: What needs it, for the error message: ``reading .blf files``.

    Raises:
        MissingExtraError: The module is not installed.

    Examples:
        >>> require("json", "none", "the example").__name__
        'json'
    """
    try:
        return importlib.import_module(module)
    except ModuleNotFoundError as error:
        if error.name != module and not module.startswith(f"{error.name}."):
            raise  # the module is there but one of its own imports is missing
        raise MissingExtraError(module, extra, needed_for) from None
