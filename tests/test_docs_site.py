"""The docs speak to users: no internal references, diagrams that work offline, wide tables
that scroll."""

from __future__ import annotations

import re
from pathlib import Path

from docgen import arbiter, capture, codec, dronecan, simulator, variables

ROOT = Path(__file__).resolve().parent.parent
DOCS = ROOT / "docs"
INTERNAL = re.compile(r"\bseeds?\b(?! nibble)|notes/|shared/|\bissue \d|\bOCR\b", re.IGNORECASE)


def _generated() -> str:
    """Every Markdown the pages' generate markers ask for."""
    modules = {"arbiter": arbiter, "capture": capture, "codec": codec, "dronecan": dronecan,
               "simulator": simulator, "variables": variables}  # fmt: skip
    parts = []
    for page in DOCS.rglob("*.md"):
        for module, name in re.findall(r"<!-- generate: docgen\.(\w+):(\w+) -->", page.read_text()):
            parts.append(getattr(modules[module], name)())
    assert len(parts) > 20
    return "\n".join(parts)


def test_pages_cite_manuals_not_internal_files() -> None:
    found = []
    for page in sorted(DOCS.rglob("*.md")):
        for number, line in enumerate(page.read_text().splitlines(), 1):
            if INTERNAL.search(line.replace("CRC seed", "").replace("per-type seed", "")):
                found.append(f"{page.relative_to(DOCS)}:{number}: {line.strip()}")
    assert found == []


def test_generated_tables_cite_manuals_not_internal_files() -> None:
    text = _generated().replace("CRC seed", "")
    assert INTERNAL.findall(text) == []


def test_mermaid_is_bundled() -> None:
    config = (ROOT / "mkdocs.yml").read_text()
    assert "  - javascripts/mermaid.min.js" in config
    bundle = (DOCS / "javascripts" / "mermaid.min.js").read_text()
    assert bundle.rstrip().endswith(
        'globalThis["mermaid"] = globalThis.__esbuild_esm_mermaid_nm["mermaid"].default;'
    )
    assert "MIT" in (DOCS / "javascripts" / "mermaid.LICENSE").read_text()


def test_wide_tables_scroll() -> None:
    css = (DOCS / "stylesheets" / "tables.css").read_text()
    assert "overflow-x: auto" in css and "min-width: 0" in css
    assert "  - stylesheets/tables.css" in (ROOT / "mkdocs.yml").read_text()


def test_code_in_a_table_cell_never_breaks_inside_a_word() -> None:
    """The DroneCAN types pages cut ``uavcan.protocol.NodeSt atus`` (the theme's
    ``word-break: break-word``): code in a cell stays on one line, the table scrolls."""
    css = (DOCS / "stylesheets" / "tables.css").read_text()
    rule = css[css.index("td code,") :]
    assert "white-space: nowrap;" in rule and "word-break: keep-all;" in rule


def test_units_in_the_generated_tables() -> None:
    types = dronecan.type_tables()
    assert "| 32 | 16 | float16 | `voltage` | V |  |" in types
    assert "| `status.uptime_sec` | s |" in types
    assert "| `EscStatus` | `temperature` | K | kelvin |" in capture.units_table()
