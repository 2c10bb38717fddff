"""The docs speak to users: no internal references, diagrams that work offline, wide tables
that scroll."""

from __future__ import annotations

import re
import types
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
    assert "| 32 | 16 | `float16` | `voltage` | V |  |" in types
    assert "| `status.uptime_sec` | s |" in types
    assert "| `EscStatus` | `temperature` | K | kelvin |" in capture.units_table()


def test_no_dotted_name_in_a_generated_table_cell_is_outside_code() -> None:
    """The DroneCAN types pages: a type name out of code
    (``uavcan.equipment.actuator.Command[<=15]`` in a DSDL column) may break where the page is
    narrow; in code it stays on one line (the rule above)."""
    dotted = re.compile(r"[A-Za-z_]\w*\.[A-Za-z_]")
    loose = []
    tables = (dronecan.types_table(), dronecan.union_tables(), dronecan.type_tables())
    for line in "\n".join(tables).splitlines():
        if not line.startswith("|"):
            continue
        for cell in line.strip("|").split("|"):
            if dotted.search(re.sub(r"`[^`]*`", "", cell)) and "](" not in cell:
                loose.append(cell.strip())
    assert loose == []


API_ORDER = re.compile(
    r"^::: (\S+)\n    options:\n(?:      .*\n)*?      members:\n((?:        - \S+\n)+)",
    re.MULTILINE,
)
"""A ``:::`` directive of an API page with its ``members`` list (the order shown)."""


def test_api_pages_list_what_users_call_first_and_miss_nothing() -> None:
    """The package pages list their members by use (``read`` before ``AlignError``, not the
    theme's constants first): each list holds the package's ``__all__`` (or every class and
    function a module without one defines), each name once."""
    import importlib

    lists = {}
    for page in sorted((DOCS / "api").glob("*.md")):
        for module, members in API_ORDER.findall(page.read_text()):
            names = re.findall(r"- (\S+)", members)
            found = importlib.import_module(module)
            assert len(set(names)) == len(names), module
            if hasattr(found, "__all__"):
                assert sorted(names) == sorted(found.__all__), module
            else:  # every class and function the module defines, and names it has
                defined = {
                    name
                    for name, value in vars(found).items()
                    if not name.startswith("_")
                    and isinstance(value, (type, types.FunctionType))
                    and value.__module__ == module
                }
                assert defined <= set(names), (module, defined - set(names))
                assert all(hasattr(found, name) for name in names), module
            lists[module] = names
    assert {m: names[0] for m, names in lists.items()} == {
        "veronte4x.capture": "read",
        "veronte4x.client": "ClientProtocol",
        "veronte4x.client.bus": "BusClient",
        "veronte4x.codec": "decode",
        "veronte4x.simulator": "SimulatedEsc",
        "veronte4x.dronecan.transfer": "encode",
    }
    client = (DOCS / "api" / "client.md").read_text()
    assert client.index("::: veronte4x.client.bus") < client.index("::: veronte4x.client\n")
