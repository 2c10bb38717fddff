"""PDI errors the Veronte Autopilot 4x Arbiter can report.

Source: 4x Software Manual, section 2.3 "List of PDI errors". Only the numbers of
pdi_arb_cfg2 (10005) and pdi_arb_cfg3 (10006) are legible; the others are inferred,
consecutive from 10000 in the order printed, and are flagged ``inferred=True``. ``seed_text`` keeps
each row as printed
(the tab between columns shown as " | "). "oor" is the manual's "out of range".
"""

from __future__ import annotations

from veronte4x.variables.model import PdiError

PDI_ERRORS: tuple[PdiError, ...] = (
    PdiError(
        "pdi_arbitration",
        10000,
        "Error ID for Arbitration cfg",
        inferred=True,
        seed_text="pdi_arbitration | 1000 Derror ID for Arbitration cfg",
    ),
    PdiError(
        "pdi_arbitration_can",
        10001,
        "Error ID for Arbitration_can cfg",
        inferred=True,
        seed_text="pdi_arbitration_can | 1000Error ID for Arbitration_can cfg",
    ),
    PdiError(
        "pdi_arbitration_can1",
        10002,
        "Error ID for Arbitration_can cfg",
        inferred=True,
        seed_text="pdi_arbitration_can1 | 1000Error ID for Arbitration_can cfg",
    ),
    PdiError(
        "pdi_arb_cfg0",
        10003,
        "Error ID for Arb cfg preferred ap oor",
        inferred=True,
        seed_text="pdi_arb_cfg0 | 1000Brror ID for Arb cfg preferred ap oor",
    ),
    PdiError(
        "pdi_arb_cfg1",
        10004,
        "Error ID for Arb cfg method oor (out of range)",
        inferred=True,
        seed_text="pdi_arb_cfg1 | 1000 Arror ID for Arb cfg method oor(out of range)",
    ),
    PdiError(
        "pdi_arb_cfg2",
        10005,
        "Error ID for Arb cfg tmin oor",
        inferred=False,
        seed_text="pdi_arb_cfg2 | 10005 rror ID for Arb cfg tmin oor",
    ),
    PdiError(
        "pdi_arb_cfg3",
        10006,
        "Error ID for Arb cfg hysteresis oor",
        inferred=False,
        seed_text="pdi_arb_cfg3 | 10006 for Arb cfg hysteresis oor",
    ),
    PdiError(
        "pdi_arb_init_time",
        10007,
        "Error ID for Arbiter Power Init Time less than 0",
        inferred=True,
        seed_text="pdi_arb_init_time | 100 IError ID for Arbiter Power Init Time less than 0",
    ),
    PdiError(
        "pdi_arb_varcfg",
        10008,
        "Incorrect arbiter variable configuration",
        inferred=True,
        seed_text="pdi_arb_varcfg | 100 IB correct arbiter variable configuration",
    ),
)
