"""Exact entries of the variable lists (seed 000 sections 2.2.1-2.2.3) and the PDI errors (2.3).

The expected rows below were read off the seed by hand; they pin ids, names, units and the
"*" (stored in the Autopilot 1x) marker of every entry.
"""

from __future__ import annotations

import pytest

from veronte4x.variables import (
    BIT_VARIABLES,
    INTEGER_VARIABLES,
    PDI_ERRORS,
    REAL_VARIABLES,
    VARIABLES,
    Kind,
    PdiError,
    Variable,
)

EXPECTED_BITS = [
    ("6", "File System Error", False),
    ("7", "System Error", False),
    ("8", "Memory allocation", False),
    ("9", "PDI Error", False),
    ("10", "CIO Low or C2 Error", False),
    ("11", "4X CAN failed", False),
    ("12", "System Power up BIT Error", False),
    ("16", "Stack C1 usage FAIL", False),
    ("20", "4XV System", True),
    ("21", "4XV System Power up BIT", True),
    ("22", "4XV PDI", True),
    ("23", "4XV Memory allocation", True),
    ("24", "4XV CAN-A BUS OFF", True),
    ("25", "4XV CAN-B BUS OFF", True),
    ("26", "4XV C1 arbiter", True),
    ("27", "4XV Acquisition arbiter", True),
    ("28", "4XV Power A", True),
    ("29", "4XV not in maintenance mode", True),
    ("30", "4XV Alive 0", True),
    ("31", "4XV Alive 1", True),
    ("32", "4XV Alive 2", True),
    ("33", "4XV Alive 3 external", True),
    ("34", "4XV Ready 0", True),
    ("35", "4XV Ready 1", True),
    ("36", "4XV Ready 2", True),
    ("37", "4XV Ready 3 external", True),
    ("38", "4XV Arbitrating", True),
    ("39", "4XV File Open Error", True),
    ("40", "4XV PDI version not compatible", True),
    ("41", "4XV Stack usage FAIL", True),
    ("42", "4XV PWM1 GPIO Off", True),
    ("43", "4XV PWM2 GPIO Off", True),
    ("44", "4XV PWM3 GPIO Off", True),
    ("45", "4XV PWM4 GPIO Off", True),
    ("46", "4XV PWM5 GPIO Off", True),
    ("47", "4XV Watchdog Error (v4.7+)", False),
    ("73", "CAN-A Error", False),
    ("74", "CAN-B Error", False),
    ("75", "CAN-A Warning", False),
    ("76", "CAN-B Warning", False),
    ("117", "Main Power Error", False),
    ("124", "4XV Vcc for Arbiter CPU Error", False),
    ("125", "4XV Vcc-A Error", False),
    ("126", "4XV Vcc-B Error", False),
    ("127", "4XV Vcc-0 Error", False),
    ("128", "4XV Vcc-1 Error", False),
    ("129", "4XV Vcc-2 Error", False),
    ("183", "4X Selected", False),
    ("230-293", "4XV Custom msg 0-63 Rx Error", False),
    ("400", "C1 Low Frequency", False),
    ("402", "Acquisition step missed", False),
    ("800-805", "PWM 0-5 GPIO Off", False),
    ("1200-1209", "User BIT 00-09 Error", False),
]

EXPECTED_RVARS = [
    ("50", "CAN-A Tx Rate", "pkts/s", False),
    ("51", "CAN-B Tx Rate", "pkts/s", False),
    ("52", "CAN-A Tx Skip Rate", "pkts/s", False),
    ("53", "CAN-B Tx Skip Rate", "pkts/s", False),
    ("300", "Relative Timestamp", "s", False),
    ("1350-1356", "4XV ADC0-6 Converted Value", "V", False),
    ("1357-1358", "4XV Internal ADC7-8 Converted Value", "V", False),
    ("1359", "4XV Internal ADC 9 Converted Value", "V", False),
    ("1360", "4XV Vcc for arbiter", "V", False),
    ("1361", "4XV Vcc-A 3.3V", None, False),
    ("1362", "4XV Vcc-B 3.3V", None, False),
    ("1363", "4XV Vcc-0", None, False),
    ("1364", "4XV Vcc-1", None, False),
    ("1365", "4XV Vcc-2", None, False),
    ("1366", "4XV Autopilot 0 Score", "customType", True),
    ("1367", "4XV Autopilot 1 Score", "customType", True),
    ("1368", "4XV Autopilot 2 Score", "customType", True),
    ("1369", "4XV Autopilot External Score", "Decimal", True),
]

EXPECTED_UVARS = [
    ("2", "Internal ADC 0", False),
    ("3-7", "ADC 0-4", False),
    ("8-17", "Internal ADC 1-10", False),
    ("53", "4XV Veronte ID", False),
    ("54", "4XV Veronte CAP", False),
    ("55", "4XV Veronte selected", True),
    ("56", "4XV Config manager status (flash / sd / safe mode)", True),
    ("57", "4XV File system status", True),
    ("58", "4XV CAN to Serial 0 frames dropped", True),
    ("59", "4XV CAN to Serial 1 frames dropped", True),
    ("60-69", "4XV Internal ADC 0-9", True),
    ("70", "4XV VCC for arbiter", True),
    ("72", "4XV VCC B", True),
    ("73", "4XV VCC 0", True),
    ("74", "4XV VCC 1", True),
    ("75", "4XV VCC 2", True),
    ("90", "Version Major", False),
    ("91", "Version Minor", False),
    ("92", "Version Revision", False),
    ("95", "UAV address", False),
    ("450", "CAN-A Tx errors", False),
    ("451", "CAN-A Rx errors", False),
    ("452", "CAN-B Tx errors", False),
    ("453", "CAN-B Rx errors", False),
    ("454-455", "CAN to Serial 0-1 frames dropped", False),
    ("496", "Global configuration state (crc) of memory (Higher 16 bits)", False),
    ("498", "Global configuration state (crc) of files", False),
    ("499", "Global configuration state (crc) of memory", False),
]


def test_bit_variables_exactly() -> None:
    assert [(v.id_text, v.name, v.stored_in_1x) for v in BIT_VARIABLES] == EXPECTED_BITS
    assert all(v.unit is None for v in BIT_VARIABLES)


def test_real_variables_exactly() -> None:
    got = [(v.id_text, v.name, v.unit, v.stored_in_1x) for v in REAL_VARIABLES]
    assert got == EXPECTED_RVARS


def test_integer_variables_exactly() -> None:
    assert [(v.id_text, v.name, v.stored_in_1x) for v in INTEGER_VARIABLES] == EXPECTED_UVARS
    assert all(v.unit is None for v in INTEGER_VARIABLES)


def test_every_entry_has_its_own_kind() -> None:
    for kind, rows in VARIABLES.items():
        assert all(v.kind is kind for v in rows)


def test_selected_entries_in_full() -> None:
    assert BIT_VARIABLES[5] == Variable(
        Kind.BIT,
        11,
        11,
        "4X CAN failed",
        "Fail of CAN communication between 1x and Arbiter - 0 for fail, 1 for communication "
        "OK. This bit is initialized with 1. When it is set as 0, it cannot recover until 1x "
        "is restarted",
        deprecated=True,
        correction='the name cell also reads "Warning: Deprecated variable" (printed "Varning", '
        '"Vyriable"), kept as deprecated=True; name printed variously as "114X CAN failed", '
        '"AY CAN foiled", "4A CAN lalled" (lines 131-143)',
    )
    assert BIT_VARIABLES[8] == Variable(
        Kind.BIT, 20, 20, "4XV System", "System Error bit (bit 7) from the Arbiter", None, True
    )
    assert REAL_VARIABLES[0] == Variable(
        Kind.RVAR, 50, 50, "CAN-A Tx Rate", "CAN-A transmission packet rate", "pkts/s"
    )
    assert INTEGER_VARIABLES[-1] == Variable(
        Kind.UVAR,
        499,
        499,
        "Global configuration state (crc) of memory",
        "Global configuration state (crc) of memory",
    )


@pytest.mark.parametrize(
    ("kind", "first", "description"),
    [
        (
            Kind.BIT,
            7,
            "This bit checks whether the system is running properly. "
            "0 for system error, 1 for system OK",
        ),
        (Kind.BIT, 29, "1 for NOT in maintenance mode - 0 for maintenance mode"),
        (Kind.BIT, 37, "External Autopilot 1x state - 0 for not ready, 1 for ready"),
        (
            Kind.BIT,
            129,
            "Power supply for inner Autopilot 1x number 2 (Based on RVar 1365) - "
            "0 for error, 1 for OK",
        ),
        (Kind.BIT, 800, "PWM GPIO 0-5 communication state - 0 for Off, 1 for On"),
        (Kind.RVAR, 1359, "4XV Internal Arbiter identifier (A or B)"),
        (Kind.UVAR, 57, "State error for DFS2 file system"),
    ],
)
def test_corrected_descriptions(kind: Kind, first: int, description: str) -> None:
    (var,) = [v for v in VARIABLES[kind] if v.first == first]
    assert var.description == description


def test_flags() -> None:
    assert [v.id_text for v in BIT_VARIABLES if v.deprecated] == ["11"]
    uncertain = [(v.kind, v.id_text) for rows in VARIABLES.values() for v in rows if v.uncertain]
    assert uncertain == [(Kind.BIT, "230-293"), (Kind.RVAR, "300"), (Kind.UVAR, "496")]
    assert all(v.correction for rows in VARIABLES.values() for v in rows if v.uncertain)


def test_ranges_are_ordered_and_disjoint_per_kind() -> None:
    for rows in VARIABLES.values():
        assert all(v.first <= v.last for v in rows)
        ids = [number for v in rows for number in v.ids]
        assert len(ids) == len(set(ids))
        assert ids == sorted(ids)


def test_names_unique_per_kind() -> None:
    for rows in VARIABLES.values():
        names = [v.name.casefold() for v in rows]
        assert len(names) == len(set(names))


def test_no_ocr_leftovers() -> None:
    texts = [t for rows in VARIABLES.values() for v in rows for t in (v.name, v.description)]
    for leftover in ("$", "AVV", "AXV", "4X V", "Ix ", " UK", "fot ", "Sate ", "mantenance"):
        assert not [t for t in texts if leftover in t], leftover


def test_pdi_errors_exactly() -> None:
    assert [(e.code, e.number, e.inferred) for e in PDI_ERRORS] == [
        ("pdi_arbitration", 10000, True),
        ("pdi_arbitration_can", 10001, True),
        ("pdi_arbitration_can1", 10002, True),
        ("pdi_arb_cfg0", 10003, True),
        ("pdi_arb_cfg1", 10004, True),
        ("pdi_arb_cfg2", 10005, False),
        ("pdi_arb_cfg3", 10006, False),
        ("pdi_arb_init_time", 10007, True),
        ("pdi_arb_varcfg", 10008, True),
    ]
    assert PDI_ERRORS[6] == PdiError(
        "pdi_arb_cfg3",
        10006,
        "Error ID for Arb cfg hysteresis oor",
        inferred=False,
        seed_text="pdi_arb_cfg3 | 10006 for Arb cfg hysteresis oor",
    )


def test_pdi_seed_text_starts_with_code() -> None:
    for error in PDI_ERRORS:
        assert error.seed_text.startswith(error.code + " | ")
        # A legible number is printed in full; an inferred one is not.
        assert (str(error.number) in error.seed_text) is not error.inferred
