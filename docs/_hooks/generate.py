"""MkDocs hook: replace ``<!-- generate: module:function -->`` with that function's Markdown.

Tables in the docs come from the code's own definitions: a page names a function that
returns Markdown, and this hook calls it at build time.
"""

from __future__ import annotations

import importlib
import re
from typing import Any

_MARKER = re.compile(r"^<!-- generate: ([\w.]+):(\w+) -->$", re.MULTILINE)


def _render(match: re.Match[str]) -> str:
    module = importlib.import_module(match.group(1))
    text: str = getattr(module, match.group(2))()
    return text


def on_page_markdown(markdown: str, **_: Any) -> str:
    """Expand every generate marker of a page."""
    return _MARKER.sub(_render, markdown)
