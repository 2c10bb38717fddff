"""The Markdown generated for docs/veronte/variables.md comes from the data."""

from __future__ import annotations

from docgen import variables as docs

from veronte4x.variables import BIT_VARIABLES, INTEGER_VARIABLES, PDI_ERRORS, REAL_VARIABLES


def _rows(markdown: str) -> list[str]:
    return markdown.strip().splitlines()[2:]


def test_one_row_per_entry() -> None:
    assert len(_rows(docs.bit_table())) == len(BIT_VARIABLES)
    assert len(_rows(docs.rvar_table())) == len(REAL_VARIABLES)
    assert len(_rows(docs.uvar_table())) == len(INTEGER_VARIABLES)
    assert len(_rows(docs.pdi_error_table())) == len(PDI_ERRORS)
    assert len(_rows(docs.status_link_table())) == 19


def test_exact_rows() -> None:
    bits = _rows(docs.bit_table())
    assert (
        bits[0] == "| 6 | File System Error | System file manager - 0 for error, 1 for running |  |"
    )
    assert bits[5].startswith("| 11 | 4X CAN failed | ")
    assert bits[5].endswith(" | deprecated |")
    assert "| 230-293 | 4XV Custom msg 0-63 Rx Error | " in bits[48]
    assert bits[48].endswith(" | uncertain |")
    assert "running frequency &lt; 10 Hz" in bits[49]
    assert _rows(docs.rvar_table())[14] == (
        "| 1366 | 4XV Autopilot 0 Score | customType | Score of Autopilot 1x number 0 | 1x |"
    )
    assert _rows(docs.pdi_error_table())[5] == (
        "| pdi_arb_cfg2 | 10005 | Error ID for Arb cfg tmin oor | legible |"
    )
    assert _rows(docs.status_link_table())[0] == "| cbit_ok | 7 System Error; 20 4XV System |"


def test_corrections_listed() -> None:
    rows = _rows(docs.correction_list())
    corrected = [v for v in (*BIT_VARIABLES, *REAL_VARIABLES, *INTEGER_VARIABLES) if v.correction]
    assert len(rows) == len(corrected)
    assert rows[0].startswith("| bit | 11 | 4X CAN failed | ")
