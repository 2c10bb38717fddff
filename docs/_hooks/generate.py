"""MkDocs hook: replace ``<!-- generate: module:function -->`` with that function's Markdown.

Tables in the docs come from the code's own definitions: a page names a function that
returns Markdown (in the ``docgen`` package next to this hook, which is not installed with
veronte4x), and this hook calls it at build time.
"""

from __future__ import annotations

import importlib
import re
import sys
from pathlib import Path
from typing import Any

_HERE = str(Path(__file__).parent)
"""Where the docgen package lives (MkDocs takes this directory off sys.path after loading)."""

_MARKER = re.compile(r"^<!-- generate: ([\w.]+):(\w+) -->$", re.MULTILINE)


def _render(match: re.Match[str]) -> str:
    if _HERE not in sys.path:
        sys.path.insert(0, _HERE)
    module = importlib.import_module(match.group(1))
    text: str = getattr(module, match.group(2))()
    return text


def on_page_markdown(markdown: str, **_: Any) -> str:
    """Expand every generate marker of a page."""
    return _MARKER.sub(_render, markdown)
