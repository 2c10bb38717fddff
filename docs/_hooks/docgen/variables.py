"""Markdown tables of the variable lists, for ``docs/veronte/variables.md``.

The docs page calls these through ``<!-- generate: docgen.variables:... -->``
markers, so the published tables are the package's own data.
"""

from __future__ import annotations

from collections.abc import Iterable

from veronte4x.variables.lookup import VARIABLES, by_id
from veronte4x.variables.model import Kind, Variable
from veronte4x.variables.pdi_errors import PDI_ERRORS
from veronte4x.variables.status_links import STATUS_FLAG_BITS, STATUS_STATE_BITS


def _cell(text: str) -> str:
    return text.replace("|", "\\|").replace("<", "&lt;").replace(">", "&gt;").replace("*", "\\*")


def _table(header: Iterable[str], rows: Iterable[Iterable[str]]) -> str:
    head = list(header)
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    lines += ["| " + " | ".join(_cell(c) for c in row) + " |" for row in rows]
    return "\n".join(lines) + "\n"


def _marks(var: Variable) -> str:
    marks = []
    if var.stored_in_1x:
        marks.append("1x")
    if var.deprecated:
        marks.append("deprecated")
    if var.uncertain:
        marks.append("uncertain")
    return ", ".join(marks)


def _variable_table(kind: Kind, with_unit: bool) -> str:
    header = ["ID", "Name", *(["Unit"] if with_unit else []), "Description", "Marks"]
    rows = [
        [
            var.id_text,
            var.name,
            *([var.unit or ""] if with_unit else []),
            var.description,
            _marks(var),
        ]
        for var in VARIABLES[kind]
    ]
    return _table(header, rows)


def bit_table() -> str:
    """The bit variables."""
    return _variable_table(Kind.BIT, with_unit=False)


def rvar_table() -> str:
    """The real variables (RVar), with their "Units/Value" column."""
    return _variable_table(Kind.RVAR, with_unit=True)


def uvar_table() -> str:
    """The integer variables (UVar)."""
    return _variable_table(Kind.UVAR, with_unit=False)


def pdi_error_table() -> str:
    """The PDI errors, with whether each number is inferred."""
    rows = [
        [e.code, str(e.number), e.explanation, "inferred" if e.inferred else "legible"]
        for e in PDI_ERRORS
    ]
    return _table(["Code", "Number", "Explanation", "Number as printed"], rows)


def _bit_names(numbers: Iterable[int]) -> str:
    names = []
    for number in numbers:
        var = by_id(Kind.BIT, number)
        names.append(f"{number} {var.name}" if var is not None else str(number))
    return "; ".join(names)


def status_link_table() -> str:
    """Status message fields and the bit variables they summarise."""
    links = {**STATUS_FLAG_BITS, **STATUS_STATE_BITS}
    return _table(["Status field", "Bit variables"], [[f, _bit_names(b)] for f, b in links.items()])


def correction_list() -> str:
    """Every entry whose reading departs from the seed's text, with what the seed printed."""
    rows = [
        [kind.value, var.id_text, var.name, var.correction]
        for kind, variables in VARIABLES.items()
        for var in variables
        if var.correction is not None
    ]
    return _table(["Kind", "ID", "Name", "Printed / reading"], rows)
